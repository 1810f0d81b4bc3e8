#!/usr/bin/env python3
"""vtkshadow-bench: speed against error for every shadow technique.

    bench/vtkshadow-bench SCENE... --out DIR [--scale F] [--frames N]
                          [--grid small|full] [--rounds R] [--light K]
                          [--peers PREFIXES] [--cache DIR]

SCENE may be a folder (every scene file under it). --scale F multiplies
each scene's image size (renders and references alike; scripts/results.sh
uses 0.5).

(bench/vtkshadow-bench runs this file with build/bin/vtkshadow-python under
tests/gl-run.sh when no X display is set.)

For each scene (light K, default 0) it runs build/bin/vtkshadow-render with
every technique of the registry (vtkShadowTechnique.GetKnownTechniques()), each
with its settings from SETTINGS below: none; vtk at map 1024, 2048, 4096;
planar when the scene has a receiver; csm at its defaults and over a grid
(small: cascades 1,2,4 x map 512,1024,2048 x filter 0 (hardware); full:
cascades 1..4 x map 512..4096 x filter 0,1,2); auto; a technique with no
SETTINGS entry once at its defaults. Each render gives the visibility and mask of light K (scored with
build/bin/vtkshadow-metrics against the POV-Ray reference of
build/bin/vtkshadow-compare --renderers povray, cached in DIR/refs) and
--stats timings: the median ms per frame over --frames (>= 30) frames along
vtkshadow-render's camera orbit, shadowed and unshadowed in the same process.

Timing on a shared machine is noisy, so: the configurations of one scene are
interleaved in --rounds rounds (the order rotates every round); every run
reports its own unshadowed time, and `ratio` = shadowed / unshadowed of the
same run (median over rounds) is the number to compare. `ms_per_frame` is
ratio x the scene's median unshadowed time over all its runs (a noise-reduced
absolute time); `raw_ms` is the plain median of the shadowed medians;
overhead_ms = ms_per_frame - unshadowed. Timings cover all lights of a scene
(vtkshadow-render renders every light); errors are for light K only.

Outputs: DIR/bench.csv (one row per scene and configuration), DIR/bench.json,
DIR/<scene>/<config>/ (visibility, mask, stats, metrics of each run),
DIR/<scene>.png (gnuplot: wrong_pct, log, floored at 1e-3, against
ms_per_frame, log; one series per technique family; Pareto front drawn),
DIR/summary.md (tables, auto's position against the Pareto front, goals).
With --peers PREFIXES, scenes whose key starts with one of them also get
Blender EEVEE rows (technique eevee, settings default / best) from
vtkshadow-compare --renderers povray,eevee,eevee-best, scored against the
same POV-Ray reference; their ms_per_frame is Blender's own seconds per
frame (offline, not comparable to an interactive frame), so peers are
plotted but are not on the Pareto front.
Progress lines go to stderr.
"""

import argparse
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "build", "bin")
WRONG_FLOOR = 1e-3

COLUMNS = ["scene", "technique", "settings", "ms_per_frame", "overhead_ms",
           "unshadowed_ms", "ratio", "raw_ms", "memory_bytes", "wrong_pct",
           "vis_mae", "edge_px", "false_shadow_pct", "false_light_pct",
           "auto_choice", "texel_px", "auto_reason"]


def log(msg):
    print("vtkshadow-bench: " + msg, file=sys.stderr, flush=True)


def scene_key(path):
    """Same naming as vtkshadow-compare: path relative to the folder of the
    nearest thresholds.json, without .json, / -> -."""
    path = os.path.abspath(path)
    d = os.path.dirname(path)
    while True:
        if os.path.exists(os.path.join(d, "thresholds.json")):
            break
        parent = os.path.dirname(d)
        if parent == d:
            d = os.path.dirname(path)
            break
        d = parent
    rel = os.path.relpath(path, d)
    if rel.endswith(".json"):
        rel = rel[:-5]
    return rel.replace(os.sep, "-")


