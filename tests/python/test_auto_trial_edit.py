"""auto's timed exact choice (vsh_auto_trial.h) in a program with a live
pipeline, shadows switched on by enable_shadows(renderer, "auto",
max_error=0.05): an isosurface of vtkRTAnalyticSource under two scene
lights, the camera orbiting.

Checks, from the technique's stats after each frame (exact_trial):
  - the trial runs (both exact techniques within the target) and settles:
    after it no frame is timed while only the camera moves;
  - after an edit (the contour value changes) nothing is timed for
    VSH_AUTO_TRIAL_SETTLE - 1 still frames, and the trial runs again on
    the SETTLE-th: the timings of the old surface are dropped;
  - a surface edited on every frame (an animation) is never timed again
    before the timings expire;
  - each exact light draws what the trial drew.

Usage: test_auto_trial_edit.py"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "render"))

import vtkshadow  # noqa: E402
import float_render as fr  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkContourFilter  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402

W, H = 640, 480
SETTLE = 30  # VSH_AUTO_TRIAL_SETTLE
TRIAL_FRAMES = 2 * (3 + 3)  # both techniques: VSH_AUTO_TRIAL_WARMUP + SAMPLES each


def stats(technique, renderer):
    text = technique.GetStatsJSON(renderer)
    return json.loads(text if text.startswith("{") else "{" + text + "}")


def main():
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-20, 20, -20, 20, -20, 20)
    contour = vtkContourFilter()
    contour.SetInputConnection(source.GetOutputPort())
    contour.SetValue(0, 150.0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    renderer.AddLight(fr.scene_light((40.0, 20.0, 60.0)))
    renderer.AddLight(fr.scene_light((-50.0, 30.0, 40.0)))
    renderer.ResetCamera()
    technique = vtkshadow.enable_shadows(renderer, "auto", max_error=0.05)
    camera = renderer.GetActiveCamera()

    def frame():
        camera.Azimuth(1.0)
        renderer.ResetCameraClippingRange()
        window.Render()
        return stats(technique, renderer)

    first = [frame() for _ in range(TRIAL_FRAMES + 4)]
    trial = first[-1]["exact_trial"]
    print("after the trial:", json.dumps(trial))
    check(trial.get("lights", 0) > 0, "the exact lights are timed")
    if not trial.get("lights"):
        finish()
    check(isinstance(trial.get(trial["incumbent"] + "_timed_ms"), (int, float)),
          "the incumbent has a timing")
    choices = first[-1]["light_choices"]
    check(all(c == trial["drawn"] for i, c in enumerate(choices) if trial["lights"] >> i & 1),
          f"the exact lights draw {trial['drawn']}: {choices}")
    still = [frame() for _ in range(20)]
    check(not any(s["exact_trial"].get("timed_frame") for s in still),
          "no frame timed while only the camera moves")

    contour.SetValue(0, 120.0)
    after = [frame() for _ in range(SETTLE + 12)]
    timed = [i for i, s in enumerate(after) if s["exact_trial"].get("timed_frame")]
    print("timed frames after the edit:", timed)
    check(timed and timed[0] == SETTLE,
          f"timed again on the {SETTLE}th still frame after the edit: {timed[:3]}")

    animated = []
    for f in range(60):
        contour.SetValue(0, 120.0 + (f % 2))
        animated.append(frame())
    check(not any(s["exact_trial"].get("timed_frame") for s in animated[SETTLE:]),
          "a surface edited every frame is not timed again")
    window.Finalize()
    finish()


if __name__ == "__main__":
    main()
