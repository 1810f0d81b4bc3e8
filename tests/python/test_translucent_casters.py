"""Translucent surfaces under one technique (issue 31; docs/translucency.md):
they cast partial shadows with the transmittance the core defines
(vsh_transmit.h: each crossing lets (1 - opacity) through, crossings
multiply), and they receive shadows on their own fragments.

A directional light straight down, an opaque floor, casters 2 units above
it; visibility I_on / I_off in float against the same scene without
shadows (float_render.py), 320x240, read on a patch of the floor under the
casters' centre (inside the shadow, not behind the caster in the image):

  case                              expected visibility
  sphere of opacity 0.5 (2 crossings)   0.25
  the same sphere at opacity 1          0     (the control: opaque)
  the same sphere at opacity 0          1
  slab of opacity 0.4 (2 crossings)     0.36
  shells 0.5 around 0.2 (4 crossings)   0.16

each within 0.03 (mean, min and max over the patch).

Coloured: a red slab (colour (0.9, 0.2, 0.1), opacity 0.5, filter 0.6,
vtkShadowPassBase.FILTER()) lets (1 - a) ((1 - f) + f c_k) through per
crossing, so two crossings leave (0.2209, 0.0676, 0.0529) in red, green and
blue: each channel's visibility within 0.03. `--grey` is for a technique
that draws tinted shadows grey (it must then say so per light).

Receiving: a translucent plate (opacity 0.5) under an opaque sphere, no
floor (drawn by order-independent blending, and again by depth peeling). Over the black background a pixel of the plate is its own light
times 0.5 in both renders, so I_on / I_off is the plate's visibility: 0
where the sphere's shadow falls when the plate receives it, 1 when it does
not. `--receives` says which the technique is to give.

`--expect-none` is for a technique that draws no translucent shadow (VTK's
own pass): every case reads 1 except the opaque control.

Usage: test_translucent_casters.py TECHNIQUE [--receives yes|no] [--expect-none] [--grey]"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import numpy as np  # noqa: E402
import float_render as fr  # noqa: E402
import robust_scenes as rs  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkCubeSource  # noqa: E402

W, H = 320, 240
TOLERANCE = 0.03
HEIGHT = 2.0       # the casters' centre above the floor
PATCH = 0.2        # the patch's half width on the floor (the casters' half width >= 0.8)


def add(renderer, poly, opacity=1.0):
    actor = rs.poly_actor(poly)
    actor.GetProperty().SetOpacity(opacity)
    renderer.AddActor(actor)
    return actor


def sphere(radius=0.8, z=HEIGHT):
    return rs.sphere_poly((0, 0, z), radius, res=128)


def slab(side, thickness, z):
    c = vtkCubeSource()
    c.SetXLength(side)
    c.SetYLength(side)
    c.SetZLength(thickness)
    c.SetCenter(0, 0, z)
    c.Update()
    return c.GetOutput()


def plate(z):
    return rs.floor_poly(half=1.5, z=z)


RED = (0.9, 0.2, 0.1)
RED_FILTER = 0.6


def red_slab_scene(renderer):
    add(renderer, rs.floor_poly(half=5.0))
    slab_actor = add(renderer, slab(1.6, 0.1, HEIGHT), 0.5)
    slab_actor.GetProperty().SetColor(*RED)
    fr.set_key(slab_actor, vtkshadow.vtkShadowPassBase.FILTER(), RED_FILTER)
    straight_down(renderer)


def straight_down(renderer):
    renderer.AddLight(fr.scene_light((0.0, 0.0, 10.0), (0.0, 0.0, 0.0)))
    fr.set_camera(renderer, (8, -8, 6), (0, 0, 0.5))


def caster_scene(casters):
    """casters: [(polydata, opacity)] over the floor."""
    def build(renderer):
        add(renderer, rs.floor_poly(half=5.0))
        for poly, opacity in casters:
            add(renderer, poly, opacity)
        straight_down(renderer)
    return build


def receiver_scene(renderer):
    # No floor: over the black background a pixel of the plate is its own
    # light times its opacity in both renders, so I_on / I_off is the
    # plate's visibility.
    add(renderer, plate(1.0), 0.5)
    add(renderer, sphere(0.5, 2.5))   # opaque, shadows the plate
    straight_down(renderer)


def patch_pixels(renderer, z, centre=(0.0, 0.0)):
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


def render(build, technique, z, centre=(0.0, 0.0), rgb=False):
    """(float image, patch pixels at height z around `centre`) of `build`
    with technique (None: no shadows)."""
    return fr.render_technique(build, technique, W, H,
                               lambda renderer, _: patch_pixels(renderer, z, centre), rgb=rgb)


def patch_visibility(build, technique, z=0.0, centre=(0.0, 0.0)):
    """(mean, min, max, valid px, patch px) of I_on / I_off on the patch."""
    off, pixels = render(build, None, z, centre)
    on, _ = render(build, technique, z, centre)
    v, valid = fr.visibility(on, off)
    rows, cols = pixels
    ok = valid[rows, cols]
    values = v[rows, cols][ok]
    if not values.size:
        return float("nan"), float("nan"), float("nan"), 0, len(rows)
    return (float(values.mean()), float(values.min()), float(values.max()), int(ok.sum()),
            len(rows))


CASES = (
    ("sphere 0.5", [(sphere(), 0.5)], 0.25),
    ("sphere 1 (control)", [(sphere(), 1.0)], 0.0),
    ("sphere 0", [(sphere(), 0.0)], 1.0),
    ("slab 0.4", [(slab(1.6, 0.1, HEIGHT), 0.4)], 0.36),
    ("shells 0.5 around 0.2", [(sphere(0.9), 0.5), (sphere(0.5), 0.2)], 0.16),
)


def check_casting(technique, expect_none):
    for name, casters, expected in CASES:
        want = expected if not expect_none or expected == 0.0 else 1.0
        mean, lo, hi, n, total = patch_visibility(caster_scene(casters), technique)
        print(f"{technique}, {name}: floor visibility under the centre {mean:.4f} "
              f"(min {lo:.4f}, max {hi:.4f}, {n} of {total} px valid); expected {want}")
        check(n == total, f"{name}: every patch pixel is valid floor ({n} of {total})")
        check(abs(mean - want) <= TOLERANCE and lo >= want - TOLERANCE
              and hi <= want + TOLERANCE,
              f"{name}: {technique}'s visibility {mean:.4f} ({lo:.4f}..{hi:.4f}) is {want} "
              f"within {TOLERANCE}")


def peeled_receiver_scene(renderer):
    renderer.UseDepthPeelingOn()
    receiver_scene(renderer)


def check_tint(technique, grey):
    """The red filter slab's shadow per colour channel."""
    off, pixels = render(red_slab_scene, None, 0.0, rgb=True)
    on, _ = render(red_slab_scene, technique, 0.0, rgb=True)
    rows, cols = pixels
    crossing = [0.5 * ((1 - RED_FILTER) + RED_FILTER * c) for c in RED]
    want = [t * t for t in crossing]
    if grey:
        want = [0.25] * 3
    for k, name in enumerate(("red", "green", "blue")):
        v, valid = fr.visibility(on[:, :, k], off[:, :, k])
        ok = valid[rows, cols]
        values = v[rows, cols][ok]
        mean = float(values.mean()) if values.size else float("nan")
        print(f"{technique}, red filter slab, {name}: visibility {mean:.4f} "
              f"({int(ok.sum())} of {len(rows)} px valid); expected {want[k]:.4f}")
        check(values.size == len(rows) and abs(mean - want[k]) <= TOLERANCE,
              f"{name}: {technique}'s visibility {mean:.4f} is {want[k]:.4f} within {TOLERANCE}")