def scene_info(path):
    with open(path) as f:
        doc = json.load(f)
    size = doc.get("size", [800, 600])
    receivers = any(o.get("receiver") for o in doc.get("objects", []))
    return size, receivers


def registered_techniques():
    """The technique names of the build's registry, in registry order
    (vtkShadowTechnique.GetKnownTechniques()). Under plain python3 (no
    vtkshadow module) build/bin/vtkshadow-python answers."""
    try:
        import vtkshadow
        names = vtkshadow.vtkShadowTechnique.GetKnownTechniques()
    except ImportError:
        cmd = [os.path.join(BIN, "vtkshadow-python"), "-c",
               "import vtkshadow; print(vtkshadow.vtkShadowTechnique.GetKnownTechniques())"]
        try:
            names = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        except (OSError, subprocess.CalledProcessError) as e:
            sys.exit("vtkshadow-bench: cannot read the technique registry (%s): %s" % (
                " ".join(cmd), e))
    return names.split()


def _grid_csm(grid):
    out = [("default", [])]
    if grid == "small":
        cascades, maps, filters = (1, 2, 4), (512, 1024, 2048), (0,)
    else:
        cascades, maps, filters = (1, 2, 3, 4), (512, 1024, 2048, 4096), (0, 1, 2)
    for c in cascades:
        for m in maps:
            for fl in filters:
                out.append(("cascades=%d map=%d filter=%d" % (c, m, fl),
                            ["--map-resolution", str(m), "--set", "cascades=%d" % c,
                             "--set", "filter=%d" % fl]))
    return out


# The settings each technique is benchmarked with, as data: technique ->
# (needs a receiver in the scene, grid -> [(settings label, extra
# vtkshadow-render args)]). A registered technique not listed here runs once,
# as ("default", []).
SETTINGS = {
    "none": (False, lambda grid: [("-", [])]),
    "vtk": (False, lambda grid: [("map=%d" % r, ["--map-resolution", str(r)])
                                 for r in (1024, 2048, 4096)]),
    "planar": (True, lambda grid: [("-", [])]),
    "csm": (False, _grid_csm),
    "auto": (False, lambda grid: [("default", [])]),
}


def configs_for(receivers, grid, techniques=None):
    """(technique, settings label, extra vtkshadow-render args) for every
    registered technique, in registry order."""
    out = []
    for tech in techniques if techniques is not None else registered_techniques():
        needs_receiver, settings = SETTINGS.get(tech, (False, lambda grid: [("default", [])]))
        if needs_receiver and not receivers:
            continue
        out.extend((tech, label, args) for label, args in settings(grid))
    return out


def config_dir(tech, settings):
    s = settings.replace(" ", "_").replace("=", "")
    return tech if s in ("-", "default") and tech != "csm" else tech + "_" + s


def run_compare(scenes, out, scale, renderers, name):
    """vtkshadow-compare into DIR/<name>, sharing one reference cache."""
    dest = os.path.join(out, name)
    cmd = [os.path.join(BIN, "vtkshadow-compare")] + scenes + [
        "--out", dest, "--cache", CACHE or os.path.join(out, "cache"), "--scale", repr(scale),
        "--renderers", renderers, "--no-report"]
    log("%s (cached): %s" % (renderers, " ".join(cmd)))
    with open(os.path.join(out, name + ".log"), "w") as logf:
        rc = subprocess.call(cmd, stdout=logf, stderr=subprocess.STDOUT)
    if rc != 0:
        log("warning: vtkshadow-compare exited %d (see %s/%s.log)" % (rc, out, name))
    return dest


def ensure_refs(scenes, out, scale):
    return run_compare(scenes, out, scale, "povray", "refs")


PEERS = (("eevee", "default"), ("eevee-best", "best"))
CACHE = None  # --cache: reference renders shared between runs


