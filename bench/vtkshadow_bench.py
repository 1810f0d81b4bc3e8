#!/usr/bin/env python3
"""vtkshadow-bench: speed against error for every shadow technique.

    bench/vtkshadow-bench SCENE... --out DIR [--scale F] [--timing-scale F]
                          [--frames N] [--rounds R] [--warmup W]
                          [--noise-tolerance T] [--grid small|full] [--light K]
                          [--peers PREFIXES] [--cache DIR] [--timing-only]

SCENE may be a folder (every scene file under it). --scale F multiplies
each scene's image size for the error measurement (renders and references
alike; scripts/results.sh uses 0.5); --timing-scale F (default: --scale)
the size the frames are timed at (scripts/results.sh: 1, the scenes'
800x600).

(bench/vtkshadow-bench runs this file with build/bin/vtkshadow-python under
tests/gl-run.sh when no X display is set.)

For each scene (light K, default 0) it takes every technique of the registry
(vtkShadowTechnique.GetKnownTechniques()), each with its settings from
SETTINGS below: none; vtk at map 1024, 2048, 4096; planar when the scene has
a receiver; csm at its defaults and over a grid (small: cascades 1,2,4 x map
512,1024,2048 x filter 0 (hardware); full: cascades 1..4 x map 512..4096 x
filter 0,1,2); auto; a technique with no SETTINGS entry once at its
defaults. Each configuration is rendered once by build/bin/vtkshadow-render
for the visibility and mask of light K, scored with
build/bin/vtkshadow-metrics against the POV-Ray reference of
build/bin/vtkshadow-compare --renderers povray (cached in DIR/refs).

Timing: one vtkshadow-render --stats process per scene times every
configuration of the scene in one window (--time-also), interleaved: after
--warmup frames each, --rounds rounds, each a block of --frames frames per
configuration along vtkshadow-render's camera orbit, the order changed every
round (a Williams design: every configuration in every position, and after
every other, equally often over a whole cycle; docs/performance.md). Each
configuration's pass stays alive across rounds, so its caches are warm as in
an application. `ms_per_frame` is the median over rounds of the block
medians, `ms_min`/`ms_max` their spread; `ratio` is the median over rounds
of (configuration / none of the same round), with `ratio_min`/`ratio_max`;
overhead_ms = ms_per_frame - none's. A second none (`none#2`) is timed like
the others: its ratio to none is the noise floor of the scene's run
(`noise_floor`), and a floor outside 1 +- --noise-tolerance (default 0.03)
marks the scene `too_noisy` (a warning, a column, a line in the summary).
Timings cover all lights of a scene (vtkshadow-render renders every light);
errors are for light K only.

--timing-only skips references, visibility and metrics (no POV-Ray): the
timing rows alone.

Outputs: DIR/bench.csv (one row per scene and configuration, plus the
none#2 row), DIR/bench.json,
DIR/<scene>/<config>/ (visibility, mask, metrics of each configuration),
DIR/<scene>/timing.json (the vtkshadow-render stats of the timing run),
DIR/<scene>.png (gnuplot: wrong_pct, log, floored at 1e-3, against
ms_per_frame, log; one series per technique family; Pareto front drawn),
DIR/summary.md (tables, auto's position against the Pareto front, issue
14's goals with verdicts from bench_goals.py, the noise floor). Every row
also carries the scene's light and receiver counts (scene_lights,
scene_receivers): the planar goal holds on scenes with one of each.
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
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_goals import scene_counts, scene_goals  # noqa: E402

BIN = os.path.join(ROOT, "build", "bin")
WRONG_FLOOR = 1e-3

COLUMNS = ["scene", "technique", "settings", "ms_per_frame", "ms_min", "ms_max", "overhead_ms",
           "unshadowed_ms", "ratio", "ratio_min", "ratio_max", "noise_floor", "too_noisy",
           "memory_bytes", "wrong_pct", "vis_mae", "edge_px", "false_shadow_pct",
           "false_light_pct", "auto_choice", "texel_px", "auto_reason", "scene_lights",
           "scene_receivers"]
NOISE_LABEL = "none#2"


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
                            [("map_resolution", m), ("cascades", c), ("filter", fl)]))
    # csm's soft settings (PCSS taps, soft=0) are measured by bench_soft.py
    # against the penumbra, where they differ: on these hard-shadow scores
    # they would repeat the default.
    return out


# The settings each technique is benchmarked with, as data: technique ->
# (needs a receiver in the scene, grid -> [(settings label, [(technique
# setting, value)])]). A registered technique not listed here runs once, as
# ("default", []).
SETTINGS = {
    "none": (False, lambda grid: [("-", [])]),
    "vtk": (False, lambda grid: [("map=%d" % r, [("map_resolution", r)])
                                 for r in (1024, 2048, 4096)]),
    "planar": (True, lambda grid: [("-", [])]),
    "csm": (False, _grid_csm),
    "auto": (False, lambda grid: [("default", [])]),
}


def configs_for(receivers, grid, techniques=None):
    """(technique, settings label, [(setting, value)]) for every registered
    technique, in registry order."""
    out = []
    for tech in techniques if techniques is not None else registered_techniques():
        needs_receiver, settings = SETTINGS.get(tech, (False, lambda grid: [("default", [])]))
        if needs_receiver and not receivers:
            continue
        out.extend((tech, label, values) for label, values in settings(grid))
    return out


def render_args(values):
    """vtkshadow-render arguments for [(setting, value)]."""
    out = []
    for key, value in values:
        out += ["--set", "%s=%s" % (key, value)]
    return out


def timing_label(tech, values):
    """The --time-also SPEC of a configuration, which is also its label in
    vtkshadow-render's stats: TECH[:KEY=VALUE,...]."""
    return tech + (":" + ",".join("%s=%s" % kv for kv in values) if values else "")


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


