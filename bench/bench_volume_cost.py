"""Calibrates the shadow-volume cost model of vsh_volume_cost.h (auto's
`volume` candidate): frame time above `none` against window pixels,
silhouette edges and scissored fill.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_volume_cost.py --bin build/bin --out DIR
          [--frames 10] [--rounds 4] [--warmup 3] [--quick] [--refit RUN.json...]

Scenes (written to DIR): one directional light; a grid of n x n spheres of
tessellation r (silhouette edges grow with n^2 r), their radius and the
camera distance changing the fill, with and without a floor (whose volume
fills most of the window), some with a non-casting sphere of tessellation t
beside them (scene triangles without volumes: the depth pre-pass draws it),
at 320x240 and 640x480. Each scene is timed by
one vtkshadow-render process with `none` and `volume` interleaved
(--time-also); the figure per scene is the median over rounds of volume's
round median minus none's. The volume pass's own --stats give the inputs
(volume_quads = sum of silhouette multiplicities, fill_px = the scissor
rectangles), so the model is fitted on the quantities auto predicts.

Fit: least squares of ms = a pixels + t triangles + b edges + c fill (no
intercept: the
model has none); a coefficient that fits negative (noise) is dropped and the
rest refitted. --refit fits the rows of earlier runs' volume_cost.json
files together (no rendering): several runs average the noise. Prints the table, the coefficients and the residuals, and
writes DIR/volume_cost.json. Not a test: timings on a shared machine are
noisy; copy the coefficients into vtkshadow/core/vsh_volume_cost.c with the
date and machine.
"""
import argparse
import json
import os
import platform
import subprocess
import sys


def triangles(path):
    import vtkshadow  # only when rendering (under vtkshadow-python)
    s = vtkshadow.vtkShadowScene()
    if not s.Load(path):
        sys.exit(f"bench_volume_cost: {path}: {s.GetErrorMessage()}")
    return sum(s.GetObjectPolyData(i).GetNumberOfPolys() for i in range(s.GetNumberOfObjects()))


def scene(size, n, res, radius, distance, floor, extra=0):
    objects = []
    if extra:
        objects.append({"sphere": {"center": [1.2, 1.0, 0.3], "radius": 0.3,
                                   "resolution": extra}, "casts": False})
    step = 3.0 * radius
    for i in range(n):
        for j in range(n):
            x, y = (i - (n - 1) / 2) * step, (j - (n - 1) / 2) * step
            objects.append({"sphere": {"center": [x, y, 1.2], "radius": radius,
                                       "resolution": res}})
    if floor:
        objects.append({"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0],
                                  "point2": [-5, 5, 0]}})
    return {"description": "bench_volume_cost", "size": list(size),
            "camera": {"position": [0, -distance, 0.6 * distance], "focal_point": [0, 0, 0.6],
                       "view_up": [0, 0, 1], "view_angle": 30},
            "lights": [{"type": "directional", "direction": [-1, -0.7, -6]}],
            "objects": objects}


CONFIGS = [  # (size, n, res, radius, distance, floor, non-casting sphere's res)
    ((320, 240), 1, 16, 0.5, 8, False), ((320, 240), 1, 128, 0.5, 8, False),
    ((320, 240), 4, 32, 0.2, 8, False), ((320, 240), 8, 16, 0.1, 8, False),
    ((320, 240), 1, 32, 1.5, 5, False), ((320, 240), 1, 32, 0.5, 8, True),
    ((320, 240), 1, 16, 0.5, 8, False, 200),
    ((640, 480), 1, 16, 0.5, 8, False), ((640, 480), 1, 160, 0.5, 8, False),
    ((640, 480), 6, 24, 0.15, 8, False), ((640, 480), 12, 12, 0.06, 8, False),
    ((640, 480), 1, 32, 1.5, 5, False), ((640, 480), 1, 32, 0.5, 8, True),
    ((640, 480), 3, 32, 0.4, 8, True), ((640, 480), 1, 16, 0.5, 8, False, 200),
]