def peer_rows(scenes, out, scale, light):
    """Blender EEVEE (default and best settings) through the same harness,
    scored against the same POV-Ray reference. Its time is Blender's own
    seconds per frame (an offline renderer: 64 samples, shadow maps rebuilt
    every frame), so it goes on the plots but not into the Pareto front."""
    dest = run_compare(scenes, out, scale, "povray,eevee,eevee-best", "peers")
    try:
        with open(os.path.join(dest, "results.json")) as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        log("peers: no results (%s)" % e)
        return {}
    rows = {}
    for sc in doc.get("scenes", []):
        key = sc.get("scene", "").replace("/", "-")
        seconds = sc.get("frame_seconds") or {}
        for test, label in PEERS:
            hit = [r for r in sc.get("results", []) if r.get("test") == test
                   and r.get("light") == light and r.get("reference") == "povray"]
            row = {c: None for c in COLUMNS}
            row.update(scene=key, technique="eevee", settings=label)
            if test in seconds:
                row["ms_per_frame"] = 1000.0 * seconds[test]
            if hit:
                for k in ("wrong_pct", "vis_mae", "edge_px", "false_shadow_pct", "false_light_pct"):
                    row[k] = hit[0].get(k)
            rows.setdefault(key, []).append(row)
    return rows


def run_render(scene, args, size, light, frames, d, want_images):
    os.makedirs(d, exist_ok=True)
    stats = os.path.join(d, "stats.json")
    cmd = [os.path.join(BIN, "vtkshadow-render"), scene, "--image",
           os.path.join(d, "image.png"), "--light", str(light), "--stats", stats,
           "--frames", str(frames), "--size", "%dx%d" % size, "--quiet"] + args
    if want_images:
        cmd += ["--visibility", os.path.join(d, "visibility.png"),
                "--mask", os.path.join(d, "mask.png")]
    if os.path.exists(stats):
        os.remove(stats)
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(d, "render.log"), "a") as f:
        f.write(" ".join(cmd) + "\n" + p.stdout)
    if p.returncode != 0 or not os.path.exists(stats):
        log("  FAILED (%d): %s" % (p.returncode, " ".join(cmd)))
        return None
    with open(stats) as f:
        return json.load(f)


def metrics(ref_vis, ref_mask, test, out_json):
    cmd = [os.path.join(BIN, "vtkshadow-metrics"), "--reference", ref_vis,
           "--mask", ref_mask, "--test", test, "--json", out_json]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0 or not os.path.exists(out_json):
        log("  metrics FAILED: " + " ".join(cmd) + "\n" + p.stderr)
        return {}
    with open(out_json) as f:
        return json.load(f)


def pareto(rows):
    """Rows not dominated in (ratio, wrong_pct): sorted by time."""
    pts = sorted((r for r in rows if r["ratio"] is not None and r["wrong_pct"] is not None),
                 key=lambda r: (r["ratio"], r["wrong_pct"]))
    front, best = [], float("inf")
    for r in pts:
        if r["wrong_pct"] < best:
            front.append(r)
            best = r["wrong_pct"]
    return front


