"""How each technique's frame time grows with triangles, pixels, lights and screen coverage.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_growth.py --out DIR
                  [--frames 15] [--rounds 4] [--warmup 5] [--noise-tolerance 0.03]
                  [--triangles 10000,100000,1000000]
                  [--sizes 320x240,640x480,1280x960,1920x1080]
                  [--lights 1,2,3,4] [--view-angles 40,20,10]
                  [--base-size 640x480] [--base-triangles 100000]

Scenes (written to DIR, in the vtkshadow scene format): a sphere over a floor
lit by one directional light, the sphere tessellated to about 10k, 100k and
1M triangles (--triangles), at 640x480 (--base-size); the 100k scene
(--base-triangles) at 320x240 to 1920x1080 (--sizes); the 100k scene with 1
to 4 lights (a directional light, then point lights; --lights); and the 100k
scene seen through narrower view angles (--view-angles), so that the sphere,
its shadow and its shadow volume cover more of the screen. Each row also
gives what the exact techniques' cost is made of, from their own stats of
the last frame: volume's silhouette edges and fill (volume pixels, light 0)
and raytrace's rays per second per thread. The ctest
cli.bench_growth runs it on a tiny configuration and checks what it writes. Each scene is rendered with every technique of the registry
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
import shlex
import sys

import vtkshadow

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtkshadow_bench import check_ranges, log, run_timing, timing_checks  # noqa: E402

# Every registered technique, in registry order ("none" first: the ratios
# are against it).
TECHNIQUES = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
TRIANGLES = "10000,100000,1000000"
SIZES = "320x240,640x480,1280x960,1920x1080"
LIGHTS = "1,2,3,4"
VIEW_ANGLES = "40,20,10"
# Lights after the first (directional) one, for the lights table.
POINT_LIGHTS = [{"type": "point", "position": [3, 2, 6]},
                {"type": "point", "position": [-3, 2, 5]},
                {"type": "point", "position": [0, -3, 6]}]


def scene(resolution, size, lights=1, view_angle=30):
    return {"description": "bench_growth: sphere over a floor, %d light(s)" % lights,
            "size": list(size),
            "camera": {"position": [0, -8, 5], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1],
                       "view_angle": view_angle},
            "lights": [{"type": "directional", "direction": [-3, -2, -6]}]
            + POINT_LIGHTS[:lights - 1],
            "objects": [{"sphere": {"center": [0, 0, 1.2], "radius": 0.5,
                                    "resolution": resolution}},
                        {"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0],
                                   "point2": [-5, 5, 0]}, "receiver": True}]}


def triangles(path):
    s = vtkshadow.vtkShadowScene()
    if not s.Load(path):
        sys.exit(f"bench_growth: {path}: {s.GetErrorMessage()}")
    return sum(s.GetObjectPolyData(i).GetNumberOfPolys() for i in range(s.GetNumberOfObjects()))


def write_scene(out, name, resolution, size, lights=1, view_angle=30):
    path = os.path.join(out, name + ".json")
    with open(path, "w") as f:
        json.dump(scene(resolution, size, lights, view_angle), f, indent=1)
    return path


def sphere_triangles(resolution):
    """Triangles of a scene sphere (docs/scene-format.md, Tessellation):
    2 R (L - 1) with L = max(2, R / 2)."""
    return 2 * resolution * (max(2, resolution // 2) - 1)


def resolution_for(out, target, size):
    """The sphere resolution whose triangle count is nearest `target`, and
    the scene's triangle count as the loader makes it (sphere and floor)."""
    best = min(range(3, 4097), key=lambda r: (abs(sphere_triangles(r) - target), r))
    count = triangles(write_scene(out, "probe", best, size))
    os.remove(os.path.join(out, "probe.json"))
    return best, count


