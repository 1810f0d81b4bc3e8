"""The scene of the translucent-caster tests (docs/translucency.md): a
directional light straight down, an opaque floor, and one caster 2 units
above it; visibility I_on / I_off in float against the same scene without
shadows (float_render.py), 320x240, read on a small patch of the floor under
the caster's centre (well inside the shadow, and not behind the caster in
the image). CASES are the casters with the visibility each must leave:

- a closed sphere (128 x 128) of opacity 0.5, crossed twice: 0.25;
- the same sphere at opacity 1 (the control): 0; at opacity 0: 1;
- a closed thin box (a slab: two crossings) of opacity 0.4: 0.36;

each within TOLERANCE (mean, min and max). check_technique() checks them
all for one technique."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check  # noqa: E402

import numpy as np  # noqa: E402
import float_render as fr  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkFiltersSources import (vtkCubeSource, vtkPlaneSource,  # noqa: E402
                                          vtkSphereSource)
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass  # noqa: E402

W, H = 320, 240
TOLERANCE = 0.03
HEIGHT = 2.0       # the caster's centre above the floor
PATCH = 0.2        # the patch's half width on the floor (the casters' half width >= 0.8)


def add(renderer, source, opacity=1.0):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = fr.lambertian(vtkActor())
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(opacity)
    renderer.AddActor(actor)
    return actor


def sphere():
    s = vtkSphereSource()
    s.SetCenter(0, 0, HEIGHT)
    s.SetRadius(0.8)
    s.SetThetaResolution(128)
    s.SetPhiResolution(128)
    return s


def slab():
    c = vtkCubeSource()
    c.SetXLength(1.6)
    c.SetYLength(1.6)
    c.SetZLength(0.1)
    c.SetCenter(0, 0, HEIGHT)
    return c


def floor():
    p = vtkPlaneSource()
    p.SetOrigin(-5, -5, 0)
    p.SetPoint1(5, -5, 0)
    p.SetPoint2(-5, 5, 0)
    return p


CASES = (("sphere 0.5", sphere, 0.5, 0.25),
         ("sphere 1 (control)", sphere, 1.0, 0.0),
         ("sphere 0", sphere, 0.0, 1.0),
         ("slab 0.4", slab, 0.4, 0.36))


def scene(caster, opacity, before=None):
    """The scene's build; before(renderer), when given, adds actors ahead of
    the floor."""
    def build(renderer):
        if before:
            before(renderer)
        add(renderer, floor())
        add(renderer, caster(), opacity)
        # Straight down; the camera sees the floor under the caster beside it.
        renderer.AddLight(fr.scene_light((0.0, 0.0, 10.0), (0.0, 0.0, 0.0)))
        fr.set_camera(renderer, (8, -8, 6), (0, 0, 0.5))
    return build


def patch_pixels(renderer):
    """(rows, cols) of the patch's pixels, row 0 on top."""
    rows, cols = [], []
    for x in np.linspace(-PATCH, PATCH, 9):
        for y in np.linspace(-PATCH, PATCH, 9):
            renderer.SetWorldPoint(x, y, 0.0, 1.0)
            renderer.WorldToDisplay()
            dx, dy, _ = renderer.GetDisplayPoint()
            rows.append(H - 1 - int(round(dy)))
            cols.append(int(round(dx)))
    return np.array(rows), np.array(cols)


def render(build, technique):
    """(float image, patch pixels) of `build` with technique (None: no shadows)."""
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    build(renderer)
    inner = (vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique) if technique
             else vtkRenderStepsPass())
    capture = fr.FloatCapture(renderer, inner)
    window.Render()
    image = capture.read()
    pixels = patch_pixels(renderer)
    capture.release()
    window.Finalize()
    return image, pixels


def patch_visibility(caster, opacity, technique, before=None):
    """(mean, min, max, valid pixels, pixels) of the patch's visibility."""
    build = scene(caster, opacity, before)
    off, pixels = render(build, None)
    on, _ = render(build, technique)
    v, valid = fr.visibility(on, off)
    rows, cols = pixels
    ok = valid[rows, cols]
    values = v[rows, cols][ok]
    return (float(values.mean()) if values.size else float("nan"),
            float(values.min()) if values.size else float("nan"),
            float(values.max()) if values.size else float("nan"), int(ok.sum()), len(rows))


def check_technique(technique):
    """Every case of CASES under `technique`, each printed and checked."""
    for name, caster, opacity, expected in CASES:
        mean, lo, hi, n, total = patch_visibility(caster, opacity, technique)
        print(f"{technique}, {name}: visibility under the centre {mean:.4f} "
              f"(min {lo:.4f}, max {hi:.4f}, {n} of {total} patch px valid); expected {expected}")
        check(n == total, f"{technique}, {name}: every patch pixel is valid floor ({n} of {total})")
        check(abs(mean - expected) <= TOLERANCE and lo >= expected - TOLERANCE
              and hi <= expected + TOLERANCE,
              f"{technique}, {name}: visibility {mean:.4f} ({lo:.4f}..{hi:.4f}) is {expected} "
              f"within {TOLERANCE}")