def bench_scene(scene, a, refs):
    key = scene_key(scene)
    size0, receivers = scene_info(scene)
    size = (max(1, round(size0[0] * a.scale)), max(1, round(size0[1] * a.scale)))
    ref_vis = os.path.join(refs, key, "povray", "light%d_visibility.png" % a.light)
    ref_mask = os.path.join(refs, key, "povray", "light%d_mask.png" % a.light)
    have_ref = os.path.exists(ref_vis) and os.path.exists(ref_mask)
    if not have_ref:
        log("%s: no POV-Ray reference at %s: errors left empty" % (key, ref_vis))
    cfgs = configs_for(receivers, a.grid)
    runs = {i: [] for i in range(len(cfgs))}
    stats_last = {}
    for rnd in range(a.rounds):
        order = list(range(len(cfgs)))
        k = (rnd * len(cfgs)) // a.rounds
        order = order[k:] + order[:k]
        if rnd % 2 == 1:
            order.reverse()
        for n, i in enumerate(order):
            tech, settings, extra = cfgs[i]
            d = os.path.join(a.out, key, config_dir(tech, settings))
            t0 = time.time()
            st = run_render(scene, ["--technique", tech] + extra, size, a.light,
                            a.frames, d, want_images=(rnd == 0))
            if st is None:
                continue
            runs[i].append(st)
            stats_last[i] = st
            log("%s: round %d/%d, %d/%d %s %s: %.1f ms (unshadowed %.1f) [%.0f s]" % (
                key, rnd + 1, a.rounds, n + 1, len(cfgs), tech, settings,
                st["shadowed_ms"]["median"], st["unshadowed_ms"]["median"],
                time.time() - t0))
    all_unsh = [s["unshadowed_ms"]["median"] for i in runs for s in runs[i]]
    unsh = statistics.median(all_unsh) if all_unsh else None
    rows = []
    for i, (tech, settings, extra) in enumerate(cfgs):
        d = os.path.join(a.out, key, config_dir(tech, settings))
        row = {c: None for c in COLUMNS}
        row.update(scene=key, technique=tech, settings=settings)
        if runs[i]:
            ratio = statistics.median(s["shadowed_ms"]["median"] / s["unshadowed_ms"]["median"]
                                      for s in runs[i])
            row["ratio"] = ratio
            row["raw_ms"] = statistics.median(s["shadowed_ms"]["median"] for s in runs[i])
            row["ms_per_frame"] = ratio * unsh
            row["unshadowed_ms"] = unsh
            row["overhead_ms"] = (ratio - 1.0) * unsh
            st = stats_last[i]
            row["memory_bytes"] = st.get("shadow_map_bytes")
            ts = st.get("technique_stats") or {}
            if tech == "auto":
                lc = ts.get("light_choices") or []
                row["auto_choice"] = "%s [%s]%s" % (
                    ts.get("choice"), ", ".join(lc),
                    " texel <= %.2f px" % ts["texel_target_px"]
                    if "csm" in str(ts.get("choice")) and ts.get("texel_target_px") else "")
                row["auto_reason"] = ts.get("reason")
            lights = ts.get("lights")
            if tech in ("csm", "auto") and isinstance(lights, list) and len(lights) > a.light:
                tp = lights[a.light].get("texel_px")
                if tp:
                    row["texel_px"] = "/".join("%.2f" % v for v in tp)
        vis = os.path.join(d, "visibility.png")
        if have_ref and os.path.exists(vis):
            m = metrics(ref_vis, ref_mask, vis, os.path.join(d, "metrics.json"))
            for k in ("wrong_pct", "vis_mae", "edge_px", "false_shadow_pct", "false_light_pct"):
                row[k] = m.get(k)
        rows.append(row)
    return key, size, rows


def fmt(v, nd=2):
    if v is None:
        return "-"
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        if v != 0 and abs(v) < 10 ** -nd:
            return "%.1e" % v
        return ("%." + str(nd) + "f") % v
    return str(v)


def mib(b):
    return "-" if b is None else ("0" if b == 0 else "%.1f MiB" % (b / 1048576.0))


def family(r):
    return r["technique"]


