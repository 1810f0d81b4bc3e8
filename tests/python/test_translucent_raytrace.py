"""raytrace's partial shadows of translucent actors (issue 31, first
technique; docs/translucency.md): a shadow ray's visibility is the product
of (1 - opacity) over the translucent surfaces it crosses (vsh_transmit.h),
0 at an opaque one. The scene and the cases are translucent_patch.py's: a
directional light straight down, an opaque floor, one caster 2 units above
it, visibility read on a patch of the floor under the caster's centre:

- a closed sphere (128 x 128) of opacity 0.5, crossed twice: 0.25;
- the same sphere at opacity 1 (the control): 0; at opacity 0: 1;
- a closed thin box (a slab: two crossings) of opacity 0.4: 0.36;
  every value within 0.03.

csm still ignores translucent casters (1 under the opacity 0.5 sphere);
planar and volume take them too (test_translucent_planar_volume.py).
Before raytrace took translucent casters the opacity 0.5 sphere's patch
read 1 (no shadow at all).

Usage: test_translucent_raytrace.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402
import translucent_patch as tp  # noqa: E402

tp.check_technique("raytrace")

# csm is unchanged: a translucent actor casts nothing there yet.
mean, lo, hi, n, total = tp.patch_visibility(tp.sphere, 0.5, "csm")
print(f"csm, sphere 0.5: visibility under the centre {mean:.4f} (min {lo:.4f}, max {hi:.4f})")
check(n == total and lo >= 1.0 - tp.TOLERANCE,
      f"csm still ignores the translucent sphere ({lo:.4f} >= {1 - tp.TOLERANCE})")
finish()
