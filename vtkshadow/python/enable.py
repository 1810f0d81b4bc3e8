"""enable_shadows: shadows on an ordinary VTK scene in one call."""
import math

from .vtkshadow import vtkShadowTechnique


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
    raises ValueError for an unknown technique or setting, TypeError for a
    renderer that is not an OpenGL renderer, and then changes nothing.
    """
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
    if renderer is None or not renderer.IsA("vtkOpenGLRenderer"):
        raise TypeError("enable_shadows: need a vtkRenderer of an OpenGL render window, got "
                        f"{type(renderer).__name__}")
    made.SetAutoKeyLight(bool(key_light))
    if not made.Enable(renderer):
        raise ValueError(f"enable_shadows: cannot enable technique {technique!r}")
    return made
