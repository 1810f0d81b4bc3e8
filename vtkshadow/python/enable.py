"""enable_shadows: shadows on an ordinary VTK scene in one call."""
import math

from vtkmodules.vtkCommonCore import vtkObjectBase

from .vtkshadow import vtkShadowTechnique


def _what_to_pass(given):
    """Why `given` is not a renderer enable_shadows takes, and what to pass
    instead; None when it is one (a vtkRenderer of an OpenGL window)."""
    if isinstance(given, vtkObjectBase):
        if given.IsA("vtkOpenGLRenderer"):
            return None
        name = given.GetClassName()
        if given.IsA("vtkRenderer"):
            return (f"got {name}, not an OpenGL one: import vtkmodules.vtkRenderingOpenGL2 "
                    "before making the renderer")
        if given.IsA("vtkRenderWindow"):
            return (f"got {name}, a vtkRenderWindow: pass one of its renderers, e.g. "
                    "window.GetRenderers().GetFirstRenderer()")
        return f"got {name}"
    if given is None:
        return "got None"
    kind = type(given).__name__
    try:
        held = getattr(given, "renderer", None)
    except Exception:  # noqa: BLE001  (a property that fails is no renderer)
        held = None
    if isinstance(held, vtkObjectBase) and held.IsA("vtkRenderer"):
        return (f"got {kind}, which holds its current renderer in .renderer: pass "
                f"{kind.lower()}.renderer")
    if isinstance(given, str) and vtkShadowTechnique.IsKnownTechnique(given):
        return (f"got str {given!r}: the renderer comes first, "
                f"enable_shadows(renderer, technique={given!r})")
    return f"got {kind}"


def enable_shadows(renderer, technique="auto", max_error=None, key_light=True,
                   residual_light=0.0, **options):
    """Switch shadows on for `renderer` (a vtkRenderer of an OpenGL window).

    technique:      a registered technique name (vtkShadowTechniqueRegistry;
                    "auto" picks per light the cheapest that meets max_error).
    max_error:      auto's error target, wrong_pct (percent of pixels whose
                    shadow state may be wrong; default 0.5). Only for "auto".
    key_light:      while the renderer has only VTK's automatic headlight
                    (or no light), keep vtkLightKit's key light on it so
                    shadows are visible. Decided at each frame from the
                    lights the application has then, not at this call: a
                    light added later (vedo's show()) counts, and the key
                    light goes again when the application adds its own
                    (technique.GetLightMessage() says what is done). Scenes
                    with their own lights are left alone. False adds none
                    and removes those an earlier call added.
    residual_light: how much of a light remains in its shadow, 0..1 (0: the
                    physical hard shadow; 0.3 keeps 30%).
    options:        any other technique setting by name (docs/techniques.md),
                    e.g. cascades=2 for csm, detect_receivers=0.

    Flat actors (floors, cut planes) become plane receivers when no actor is
    marked (technique.GetDetectedReceiver(i)). Returns the vtkShadowTechnique;
    raises TypeError for anything but a vtkRenderer of an OpenGL window
    (saying what to pass: for vedo's or PyVista's Plotter, plotter.renderer),
    ValueError for an unknown technique or setting, and then changes nothing.
    """
    wrong = _what_to_pass(renderer)
    if wrong:
        raise TypeError("enable_shadows: needs a vtkRenderer of an OpenGL render window; " + wrong)
    made = vtkShadowTechnique()
    if not vtkShadowTechnique.IsKnownTechnique(technique):
        raise ValueError(f"enable_shadows: unknown technique {technique!r}; known: "
                         f"{vtkShadowTechnique.GetKnownTechniques()}")
    made.SetName(technique)
    settings = dict(options)
    if max_error is not None:
        settings["max_error"] = max_error
    settings["residual_light"] = residual_light
    for key, value in settings.items():
        if isinstance(value, bool):
            value = int(value)
        if not isinstance(value, (int, float)) or not math.isfinite(value) \
                or not made.SetOption(key, float(value)):
            raise ValueError(f"enable_shadows: technique {technique!r} has no setting "
                             f"{key}={value!r} (docs/techniques.md lists the keys)")
    made.SetAutoKeyLight(bool(key_light))
    if not made.Enable(renderer):
        raise ValueError(f"enable_shadows: cannot enable technique {technique!r}: "
                         f"{made.GetPassMessage() or 'see the VTK error above'}")
    return made
