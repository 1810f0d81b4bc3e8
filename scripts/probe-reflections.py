"""Interleaved cost of planar mirrors in one process (tests/gl-run.sh
 build/bin/vtkshadow-python scripts/probe-reflections.py SCENE ROUNDS): one
 window per configuration (technique x reflections; "none/off" twice, the
 noise floor), one frame of each per round with the camera orbiting, median
 and min ms per configuration, then the shadow maps csm renders per still
 frame (GetTotalMapsRendered). Timings on a shared machine are noisy:
 compare within one run."""
import statistics
import sys
import time

import vtkshadow
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa

scene_path, rounds = sys.argv[1], int(sys.argv[2])
configs = [("none", "off"), ("none", "off#2"), ("none", "on"), ("csm", "off"), ("csm", "on"),
           ("csm", "no-shadows"), ("planar", "off"), ("planar", "on")]
setups = []
for tech, refl in configs:
    scene = vtkshadow.vtkShadowScene()
    assert scene.Load(scene_path), scene.GetErrorMessage()
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.StencilCapableOn()
    ren = vtkRenderer()
    win.AddRenderer(ren)
    win.SetSize(640, 480)
    scene.Populate(ren)
    t = vtkshadow.vtkShadowTechnique()
    t.SetName(tech)
    inner = t.CreatePass()
    p = vtkshadow.vtkPlanarReflectionPass()
    p.SetDelegatePass(inner)
    p.SetReflections(refl.startswith("on") or refl == "no-shadows")
    p.SetReflectShadows(refl != "no-shadows")
    ren.SetPass(p)
    win.Render()
    setups.append((tech + "/" + refl, win, ren, p, inner))
times = {s[0]: [] for s in setups}
for i in range(rounds):
    for name, win, ren, p, inner in setups:
        cam = ren.GetActiveCamera()
        cam.Azimuth(0.5 if (i // 10) % 2 == 0 else -0.5)
        t0 = time.perf_counter()
        win.Render()
        ren.GetRenderWindow().WaitForCompletion()
        times[name].append(1000 * (time.perf_counter() - t0))
for name, win, ren, p, inner in setups:
    st = p.GetStatsJSON(ren)
    extra = ""
    if "maps_reused_last_frame" in st:
        i = st.index("maps_reused_last_frame")
        extra = st[i:i + 30]
    print("%-16s median %7.1f ms  min %7.1f  %s" % (name, statistics.median(times[name]),
                                                      min(times[name]), extra))
# Maps rendered per frame (csm), over 5 still frames.
for name, win, ren, p, inner in setups:
    if not name.startswith("csm"):
        continue
    a = inner.GetTotalMapsRendered()
    for _ in range(5):
        win.Render()
    print("%-16s maps rendered per still frame: %.1f" % (name, (inner.GetTotalMapsRendered() - a) / 5))
