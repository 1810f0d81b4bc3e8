"""Assemble docs/results.md from a vtkshadow-bench run and a bench_growth run.

  python3 bench/make_results.py --bench DIR --growth DIR --command CMD
                                [--output docs/results.md]

Reads DIR/bench.json and DIR/summary.md (vtkshadow-bench), DIR/growth.md
(bench_growth.py); copies the plots into docs/img/bench/ and writes one
Markdown file: the command that made it, the goals per scene, auto's
choices, the EEVEE peer rows, the full per-scene tables with their plots,
and the growth tables. Nothing in it is typed by hand.
"""
import argparse
import json
import os
import platform
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from vtkshadow_bench import (NOISE_LABEL, WRONG_FLOOR, fmt, front_position,  # noqa: E402
                             goal_figures)


def by_scene(rows):
    out = {}
    for r in rows:
        out.setdefault(r["scene"], []).append(r)
    return out


def pick(rows, tech, settings):
    return next((r for r in rows if r["technique"] == tech and r["settings"] == settings
                 and (r.get("wrong_pct") is not None)), None)


def goals_table(scenes):
    lines = ["| scene | csm wrong_pct | vtk 2048 wrong_pct | error ratio (goal >= 10) | "
             "csm / vtk time (goal <= 1.2) | planar overhead (goal <= 15%) | auto chose | "
             "auto / front (goal <= 1.10) | noise floor none#2 / none |",
             "|---|---:|---:|---:|---:|---:|---|---:|---:|"]
    tally = {"err": [0, 0], "time": [0, 0], "planar": [0, 0], "auto": [0, 0], "noisy": [0, 0]}
    for key in sorted(scenes):
        rows = scenes[key]
        g = goal_figures(rows)
        csm, vtk, auto = g["csm"], g["vtk"], pick(rows, "auto", "default")
        hard = key.startswith("hard-")
        err, time_ratio, ov = g["error_ratio"], g["time_ratio"], g["planar_overhead"]
        if err is not None:
            if not hard:
                tally["err"][0] += err >= 10
                tally["err"][1] += 1
                tally["time"][0] += time_ratio <= 1.2
                tally["time"][1] += 1
        if ov is not None and not hard:
            tally["planar"][0] += ov <= 0.15
            tally["planar"][1] += 1
        _, _, rel = front_position(rows)
        if rel is not None:
            tally["auto"][0] += rel <= 1.10
            tally["auto"][1] += 1
        floor = next((r for r in rows if r["technique"] == NOISE_LABEL
                      and r.get("ratio") is not None), None)
        if floor:
            tally["noisy"][0] += bool(floor.get("too_noisy"))
            tally["noisy"][1] += 1
        lines.append("| %s%s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            key, " (hard)" if hard else "", fmt(csm and csm["wrong_pct"], 3),
            fmt(vtk and vtk["wrong_pct"], 3), "-" if err is None else "%.1fx" % err,
            "-" if time_ratio is None else "%.2fx" % time_ratio,
            "-" if ov is None else "%.0f%%" % (100 * ov),
            (auto or {}).get("auto_choice") or "-", "-" if rel is None else "%.2fx" % rel,
            "-" if not floor else "%.3f%s" % (floor["ratio"],
                                             " TOO NOISY" if floor.get("too_noisy") else "")))
    return lines, tally