def check_receiving(technique, receives):
    want = 0.0 if receives else 1.0
    # Depth peeling as well as the default order-independent blending.
    mean, lo, hi, n, total = patch_visibility(peeled_receiver_scene, technique, z=1.0)
    print(f"{technique}, depth peeling, translucent plate under an opaque sphere: I_on / I_off "
          f"{mean:.4f} (min {lo:.4f}, max {hi:.4f}); expected {want}")
    check(n == total and abs(mean - want) <= 0.05 and hi <= want + 0.05 and lo >= want - 0.05,
          f"depth peeling: the plate's visibility {mean:.4f} is {want} within 0.05")
    mean, lo, hi, n, total = patch_visibility(receiver_scene, technique, z=1.0)
    print(f"{technique}, translucent plate under an opaque sphere: I_on / I_off {mean:.4f} "
          f"(min {lo:.4f}, max {hi:.4f}, {n} of {total} px valid); expected {want} "
          f"({'receives' if receives else 'does not receive'})")
    check(n == total and abs(mean - want) <= 0.05 and hi <= want + 0.05 and lo >= want - 0.05,
          f"the translucent plate {'receives' if receives else 'does not receive'} the "
          f"sphere's shadow under {technique}: {mean:.4f} is {want} within 0.05")
    # Outside the sphere's shadow the plate stays lit: it does not shadow
    # its own fragments.
    mean, lo, hi, n, total = patch_visibility(receiver_scene, technique, z=1.0,
                                              centre=(1.1, 1.1))
    print(f"{technique}, translucent plate outside the shadow: I_on / I_off {mean:.4f} "
          f"(min {lo:.4f}, max {hi:.4f}, {n} of {total} px valid); expected 1")
    check(n == total and lo >= 0.97,
          f"the translucent plate is lit outside the shadow under {technique}: min {lo:.4f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("technique")
    parser.add_argument("--receives", choices=("yes", "no"), default="yes")
    parser.add_argument("--expect-none", action="store_true")
    parser.add_argument("--grey", action="store_true")
    args = parser.parse_args()
    check_casting(args.technique, args.expect_none)
    if not args.expect_none:
        check_tint(args.technique, args.grey)
    check_receiving(args.technique, args.receives == "yes")
    finish()


main()
