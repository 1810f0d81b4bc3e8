"""Where enable_shadows is called in a vedo program does not change the
picture (issue 29): right after Plotter() (before vedo adds its lights and
actors in show()), after show(), and after another technique was enabled
first. vedo's Plotter turns LightFollowCamera off and adds its lights in
show(); the key light and the lights are decided at each frame.

A sphere over a thin box floor (vedo's usual floor, whose top is a flat
part planar receives on), 400x300 offscreen, techniques none, csm, planar,
volume, raytrace, auto: the three placements give frames that differ in at
most 20 pixels by more than 8/255; and every technique but none darkens
the floor under the sphere (so the test would see a placement that loses
the shadow). Each frame is its own process with one window: VTK's GLX
window creation aborts now and then in a process that has opened and closed
many (seen without vtkshadow too).

Usage: test_vedo_placement.py
       test_vedo_placement.py --frame WHERE TECHNIQUE OUT.npy   (one frame)"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

import numpy as np  # noqa: E402
import vedo  # noqa: E402
import vtkshadow  # noqa: E402

CAMERA = dict(pos=(5, -9, 7), focal_point=(0, 0, 0.5), viewup=(0, 0, 1))


def frame(where, technique):
    sphere = vedo.Sphere(pos=(0, 0, 1.5), r=0.6).color("tomato")
    floor = vedo.Box(pos=(0, 0, -0.05), length=8, width=8, height=0.1).color("lightgray")
    plt = vedo.Plotter(size=(400, 300), offscreen=True)
    if where == "before show":
        vtkshadow.enable_shadows(plt.renderer, technique=technique)
    plt.show(sphere, floor, camera=CAMERA, interactive=False)
    if where == "after show":
        vtkshadow.enable_shadows(plt.renderer, technique=technique)
    if where == "after another":
        vtkshadow.enable_shadows(plt.renderer, technique="csm" if technique != "csm" else "none")
        plt.render()
        vtkshadow.enable_shadows(plt.renderer, technique=technique)
    plt.render()
    image = plt.screenshot(asarray=True).astype(float)
    # Free the window's X resources now: llvmpipe's GLX runs out of them
    # after some twenty windows a process leaves open.
    window = plt.window
    plt.close()
    window.Finalize()
    return image


def differing(a, b, level=8):
    return int((np.abs(a - b).max(axis=2) > level).sum())


def frame_in_child(where, technique, folder):
    out = os.path.join(folder, f"{technique}-{where.replace(' ', '_')}.npy")
    subprocess.run([sys.executable, os.path.abspath(__file__), "--frame", where, technique, out],
                   check=True)
    return np.load(out)


def main():
    with tempfile.TemporaryDirectory() as folder:
        unshadowed = None
        for technique in ("none", "csm", "planar", "volume", "raytrace", "auto"):
            frames = {where: frame_in_child(where, technique, folder)
                      for where in ("before show", "after show", "after another")}
            for where in ("after show", "after another"):
                n = differing(frames[where], frames["before show"])
                check(n <= 20, f"{technique}: enabled {where} = enabled before show "
                      f"({n} px differ by > 8/255, at most 20)")
            if technique == "none":
                unshadowed = frames["before show"]
                continue
            darker = int(((unshadowed - frames["before show"]).max(axis=2) > 40).sum())
            check(darker > 300, f"{technique}: the shadow is drawn ({darker} px darker than "
                  "none by > 40/255, more than 300)")
    finish()


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "--frame":
        np.save(sys.argv[4], frame(sys.argv[2], sys.argv[3]))
    else:
        main()
