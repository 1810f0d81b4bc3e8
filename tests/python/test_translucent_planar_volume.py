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
from checks import finish  # noqa: E402
import translucent_patch as tp  # noqa: E402

for technique in sys.argv[1:] or ("planar", "volume"):
    tp.check_technique(technique)
finish()
