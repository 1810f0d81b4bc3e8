"""The Python wrapping: `import vtkshadow` gives working VTK-style classes."""
import os
import sys

import vtkshadow
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory overrides)

source = sys.argv[1]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


scene = vtkshadow.vtkShadowScene()
check(scene.Load(os.path.join(source, "scenes/basic/sphere-plane.json")), "load the basic scene")
check(scene.GetNumberOfLights() == 3, "three lights")
check(scene.GetNumberOfObjects() == 2, "two objects")
check(scene.GetLightTypeName(2) == "spot", "light 2 is a spot")
check(scene.GetObjectIsReceiver(1) and not scene.GetObjectIsReceiver(0), "the plane receives")
poly = scene.GetObjectPolyData(0)
check(poly is not None and poly.GetNumberOfPolys() > 1000, "the sphere is tessellated")
check(poly.GetPoints().GetDataType() == 11, "points are double precision")  # VTK_DOUBLE
bounds = [0.0] * 6
scene.GetBounds(bounds)
check(abs(bounds[0] + 5) < 1e-12 and abs(bounds[5] - 1.7) < 1e-9, f"bounds {bounds}")

bad = vtkshadow.vtkShadowScene()
check(not bad.Load(os.path.join(source, "tests/scene/data/bad/sphere_radius_negative.json")),
      "a bad scene is rejected")
check("radius" in bad.GetErrorMessage(), "the message names the field: " + bad.GetErrorMessage())

technique = vtkshadow.vtkShadowTechnique()
check(technique.GetName() == "none", "default technique")
technique.SetName("vtk")
check(technique.IsValid() and technique.GetMapResolution() == 2048, "vtk at 2048")
check(vtkshadow.vtkShadowTechnique.IsKnownTechnique("vtk"), "static lookup")
check(not vtkshadow.vtkShadowTechnique.IsKnownTechnique("bogus"), "unknown name")

# The registry is the one list of techniques: names, descriptions, passes.
registry = vtkshadow.vtkShadowTechniqueRegistry
names = [registry.GetName(i) for i in range(registry.GetNumberOfTechniques())]
check(names[:5] == ["none", "vtk", "planar", "csm", "auto"], f"registry order {names}")
check(" ".join(names) == vtkshadow.vtkShadowTechnique.GetKnownTechniques(), "known = registry")
check(registry.GetName(len(names)) is None and registry.GetName(-1) is None, "out of range")
for i, name in enumerate(names):
    check(len(registry.GetDescription(i)) > 20, f"{name} has a description")
    made = registry.CreatePass(name)
    check(made is not None and made.IsA("vtkShadowPassBase"), f"{name} makes a vtkShadowPassBase")
    check(registry.FindTechnique(name) == i, f"find {name}")
check(registry.CreatePass("bogus") is None and registry.FindTechnique("bogus") == -1, "bogus")
# Settings are checked by the named technique's pass.
csm = vtkshadow.vtkShadowTechnique()
csm.SetName("csm")
check(csm.SetOption("cascades", 3) and not csm.SetOption("cascades", 9), "csm cascades range")
planar = vtkshadow.vtkShadowTechnique()
planar.SetName("planar")
check(not planar.SetOption("cascades", 3), "planar has no cascades")
check(planar.SetOption("plane_tolerance", 1e-4) and planar.SetOption("map_resolution", 1024),
      "planar takes plane_tolerance and the technique-wide map_resolution")
check(planar.SetOption("cast_headlight", 1) and not planar.SetOption("cast_headlight", 2),
      "every pass takes cast_headlight 0/1")

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(96, 96)
renderer = vtkRenderer()
window.AddRenderer(renderer)
check(scene.Populate(renderer), "populate")
check(renderer.GetActors().GetNumberOfItems() == 2, "two actors")
check(renderer.GetLights().GetNumberOfItems() == 3, "three lights in the renderer")
check(technique.Install(renderer), "install the vtk technique")
check(technique.GetShadowMapMemory(renderer) == 0, "no maps before the first frame")
window.Render()
check(technique.GetShadowMapMemory(renderer) > 0, "the vtk maps take memory after a frame")

visibility = vtkshadow.vtkShadowVisibility()
visibility.SetScene(scene)
visibility.SetTechnique(technique)
visibility.SetSize(96, 72)
visibility.SetLight(0)
check(visibility.Compute(), "compute visibility")
image = visibility.GetVisibility()
check(image.GetDimensions() == (96, 72, 1), f"visibility size {image.GetDimensions()}")
lo, hi = image.GetScalarRange()
check(lo == 0.0 and hi == 1.0, f"visibility spans [0, 1] (got [{lo}, {hi}])")
visibility.SetLight(7)
check(not visibility.Compute() and "out of range" in visibility.GetErrorMessage(),
      "an out-of-range light is an error")