def cost_details(entries):
    """What the exact techniques' cost is made of, from their stats of the
    last timed frame: volume's silhouette edges and fill (volume pixels) of
    light 0, raytrace's rays per second per thread. None where a technique
    is not registered or did not say."""
    vol = ((entries.get("volume") or {}).get("technique_stats") or {}).get("lights") or [{}]
    rt = (entries.get("raytrace") or {}).get("technique_stats") or {}
    threads = rt.get("threads") or 0
    return {"volume_silhouette_edges": vol[0].get("silhouette_edges"),
            "volume_fill_px": vol[0].get("fill_px"),
            "raytrace_rays_per_s_per_thread": (rt["rays_per_second"] / threads
                                               if threads and rt.get("rays_per_second")
                                               else None)}


def measure(cases, a):
    """cases: [(label, path, size)] -> {label: {technique: (ms, ratio, min ms, max ms)},
    with "none#2" (the noise floor), "too_noisy" and "details" (cost_details)}."""
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
        results[label]["details"] = cost_details(entries)
        log(f"growth {label}: " + ", ".join(f"{t} {results[label][t][0]:.1f} ms "
                                            f"({results[label][t][1]:.2f})"
                                            for t in TECHNIQUES + ["none#2"]))
    return results


DETAIL_COLUMNS = [("volume_silhouette_edges", "volume silhouette edges", "{:,}"),
                  ("volume_fill_px", "volume fill px", "{:,}"),
                  ("raytrace_rays_per_s_per_thread", "raytrace rays/s per thread", "{:,.0f}")]


def table(title, results, labels):
    lines = [f"| {title} | " + " | ".join(f"{t} ms (x none)" for t in TECHNIQUES) +
             " | noise floor none#2 / none | " + " | ".join(h for _, h, _ in DETAIL_COLUMNS) +
             " |", "|---|" + "---:|" * (len(TECHNIQUES) + 1 + len(DETAIL_COLUMNS))]
    for label in labels:
        r = results[label]
        det = r["details"]
        lines.append(f"| {label} | " + " | ".join(
            f"{r[t][0]:.1f} ({r[t][1]:.2f})" for t in TECHNIQUES) +
            f" | {r['none#2'][1]:.3f}{' TOO NOISY' if r['too_noisy'] else ''} | " +
            " | ".join("-" if det[k] is None else f.format(det[k]) for k, _, f in DETAIL_COLUMNS)
            + " |")
    return lines


def parse_list(ap, name, text, parse):
    """A comma-separated option, each item through parse (ValueError: the
    option, the item and what is expected, exit status 2)."""
    out = []
    for item in text.split(","):
        try:
            out.append(parse(item.strip()))
        except ValueError as e:
            ap.error(f"{name}: {e} (got {item.strip()!r} in {text!r})")
    if not out:
        ap.error(f"{name}: empty list (got {text!r})")
    return out


def size_of(text):
    w, sep, h = text.partition("x")
    if not sep or not w.isdigit() or not h.isdigit() or not (1 <= int(w) <= 16384
                                                             and 1 <= int(h) <= 16384):
        raise ValueError("expected WxH, whole numbers in 1..16384")
    return int(w), int(h)


def triangle_count(text):
    if not text.isdigit() or not 12 <= int(text) <= 20_000_000:
        raise ValueError("expected a whole number of triangles in 12..20000000")
    return int(text)


def light_count(text):
    if not text.isdigit() or not 1 <= int(text) <= 1 + len(POINT_LIGHTS):
        raise ValueError(f"expected a whole number of lights in 1..{1 + len(POINT_LIGHTS)}")
    return int(text)


def view_angle(text):
    try:
        v = float(text)
    except ValueError:
        v = float("nan")
    if not 1 <= v <= 120:
        raise ValueError("expected a view angle in degrees in [1, 120]")
    return v


