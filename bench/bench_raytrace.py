"""The cost of ray-traced shadows (--technique raytrace) against pixels,
triangles and lights, next to none and csm; rays per second per core.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_raytrace.py --out DIR
                  [--frames 10] [--rounds 1] [--quick]

Scenes (written to DIR): a sphere over a floor, one directional light; the
sphere at about 10k, 100k and 1M triangles at 640x480; the 100k scene at
320x240, 640x480, 1280x720 and 1920x1080; and 1 to 4 lights (a directional
light plus point lights) at 640x480. vtkshadow-render --stats runs each
(its camera orbit moves every frame, so every frame traces: the cost of a
moving camera; a still camera costs nothing), techniques interleaved per
round with the order rotated. Per row: median ms per frame, its ratio to
none of the same round, and from raytrace's own stats (last frame): the
shadow stage's ms, rays traced, rays per second and per thread, threads.

Writes DIR/raytrace-cost.json and DIR/raytrace-cost.md. Timings on a shared
machine are noisy: compare within a run, as ratios.
"""
import argparse
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_growth import resolution_for  # noqa: E402
from vtkshadow_bench import log, run_render  # noqa: E402

TECHNIQUES = ["none", "csm", "raytrace"]
SIZES = [(320, 240), (640, 480), (1280, 720), (1920, 1080)]
TRIANGLES = [10_000, 100_000, 1_000_000]
POINT_LIGHTS = [{"type": "point", "position": [3, 2, 6]},
                {"type": "point", "position": [-3, 2, 5]},
                {"type": "point", "position": [0, -3, 6]}]


def scene(resolution, size, lights=1):
    return {"description": "bench_raytrace: sphere over a floor",
            "size": list(size),
            "camera": {"position": [0, -8, 5], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1],
                       "view_angle": 30},
            "lights": [{"type": "directional", "direction": [-3, -2, -6]}]
            + POINT_LIGHTS[:lights - 1],
            "objects": [{"sphere": {"center": [0, 0, 1.2], "radius": 0.5,
                                    "resolution": resolution}},
                        {"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0],
                                   "point2": [-5, 5, 0]}, "receiver": True}]}


def write(out, name, resolution, size, lights=1):
    path = os.path.join(out, name + ".json")
    with open(path, "w") as f:
        json.dump(scene(resolution, size, lights), f, indent=1)
    return path


def measure(label, path, size, a):
    times = {t: [] for t in TECHNIQUES}
    ratios = {t: [] for t in TECHNIQUES}
    rt = {}
    for rnd in range(a.rounds):
        k = rnd % len(TECHNIQUES)
        this = {}
        for t in TECHNIQUES[k:] + TECHNIQUES[:k]:
            d = os.path.join(a.out, "runs", label.replace(" ", "_"), t)
            st = run_render(path, ["--technique", t], size, 0, a.frames, d, want_images=False)
            if st is None:
                sys.exit(f"bench_raytrace: {label} {t}: vtkshadow-render failed (see {d})")
            this[t] = st["shadowed_ms"]["median"]
            times[t].append(this[t])
            if t == "raytrace":
                rt = st.get("technique_stats", {})
            log(f"raytrace cost {label}: round {rnd + 1} {t}: {this[t]:.1f} ms")
        for t in TECHNIQUES:
            ratios[t].append(this[t] / this["none"])
    row = {t: (statistics.median(times[t]), statistics.median(ratios[t])) for t in TECHNIQUES}
    threads = max(1, rt.get("threads", 1))
    row["rt"] = {"stage_ms": rt.get("shadow_stage_ms"), "trace_ms": rt.get("trace_ms"),
                 "rays": rt.get("rays_traced"), "rays_per_s": rt.get("rays_per_second"),
                 "rays_per_s_per_thread": (rt.get("rays_per_second") or 0) / threads,
                 "threads": threads, "triangles": rt.get("triangles")}
    return row


def lines_for(title, results):
    out = [f"| {title} | none ms | csm ms (x none) | raytrace ms (x none) | raytrace stage ms | "
           "rays | rays/s | rays/s per thread (threads) |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for label, r in results:
        q = r["rt"]
        out.append(f"| {label} | {r['none'][0]:.1f} | {r['csm'][0]:.1f} ({r['csm'][1]:.2f}) | "
                   f"{r['raytrace'][0]:.1f} ({r['raytrace'][1]:.2f}) | {q['stage_ms'] or 0:.1f} | "
                   f"{q['rays'] or 0:,} | {q['rays_per_s'] or 0:,.0f} | "
                   f"{q['rays_per_s_per_thread']:,.0f} ({q['threads']}) |")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=10)
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--quick", action="store_true", help="skip 1M triangles and 1920x1080")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    res = {}
    for target in TRIANGLES[:2] if a.quick else TRIANGLES:
        res[target] = resolution_for(a.out, target)
        log(f"raytrace cost: {target:,} triangles -> resolution {res[target][0]} "
            f"({res[target][1]:,})")
    r100 = res[100_000][0]
    tri = [(f"{n:,} triangles", write(a.out, f"tri-{t}", r, (640, 480)), (640, 480))
           for t, (r, n) in res.items()]
    px = [(f"{w}x{h}", write(a.out, f"px-{w}x{h}", r100, (w, h)), (w, h))
          for w, h in (SIZES[:3] if a.quick else SIZES)]
    li = [(f"{k} light{'s' if k > 1 else ''}", write(a.out, f"lights-{k}", r100, (640, 480), k),
           (640, 480)) for k in (1, 2, 3, 4)]
    results = {}
    sections = []
    for title, cases in (("pixels (100k triangles, 1 light)", px),
                         ("triangles (640x480, 1 light)", tri),
                         ("lights (640x480, 100k triangles)", li)):
        rows = [(label, measure(label, path, size, a)) for label, path, size in cases]
        results[title] = dict(rows)
        sections.append(lines_for(title, rows))
    with open(os.path.join(a.out, "raytrace-cost.json"), "w") as f:
        json.dump(results, f, indent=1)
    cmd = (f"tests/gl-run.sh build/bin/vtkshadow-python bench/bench_raytrace.py --out {a.out} "
           f"--frames {a.frames} --rounds {a.rounds}" + (" --quick" if a.quick else ""))
    text = ["## Cost of ray-traced shadows", "", f"Produced by `{cmd}`.", ""]
    for s in sections:
        text += s + [""]
    with open(os.path.join(a.out, "raytrace-cost.md"), "w") as f:
        f.write("\n".join(text))
    print("\n".join(text))


if __name__ == "__main__":
    main()
