"""The scenes and measurements of the translucency tests (issue 31;
docs/translucency.md), shared by test_translucent_casters.py (every
technique) and test_translucent_csm.py (csm's own variants).

A directional light straight down, an opaque floor at z = 0, casters
centred HEIGHT above it; the camera sees the floor under them beside them.
Visibility is I_on / I_off in float against the same scene without shadows
(float_render.py), 320x240, read on a 9 x 9 patch of points around a
centre at a given height (the floor under the casters' centre unless said
otherwise). Expected values follow the core's rule (vsh_transmit.h): each
crossing lets (1 - opacity) through, crossings multiply."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "render"))

import numpy as np  # noqa: E402
import float_render as fr  # noqa: E402
import robust_scenes as rs  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkCubeSource  # noqa: E402

W, H = 320, 240
TOLERANCE = 0.03
HEIGHT = 2.0       # the casters' centre above the floor
PATCH = 0.2        # the patch's half width (the casters' half width >= 0.8)


def add(renderer, poly, opacity=1.0):
    """A white Lambertian actor of `poly` at `opacity`."""
    actor = rs.poly_actor(poly)
    actor.GetProperty().SetOpacity(opacity)
    renderer.AddActor(actor)
    return actor


def sphere(radius=0.8, z=HEIGHT):
    return rs.sphere_poly((0, 0, z), radius, res=128)


def slab(side=1.6, thickness=0.1, z=HEIGHT):
    c = vtkCubeSource()
    c.SetXLength(side)
    c.SetYLength(side)
    c.SetZLength(thickness)
    c.SetCenter(0, 0, z)
    c.Update()
    return c.GetOutput()


def square(half, z):
    """A horizontal square of half width `half` at height z."""
    return rs.floor_poly(half=half, z=z)


def straight_down(renderer):
    renderer.AddLight(fr.scene_light((0.0, 0.0, 10.0), (0.0, 0.0, 0.0)))
    fr.set_camera(renderer, (8, -8, 6), (0, 0, 0.5))


def caster_scene(casters, extra=None):
    """The floor and casters [(polydata, opacity)] under the light, then
    extra(renderer) when given."""
    def build(renderer):
        add(renderer, square(5.0, 0.0))
        for poly, opacity in casters:
            add(renderer, poly, opacity)
        straight_down(renderer)
        if extra:
            extra(renderer)
    return build


# (name, casters, expected visibility under the centre)
CASES = (
    ("sphere 0.5", [(sphere(), 0.5)], 0.25),
    ("sphere 1 (control)", [(sphere(), 1.0)], 0.0),
    ("sphere 0", [(sphere(), 0.0)], 1.0),
    ("slab 0.4", [(slab(), 0.4)], 0.36),
    ("shells 0.5 around 0.2", [(sphere(0.9), 0.5), (sphere(0.5), 0.2)], 0.16),
)


def patch_pixels(renderer, z=0.0, centre=(0.0, 0.0)):
    """(rows, cols) of the patch at height z around `centre` (x, y), row 0
    on top."""
    rows, cols = [], []
    for x in np.linspace(-PATCH, PATCH, 9):
        for y in np.linspace(-PATCH, PATCH, 9):
            renderer.SetWorldPoint(centre[0] + x, centre[1] + y, z, 1.0)
            renderer.WorldToDisplay()
            dx, dy, _ = renderer.GetDisplayPoint()
            rows.append(H - 1 - int(round(dy)))
            cols.append(int(round(dx)))
    return np.array(rows), np.array(cols)


def render(build, technique, z=0.0, centre=(0.0, 0.0), rgb=False):
    """(float image, patch pixels) of `build` through `technique` (a
    registry name, a pass, or None: no shadows)."""
    return fr.render_technique(build, technique, W, H,
                               lambda renderer, _: patch_pixels(renderer, z, centre), rgb=rgb)


def patch_values(build, technique, z=0.0, centre=(0.0, 0.0), channel=None):
    """(visibility of the valid patch pixels, patch pixel count); `channel`
    0-2 measures one colour channel, None the summed RGB."""
    rgb = channel is not None
    off, pixels = render(build, None, z, centre, rgb)
    on, _ = render(build, technique, z, centre, rgb)
    if rgb:
        on, off = on[:, :, channel], off[:, :, channel]
    v, valid = fr.visibility(on, off)
    rows, cols = pixels
    ok = valid[rows, cols]
    return v[rows, cols][ok], len(rows)


def patch_visibility(build, technique, z=0.0, centre=(0.0, 0.0)):
    """(mean, min, max, valid px, patch px) of I_on / I_off on the patch."""
    values, total = patch_values(build, technique, z, centre)
    if not values.size:
        return float("nan"), float("nan"), float("nan"), 0, total
    return (float(values.mean()), float(values.min()), float(values.max()), int(values.size),
            total)


def check_patch(check, label, build, technique, expected, tolerance=TOLERANCE, **where):
    """The patch is all valid and its visibility (mean, min and max) is
    `expected` within `tolerance`."""
    mean, lo, hi, n, total = patch_visibility(build, technique, **where)
    print(f"{label}: visibility {mean:.4f} (min {lo:.4f}, max {hi:.4f}, {n} of {total} "
          f"patch px valid); expected {expected}")
    check(n == total and abs(mean - expected) <= tolerance and lo >= expected - tolerance
          and hi <= expected + tolerance,
          f"{label}: {mean:.4f} ({lo:.4f}..{hi:.4f}) is {expected} within {tolerance}")


def check_cases(check, label, technique, cases=CASES, expect_none=False):
    """Every case under `technique` (a name or a make-pass callable's
    pass); with expect_none, everything but the opaque control reads 1."""
    for name, casters, expected in cases:
        want = expected if not expect_none or expected == 0.0 else 1.0
        make = technique() if callable(technique) else technique
        check_patch(check, f"{label}, {name}, floor under the centre", caster_scene(casters),
                    make, want)