def run_render(scene, args, size, light, d):
    """One render of a configuration for its visibility and mask of light K.
    True on success."""
    os.makedirs(d, exist_ok=True)
    cmd = [os.path.join(BIN, "vtkshadow-render"), scene, "--image",
           os.path.join(d, "image.png"), "--light", str(light), "--size", "%dx%d" % size,
           "--quiet", "--visibility", os.path.join(d, "visibility.png"),
           "--mask", os.path.join(d, "mask.png")] + args
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(d, "render.log"), "a") as f:
        f.write(" ".join(cmd) + "\n" + p.stdout)
    if p.returncode != 0:
        log("  FAILED (%d): %s" % (p.returncode, " ".join(cmd)))
        return False
    return True


def run_timing(scene, labels, size, d, timing):
    """Every configuration of a scene timed in one vtkshadow-render process,
    interleaved (labels: --time-also SPECs; "none" and "none#2" are always
    timed). `timing`: (frames, rounds, warmup, noise tolerance). The stats
    document, or None when the run failed."""
    os.makedirs(d, exist_ok=True)
    stats = os.path.join(d, "timing.json")
    frames, rounds, warmup, tolerance = timing
    cmd = [os.path.join(BIN, "vtkshadow-render"), scene, "--technique", "none", "--image",
           os.path.join(d, "timing.png"), "--stats", stats, "--size", "%dx%d" % size,
           "--frames", str(frames), "--rounds", str(rounds), "--warmup", str(warmup),
           "--noise-tolerance", repr(tolerance)]
    for label in labels:
        if label != "none":
            cmd += ["--time-also", label]
    if os.path.exists(stats):
        os.remove(stats)
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    with open(os.path.join(d, "timing.log"), "w") as f:
        f.write(" ".join(cmd) + "\n" + p.stderr)
    sys.stderr.write(p.stderr)
    if p.returncode != 0 or not os.path.exists(stats):
        log("  timing FAILED (%d): %s" % (p.returncode, " ".join(cmd)))
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


def timing_row(key, tech, settings, entry, none, noise):
    """A result row from a timing entry of vtkshadow-render's stats."""
    row = {c: None for c in COLUMNS}
    row.update(scene=key, technique=tech, settings=settings)
    if entry is None:
        return row
    ms, ratio = entry["ms"], entry["ratio_to_none"]
    row.update(ms_per_frame=ms["median"], ms_min=ms["min"], ms_max=ms["max"],
               unshadowed_ms=none["ms"]["median"], ratio=ratio["median"],
               ratio_min=ratio["min"], ratio_max=ratio["max"],
               overhead_ms=ms["median"] - none["ms"]["median"],
               memory_bytes=entry.get("shadow_map_bytes"),
               noise_floor=noise["ratio"], too_noisy=noise["too_noisy"])
    return row