def measure(args, index, config):
    sc = scene(*config)
    path = os.path.join(args.out, "scene%02d.json" % index)
    with open(path, "w") as f:
        json.dump(sc, f)
    stats = os.path.join(args.out, "stats%02d.json" % index)
    cmd = [os.path.join(args.bin, "vtkshadow-render"), path, "--technique", "none",
           "--time-also", "volume", "--image", os.path.join(args.out, "scene%02d.png" % index),
           "--stats", stats, "--frames", str(args.frames), "--rounds", str(args.rounds),
           "--warmup", str(args.warmup), "--quiet"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("bench_volume_cost: %s failed (%d): %s" % (" ".join(cmd), run.returncode,
                                                            run.stderr))
    with open(stats) as f:
        entries = {e["label"]: e for e in json.load(f)["timing"]["entries"]}
    none, vol = entries["none"], entries["volume"]
    diffs = sorted(v - n for v, n in zip(vol["round_medians_ms"], none["round_medians_ms"]))
    mid = len(diffs) // 2
    ms = diffs[mid] if len(diffs) % 2 else 0.5 * (diffs[mid - 1] + diffs[mid])
    light = vol["technique_stats"]["lights"][0]
    w, h = config[0]
    return {"config": list(config), "pixels": w * h, "triangles": triangles(path),
            "edges": light["volume_quads"],
            "fill_px": light["fill_px"], "ms": ms, "none_ms": none["ms"]["median"],
            "noise": entries["none#2"]["ratio_to_none"]["median"]}


TERMS = ["pixels", "triangles", "edges", "fill_px"]


def solve(rows, terms):
    """Least squares without intercept over `terms` (normal equations)."""
    k = len(terms)
    a = [[sum(r[terms[i]] * r[terms[j]] for r in rows) for j in range(k)] for i in range(k)]
    b = [sum(r[terms[i]] * r["ms"] for r in rows) for i in range(k)]
    for col in range(k):  # Gauss-Jordan with partial pivoting
        p = max(range(col, k), key=lambda r: abs(a[r][col]))
        a[col], a[p], b[col], b[p] = a[p], a[col], b[p], b[col]
        if a[col][col] == 0:
            return None
        for r in range(k):
            if r != col:
                f = a[r][col] / a[col][col]
                a[r] = [x - f * y for x, y in zip(a[r], a[col])]
                b[r] -= f * b[col]
    return {terms[i]: b[i] / a[i][i] for i in range(k)}


def fit(rows):
    terms = list(TERMS)
    while terms:
        coef = solve(rows, terms)
        negative = [t for t in terms if coef is None or coef[t] < 0]
        if not negative:
            return {t: coef.get(t, 0.0) for t in TERMS} | {
                "dropped": [t for t in TERMS if t not in terms]}
        terms.remove(negative[0])
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=10)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="the first 4 scenes only")
    ap.add_argument("--refit", nargs="+", default=[], help="volume_cost.json of earlier runs")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for path in args.refit:
        with open(path) as f:
            rows += json.load(f)["rows"]
    configs = [] if args.refit else CONFIGS[:4] if args.quick else CONFIGS
    for i, config in enumerate(configs):
        rows.append(measure(args, i, config))
        r = rows[-1]
        print("%-44s pixels %6d triangles %7d edges %5d fill %8d: volume - none %7.3f ms "
              "(none %.2f, noise %.3f)" % (str(config), r["pixels"], r["triangles"], r["edges"],
                                          r["fill_px"], r["ms"], r["none_ms"], r["noise"]),
              flush=True)
    coef = fit(rows)
    if coef is None:
        sys.exit("bench_volume_cost: no fit (every term came out negative)")
    print("fit: ms = %.4g * pixels + %.4g * triangles + %.4g * edges + %.4g * fill_px "
          "(dropped: %s)" % (coef["pixels"], coef["triangles"], coef["edges"], coef["fill_px"],
                             coef["dropped"] or "none"))
    for r in rows:
        pred = sum(coef[t] * r[t] for t in TERMS)
        print("  %-44s measured %8.3f predicted %8.3f" % (str(r["config"]), r["ms"], pred))
    with open(os.path.join(args.out, "volume_cost.json"), "w") as f:
        json.dump({"machine": platform.node(), "cpu": platform.processor(), "rows": rows,
                   "coefficients": coef}, f, indent=1)


if __name__ == "__main__":
    main()
