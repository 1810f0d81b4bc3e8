"""Still frames under vtkPlanarReflectionPass: the technique's work that a
still frame should skip, counted per frame.

csm (default): shadow maps baked per frame
(vtkCascadedShadowMapPass::GetTotalMapsRendered). The mirrored draw sets
every actor's user matrix and sets it back, which moves the matrices'
MTime; csm judges its held maps by the casters' content, and keeps one set
of held maps per world (vtkShadowPassBase::SetWorldKey: 0 the scene, 1 the
mirror's reflection). So a still frame bakes nothing without reflections,
with the reflection drawn without shadows, and with shadows in the
reflection (before the per-world maps the last baked 2 x 6 maps every
frame: each world's bake overwrote the other's tiles).

raytrace: frames traced (vtkRayTracedShadowPass::GetNumberOfTracedFrames,
one per world traced). The first frame traces the scene and the mirrored
world; a still frame traces neither (before, the two views alternated in one
still-frame state and both traced every frame).

Both: the memory held for the mirror's world is reported (mirror_worlds_bytes
in the reflection pass's stats, > 0 with shadows in the reflection) and
freed when the reflections are switched off.

Usage: test_reflection_bakes.py SOURCE_DIR [csm|raytrace]"""
import json
import os
import sys

import vtkshadow
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer, vtkWindowToImageFilter

source = sys.argv[1]
technique = sys.argv[2] if len(sys.argv) > 2 else "csm"
scene_path = os.path.join(source, "scenes/mirror/sphere-mirror-floor.json")
failures = []


def make_pass():
    if technique == "csm":
        made = vtkshadow.vtkCascadedShadowMapPass()
        return made, made.GetTotalMapsRendered
    if technique == "raytrace":
        made = vtkshadow.vtkRayTracedShadowPass()
        return made, made.GetNumberOfTracedFrames
    sys.exit(f"test_reflection_bakes.py: unknown technique {technique!r} (csm or raytrace)")


def reflection_stats(mirror, renderer):
    return json.loads("{" + mirror.GetStatsJSON(renderer) + "}")["reflections"]


def grab(window):
    shot = vtkWindowToImageFilter()
    shot.SetInput(window)
    shot.ReadFrontBufferOff()
    shot.ShouldRerenderOff()  # the frame just rendered, not one more
    shot.Update()
    return vtk_to_numpy(shot.GetOutput().GetPointData().GetScalars()).copy()


def work(reflections, shadows, frames=6):
    """Work done per frame, the reflection stats of the last frame, the
    mirror worlds' bytes after the reflections are switched off, and the
    pixels that differ between the first frame and the last (a still frame
    that reuses each world's maps or mask draws the same image)."""
    scene = vtkshadow.vtkShadowScene()
    if not scene.Load(scene_path):
        sys.exit(scene.GetErrorMessage())
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.StencilCapableOn()
    window.SetSize(200, 150)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    if not scene.Populate(renderer):
        sys.exit(scene.GetErrorMessage())
    shadow_pass, total = make_pass()
    mirror = None
    if reflections:
        mirror = vtkshadow.vtkPlanarReflectionPass()
        mirror.SetDelegatePass(shadow_pass)
        mirror.SetReflectShadows(shadows)
        renderer.SetPass(mirror)
    else:
        renderer.SetPass(shadow_pass)
    counts, images = [], []
    for _ in range(frames):
        before = total()
        window.Render()
        counts.append(total() - before)
        images.append(grab(window))
    changed = int((images[0] != images[-1]).any(axis=-1).sum())
    if not (images[0] != images[0][0]).any():
        changed = -1  # a blank image proves nothing
    stats, released = {}, None
    if mirror:
        stats = reflection_stats(mirror, renderer)
        mirror.SetReflections(False)
        window.Render()
        released = shadow_pass.GetWorldsMemoryBytes()
    window.Finalize()
    return counts, stats, released, changed


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


unit = "maps baked" if technique == "csm" else "worlds traced"
off, _, _, changed = work(False, False)
check(off[0] > 0 and sum(off[1:]) == 0, f"{technique}, no reflections: {unit} per frame {off}")
check(changed == 0, f"no reflections: the last still frame equals the first ({changed} px differ)")
plain, stats, _, changed = work(True, False)
check(stats.get("drawn") == 1, f"the mirror is drawn: {stats}")
check(plain[0] > 0 and sum(plain[1:]) == 0,
      f"{technique}, reflections without shadows: {unit} per frame {plain} (a still frame: none)")
check(stats.get("mirror_worlds_bytes") == 0,
      f"without shadows in the reflection no memory is held for the mirror's world: {stats}")
check(changed == 0, f"no-shadows: the last still frame equals the first ({changed} px differ)")
shadowed, stats, released, changed = work(True, True)
check(stats.get("drawn") == 1, f"the mirror is drawn: {stats}")
check(shadowed[0] > off[0] and sum(shadowed[1:]) == 0,
      f"{technique}, reflections with shadows: {unit} per frame {shadowed} (the first frame "
      f"more than {off[0]}: both worlds; a still frame: none)")
check(changed == 0, f"with shadows: the last still frame equals the first ({changed} px differ)")
check(stats.get("mirror_worlds_bytes", 0) > 0,
      f"the mirror's world holds memory, reported: {stats.get('mirror_worlds_bytes')}")
check(released == 0, f"switching the reflections off frees it: {released} bytes left")
print("FAIL" if failures else "PASS")
sys.exit(1 if failures else 0)