def technique_details(row, tech, ts, light):
    """auto's choice and the csm texel sizes of light K from technique_stats."""
    if tech == "auto":
        lc = ts.get("light_choices") or []
        row["auto_choice"] = "%s [%s]%s" % (
            ts.get("choice"), ", ".join(lc),
            " texel <= %.2f px" % ts["texel_target_px"]
            if "csm" in str(ts.get("choice")) and ts.get("texel_target_px") else "")
        row["auto_reason"] = ts.get("reason")
    lights = ts.get("lights")
    if tech in ("csm", "auto") and isinstance(lights, list) and len(lights) > light:
        tp = lights[light].get("texel_px")
        if tp:
            row["texel_px"] = "/".join("%.2f" % v for v in tp)


def bench_scene(scene, a, refs):
    key = scene_key(scene)
    size0, receivers = scene_info(scene)
    size = (max(1, round(size0[0] * a.scale)), max(1, round(size0[1] * a.scale)))
    tsize = (max(1, round(size0[0] * a.timing_scale)), max(1, round(size0[1] * a.timing_scale)))
    cfgs = configs_for(receivers, a.grid)
    labels = [timing_label(t, v) for t, _, v in cfgs]
    t0 = time.time()
    st = run_timing(scene, labels, tsize, os.path.join(a.out, key),
                    (a.frames, a.rounds, a.warmup, a.noise_tolerance))
    entries = {e["label"]: e for e in (st or {}).get("timing", {}).get("entries", [])}
    noise = (st or {}).get("noise_floor")
    log("%s: timed %d configurations interleaved at %dx%d [%.0f s]; noise floor %s" % (
        key, len(cfgs), tsize[0], tsize[1], time.time() - t0,
        "-" if not noise else "%.3f%s" % (noise["ratio"] or float("nan"),
                                          " TOO NOISY" if noise["too_noisy"] else "")))
    ref_vis = os.path.join(refs, key, "povray", "light%d_visibility.png" % a.light) if refs else ""
    ref_mask = os.path.join(refs, key, "povray", "light%d_mask.png" % a.light) if refs else ""
    have_ref = bool(refs) and os.path.exists(ref_vis) and os.path.exists(ref_mask)
    if refs and not have_ref:
        log("%s: no POV-Ray reference at %s: errors left empty" % (key, ref_vis))
    rows = []
    none = entries.get("none")
    for (tech, settings, values), label in zip(cfgs, labels):
        entry = entries.get(label) if none else None
        row = timing_row(key, tech, settings, entry, none, noise)
        if entry is not None:
            technique_details(row, tech, entry.get("technique_stats") or {}, a.light)
        d = os.path.join(a.out, key, config_dir(tech, settings))
        if have_ref and run_render(scene, ["--technique", tech] + render_args(values), size,
                                   a.light, d):
            m = metrics(ref_vis, ref_mask, os.path.join(d, "visibility.png"),
                        os.path.join(d, "metrics.json"))
            for k in ("wrong_pct", "vis_mae", "edge_px", "false_shadow_pct", "false_light_pct"):
                row[k] = m.get(k)
        rows.append(row)
    # The noise floor: none timed a second time, like every configuration.
    rows.append(timing_row(key, NOISE_LABEL, "noise floor", entries.get(NOISE_LABEL) if none
                           else None, none, noise))
    # What issue 14's planar goal needs to know (one receiver, one light).
    lights, nrecv = scene_counts(scene)
    for r in rows:
        r.update(scene_lights=lights, scene_receivers=nrecv)
    return key, size, tsize, rows


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
        "set label 1 'time = median over interleaved rounds (one window per scene)' at graph 0.02,0.04 font ',8'",
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


