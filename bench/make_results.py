"""Assemble docs/results.md from a vtkshadow-bench run and a bench_growth run.

  python3 bench/make_results.py --bench DIR --growth DIR --command CMD
                                [--soft DIR] [--output docs/results.md]

Reads DIR/bench.json and DIR/summary.md (vtkshadow-bench), DIR/growth.md
(bench_growth.py) and, with --soft, DIR/soft.md (bench_soft.py); copies the plots into docs/img/bench/ and writes one
Markdown file: the command that made it, issue 14's goals per scene with
their verdicts (bench_goals.py: met, missed by how much, or too noisy),
auto's choices, every technique of the run with its time ratio and error
(the technique list comes from the rows, so a technique newly added to the
registry appears by itself), the EEVEE peer rows, the growth tables, the
soft-shadow section and the full per-scene tables with their plots. Nothing in it is typed by
hand. tests/timing/test_make_results.py runs it on a synthetic run.
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
from bench_goals import GOALS, NOISE_LABEL, floor_row, headline, scene_counts, scene_goals  # noqa: E402
from vtkshadow_bench import WRONG_FLOOR, fmt, scene_key  # noqa: E402

PEER = "eevee"  # rows from another renderer: no same-run ratio, own table


def by_scene(rows):
    out = {}
    for r in rows:
        out.setdefault(r["scene"], []).append(r)
    return out


def techniques(rows):
    """Every technique timed in the run, in order of first appearance (the
    bench writes the registry's order), without the noise floor and peers:
    a technique added to the registry shows up here by itself."""
    out = []
    for r in rows:
        t = r["technique"]
        if t not in out and t not in (NOISE_LABEL, PEER) and r.get("ratio") is not None:
            out.append(t)
    return out


def scene_files(root):
    """scene key -> scene file, for runs whose rows predate the scene_lights
    and scene_receivers columns."""
    out = {}
    for dp, dn, fn in os.walk(root):
        dn[:] = sorted(x for x in dn if x != "meshes")
        for f in fn:
            if f.endswith(".json") and f not in ("thresholds.json", "known-failures.json"):
                out[scene_key(os.path.join(dp, f))] = os.path.join(dp, f)
    return out


def scene_meta(key, rows, files):
    """(lights, receivers) of a scene: from its rows, else from its file,
    else (None, None) (the planar goal is then not applied)."""
    r = next((r for r in rows if r.get("scene_lights") is not None), None)
    if r:
        return r["scene_lights"], r.get("scene_receivers")
    if key in files:
        return scene_counts(files[key])
    return None, None


def goals_table(scenes, files):
    """One row per scene: each goal's figure and verdict, the auto choice and
    the noise floor; and the tally {goal: {met, missed, too noisy, n}} over
    the non-hard scenes where the goal applies."""
    head = " | ".join("%s (goal <= %.2fx)" % (what, limit) for _, what, limit, _ in GOALS)
    lines = ["| scene | %s | auto chose | noise floor none#2 / none |" % head,
             "|---|" + "---|" * len(GOALS) + "---|---:|"]
    tally = {g[0]: {"met": 0, "missed": 0, "too noisy": 0, "n": 0} for g in GOALS}
    for key in sorted(scenes):
        rows = scenes[key]
        lights, receivers = scene_meta(key, rows, files)
        results = scene_goals(key, rows, lights, receivers)
        for g in results:
            if g["counted"] and g["applies"] and g["state"] in ("met", "missed", "too noisy"):
                tally[g["goal"]][g["state"]] += 1
                tally[g["goal"]]["n"] += 1
        auto = headline(rows, "auto")
        floor = floor_row(rows)
        lines.append("| %s%s | %s | %s | %s |" % (
            key, " (hard)" if key.startswith("hard-") else "",
            " | ".join(g["text"] for g in results), (auto or {}).get("auto_choice") or "-",
            "-" if not floor else "%.3f%s" % (floor["ratio"],
                                             " TOO NOISY" if floor.get("too_noisy") else "")))
    return lines, tally


def techniques_table(scenes):
    """Every technique of the run per scene: time ratio to none and
    wrong_pct of its headline configuration (bench_goals.headline)."""
    names = techniques([r for key in sorted(scenes) for r in scenes[key]])
    lines = ["| scene | " + " | ".join("%s x none / wrong_pct" % t for t in names) +
             " | noise floor |", "|---|" + "---:|" * (len(names) + 1)]
    for key in sorted(scenes):
        rows = scenes[key]
        cells = []
        for t in names:
            r = headline(rows, t)
            cells.append("-" if r is None else "%s / %s" % (fmt(r.get("ratio"), 2),
                                                           fmt(r.get("wrong_pct"), 3)))
        floor = floor_row(rows)
        lines.append("| %s | %s | %s |" % (key, " | ".join(cells), "-" if not floor else
                                           "%.3f%s" % (floor["ratio"], " TOO NOISY" if
                                                       floor.get("too_noisy") else "")))
    return lines, names


def peers_table(scenes):
    lines = ["| scene | technique | wrong_pct | vis_mae | edge_px | s per frame (offline) |",
             "|---|---|---:|---:|---:|---:|"]
    n = 0
    for key in sorted(scenes):
        rows = scenes[key]
        peers = [r for r in rows if r["technique"] == PEER]
        if not peers:
            continue
        mine = [headline(rows, t) for t in techniques(rows) if t != "none"]
        for r in peers + [m for m in mine if m and m.get("wrong_pct") is not None]:
            n += 1
            lines.append("| %s | %s %s | %s | %s | %s | %s |" % (
                key, r["technique"], r["settings"], fmt(r.get("wrong_pct"), 3),
                fmt(r.get("vis_mae"), 4), fmt(r.get("edge_px"), 2),
                fmt(r["ms_per_frame"] / 1000.0, 2) if r["technique"] == PEER
                and r.get("ms_per_frame") else "-"))
    return lines if n else []


def tally_lines(tally):
    out = []
    for goal, what, limit, single in GOALS:
        t = tally[goal]
        out.append("- %s at most %.2fx: met on %d, missed on %d, too noisy on %d of %d non-hard "
                   "scenes%s" % (what, limit, t["met"], t["missed"], t["too noisy"], t["n"],
                                 " with one receiver and one light" if single else ""))
    return out


GOALS_TEXT = (
    "From issue 14 (item 4), on every non-hard scene, as interleaved ratios at the scenes' "
    "800x600: `csm` at its defaults at most 1.0x the frame time of `vtk` (map 2048); `auto` at "
    "its default error target at most 1.5x `none`; `planar` at most 1.15x `none` on scenes with "
    "one receiver and one light. Times: every configuration of a scene is timed in one "
    "vtkshadow-render process and one window, interleaved in blocks with the order changed every "
    "round; a ratio is the median over rounds of (configuration / none of the same round), and "
    "csm / vtk divides those. *Noise floor*: none timed again against none the same way. A "
    "verdict reads *too noisy* where the scene's floor is outside 1.00 +- its tolerance and the "
    "figure is no further from the goal (relatively) than the floor is from 1.00; where the "
    "margin is larger, met or missed stands and is marked as from a noisy run (method: "
    "[performance.md](performance.md#how-frames-are-timed)). Hard scenes are listed but not "
    "counted.")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bench", required=True)
    ap.add_argument("--growth", required=True)
    ap.add_argument("--soft", default=None,
                    help="a bench_soft.py run (DIR/soft.md): the soft-shadow section")
    ap.add_argument("--command", required=True)
    ap.add_argument("--output", default=os.path.join(ROOT, "docs", "results.md"))
    a = ap.parse_args()
    with open(os.path.join(a.bench, "bench.json")) as f:
        rows = json.load(f)
    with open(os.path.join(a.bench, "summary.md")) as f:
        summary = f.read()
    with open(os.path.join(a.growth, "growth.md")) as f:
        growth = f.read()
    soft = ""
    if a.soft:
        with open(os.path.join(a.soft, "soft.md")) as f:
            soft = f.read()
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
    goals, tally = goals_table(scenes, scene_files(os.path.join(ROOT, "scenes")))
    overview, names = techniques_table(scenes)
    peers = peers_table(scenes)
    noisy = sum(1 for key in scenes if (floor_row(scenes[key]) or {}).get("too_noisy"))
    timed = sum(1 for key in scenes if floor_row(scenes[key]))

    out = ["# vtkshadow results", "",
           "Generated by one command, from the repository root, after a build:", "",
           "    " + a.command, "",
           "It runs `bench/vtkshadow-bench` over every scene in `scenes/` (POV-Ray references and "
           "the EEVEE peer through `vtkshadow-compare`), `bench/bench_growth.py`, "
           "`bench/bench_soft.py` (lights with a size) and "
           "`bench/make_results.py`, which writes this file; nothing here is edited by hand. "
           "How frames are timed and where the time goes: [performance.md](performance.md).", "",
           "Run %s on %s (%s), 2 cores, no GPU: Mesa llvmpipe under Xvfb. The machine is shared, "
           "so compare techniques within a scene as ratios measured in the same run." % (
               time.strftime("%Y-%m-%d %H:%M UTC",
                             time.gmtime(os.path.getmtime(os.path.join(a.bench, "bench.json")))),
               platform.node() or "?", platform.machine()), "",
           "## Goals", "", GOALS_TEXT, ""] + tally_lines(tally) + [
           "- timing too noisy (noise floor none#2 / none outside 1.00 +- tolerance): %d of %d "
           "scenes" % (noisy, timed), ""] + goals + [""]
    out += ["## Every technique", "",
            "Each technique of the run (%s), at its defaults (vtk: map 2048): frame time as a "
            "ratio to `none` of the same rounds, and wrong_pct against POV-Ray (floored at %g in "
            "the plots only). The per-scene tables below list every configuration." % (
                ", ".join(names), WRONG_FLOOR), ""] + overview + [""]
    if peers:
        out += ["## Peer: Blender EEVEE", "",
                "EEVEE (Blender's rasterizer with cascaded soft shadow maps) renders the same "
                "scenes through the same harness and is scored against the same POV-Ray "
                "reference: `default` is Blender's own shadow settings, `best` the settings that "
                "serve these hard-shadow scenes best (docs/harness.md says which and why). Its "
                "time is Blender's seconds per frame for an offline render on llvmpipe (64 "
                "samples, shadow maps rebuilt), not comparable to an interactive frame; the rows "
                "for every other technique of the run (each at its defaults, vtk at map 2048) "
                "are from the same scenes.", ""]
        out += peers + [""]
    out += [growth] + ([soft] if soft else []) + ["## Every scene", "", summary]
    text = "\n".join(out) + "\n"
    tmp = a.output + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, a.output)
    print(a.output)


if __name__ == "__main__":
    main()
