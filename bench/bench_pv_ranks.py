"""What csm's reductions across ranks cost in pvbatch (docs/scale-out.md).

    python3 bench/bench_pv_ranks.py BUILD/bin [--ranks 1 2 4] [--sizes 512 1024 2048]
        [--reps 10] [--frames 4]

runs `mpiexec --oversubscribe -np P vtkshadow-pvbatch [--symmetric]
bench/bench_pv_ranks.py collectives|frames ...` for every P and prints one
markdown table. Per P:

- the collectives the pass makes, timed alone with the controller it uses
  (vtkMultiProcessController::AllReduce, as vtkShadowRankReduction does):
  the bounds (6 doubles, MIN) and a whole map tile of R x R floats (MIN) for
  every R of --sizes, median of --reps, each after a barrier (pvbatch
  --symmetric: every rank runs the script);
- whole frames of the test scene split over the ranks (floor on rank 0,
  sphere on the last rank, tests/paraview/test_pv_ranks.py), csm at 2048:
  a still frame (nothing changed: csm reuses its maps, only the bounds,
  count and time are reduced) and a frame after a change (the light moved:
  every tile is baked and min-reduced, plus its GPU read-back and upload),
  median of --frames.

Timings mean little on a loaded machine with fewer cores than ranks: say so
next to them.
"""
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(HERE)


def timed_collectives(controller, sizes, reps):
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray
    from vtkmodules.vtkParallelCore import vtkCommunicator
    out = {}

    def median_ms(make, n):
        a, b = make(), make()
        a.SetNumberOfValues(n)
        a.Fill(1.0)
        b.SetNumberOfValues(n)
        times = []
        for _ in range(reps):
            controller.Barrier()
            t = time.perf_counter()
            controller.AllReduce(a, b, vtkCommunicator.MIN_OP)
            times.append(time.perf_counter() - t)
        return 1000 * statistics.median(times)

    out["bounds_ms"] = median_ms(vtkDoubleArray, 6)
    out["map_ms"] = {str(r): median_ms(vtkFloatArray, r * r) for r in sizes}
    return out


def timed_frames(frames):
    sys.path.insert(0, os.path.join(SOURCE, "tests", "paraview"))
    import test_pv_ranks  # noqa: F401  (the scene split over the ranks)
    from paraview.simple import GetActiveView, Render
    scene = os.path.join(SOURCE, "scenes", "basic", "sphere-directional.json")
    import tempfile
    test_pv_ranks.render(scene, tempfile.mkdtemp(prefix="vtkshadow-bench-pv-ranks-"), "csm")
    view = GetActiveView()
    light = view.AdditionalLights[0]
    still, change = [], []
    for i in range(frames):
        t = time.perf_counter()
        Render(view)
        still.append(time.perf_counter() - t)
        p = list(light.Position)
        light.Position = [p[0] + (0.05 if i % 2 == 0 else -0.05), p[1], p[2]]
        t = time.perf_counter()
        Render(view)
        change.append(time.perf_counter() - t)
    view.UpdatePropertyInformation()
    status = json.loads(view.GetProperty("ShadowStatus")[0])
    return {"still_ms": 1000 * statistics.median(still),
            "change_ms": 1000 * statistics.median(change),
            "maps_rendered_total": status.get("maps_rendered_total")}


def run(mode, args):
    # pvbatch runs a script on rank 0 only (the others serve its proxies);
    # the collectives need every rank: that run uses pvbatch --symmetric.
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    controller = vtkMultiProcessController.GetGlobalController()
    if mode == "collectives":
        result = timed_collectives(controller, [int(s) for s in args["sizes"]], int(args["reps"]))
    else:
        result = timed_frames(int(args["frames"]))
    if controller.GetLocalProcessId() == 0:
        print("RESULT " + json.dumps(result), flush=True)


def drive(argv):
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("bin")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--sizes", type=int, nargs="+", default=[512, 1024, 2048])
    parser.add_argument("--reps", type=int, default=10)
    parser.add_argument("--frames", type=int, default=4)
    a = parser.parse_args(argv)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rows = []
    args = json.dumps({"sizes": a.sizes, "reps": a.reps, "frames": a.frames})
    for p in a.ranks:
        row = {"ranks": p}
        for mode, extra in (("collectives", ["--symmetric"]), ("frames", [])):
            cmd = ["timeout", "900", "mpiexec", "--oversubscribe", "-np", str(p),
                   os.path.join(a.bin, "vtkshadow-pvbatch")] + extra + [
                   os.path.abspath(__file__), mode, args]
            out = subprocess.run(cmd, env=env, capture_output=True, text=True)
            line = next((l for l in out.stdout.splitlines() if l.startswith("RESULT ")), None)
            if out.returncode != 0 or line is None:
                sys.exit("bench_pv_ranks.py: %s on %d ranks failed (status %d):\n%s" % (
                    mode, p, out.returncode, out.stderr[-2000:]))
            row.update(json.loads(line[len("RESULT "):]))
        rows.append(row)
    maps = " | ".join("map %d^2 MIN (ms)" % r for r in a.sizes)
    print("| ranks | bounds MIN (ms) | %s | still frame (ms) | frame after a change (ms) "
          "| maps baked in %d+%d frames |" % (maps, a.frames, a.frames))
    print("|---:|---:|%s---:|---:|---:|" % ("---:|" * len(a.sizes)))
    for r in rows:
        cells = " | ".join("%.2f" % r["map_ms"][str(s)] for s in a.sizes)
        print("| %d | %.3f | %s | %.0f | %.0f | %s |" % (r["ranks"], r["bounds_ms"], cells,
              r["still_ms"], r["change_ms"], r["maps_rendered_total"]))


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] in ("collectives", "frames"):
        run(sys.argv[1], json.loads(sys.argv[2]))
    else:
        drive(sys.argv[1:])
