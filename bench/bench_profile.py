"""Where the frame time goes (issue 14, item 4): for each scene, the goal
techniques timed interleaved against none in one window
(vtkshadow-render --stats), then a stage profile of each
(--profile-frames: glFinish after every stage, process CPU time per stage).

For every scene it reports
  - the interleaved wall-clock ratios of the goals (csm / vtk, auto / none,
    planar / none) with the noise floor none#2 / none;
  - the same ratios in process CPU time of the profiled frames (steadier on
    a shared machine: it does not grow while the process waits for a core);
  - each technique's overhead over none split into its stages: the shadow
    work before the lit draw (maps, masks, pre-passes, resolves, rays) and
    the extra cost of the lit draw itself (its "scene" stage minus none's:
    the per-fragment lookups and mask reads);
  - the stage that costs most: the answer to "where does the time go".

Usage (from the repository root):
    tests/gl-run.sh /usr/bin/python3 bench/bench_profile.py --out out/profile \\
        [--bin build/bin] [--rounds 4] [--frames 5] [--profile-frames 10] SCENE.json...

Writes OUT/profile.json (every figure) and OUT/profile.md (the tables).
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_goals  # noqa: E402

TECHNIQUES = ("vtk", "csm", "auto", "planar")


def log(msg):
    print("bench_profile: " + msg, file=sys.stderr, flush=True)


def run_scene(a, scene, out_dir):
    """One vtkshadow-render run: csm is the main technique, the others
    --time-also. Returns the stats document."""
    stats = os.path.join(out_dir, "stats.json")
    cmd = [os.path.join(a.bin, "vtkshadow-render"), scene, "--technique", "csm",
           "--image", os.path.join(out_dir, "csm.png"), "--stats", stats,
           "--rounds", str(a.rounds), "--frames", str(a.frames), "--warmup", str(a.warmup),
           "--profile-frames", str(a.profile_frames), "--quiet"]
    for t in TECHNIQUES:
        if t != "csm":
            cmd += ["--time-also", t]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 3):
        raise RuntimeError("%s: vtkshadow-render status %d: %s" % (scene, p.returncode,
                                                                   p.stderr[-2000:]))
    with open(stats) as f:
        return json.load(f)


def breakdown(entry, none):
    """A technique's overhead over none per stage, CPU ms: its own stages, and
    'lit draw' = its scene stage minus none's."""
    cpu = entry["stages_cpu_ms"]
    base = none["stages_cpu_ms"]
    parts = {}
    for stage, ms in cpu.items():
        if stage in ("setup", "finish"):
            continue
        parts["lit draw (+lookups)" if stage == "scene" else stage] = \
            ms - base.get("scene", 0.0) if stage == "scene" else ms
    return parts


def scene_row(scene, doc):
    entries = {e["label"]: e for e in doc["timing"]["entries"]}
    none = entries["none"]
    cpu_total = {k: sum(e["stages_cpu_ms"].values()) for k, e in entries.items()}
    wall = {k: e["ratio_to_none"]["median"] for k, e in entries.items()}
    lights, receivers = bench_goals.scene_counts(scene)
    row = {"scene": scene, "lights": lights, "receivers": receivers,
           "noise_floor": doc["noise_floor"]["ratio"],
           "too_noisy": doc["noise_floor"]["too_noisy"],
           "wall_ratio": wall,
           "cpu_ms": cpu_total,
           "cpu_ratio": {k: v / cpu_total["none"] for k, v in cpu_total.items()},
           "breakdown": {k: breakdown(entries[k], none) for k in TECHNIQUES if k in entries},
           "auto_choice": (entries["auto"].get("technique_stats") or {}).get("choice"),
           "stages_ms": {k: e["stages_ms"] for k, e in entries.items()},
           "stages_cpu_ms": {k: e["stages_cpu_ms"] for k, e in entries.items()}}
    row["csm_vs_vtk"] = {"wall": wall["csm"] / wall["vtk"],
                         "cpu": cpu_total["csm"] / cpu_total["vtk"]}
    return row


