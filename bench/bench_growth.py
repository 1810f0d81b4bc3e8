"""How each technique's frame time grows with triangle count and with pixel count.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_growth.py --out DIR
                  [--frames 15] [--rounds 4] [--warmup 5] [--noise-tolerance 0.03]

Scenes (written to DIR, in the vtkshadow scene format): a sphere over a floor
lit by one directional light, the sphere tessellated to about 10k, 100k and
1M triangles, at 640x480; and the 100k scene at 320x240, 640x480 and
1280x960. Each scene is rendered with every technique of the registry
(vtkShadowTechnique.GetKnownTechniques(): none, vtk (map 2048), planar, csm,
auto, ...) in one vtkshadow-render --stats process per scene: every
technique in the same window, interleaved in blocks (--warmup frames each,
then --rounds rounds of one block of --frames frames per technique, the order
changed every round), the same camera orbit for all. For each cell: the
median over rounds of the block medians, and the median over rounds of its
ratio to none of the same round (the figure to compare: the machine is
shared and noisy). none is timed twice; none#2 / none is the noise floor of
the row, and a row outside 1 +- --noise-tolerance is marked too noisy.

Writes DIR/growth.json and DIR/growth.md (a Markdown section). Progress
lines go to stderr.
"""
import argparse
import json
import os
import statistics
import sys

import vtkshadow

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtkshadow_bench import log, run_timing  # noqa: E402

# Every registered technique, in registry order ("none" first: the ratios
# are against it).
TECHNIQUES = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
TRIANGLES = [10_000, 100_000, 1_000_000]
SIZES = [(320, 240), (640, 480), (1280, 960)]


def scene(resolution, size):
    return {"description": "bench_growth: sphere over a floor, one directional light",
            "size": list(size),
            "camera": {"position": [0, -8, 5], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1],
                       "view_angle": 30},
            "lights": [{"type": "directional", "direction": [-3, -2, -6]}],
            "objects": [{"sphere": {"center": [0, 0, 1.2], "radius": 0.5,
                                    "resolution": resolution}},
                        {"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0],
                                   "point2": [-5, 5, 0]}, "receiver": True}]}


def triangles(path):
    s = vtkshadow.vtkShadowScene()
    if not s.Load(path):
        sys.exit(f"bench_growth: {path}: {s.GetErrorMessage()}")
    return sum(s.GetObjectPolyData(i).GetNumberOfPolys() for i in range(s.GetNumberOfObjects()))


def write_scene(out, name, resolution, size):
    path = os.path.join(out, name + ".json")
    with open(path, "w") as f:
        json.dump(scene(resolution, size), f, indent=1)
    return path


def resolution_for(out, target):
    """The sphere resolution whose triangle count is nearest `target`."""
    lo, hi = 3, 4096
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if triangles(write_scene(out, "probe", mid, SIZES[1])) < target:
            lo = mid
        else:
            hi = mid
    counts = {r: triangles(write_scene(out, "probe", r, SIZES[1])) for r in (lo, hi)}
    os.remove(os.path.join(out, "probe.json"))
    best = min(counts, key=lambda r: abs(counts[r] - target))
    return best, counts[best]


def measure(cases, a):
    """cases: [(label, path, size)] -> {label: {technique: (ms, ratio, min ms, max ms)},
    with "none#2" (the noise floor) and "too_noisy"}."""
    results = {}
    for label, path, size in cases:
        d = os.path.join(a.out, "runs", label.replace(" ", "_").replace(",", ""))
        st = run_timing(path, TECHNIQUES, size, d, (a.frames, a.rounds, a.warmup,
                                                    a.noise_tolerance))
        if st is None:
            sys.exit(f"bench_growth: {label}: vtkshadow-render failed (see {d})")
        entries = {e["label"]: e for e in st["timing"]["entries"]}
        results[label] = {t: (entries[t]["ms"]["median"], entries[t]["ratio_to_none"]["median"],
                              entries[t]["ms"]["min"], entries[t]["ms"]["max"])
                          for t in TECHNIQUES + ["none#2"]}
        results[label]["too_noisy"] = st["noise_floor"]["too_noisy"]
        log(f"growth {label}: " + ", ".join(f"{t} {results[label][t][0]:.1f} ms "
                                            f"({results[label][t][1]:.2f})"
                                            for t in TECHNIQUES + ["none#2"]))
    return results