def peers_table(scenes):
    lines = ["| scene | technique | wrong_pct | vis_mae | edge_px | s per frame (offline) |",
             "|---|---|---:|---:|---:|---:|"]
    n = 0
    for key in sorted(scenes):
        rows = scenes[key]
        mine = [pick(rows, "csm", "default"), pick(rows, "auto", "default"),
                pick(rows, "vtk", "map=2048")]
        peers = [r for r in rows if r["technique"] == "eevee"]
        if not peers:
            continue
        for r in peers + [m for m in mine if m]:
            n += 1
            lines.append("| %s | %s %s | %s | %s | %s | %s |" % (
                key, r["technique"], r["settings"], fmt(r.get("wrong_pct"), 3),
                fmt(r.get("vis_mae"), 4), fmt(r.get("edge_px"), 2),
                fmt(r["ms_per_frame"] / 1000.0, 2) if r["technique"] == "eevee"
                and r.get("ms_per_frame") else "-"))
    return lines if n else []


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bench", required=True)
    ap.add_argument("--growth", required=True)
    ap.add_argument("--command", required=True)
    ap.add_argument("--output", default=os.path.join(ROOT, "docs", "results.md"))
    a = ap.parse_args()
    with open(os.path.join(a.bench, "bench.json")) as f:
        rows = json.load(f)
    with open(os.path.join(a.bench, "summary.md")) as f:
        summary = f.read()
    with open(os.path.join(a.growth, "growth.md")) as f:
        growth = f.read()
    scenes = by_scene(rows)
    img = os.path.join(os.path.dirname(a.output), "img", "bench")
    os.makedirs(img, exist_ok=True)
    for key in scenes:
        png = os.path.join(a.bench, key + ".png")
        if os.path.exists(png):
            shutil.copy(png, os.path.join(img, key + ".png"))
    # The per-scene plots are linked from the docs copy, not the run folder.
    summary = "\n".join(
        "- plot: ![%s](img/bench/%s.png)" % (os.path.basename(l.split(": ", 1)[1])[:-4],
                                               os.path.basename(l.split(": ", 1)[1])[:-4])
        if l.startswith("- plot: ") else l for l in summary.splitlines())
    summary = summary.replace("### ", "#### ")
    goals, tally = goals_table(scenes)
    peers = peers_table(scenes)

    def count(k):
        return "%d of %d" % tuple(tally[k])

    out = ["# vtkshadow results", "",
           "Generated by one command, from the repository root, after a build:", "",
           "    " + a.command, "",
           "It runs `bench/vtkshadow-bench` over every scene in `scenes/` (POV-Ray references and "
           "the EEVEE peer through `vtkshadow-compare`), `bench/bench_growth.py`, and "
           "`bench/make_results.py`, which writes this file; nothing here is edited by hand. "
           "Analysis and history: [performance.md](performance.md).", "",
           "Run %s on %s (%s), 2 cores, no GPU: Mesa llvmpipe under Xvfb. The machine is shared, "
           "so compare techniques within a scene as ratios measured in the same run." % (
               time.strftime("%Y-%m-%d %H:%M UTC",
                             time.gmtime(os.path.getmtime(os.path.join(a.bench, "bench.json")))), platform.node() or "?", platform.machine()), "",
           "## Goals", "",
           "From issue #6, on every non-hard scene: `csm` at its defaults has at least 10x lower "
           "wrong_pct than `vtk` (2048) at no more than 1.2x its frame time; `planar` costs at most "
           "15% over the unshadowed frame; `auto` lies on or within 10% in time of the Pareto front "
           "of the manual settings at equal error (all scenes).", "",
           "- csm error at least 10x lower than vtk: %s non-hard scenes" % count("err"),
           "- csm frame time at most 1.2x vtk: %s non-hard scenes" % count("time"),
           "- planar overhead at most 15%%: %s non-hard scenes with receivers" % count("planar"),
           "- auto within 10%% of the front: %s scenes" % count("auto"),
           "- timing too noisy (noise floor none#2 / none outside 1.00 +- tolerance): %s scenes"
           % count("noisy"), "",
           "Error ratio: vtk wrong_pct / csm wrong_pct (csm floored at %g). Times: every "
           "configuration of a scene is timed in one vtkshadow-render process and one window, "
           "interleaved in blocks with the order changed every round; a ratio is the median over "
           "rounds of (configuration / none of the same round), and csm / vtk divides those. "
           "*Noise floor*: none timed again against none the same way; where it is marked TOO "
           "NOISY the scene's ratios cannot resolve differences of that size (method: "
           "[performance.md](performance.md#how-frames-are-timed)). *auto / front*: auto's time "
           "over that of the fastest manual configuration with wrong_pct no higher than "
           "auto's." % WRONG_FLOOR, ""] + goals + [""]
    if peers:
        out += ["## Peer: Blender EEVEE", "",
                "EEVEE (Blender's rasterizer with cascaded soft shadow maps) renders the same "
                "scenes through the same harness and is scored against the same POV-Ray "
                "reference: `default` is Blender's own shadow settings, `best` the settings that "
                "serve these hard-shadow scenes best (docs/harness.md says which and why). Its "
                "time is Blender's seconds per frame for an offline render on llvmpipe (64 "
                "samples, shadow maps rebuilt), not comparable to an interactive frame; the rows "
                "for vtkshadow's csm and auto and VTK's own pass are from the same scenes.", ""]
        out += peers + [""]
    out += [growth, "## Every scene", "", summary]
    text = "\n".join(out) + "\n"
    tmp = a.output + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, a.output)
    print(a.output)


if __name__ == "__main__":
    main()