def goals(key, rows):
    """Issue 14's goals on one scene, one line each (bench_goals.py)."""
    lights, receivers = (rows[0].get("scene_lights"), rows[0].get("scene_receivers")) if rows \
        else (None, None)
    out = []
    for g in scene_goals(key, rows, lights, receivers):
        if g["applies"]:
            out.append("goal %s <= %.2fx: %s%s" % (g["what"], g["limit"], g["text"],
                                                   "" if g["counted"] else
                                                   " (hard scene: not part of the goal)"))
    return out


def timing_method(a):
    """How the timings were taken, in one paragraph (summary.md, results.md)."""
    return ("Timing: per scene one vtkshadow-render process times every configuration in one "
            "window, interleaved: %d warm-up frames each, then %d rounds of one block of %d frames "
            "per configuration on vtkshadow-render's camera orbit, the order changed every round "
            "(Williams design); each configuration's pass stays alive, so its caches are warm. "
            "ms/frame = median over rounds of the block medians, [min-max] their spread; `ratio` = "
            "median over rounds of (configuration / none of the same round) [min-max]; overhead = "
            "ms/frame - none's. `none#2` is none timed again: its ratio is the noise floor, and a "
            "scene whose floor is outside 1.00 +- %.2f is marked TOO NOISY (its ratios cannot "
            "resolve differences of that size). Shared 2-core llvmpipe machine: compare ratios "
            "within a scene. Times include every light of the scene; errors are light %d against "
            "POV-Ray." % (a.warmup, a.rounds, a.frames, a.noise_tolerance, a.light))


def noise_line(rows, tolerance):
    """The scene's noise-floor verdict."""
    r = next((r for r in rows if r["technique"] == NOISE_LABEL and r.get("ratio") is not None),
             None)
    if r is None:
        return "noise floor: no timing"
    return "noise floor none#2 / none = %.3f [%.3f-%.3f]: %s 1.00 +- %.2f" % (
        r["ratio"], r["ratio_min"], r["ratio_max"],
        "TOO NOISY, outside" if r["too_noisy"] else "within", tolerance)


