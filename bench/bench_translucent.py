"""What a translucent caster costs planar and volume (docs/translucency.md):
the scene of tests/python/translucent_patch.py (a 128 x 128 sphere over a
floor, directional light straight down) at 800x600, the sphere at opacity
0.5 casting against the same sphere marked NO_CAST (drawn, casting
nothing), and at opacity 1 (opaque). Per configuration: the median frame
time over FRAMES frames (the camera turning 1 degree a frame, after WARMUP
frames) and the pass's stats. Each configuration runs in a process of its
own, one after the other: on a shared machine the times are only as steady
as its load.

Usage: xvfb-run -a build/bin/vtkshadow-python bench/bench_translucent.py"""
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "python"))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "render"))

FRAMES, WARMUP = 20, 3
CONFIGS = (("planar", 1.0, True), ("planar", 0.5, False), ("planar", 0.5, True),
           ("volume", 1.0, True), ("volume", 0.5, False), ("volume", 0.5, True))


def run_one(technique, opacity, cast):
    """Median frame time (ms) and the stats of one configuration."""
    import float_render as fr
    import translucent_patch as tp
    import vtkshadow
    window = fr.new_window(800, 600)
    renderer = fr.new_renderer(window)
    tp.scene(tp.sphere, opacity)(renderer)
    if not cast:
        actors = renderer.GetActors()
        actors.InitTraversal()
        actors.GetNextActor()  # the floor
        fr.set_key(actors.GetNextActor(), vtkshadow.vtkShadowPassBase.NO_CAST())
    shadow_pass = vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique)
    renderer.SetPass(shadow_pass)
    times = []
    for i in range(WARMUP + FRAMES):
        renderer.GetActiveCamera().Azimuth(1.0)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        if i >= WARMUP:
            times.append(1000.0 * (time.perf_counter() - start))
    stats = shadow_pass.GetStatsJSON(renderer)
    window.Finalize()
    return sorted(times)[len(times) // 2], stats


if len(sys.argv) == 4:
    ms, stats = run_one(sys.argv[1], float(sys.argv[2]), sys.argv[3] == "cast")
    print(f"{ms:.1f}\t{stats}")
    sys.exit(0)
print("technique\topacity\tcasts\tmedian ms\tstats")
for technique, opacity, cast in CONFIGS:
    out = subprocess.run([sys.executable, __file__, technique, str(opacity),
                          "cast" if cast else "nocast"], capture_output=True, text=True)
    line = out.stdout.strip().splitlines()[-1] if out.stdout.strip() else "failed\t" + out.stderr[-200:]
    print(f"{technique}\t{opacity}\t{'yes' if cast else 'no (NO_CAST)'}\t{line}")