def plot(key, rows, front, out):
    gp = shutil.which("gnuplot")
    if not gp:
        log("gnuplot not found (apt-get install gnuplot-nox): no plot")
        return None
    ddir = os.path.join(out, key)
    os.makedirs(ddir, exist_ok=True)
    fams = []
    for r in rows:
        if r["ms_per_frame"] is None or r["wrong_pct"] is None:
            continue
        f = family(r)
        if f not in fams:
            fams.append(f)
        with open(os.path.join(ddir, "plot_%s.dat" % f), "a" if fams.count(f) and os.path.exists(
                os.path.join(ddir, "plot_%s.dat" % f)) else "w") as fh:
            fh.write("%g %g\n" % (r["ms_per_frame"], max(r["wrong_pct"], WRONG_FLOOR)))
    with open(os.path.join(ddir, "plot_front.dat"), "w") as fh:
        for r in front:
            fh.write("%g %g\n" % (r["ms_per_frame"], max(r["wrong_pct"], WRONG_FLOOR)))
    png = os.path.join(out, key + ".png")
    styles = {"none": "pt 6 ps 1.5 lc rgb '#777777'", "vtk": "pt 5 ps 1.5 lc rgb '#d62728'",
              "planar": "pt 9 ps 1.5 lc rgb '#2ca02c'", "csm": "pt 7 ps 1.5 lc rgb '#1f77b4'",
              "auto": "pt 3 ps 2.5 lc rgb '#000000'", "eevee": "pt 11 ps 1.5 lc rgb '#9467bd'"}
    plots = ["'%s' using 1:2 with linespoints dt 2 lw 1.5 lc rgb '#ff7f0e' pt 1 title 'Pareto front'"
             % os.path.join(ddir, "plot_front.dat")]
    for f in fams:
        plots.append("'%s' using 1:2 with points %s title '%s'" % (
            os.path.join(ddir, "plot_%s.dat" % f), styles.get(f, "pt 1"), f))
    script = "\n".join([
        "set terminal pngcairo size 720,480 noenhanced" if _has_cairo(gp) else
        "set terminal png size 720,480 noenhanced",
        "set output '%s'" % png,
        "set title '%s: wrong_pct (light 0) against ms/frame'" % key,
        "set label 1 'time = same-run shadowed/unshadowed ratio x median unshadowed' at graph 0.02,0.04 font ',8'",
        "set logscale xy",
        "set xlabel 'ms per frame (log)'",
        "set ylabel 'wrong_pct (log, floor %g)'" % WRONG_FLOOR,
        "set grid",
        "set key top right",
        "plot " + ", ".join(plots),
    ]) + "\n"
    p = subprocess.run([gp], input=script, text=True, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE)
    if p.returncode != 0:
        log("gnuplot failed: " + p.stderr)
        return None
    return png


_CAIRO = None