def table(title, results, labels):
    lines = [f"| {title} | " + " | ".join(f"{t} ms (x none)" for t in TECHNIQUES) +
             " | noise floor none#2 / none |",
             "|---|" + "---:|" * (len(TECHNIQUES) + 1)]
    for label in labels:
        r = results[label]
        lines.append(f"| {label} | " + " | ".join(
            f"{r[t][0]:.1f} ({r[t][1]:.2f})" for t in TECHNIQUES) +
            f" | {r['none#2'][1]:.3f}{' TOO NOISY' if r['too_noisy'] else ''} |")
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=15, help="timed frames per block")
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=5, help="untimed frames per technique first")
    ap.add_argument("--noise-tolerance", type=float, default=0.03)
    a = ap.parse_args()
    for name, value, ok, want in (
            ("--frames", a.frames, 1 <= a.frames <= 100000, "an integer in [1, 100000]"),
            ("--rounds", a.rounds, 1 <= a.rounds <= 1000, "an integer in [1, 1000]"),
            ("--warmup", a.warmup, 0 <= a.warmup <= 10000, "an integer in [0, 10000]"),
            ("--noise-tolerance", a.noise_tolerance, 0 < a.noise_tolerance < 1,
             "a number in (0, 1)")):
        if not ok:
            ap.error(f"{name}: expected {want} (got {value!r})")
    os.makedirs(a.out, exist_ok=True)
    tri_cases, size_cases = [], []
    res_100k = None
    for target in TRIANGLES:
        res, count = resolution_for(a.out, target)
        label = f"{count:,} triangles"
        tri_cases.append((label, write_scene(a.out, f"tri-{target}", res, SIZES[1]), SIZES[1]))
        if target == 100_000:
            res_100k = (res, count)
        log(f"growth: {target:,} triangles -> sphere resolution {res} ({count:,} triangles)")
    for w, h in SIZES:
        label = f"{w}x{h} ({w * h:,} px)"
        size_cases.append((label, write_scene(a.out, f"px-{w}x{h}", res_100k[0], (w, h)), (w, h)))
    results = measure(tri_cases + size_cases, a)
    with open(os.path.join(a.out, "growth.json"), "w") as f:
        json.dump(results, f, indent=1)
    cmd = (f"tests/gl-run.sh build/bin/vtkshadow-python bench/bench_growth.py --out {a.out} "
           f"--frames {a.frames} --rounds {a.rounds} --warmup {a.warmup} "
           f"--noise-tolerance {a.noise_tolerance}")
    noisy = sum(1 for r in results.values() if r["too_noisy"])
    lines = ["## How cost grows with triangles and pixels", "",
             f"Produced by `{cmd}` (also run by `sh scripts/results.sh`). A sphere over a floor, "
             "one directional light, camera orbit of vtkshadow-render. Each row is one "
             "vtkshadow-render process timing every technique in one window, interleaved: "
             f"{a.warmup} warm-up frames each, then {a.rounds} rounds of one {a.frames}-frame "
             "block per technique, the order changed every round. Each cell: median over rounds "
             "of the block medians in ms, and in brackets the median over rounds of (technique / "
             "none of the same round). The last column is none timed again against none: the "
             f"row's noise floor, TOO NOISY outside 1.00 +- {a.noise_tolerance:.2f}"
             f" ({noisy} of {len(results)} rows)." , ""]
    lines += table("triangles, 640x480", results, [c[0] for c in tri_cases]) + [""]
    lines += table(f"pixels, {res_100k[1]:,} triangles", results, [c[0] for c in size_cases])
    lines.append("")
    with open(os.path.join(a.out, "growth.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
