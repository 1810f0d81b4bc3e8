"""planar's translucent casters beyond the shared cases (issue 31;
docs/planar-shadows.md): the transmittance has four channels, one per
(receiver, light) pair, and the pairs that take them are those a
translucent caster can shadow. With five small receivers ahead of the floor
that the opacity 0.5 sphere cannot shadow, the floor (the sixth receiver)
keeps its partial shadow: 0.25 within 0.03 (translucent_scene.py's patch).
Without the choice of pairs it read 1.

Usage: test_translucent_planar.py"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import robust_scenes as rs  # noqa: E402
import translucent_scene as ts  # noqa: E402


def shelves(renderer):
    """Five small flat actors 3 above the floor, behind the sphere as the
    camera sees it: detected receivers ahead of the floor, the sphere below
    all of them (it casts nothing on them)."""
    for x in (-4, -2, 0, 2, 4):
        actor = ts.add(renderer, rs.floor_poly(half=0.3, z=3.0))
        actor.SetPosition(x, 4.3, 0.0)


ts.check_patch(check, "planar, the floor under the opacity 0.5 sphere after five other receivers",
               ts.caster_scene([(ts.sphere(), 0.5)], shelves), "planar", 0.25)
finish()