def _has_cairo(gp):
    global _CAIRO
    if _CAIRO is None:
        p = subprocess.run([gp, "-e", "set terminal"], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        _CAIRO = "pngcairo" in p.stdout
    return _CAIRO


def front_position(rows):
    """auto against the Pareto front of the manual configurations of the same
    run: (auto's row, the fastest other configuration with wrong_pct <= auto's
    or None when auto's error is the lowest, auto's time / that one's).
    (None, None, None) without an auto result. Rows without a same-run ratio
    (the EEVEE peer) never count."""
    a = next((r for r in rows if r["technique"] == "auto" and r.get("ratio") is not None), None)
    if not a or a.get("wrong_pct") is None:
        return None, None, None
    others = [r for r in rows if r["technique"] != "auto" and r.get("ratio") is not None
              and r.get("wrong_pct") is not None and r["wrong_pct"] <= a["wrong_pct"] + 1e-9]
    if not others:
        return a, None, 1.0
    best = min(others, key=lambda r: r["ratio"])
    return a, best, a["ratio"] / best["ratio"]


def auto_check(rows):
    """auto passes when its time is within 10% of the front's at its error."""
    a, best, rel = front_position(rows)
    if a is None:
        return "auto: no result"
    if best is None:
        return ("auto (%s): wrong_pct %s, lower than every other configuration: on the front"
                % (a["auto_choice"], fmt(a["wrong_pct"], 3)))
    verdict = "on or within 10% of the front" if rel <= 1.10 else "NOT within 10% of the front"
    return ("auto (%s): wrong_pct %s at %.1f ms; fastest other with wrong_pct <= that: %s %s, "
            "wrong_pct %s at %.1f ms; auto/that = %.2fx: %s" % (
                a["auto_choice"], fmt(a["wrong_pct"], 3), a["ms_per_frame"], best["technique"],
                best["settings"], fmt(best["wrong_pct"], 3), best["ms_per_frame"], rel, verdict))


def goal_figures(rows):
    """Issue #6's goals for one scene: the csm default and vtk (2048) rows,
    vtk's wrong_pct over csm's (csm floored at WRONG_FLOOR), csm's frame-time
    ratio over vtk's, and planar's overhead as a fraction of the unshadowed
    frame (None where a row is missing)."""
    get = lambda t, s: next((r for r in rows if r["technique"] == t and r["settings"] == s
                             and r.get("ratio") is not None), None)
    csm, vtk, planar = get("csm", "default"), get("vtk", "map=2048"), get("planar", "-")
    none = get("none", "-")
    err = time_ratio = None
    if csm and vtk and csm["wrong_pct"] is not None and vtk["wrong_pct"] is not None:
        err = vtk["wrong_pct"] / max(csm["wrong_pct"], WRONG_FLOOR)
        time_ratio = csm["ratio"] / vtk["ratio"]
    overhead = planar["ratio"] - 1.0 if planar and none else None
    return {"csm": csm, "vtk": vtk, "planar": planar, "error_ratio": err,
            "time_ratio": time_ratio, "planar_overhead": overhead}


def goals(key, rows):
    out = []
    g = goal_figures(rows)
    csm, vtk, planar = g["csm"], g["vtk"], g["planar"]
    hard = key.startswith("hard-")
    if g["error_ratio"] is not None:
        f_err, f_time = g["error_ratio"], g["time_ratio"]
        ok = f_err >= 10 and f_time <= 1.2
        out.append("csm default vs vtk (2048): wrong_pct %s vs %s (%.1fx lower%s), frame time %.2fx "
                   "of vtk's -> %s%s" % (
                       fmt(csm["wrong_pct"], 3), fmt(vtk["wrong_pct"], 3), f_err,
                       ", csm floored at %g" % WRONG_FLOOR if csm["wrong_pct"] < WRONG_FLOOR else "",
                       f_time, "met" if ok else "MISSED", " (hard scene: not part of the goal)" if hard else ""))
    if g["planar_overhead"] is not None:
        ov = g["planar_overhead"]
        out.append("planar overhead %.1f ms = %.0f%% of the unshadowed frame (goal <= 15%%) -> %s" % (
            planar["overhead_ms"], 100 * ov, "met" if ov <= 0.15 else "MISSED by %.0f points" % (100 * ov - 15)))
    return out


def summary(results, a, cmdline):
    lines = ["Command: `%s`" % cmdline, "",
             "Timing: per scene the configurations are interleaved in %d round(s) (order rotated), "
             "%d timed frames each on vtkshadow-render's camera orbit; `ratio` = shadowed / unshadowed "
             "median of the same vtkshadow-render process (median over rounds); ms/frame = ratio x the "
             "scene's median unshadowed time; overhead = ms/frame - unshadowed. Compare ratios, not "
             "absolute times (shared 2-core llvmpipe machine). Times include every light of the scene; "
             "errors are light %d against POV-Ray." % (a.rounds, a.frames, a.light), ""]
    for key, size, rows, front, png in results:
        lines += ["### %s (%dx%d)" % (key, size[0], size[1]), "",
                  "| technique | settings | ms/frame | overhead ms | ratio | memory | wrong_pct | "
                  "vis_mae | edge_px | false_shadow_pct | false_light_pct |",
                  "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        fset = set(id(r) for r in front)
        for r in rows:
            lines.append("| %s | %s%s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["technique"], r["settings"], " (front)" if id(r) in fset else "",
                fmt(r["ms_per_frame"], 1), fmt(r["overhead_ms"], 1), fmt(r["ratio"], 2),
                mib(r["memory_bytes"]), fmt(r["wrong_pct"], 3), fmt(r["vis_mae"], 4),
                fmt(r["edge_px"], 2), fmt(r["false_shadow_pct"], 3), fmt(r["false_light_pct"], 3)))
        lines += ["", "- " + auto_check(rows)]
        for g in goals(key, rows):
            lines.append("- " + g)
        if png:
            lines.append("- plot: %s" % png)
        lines.append("")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(prog="vtkshadow-bench", description=__doc__.split("\n\n")[0])
    p.add_argument("scenes", nargs="+")
    p.add_argument("--out", required=True)
    p.add_argument("--scale", type=float, default=1.0,
                   help="multiply each scene's image size (renders and references)")
    p.add_argument("--frames", type=int, default=30)
    p.add_argument("--grid", choices=("small", "full"), default="small")
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--light", type=int, default=0)
    p.add_argument("--cache", default=None,
                   help="reference cache of vtkshadow-compare (default DIR/cache); keyed by scene "
                        "content, renderer version and settings, so it can be kept between runs")
    p.add_argument("--peers", default="",
                   help="comma-separated scene-key prefixes (e.g. basic,scivis,cad) that also get "
                        "Blender EEVEE rows at its default and best settings")
    a = p.parse_args()
    global CACHE
    CACHE = os.path.abspath(a.cache) if a.cache else None
    if a.frames < 30:
        p.error("--frames must be >= 30")
    scenes = []
    for s in a.scenes:
        if os.path.isdir(s):
            for dp, dn, fn in os.walk(s):
                dn[:] = sorted(x for x in dn if x != "meshes")
                scenes += [os.path.join(dp, f) for f in sorted(fn)
                           if f.endswith(".json") and f not in ("thresholds.json", "known-failures.json")]
        else:
            scenes.append(s)
    os.makedirs(a.out, exist_ok=True)
    for x in ("vtkshadow-render", "vtkshadow-metrics", "vtkshadow-compare"):
        if not os.access(os.path.join(BIN, x), os.X_OK):
            p.error("missing %s (build first)" % os.path.join(BIN, x))
    refs = ensure_refs(scenes, a.out, a.scale)
    prefixes = [x for x in a.peers.split(",") if x]
    peer_scenes = [s for s in scenes if any(scene_key(s).startswith(x) for x in prefixes)]
    peers = peer_rows(peer_scenes, a.out, a.scale, a.light) if peer_scenes else {}
    log("timings: techniques interleaved in %d rounds; compare ratios within a run, "
        "not absolute times" % a.rounds)
    results, allrows = [], []
    for s in scenes:
        key, size, rows = bench_scene(s, a, refs)
        front = pareto(rows)  # peers have no same-run ratio: never on the front
        rows += peers.get(key, [])
        for f in os.listdir(os.path.join(a.out, key)) if os.path.isdir(os.path.join(a.out, key)) else []:
            if f.startswith("plot_") and f.endswith(".dat"):
                os.remove(os.path.join(a.out, key, f))
        png = plot(key, rows, front, a.out)
        results.append((key, size, rows, front, png))
        allrows += rows
        log("%s: done; %s" % (key, auto_check(rows)))
    with open(os.path.join(a.out, "bench.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in allrows:
            w.writerow({k: ("" if v is None else v) for k, v in r.items()})
    with open(os.path.join(a.out, "bench.json"), "w") as f:
        json.dump(allrows, f, indent=1)
    cmdline = "bench/vtkshadow-bench " + " ".join(sys.argv[1:])
    md = summary(results, a, cmdline)
    with open(os.path.join(a.out, "summary.md"), "w") as f:
        f.write(md + "\n")
    print("NOTE: timings are interleaved per scene; compare ratios within this run, "
          "not absolute times across runs.")
    print(md)
    print(os.path.join(a.out, "bench.csv"))


if __name__ == "__main__":
    main()
