"""csm under vtkPlanarReflectionPass on still frames: how many shadow maps
are baked per frame (vtkCascadedShadowMapPass::GetTotalMapsRendered).

The mirrored draw sets every actor's user matrix and sets it back, which
moves the matrices' MTime; csm judges its held maps by the casters'
content, so with the reflection drawn without shadows (no-shadows) a still
frame must bake nothing, as without reflections. With shadows in the
reflection the mirrored world bakes into the same atlas, so both worlds
re-bake every frame: at most one map set per world (the count is reported,
and must not exceed 2 x the first frame's).

Usage: test_reflection_bakes.py SOURCE_DIR"""
import os
import sys

import vtkshadow
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer

source = sys.argv[1]
scene_path = os.path.join(source, "scenes/mirror/sphere-mirror-floor.json")
failures = []


def bakes(reflections, shadows, frames=6):
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
    csm = vtkshadow.vtkCascadedShadowMapPass()
    if reflections:
        mirror = vtkshadow.vtkPlanarReflectionPass()
        mirror.SetDelegatePass(csm)
        mirror.SetReflectShadows(shadows)
        renderer.SetPass(mirror)
    else:
        renderer.SetPass(csm)
    counts = []
    for _ in range(frames):
        before = csm.GetTotalMapsRendered()
        window.Render()
        counts.append(csm.GetTotalMapsRendered() - before)
    drawn = mirror.GetStatsJSON(renderer) if reflections else ""
    window.Finalize()
    return counts, drawn


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


off, _ = bakes(False, False)
check(off[0] > 0 and sum(off[1:]) == 0, f"no reflections: maps baked per frame {off}")
plain, stats = bakes(True, False)
check('"drawn": 1' in stats, "the mirror is drawn: " + stats)
check(plain[0] > 0 and sum(plain[1:]) == 0,
      f"reflections without shadows: maps baked per frame {plain} (a still frame bakes none)")
shadowed, stats = bakes(True, True)
check('"drawn": 1' in stats, "the mirror is drawn: " + stats)
check(all(n <= 2 * off[0] for n in shadowed),
      f"reflections with shadows: maps baked per frame {shadowed} (at most 2 x {off[0]}: "
      "the mirrored world shares the atlas)")
print("FAIL" if failures else "PASS")
sys.exit(1 if failures else 0)
