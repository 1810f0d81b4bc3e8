"""The plugin in pvpython: RenderViewWithShadows exists, lists the registry's
techniques, rejects an unknown one, and renders a library scene with every
technique with the shadow where it belongs.

Run by build/bin/vtkshadow-pvpython (the plugin loaded by PV_PLUGIN_PATH):
    vtkshadow-pvpython test_pv_view.py SCENE OUTDIR

The measure: the floor at the point where the light's ray through the
sphere's centre meets it (the middle of the shadow) must be at most 60% as
bright as in the same view with technique "none", and a lit floor point away
from the shadow within 10% of it (no acne, no global darkening).
"""
import os
import sys

from paraview.simple import CreateView, Render, SaveScreenshot

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pv_scene  # noqa: E402

scene_path, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
scene = pv_scene.load(scene_path)
failures = []

view = CreateView("RenderViewWithShadows")
view.ViewSize = [480, 360]
pv_scene.populate(view, scene)

view.UpdatePropertyInformation()
names = list(view.GetProperty("ShadowTechniqueNames"))
print("techniques from the view:", names)
for required in ("none", "planar", "csm", "auto"):
    if required not in names:
        failures.append("ShadowTechniqueNames lacks %s (got %s)" % (required, names))
if view.ShadowTechnique != "csm":
    failures.append("default ShadowTechnique is %r, not csm" % view.ShadowTechnique)

sphere = next(o["sphere"] for o in scene["objects"] if "sphere" in o)
middle = pv_scene.shadow_point(scene, sphere["center"])
# A lit floor point: the shadow's middle reflected through the sphere's foot
# and moved three times as far (clear of the sphere and its shadow).
lit = [sphere["center"][i] + 3 * (sphere["center"][i] - middle[i]) for i in range(2)] + [0.0]


def shoot(technique):
    view.ShadowTechnique = technique
    Render(view)
    png = os.path.join(out, "%s.png" % technique)
    SaveScreenshot(png, view, ImageResolution=view.ViewSize)
    return png


# Known wrong, and not ParaView's doing: VTK's own baseline ("vtk", VTK's
# vtkShadowMapBakerPass + vtkShadowMapPass) darkens lit floor far from the
# caster. The renderer here has one light (the scene's, a vtkPVLight scene
# light; the light kit is off), so no headlight or fill light is involved,
# and vtkshadow-render outside ParaView gives the same figure at the same
# world point (81% there, 82% here; docs/paraview.md). It is reported as
# KNOWN FAILURE; once it works it fails the test until taken off this list.
# (planar, and auto picking planar, were on it until receivers drawn by
# ParaView's vtkPVLODActor through its inner Device actor were recognised.)
KNOWN = {("vtk", "lit")}
known_seen = set()


def check(technique, what, ok, message):
    if (technique, what) in KNOWN:
        known_seen.add((technique, what))
        if ok:
            failures.append("%s %s now works: take it off KNOWN" % (technique, what))
        else:
            print("KNOWN FAILURE: " + message)
    elif not ok:
        failures.append(message)


base = shoot("none")
shadow_px, lit_px = pv_scene.to_pixel(view, middle), pv_scene.to_pixel(view, lit)
base_shadow = pv_scene.luminance(base, shadow_px)
base_lit = pv_scene.luminance(base, lit_px)
print("none: shadow point %s lum %.1f, lit point %s lum %.1f" % (
    shadow_px, base_shadow, lit_px, base_lit))
if base_shadow < 40 or base_lit < 40:
    failures.append("the floor is not lit without shadows (%.1f, %.1f)" % (base_shadow, base_lit))

for technique in names:
    if technique == "none":
        continue
    png = shoot(technique)
    s = pv_scene.luminance(png, shadow_px)
    l = pv_scene.luminance(png, lit_px)
    view.UpdatePropertyInformation()
    print("%s: shadow %.1f (%.0f%% of none), lit %.1f (%.0f%%); status %s" % (
        technique, s, 100 * s / base_shadow, l, 100 * l / base_lit, view.GetProperty("ShadowStatus")[0]))
    check(technique, "shadow", s <= 0.6 * base_shadow,
          "%s: no shadow: floor under the sphere %.1f vs %.1f without" % (technique, s, base_shadow))
    check(technique, "lit", abs(l - base_lit) <= 0.1 * base_lit,
          "%s: lit floor changed: %.1f vs %.1f without" % (technique, l, base_lit))
    if technique == "csm" and not s <= 0.6 * base_shadow:
        failures.append("csm must shadow in ParaView")

# Bad input: an unknown technique is refused (an error naming it) and the
# view keeps the technique it had.
view.ShadowTechnique = "planar"
Render(view)
view.ShadowTechnique = "no-such-technique"
Render(view)
view.UpdatePropertyInformation()
if '"technique": "planar"' not in view.GetProperty("ShadowStatus")[0]:
    failures.append("an unknown technique changed the view: %s" % view.GetProperty("ShadowStatus")[0])

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok: %d techniques checked in RenderViewWithShadows; known failures: %s" % (
    len(names) - 1, ", ".join("%s %s" % k for k in sorted(known_seen)) or "none"))
