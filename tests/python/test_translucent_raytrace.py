"""raytrace's partial shadows of translucent actors (issue 31, first
technique; docs/translucency.md): a shadow ray's visibility is the product
of (1 - opacity) over the translucent surfaces it crosses (vsh_transmit.h),
0 at an opaque one. The scene and the expectations are
translucent_scene.py's: under a directional light straight down, the floor
under a closed sphere of opacity 0.5 reads 0.25, at opacity 1 0, at
opacity 0 1, under a slab of opacity 0.4 0.36, every value within 0.03.

planar still ignores translucent casters (1 under the opacity 0.5 sphere);
csm casts them through its transmittance maps (0.25 there,
test_translucent_csm.py checks every case). Before raytrace took
translucent casters the opacity 0.5 sphere's patch read 1 (no shadow at
all).

Usage: test_translucent_raytrace.py"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from checks import check, finish  # noqa: E402

import translucent_scene as ts  # noqa: E402

ts.check_cases("raytrace")

# The other techniques: planar ignores a translucent actor, csm casts it.
for technique, expected, what in (("planar", 1.0, "still ignores the translucent sphere"),
                                  ("csm", 0.25, "casts the translucent sphere's partial shadow")):
    mean, lo, hi, n, total = ts.patch_visibility(ts.sphere, 0.5, technique)
    print(f"{technique}, sphere 0.5: visibility under the centre {mean:.4f} "
          f"(min {lo:.4f}, max {hi:.4f})")
    check(n == total and lo >= expected - ts.TOLERANCE and hi <= expected + ts.TOLERANCE,
          f"{technique} {what} ({lo:.4f}..{hi:.4f} is {expected} within {ts.TOLERANCE})")
finish()