def options():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=15, help="timed frames per block")
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=5, help="untimed frames per technique first")
    ap.add_argument("--noise-tolerance", type=float, default=0.03)
    ap.add_argument("--triangles", default=TRIANGLES, help="triangle counts of the first table")
    ap.add_argument("--sizes", default=SIZES, help="window sizes of the second table")
    ap.add_argument("--lights", default=LIGHTS, help="light counts of the third table (1..4)")
    ap.add_argument("--view-angles", default=VIEW_ANGLES,
                    help="camera view angles in degrees of the fourth table (coverage)")
    ap.add_argument("--base-size", default="640x480", help="window of the first table")
    ap.add_argument("--base-triangles", default="100000", help="triangles of the second table")
    a = ap.parse_args()
    check_ranges(ap, timing_checks(a))
    a.triangles = parse_list(ap, "--triangles", a.triangles, triangle_count)
    a.sizes = parse_list(ap, "--sizes", a.sizes, size_of)
    a.lights = parse_list(ap, "--lights", a.lights, light_count)
    a.view_angles = parse_list(ap, "--view-angles", a.view_angles, view_angle)
    a.base_size = parse_list(ap, "--base-size", a.base_size, size_of)[0]
    a.base_triangles = parse_list(ap, "--base-triangles", a.base_triangles, triangle_count)[0]
    return a


def main():
    a = options()
    os.makedirs(a.out, exist_ok=True)
    tri_cases, size_cases = [], []
    bw, bh = a.base_size
    for target in a.triangles:
        res, count = resolution_for(a.out, target, a.base_size)
        label = f"{count:,} triangles"
        tri_cases.append((label, write_scene(a.out, f"tri-{target}", res, a.base_size),
                          a.base_size))
        log(f"growth: {target:,} triangles -> sphere resolution {res} ({count:,} triangles)")
    res, base_count = resolution_for(a.out, a.base_triangles, a.base_size)
    for w, h in a.sizes:
        label = f"{w}x{h} ({w * h:,} px)"
        size_cases.append((label, write_scene(a.out, f"px-{w}x{h}", res, (w, h)), (w, h)))
    light_cases = [(f"{k} light{'s' if k > 1 else ''}",
                    write_scene(a.out, f"lights-{k}", res, a.base_size, lights=k), a.base_size)
                   for k in a.lights]
    angle_cases = [(f"view angle {v:g} deg",
                    write_scene(a.out, f"angle-{v:g}", res, a.base_size, view_angle=v),
                    a.base_size) for v in a.view_angles]
    results = measure(tri_cases + size_cases + light_cases + angle_cases, a)
    with open(os.path.join(a.out, "growth.json"), "w") as f:
        json.dump(results, f, indent=1)
    cmd = " ".join(shlex.quote(x) for x in ["tests/gl-run.sh", "build/bin/vtkshadow-python",
                                            "bench/bench_growth.py"] + sys.argv[1:])
    noisy = sum(1 for r in results.values() if r["too_noisy"])
    lines = ["## How cost grows with triangles, pixels, lights and coverage", "",
             f"Produced by `{cmd}` (also run by `sh scripts/results.sh`). A sphere over a floor, "
             "one directional light (the lights table adds point lights), camera orbit of "
             "vtkshadow-render. Each row is one "
             "vtkshadow-render process timing every technique in one window, interleaved: "
             f"{a.warmup} warm-up frames each, then {a.rounds} rounds of one {a.frames}-frame "
             "block per technique, the order changed every round. Each cell: median over rounds "
             "of the block medians in ms, and in brackets the median over rounds of (technique / "
             "none of the same round). The noise floor column is none timed again against none: "
             f"the row's noise floor, TOO NOISY outside 1.00 +- {a.noise_tolerance:.2f}"
             f" ({noisy} of {len(results)} rows). The last columns are what the exact "
             "techniques' cost is made of (their stats of the last frame): volume's silhouette "
             "edges and fill (pixels its volumes cover, light 0; the cost that grows with "
             "coverage) and raytrace's occlusion rays per second per thread.", ""]
    lines += table(f"triangles, {bw}x{bh}", results, [c[0] for c in tri_cases]) + [""]
    lines += table(f"pixels, {base_count:,} triangles", results, [c[0] for c in size_cases])
    lines += [""] + table(f"lights, {bw}x{bh}, {base_count:,} triangles", results,
                          [c[0] for c in light_cases])
    lines += [""] + table(f"coverage, {bw}x{bh}, {base_count:,} triangles", results,
                          [c[0] for c in angle_cases])
    lines.append("")
    with open(os.path.join(a.out, "growth.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
