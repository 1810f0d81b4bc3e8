"""Translucent surfaces under one technique (issue 31; docs/translucency.md):
they cast partial shadows with the transmittance the core defines
(vsh_transmit.h: each crossing lets (1 - opacity) through, crossings
multiply), and they receive shadows on their own fragments.

The scenes and measurement are translucent_scene.py's: a directional light
straight down, an opaque floor, casters 2 units above it; visibility
I_on / I_off in float against the same scene without shadows, 320x240, on
a patch of the floor under the casters' centre:

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
own pass, which does not draw translucent actors at all): every case reads
1 except the opaque control, and it says so per light (GetLightNote).

Usage: test_translucent_casters.py TECHNIQUE [--receives yes|no] [--expect-none] [--grey]"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import float_render as fr  # noqa: E402
import translucent_scene as ts  # noqa: E402
import vtkshadow  # noqa: E402

RED = (0.9, 0.2, 0.1)
RED_FILTER = 0.6


def red_slab_scene(renderer):
    slab = ts.add(renderer, ts.slab(), 0.5)
    slab.GetProperty().SetColor(*RED)
    fr.set_key(slab, vtkshadow.vtkShadowPassBase.FILTER(), RED_FILTER)
    ts.caster_scene([])(renderer)


def receiver_scene(renderer, peel=False):
    # No floor: over the black background a pixel of the plate is its own
    # light times its opacity in both renders, so I_on / I_off is the
    # plate's visibility.
    renderer.SetUseDepthPeeling(peel)
    ts.add(renderer, ts.square(1.5, 1.0), 0.5)   # the translucent plate
    ts.add(renderer, ts.sphere(0.5, 2.5))        # opaque, shadows the plate
    ts.straight_down(renderer)


def check_tint(technique, grey):
    """The red filter slab's shadow per colour channel."""
    crossing = [0.5 * ((1 - RED_FILTER) + RED_FILTER * c) for c in RED]
    want = [0.25] * 3 if grey else [t * t for t in crossing]
    for k, name in enumerate(("red", "green", "blue")):
        values, total = ts.patch_values(red_slab_scene, technique, channel=k)
        mean = float(values.mean()) if values.size else float("nan")
        print(f"{technique}, red filter slab, {name}: visibility {mean:.4f} "
              f"({values.size} of {total} px valid); expected {want[k]:.4f}")
        check(values.size == total and abs(mean - want[k]) <= ts.TOLERANCE,
              f"{name}: {technique}'s visibility {mean:.4f} is {want[k]:.4f} within "
              f"{ts.TOLERANCE}")


def light_note(build, technique):
    """The pass's GetLightNote(0) after a frame of `build`."""
    return fr.render_technique(build, technique, ts.W, ts.H,
                               lambda renderer, inner: inner.GetLightNote(0))[1]


def check_note(technique, grey, expect_none):
    """What a technique leaves out, it says per light: grey filters, or
    (VTK's pass) no translucent shadow at all; nothing where it draws it."""
    note = light_note(red_slab_scene, technique)
    print(f"{technique}, red filter slab: light 0's note {note!r}")
    if expect_none:
        check("cast no shadow" in note, f"{technique} says translucent actors cast nothing")
    elif grey:
        check("grey" in note, f"{technique} says the filter colour is drawn grey")
    else:
        check(note == "", f"{technique} leaves nothing out: no note")


def check_receiving(technique, receives):
    want = 0.0 if receives else 1.0
    verb = "receives" if receives else "does not receive"
    for peel in (False, True):
        ts.check_patch(check, f"{technique}, {'depth peeling' if peel else 'blending'}: the "
                       f"translucent plate {verb} the sphere's shadow",
                       lambda r, peel=peel: receiver_scene(r, peel), technique, want, 0.05, z=1.0)
    # Outside the sphere's shadow the plate stays lit: it does not shadow
    # its own fragments.
    ts.check_patch(check, f"{technique}: the translucent plate outside the shadow",
                   receiver_scene, technique, 1.0, z=1.0, centre=(1.1, 1.1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("technique")
    parser.add_argument("--receives", choices=("yes", "no"), default="yes")
    parser.add_argument("--expect-none", action="store_true")
    parser.add_argument("--grey", action="store_true")
    args = parser.parse_args()
    ts.check_cases(check, args.technique, args.technique, expect_none=args.expect_none)
    if not args.expect_none:
        check_tint(args.technique, args.grey)
    check_note(args.technique, args.grey, args.expect_none)
    if not args.expect_none:  # VTK's own pass does not draw translucent actors at all
        check_receiving(args.technique, args.receives == "yes")
    finish()


main()