# vtkAutoShadowPass as docs/auto.md uses it, on hand-built actors: a
# sphere over a floor marked as a receiver, one sun. Its shadow falls on the
# floor only, so auto chooses planar; with no receiver marked it needs maps.
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper  # noqa: E402


def auto_choice(mark_floor, detect=True):
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetSize(96, 72)
    ren = vtkRenderer()
    win.AddRenderer(ren)
    actors = []
    for src in (vtkSphereSource(), vtkPlaneSource()):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(src.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        ren.AddActor(actor)
        actors.append(actor)
    actors[0].SetPosition(0, 0, 1.2)
    actors[1].SetScale(10, 10, 1)
    if mark_floor is not None:  # 1: marked, 0: opted out, None: unmarked
        from vtkmodules.vtkCommonCore import vtkInformation
        keys = vtkInformation()
        keys.Set(vtkshadow.vtkPlanarShadowPass.RECEIVER(), mark_floor)
        actors[1].SetPropertyKeys(keys)
    sun = vtkLight()
    sun.SetPositional(0)
    sun.SetPosition(1, 1, 4)
    sun.SetFocalPoint(0, 0, 0)
    ren.AddLight(sun)
    ren.GetActiveCamera().SetPosition(0, -8, 5)
    ren.GetActiveCamera().SetFocalPoint(0, 0, 0.5)
    ren.ResetCameraClippingRange()
    automatic = vtkshadow.vtkAutoShadowPass()
    automatic.SetMaxError(0.25)
    automatic.GetPlanarPass().SetDetectReceivers(detect)
    ren.SetPass(automatic)
    win.Render()
    lights = [automatic.GetLightChoice(i) for i in range(automatic.GetNumberOfLightChoices())]
    detected = [automatic.GetDetectedReceiver(i) is actors[1]
                for i in range(automatic.GetNumberOfDetectedReceivers())]
    return automatic.GetChoice(), lights, automatic.GetReason() + f" detected {detected}"


choice, lights, reason = auto_choice(1)
check(choice == "planar" and lights == ["planar"] and reason.endswith("detected []"),
      f"auto with a receiver: {choice} {lights} ({reason})")
# Unmarked, the flat floor is found as the receiver (detect_receivers, default on).
choice, lights, reason = auto_choice(None)
check(choice == "planar" and lights == ["planar"] and reason.endswith("detected [True]"),
      f"auto with the floor detected: {choice} {lights} ({reason})")
for mark, detect, label in ((0, True, "opted out"), (None, False, "detection off")):
    choice, lights, reason = auto_choice(mark, detect)
    # No plane receiver: a general technique; the sphere's outline is long
    # for this small window, so maps' outline floor leaves an exact one.
    check(choice in ("raytrace", "volume") and lights == [choice] and
          reason.endswith("detected []"),
          f"auto without a receiver ({label}): {choice} {lights} ({reason})")
# raytrace's cost estimate (what auto weighs it by): a hard light traces
# one ray per pixel, a light with a size Samples (adaptive off) or 8 plus
# the rest on the penumbra's share of pixels (adaptive, the default); with
# Samples 1 they agree.
if hasattr(vtkshadow, "vtkRayTracedShadowPass"):
    rt = vtkshadow.vtkRayTracedShadowPass()
    hard = rt.EstimateFrameMilliseconds(480000, 1.0, 1, False)
    adaptive = rt.EstimateFrameMilliseconds(480000, 1.0, 1, True)
    rt.SetAdaptive(0)
    sized = rt.EstimateFrameMilliseconds(480000, 1.0, 1, True)
    check(0 < hard and sized > 10 * hard,
          f"raytrace estimate: hard {hard} ms, sized ({rt.GetSamples()} rays) {sized} ms")
    check(4 * hard < adaptive < 0.6 * sized,
          f"raytrace estimate: adaptive {adaptive} ms, not between 4x hard {hard} and 0.6x {sized}")
    rt.SetAdaptive(1)
    rt.SetSamples(1)
    check(rt.EstimateFrameMilliseconds(480000, 1.0, 1, True) == hard,
          "raytrace estimate: 1 sample equals the hard light's")
print(str(technique)[:40].replace("\n", " "), "...")
print("python.api:", "FAILED" if failures else "ok", f"({len(failures)} failures)")
sys.exit(1 if failures else 0)