def summary(results, a, cmdline):
    lines = ["Command: `%s`" % cmdline, "", timing_method(a), ""]
    for key, size, tsize, rows, front, png in results:
        lines += ["### %s (errors %dx%d, timing %dx%d)" % (key, size[0], size[1], tsize[0],
                                                             tsize[1]), "",
                  "| technique | settings | ms/frame [rounds] | overhead ms | ratio [rounds] | "
                  "memory | wrong_pct | vis_mae | edge_px | false_shadow_pct | false_light_pct |",
                  "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        fset = set(id(r) for r in front)
        for r in rows:
            spread = (" [%s-%s]" % (fmt(r["ms_min"], 1), fmt(r["ms_max"], 1))
                      if r.get("ms_min") is not None else "")
            rspread = (" [%s-%s]" % (fmt(r["ratio_min"], 2), fmt(r["ratio_max"], 2))
                       if r.get("ratio_min") is not None else "")
            lines.append("| %s | %s%s | %s%s | %s | %s%s | %s | %s | %s | %s | %s | %s |" % (
                r["technique"], r["settings"], " (front)" if id(r) in fset else "",
                fmt(r["ms_per_frame"], 1), spread, fmt(r["overhead_ms"], 1),
                fmt(r["ratio"], 2), rspread,
                mib(r["memory_bytes"]), fmt(r["wrong_pct"], 3), fmt(r["vis_mae"], 4),
                fmt(r["edge_px"], 2), fmt(r["false_shadow_pct"], 3), fmt(r["false_light_pct"], 3)))
        lines += ["", "- " + noise_line(rows, a.noise_tolerance), "- " + auto_check(rows)]
        for g in goals(key, rows):
            lines.append("- " + g)
        if png:
            lines.append("- plot: %s" % png)
        lines.append("")
    return "\n".join(lines)


def timing_checks(a):
    """(option, value, ok, what is expected) of the interleaved-timing
    options every bench shares: --frames, --rounds, --warmup,
    --noise-tolerance."""
    return [("--frames", a.frames, 1 <= a.frames <= 100000, "an integer in [1, 100000]"),
            ("--rounds", a.rounds, 1 <= a.rounds <= 1000, "an integer in [1, 1000]"),
            ("--warmup", a.warmup, 0 <= a.warmup <= 10000, "an integer in [0, 10000]"),
            ("--noise-tolerance", a.noise_tolerance, 0 < a.noise_tolerance < 1,
             "a number in (0, 1)")]


def check_ranges(p, checks):
    """p.error (exit status 2, naming the option and the value) for the first
    of `checks` ((option, value, ok, expected)) that is not ok."""
    for name, value, ok, want in checks:
        if not ok:
            p.error("%s: expected %s (got %r)" % (name, want, value))


def check_options(p, a):
    """Ranges of the numeric options (p.error: exit status 2, naming the
    option and the value)."""
    a.timing_scale = a.scale if a.timing_scale is None else a.timing_scale
    check_ranges(p, timing_checks(a) + [
        ("--scale", a.scale, 0 < a.scale <= 8, "a number in (0, 8]"),
        ("--timing-scale", a.timing_scale, 0 < a.timing_scale <= 8, "a number in (0, 8]"),
        ("--light", a.light, a.light >= 0, "an integer >= 0")])


def main():
    p = argparse.ArgumentParser(prog="vtkshadow-bench", description=__doc__.split("\n\n")[0])
    p.add_argument("scenes", nargs="+")
    p.add_argument("--out", required=True)
    p.add_argument("--scale", type=float, default=1.0,
                   help="multiply each scene's image size (renders and references)")
    p.add_argument("--timing-scale", type=float, default=None,
                   help="multiply each scene's image size for the timing (default: --scale)")
    p.add_argument("--frames", type=int, default=15, help="timed frames per block (default 15)")
    p.add_argument("--rounds", type=int, default=4, help="interleaved rounds (default 4)")
    p.add_argument("--warmup", type=int, default=5,
                   help="untimed frames per configuration before the rounds (default 5)")
    p.add_argument("--noise-tolerance", type=float, default=0.03,
                   help="a scene is too noisy when none#2 / none is outside 1 +- T (default 0.03)")
    p.add_argument("--timing-only", action="store_true",
                   help="no references, visibility or metrics: timing rows only")
    p.add_argument("--grid", choices=("small", "full"), default="small")
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
    check_options(p, a)
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
    for x in ("vtkshadow-render",) + (() if a.timing_only else
                                       ("vtkshadow-metrics", "vtkshadow-compare")):
        if not os.access(os.path.join(BIN, x), os.X_OK):
            p.error("missing %s (build first)" % os.path.join(BIN, x))
    refs = None if a.timing_only else ensure_refs(scenes, a.out, a.scale)
    prefixes = [x for x in a.peers.split(",") if x] if not a.timing_only else []
    peer_scenes = [s for s in scenes if any(scene_key(s).startswith(x) for x in prefixes)]
    peers = peer_rows(peer_scenes, a.out, a.scale, a.light) if peer_scenes else {}
    log("timings: every configuration of a scene interleaved in one window, %d rounds x %d "
        "frames; compare ratios within a scene, not absolute times" % (a.rounds, a.frames))
    results, allrows = [], []
    for s in scenes:
        key, size, tsize, rows = bench_scene(s, a, refs)
        front = pareto(rows)  # peers have no same-run ratio: never on the front
        rows += peers.get(key, [])
        for f in os.listdir(os.path.join(a.out, key)) if os.path.isdir(os.path.join(a.out, key)) else []:
            if f.startswith("plot_") and f.endswith(".dat"):
                os.remove(os.path.join(a.out, key, f))
        png = None if a.timing_only else plot(key, rows, front, a.out)  # no errors to plot
        results.append((key, size, tsize, rows, front, png))
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
    noisy = [r["scene"] for r in allrows if r["technique"] == NOISE_LABEL and r.get("too_noisy")]
    print("NOTE: timings are interleaved per scene; compare ratios within this run, "
          "not absolute times across runs.")
    if noisy:
        print("WARNING: timing too noisy (none#2 / none outside 1.00 +- %.2f) on %d of %d scenes: %s"
              % (a.noise_tolerance, len(noisy), len(results), ", ".join(noisy)))
    print(md)
    print(os.path.join(a.out, "bench.csv"))


if __name__ == "__main__":
    main()
