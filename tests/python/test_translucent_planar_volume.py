"""planar's and volume's partial shadows of translucent actors (issue 31;
docs/translucency.md): the light through a translucent caster is the
product of (1 - opacity) over its surfaces the ray to the light crosses.
The scene and the cases are translucent_patch.py's (those of raytrace's
test): a directional light straight down, an opaque floor, one caster 2
units above it, visibility read on a patch of the floor under the caster's
centre:

- a closed sphere (128 x 128) of opacity 0.5, crossed twice: 0.25;
- the same sphere at opacity 1 (the control): 0; at opacity 0: 1;
- a closed thin box (a slab: two crossings) of opacity 0.4: 0.36;
  every value within 0.03.

planar multiplies the projected triangles of a translucent caster into a
transmittance channel of the (receiver, light) pair; volume counts each
translucent caster's crossings with the volumes of all its faces (z-fail)
and multiplies the light's mask by (1 - opacity) per crossing. Before they
took translucent casters the opacity 0.5 sphere's patch read 1 under both.

Usage: test_translucent_planar_volume.py [technique ...] (default: planar volume)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402
import translucent_patch as tp  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource  # noqa: E402


def shelves(renderer):
    """Five small flat actors 3 above the floor, behind the sphere as the
    camera sees it: detected receivers ahead of the floor, the sphere below
    all of them (it casts nothing on them)."""
    for x in (-4, -2, 0, 2, 4):
        p = vtkPlaneSource()
        p.SetOrigin(x - 0.3, 4.0, 3.0)
        p.SetPoint1(x + 0.3, 4.0, 3.0)
        p.SetPoint2(x - 0.3, 4.6, 3.0)
        tp.add(renderer, p)


techniques = sys.argv[1:] or ("planar", "volume")
for technique in techniques:
    tp.check_technique(technique)

# planar's transmittance has four channels, one per (receiver, light) pair:
# the pairs that take them are those a translucent caster can shadow, so
# the floor (the sixth receiver here) keeps its partial shadow.
if "planar" in techniques:
    mean, lo, hi, n, total = tp.patch_visibility(tp.sphere, 0.5, "planar", shelves)
    print(f"planar, sphere 0.5 after five other receivers: {mean:.4f} (min {lo:.4f}, max {hi:.4f})")
    check(n == total and abs(mean - 0.25) <= tp.TOLERANCE and lo >= 0.25 - tp.TOLERANCE
          and hi <= 0.25 + tp.TOLERANCE,
          f"planar, the floor after five receivers the sphere cannot shadow: {mean:.4f} "
          f"({lo:.4f}..{hi:.4f}) is 0.25 within {tp.TOLERANCE}")
finish()
