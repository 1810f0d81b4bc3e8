"""csm's partial shadows of translucent actors (issue 31; docs/translucency.md,
docs/cascaded-shadow-maps.md "Translucent casters"): beside each depth map a
transmittance map holds the product of (1 - opacity) over the translucent
surfaces in front of the opaque map, and a depth map their nearest depth; a
receiver behind that nearest depth is lit by the opaque lookup times the
transmittance. The scene and the expectations are translucent_scene.py's
(every technique's cases run in test_translucent_casters.py); here csm's
own variants, each value (mean, min and max of the patch) within 0.03.

The sphere 0.5 case (0.25 under it) runs with the screen
resolve, PCF 5x5 and the Poisson disc, which read the same transmittance,
and with the light 2 degrees wide under PCSS and under 16 sampled maps (the
patch stays in the umbra). Then, under the opacity 0.5 sphere: a small
plate above it marked NO_CAST (in no map) reads 1 on its top, as only the
nearest translucent depth can tell, and the floor under it still 0.25; the
sphere itself marked NO_CAST casts nothing (1). And the cost: the
translucent maps exist only while a translucent actor casts (the maps'
bytes 2.5 times the opaque scene's with one, equal without), a still frame
bakes no map, and a new opacity bakes them again.

Usage: test_translucent_csm.py"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import float_render as fr  # noqa: E402
import translucent_scene as ts  # noqa: E402
import vtkshadow  # noqa: E402

PLATE = ts.HEIGHT + 1.2  # the no-cast plate's height (the sphere's top: HEIGHT + 0.8)
made = []  # every pass csm() made, the last one last


def csm(**options):
    def make():
        p = vtkshadow.vtkCascadedShadowMapPass()
        for key, value in options.items():
            if not p.SetOption(key, value):
                raise ValueError(f"csm: SetOption({key}, {value}) refused")
        made.append(p)
        return p
    return make


def plate(renderer):
    """A small opaque plate above the sphere (top at HEIGHT + 0.8), marked
    not to cast: it is in no map, so only the nearest translucent depth says
    that it is nearer the light than the sphere."""
    fr.set_key(ts.add(renderer, ts.square(0.5, PLATE)), vtkshadow.vtkShadowPassBase.NO_CAST(), 1)


def no_cast(renderer):
    """The translucent caster itself marked not to cast."""
    actors = renderer.GetActors()
    actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        if actor.GetProperty().GetOpacity() < 1.0:
            fr.set_key(actor, vtkshadow.vtkShadowPassBase.NO_CAST(), 1)


def sun(renderer):
    """The light 2 degrees wide (a sun): PCSS or sampled maps."""
    light = renderer.GetLights().GetItemAsObject(0)
    light.GetInformation().Set(vtkshadow.vtkShadowPassBase.LIGHT_ANGLE(), 2.0)


def check_patch(label, expected, options=None, extra=None, **where):
    ts.check_patch(check, f"csm, {label}", ts.caster_scene([(ts.sphere(), 0.5)], extra),
                   csm(**(options or {}))(), expected, **where)


# Without a translucent caster nothing more is allocated: the depth atlas
# alone (4 bytes a texel); with one, its nearest depths (4) and
# transmittances (2) beside it: 2.5 times the bytes.
def map_bytes(opacity):
    window = fr.new_window(ts.W, ts.H)
    renderer = fr.new_renderer(window)
    ts.caster_scene([(ts.sphere(), opacity)])(renderer)
    p = csm()()
    renderer.SetPass(p)
    window.Render()
    out = p.GetMemoryBytes()
    window.Finalize()
    return out


opaque_bytes, translucent_bytes = map_bytes(1.0), map_bytes(0.5)
print(f"csm: {opaque_bytes} bytes of maps with the opaque sphere, {translucent_bytes} with the "
      f"opacity 0.5 one")
check(opaque_bytes > 0 and translucent_bytes == 2.5 * opaque_bytes,
      f"csm: the translucent maps take 1.5 times the depth atlas's bytes, and only when a "
      f"translucent actor casts ({translucent_bytes} = 2.5 x {opaque_bytes})")
# A still frame bakes nothing; a new opacity bakes the maps again.
window = fr.new_window(ts.W, ts.H)
renderer = fr.new_renderer(window)
ts.caster_scene([(ts.sphere(), 0.5)])(renderer)
still = csm()()
renderer.SetPass(still)
baked = []
for opacity in (0.5, 0.5, 0.4):
    renderer.GetActors().GetItemAsObject(1).GetProperty().SetOpacity(opacity)
    window.Render()
    baked.append(still.GetNumberOfMapsRendered())
window.Finalize()
print(f"csm: maps baked by a first frame, a still one, one after an opacity change: {baked}")
check(baked[0] > 0 and baked[1] == 0 and baked[2] > 0,
      f"csm: a still frame bakes no map, an opacity change bakes again ({baked})")

sphere_half = (ts.CASES[0],)
for label, options in (("csm screen resolve", {"resolve": 1}),
                       ("csm PCF 5", {"filter": 1, "pcf_size": 5}),
                       ("csm Poisson", {"filter": 2})):
    ts.check_cases(check, label, csm(**options), cases=sphere_half)
check_patch("2-degree sun, PCSS", 0.25, extra=sun)
check(made[-1].GetUsedPCSS(), "csm, 2-degree sun: PCSS was used")
check_patch("2-degree sun, 16 sampled maps", 0.25, {"soft": 2}, extra=sun)
check(made[-1].GetUsedSampled(), "csm, 2-degree sun: the sampled maps were used")
check_patch("no-cast plate above the opacity 0.5 sphere, on the plate", 1.0, extra=plate,
            z=PLATE)
check_patch("floor under the no-cast plate and the opacity 0.5 sphere", 0.25, extra=plate)
check_patch("floor under the opacity 0.5 sphere marked NO_CAST", 1.0, extra=no_cast)
finish()