def top_stage(parts):
    if not parts:
        return "-"
    stage, ms = max(parts.items(), key=lambda kv: kv[1])
    return "%s %.1f" % (stage, ms)


def fmt_parts(parts):
    return ", ".join("%s %.1f" % (k, v) for k, v in parts.items()) or "-"


def markdown(rows, a):
    out = ["Produced by:", "",
           "    tests/gl-run.sh /usr/bin/python3 bench/bench_profile.py --out %s --rounds %d "
           "--frames %d --profile-frames %d SCENES" % (a.out, a.rounds, a.frames,
                                                      a.profile_frames), "",
           "Ratios: *wall* = interleaved medians (rounds of %d frames, order rotated), "
           "*CPU* = process CPU time of the %d profiled frames per technique (glFinish after "
           "every stage). Overheads are CPU ms per frame over `none`; *lit draw* is the "
           "technique's scene draw minus none's (its per-fragment lookups or mask reads)."
           % (a.frames, a.profile_frames), "",
           "| scene | none#2 / none | csm / vtk wall (CPU) | auto / none wall (CPU) | "
           "planar / none wall (CPU) | none CPU ms |",
           "|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        w, c = r["wall_ratio"], r["cpu_ratio"]
        planar = "%.2f (%.2f)" % (w["planar"], c["planar"]) \
            if r["lights"] == 1 and r["receivers"] == 1 else \
            "%.2f (%.2f) n/a" % (w["planar"], c["planar"])
        out.append("| %s | %.2f%s | %.2f (%.2f) | %.2f (%.2f) | %s | %.1f |" % (
            r["scene"], r["noise_floor"], " noisy" if r["too_noisy"] else "",
            r["csm_vs_vtk"]["wall"], r["csm_vs_vtk"]["cpu"], w["auto"], c["auto"], planar,
            r["cpu_ms"]["none"]))
    out += ["", "Where the time goes (CPU ms per frame over none; largest part first column):",
            "", "| scene | technique | largest | every part |", "|---|---|---|---|"]
    for r in rows:
        for t in TECHNIQUES:
            parts = r["breakdown"].get(t, {})
            label = t + (" (%s)" % r["auto_choice"] if t == "auto" and r["auto_choice"] else "")
            out.append("| %s | %s | %s | %s |" % (r["scene"], label, top_stage(parts),
                                                  fmt_parts(parts)))
    return "\n".join(out) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("scenes", nargs="+")
    p.add_argument("--out", required=True)
    p.add_argument("--bin", default="build/bin")
    p.add_argument("--rounds", type=int, default=4)
    p.add_argument("--frames", type=int, default=5)
    p.add_argument("--warmup", type=int, default=3)
    p.add_argument("--profile-frames", type=int, default=10)
    a = p.parse_args()
    for name, v, lo in (("--rounds", a.rounds, 1), ("--frames", a.frames, 1),
                        ("--warmup", a.warmup, 0), ("--profile-frames", a.profile_frames, 1)):
        if v < lo:
            p.error("%s %d: must be at least %d" % (name, v, lo))
    for s in a.scenes:
        if not os.path.isfile(s):
            p.error("scene %s: no such file" % s)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for i, scene in enumerate(a.scenes):
        log("[%d/%d] %s" % (i + 1, len(a.scenes), scene))
        d = os.path.join(a.out, os.path.splitext(os.path.basename(scene))[0])
        os.makedirs(d, exist_ok=True)
        rows.append(scene_row(scene, run_scene(a, scene, d)))
    with open(os.path.join(a.out, "profile.json"), "w") as f:
        json.dump(rows, f, indent=1)
    with open(os.path.join(a.out, "profile.md"), "w") as f:
        f.write(markdown(rows, a))
    log("wrote %s" % os.path.join(a.out, "profile.md"))
    if not rows:
        sys.exit(2)



if __name__ == "__main__":
    main()
