"""Interleaved timing, end to end: vtkshadow-render --stats and
bench/vtkshadow-bench --timing-only on a small window. Checks the structure
of what they write (every timed technique, none and none#2 with finite
figures, the schedule a permutation per round with every technique's mean
position in the middle, the noise verdict consistent with the floor and the
tolerance, no state leaked between passes), never a speed."""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--bin", required=True)
ap.add_argument("--source", required=True)
ap.add_argument("--out", required=True)
args = ap.parse_args()
os.makedirs(args.out, exist_ok=True)
render = os.path.join(args.bin, "vtkshadow-render")
scene = os.path.join(args.source, "scenes/basic/sphere-plane.json")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def finite_positive(v):
    return isinstance(v, (int, float)) and math.isfinite(v) and v > 0


def run(name, extra, scene_path=scene):
    stats = os.path.join(args.out, name + ".json")
    if os.path.exists(stats):
        os.remove(stats)
    cmd = [render, scene_path, "--image", os.path.join(args.out, name + ".png"), "--stats", stats,
           "--size", "160x120", "--frames", "3", "--rounds", "4", "--warmup", "1"] + extra
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    doc = None
    if os.path.exists(stats):
        with open(stats) as f:
            doc = json.load(f)
    return p, doc


def check_schedule(name, timing, labels, rounds):
    schedule = timing["schedule"]
    check(len(schedule) == rounds, f"{name}: {len(schedule)} rounds in the schedule")
    positions = {label: 0 for label in labels}
    for order in schedule:
        check(sorted(order) == sorted(labels), f"{name}: round {order} is not a permutation")
        for p, label in enumerate(order):
            positions[label] = positions.get(label, 0) + p
    # 4 rounds: each order is paired with its reverse, so the mean position
    # of every technique is the middle.
    middle = rounds * (len(labels) - 1) / 2
    check(all(v == middle for v in positions.values()),
          f"{name}: summed positions {positions}, expected {middle} each")
    whole = rounds % (len(labels) if len(labels) % 2 == 0 else 2 * len(labels)) == 0
    check(timing["balance"].startswith("whole cycles" if whole else "mirrored"),
          f"{name}: balance {timing['balance']}")


def check_entries(name, doc, labels):
    timing = doc["timing"]
    entries = {e["label"]: e for e in timing["entries"]}
    check(sorted(entries) == sorted(labels), f"{name}: entries {sorted(entries)}")
    for label, e in entries.items():
        ms = e["ms"]
        check(all(finite_positive(ms[k]) for k in ("median", "min", "max", "q1", "q3")) and
              ms["min"] <= ms["q1"] <= ms["median"] <= ms["q3"] <= ms["max"],
              f"{name} {label}: ms {ms}")
        r = e["ratio_to_none"]
        check(all(finite_positive(r[k]) for k in ("median", "min", "max")) and
              r["min"] <= r["median"] <= r["max"], f"{name} {label}: ratio {r}")
        check(len(e["round_medians_ms"]) == 4 and all(map(finite_positive, e["round_medians_ms"])),
              f"{name} {label}: round medians {e['round_medians_ms']}")
        # A pass switched out and back draws what it drew before the rounds.
        check(e["pixels_changed_after_timing"] == 0,
              f"{name} {label}: {e['pixels_changed_after_timing']} pixels changed after timing")
    none = entries.get("none", {}).get("ratio_to_none", {})
    check(none.get("median") == 1 and none.get("min") == 1 and none.get("max") == 1,
          f"{name}: none against itself {none}")
    floor = entries.get("none#2", {}).get("ratio_to_none", {})
    noise = doc["noise_floor"]
    check(noise["ratio"] == floor.get("median") and noise["min"] == floor.get("min"),
          f"{name}: noise_floor {noise} is not none#2's ratio {floor}")
    check(noise["too_noisy"] == (abs(noise["ratio"] - 1) > noise["tolerance"] + 1e-9),
          f"{name}: too_noisy {noise['too_noisy']} for ratio {noise['ratio']}")
    check_schedule(name, timing, labels, 4)
    return entries


# 1. csm with two more techniques.
p, doc = run("csm", ["--technique", "csm", "--time-also", "vtk:map_resolution=1024",
                     "--time-also", "planar"])
check(p.returncode == 0, f"csm: status {p.returncode}: {p.stderr}")
if doc:
    labels = ["csm", "none", "none#2", "vtk:map_resolution=1024", "planar"]
    entries = check_entries("csm", doc, labels)
    check(doc["frames"] == 3 and doc["rounds"] == 4 and doc["warmup_frames"] == 1,
          "csm: the run's settings echoed")
    check(doc["shadowed_ms"] == entries["csm"]["ms"] and doc["unshadowed_ms"] ==
          entries["none"]["ms"], "csm: shadowed_ms / unshadowed_ms are csm's and none's")
    check(doc["ratio"] == entries["csm"]["ratio_to_none"]["median"], "csm: top-level ratio")
    check(entries["vtk:map_resolution=1024"]["shadow_map_bytes"] > 0 and
          entries["none"]["shadow_map_bytes"] == 0, "csm: memory per technique")
    check(entries["vtk:map_resolution=1024"]["settings"] == {"map_resolution": 1024},
          "csm: settings of a --time-also entry")
    check("resolution" in doc["technique_stats"], "csm: the pass's details")
    check("noise floor none#2 / none = " in p.stderr, "csm: the noise-floor line on stderr")
    check(("warning: timing too noisy" in p.stderr) == doc["noise_floor"]["too_noisy"],
          "csm: the warning line when (and only when) too noisy")
else:
    check(False, "csm: no stats written")

# 2. none alone: none and none#2; --fail-if-noisy with a tolerance no real
# run meets exits 3 with every output written.
p, doc = run("none", ["--technique", "none", "--quiet", "--fail-if-noisy",
                      "--noise-tolerance", "1e-12"])
check(p.returncode == 3, f"none: status {p.returncode}, expected 3 (too noisy at 1e-12)")
check("warning: timing too noisy" in p.stderr, "none: the warning also with --quiet")
check(os.path.exists(os.path.join(args.out, "none.png")), "none: image written")
if doc:
    check_entries("none", doc, ["none", "none#2"])
    check(doc["noise_floor"]["too_noisy"] is True, "none: too_noisy in the JSON")
    check(doc["shadowed_ms"] == doc["unshadowed_ms"], "none: shadowed is none")
else:
    check(False, "none: no stats written")

# 2b. A scene with a mirror: every entry draws the mirrors as the main one
# does (each through its own reflection pass), so none#2 and a --time-also
# technique are timed with their reflections, not without.
p, doc = run("mirror", ["--technique", "none", "--time-also", "csm", "--quiet"],
             os.path.join(args.source, "scenes/mirror/sphere-mirror-floor.json"))
check(p.returncode == 0, f"mirror: status {p.returncode}: {p.stderr[-2000:]}")
for e in (doc or {}).get("timing", {}).get("entries", []):
    refl = (e.get("technique_stats") or {}).get("reflections") or {}
    check(refl.get("mirrors", 0) >= 1 and refl.get("drawn", 0) >= 1,
          f"mirror: entry {e.get('label')} drew no mirror: {refl}")
check(doc and len(doc["timing"]["entries"]) == 3, "mirror: none, none#2 and csm timed")

# 2c. The stage profile (--profile-frames): every entry gets its stages,
# each pass its own, in the order they run; stages are non-negative and, in
# every profiled frame, add up to that frame; none has no shadow stage.
# (Proportions, never a speed.) The stage medians need not add up to the
# frame median: on a loaded machine a stall lands in a different stage in
# each frame and every stage's median drops it (CI: 13 ms against 38 ms).
p, doc = run("profile", ["--technique", "csm", "--set", "resolve=1", "--time-also", "planar",
                         "--time-also", "vtk", "--time-also", "volume", "--profile-frames", "3",
                         "--rounds", "1"])
check(p.returncode == 0, f"profile: status {p.returncode}: {p.stderr[-2000:]}")
check("stage profile (3 frames each" in p.stderr, "profile: the stage lines on stderr")
expected = {"csm:resolve=1": ["setup", "csm.plan", "csm.maps", "csm.prepass", "csm.resolve",
                              "scene", "finish"],
            "none": ["setup", "scene", "finish"],
            "planar": ["setup", "planar.plan", "planar.mask", "scene", "finish"],
            "vtk": ["setup", "vtk.maps", "scene", "finish"],
            "volume": ["setup", "volume.prepass", "volume.stencil", "scene", "finish"]}
for e in (doc or {}).get("timing", {}).get("entries", []):
    label = e.get("label")
    stages = e.get("stages_ms") or {}
    cpu = e.get("stages_cpu_ms") or {}
    if label in expected:
        check(list(stages) == expected[label],
              f"profile: {label} stages {list(stages)}, expected {expected[label]}")
    check(list(cpu) == list(stages), f"profile: {label} CPU stages match the wall stages")
    check(all(isinstance(v, (int, float)) and math.isfinite(v) and v >= 0
              for v in list(stages.values()) + list(cpu.values())),
          f"profile: {label} stage times finite and >= 0: {stages} {cpu}")
    total = e.get("profiled_frame_ms", 0)
    check(finite_positive(total), f"profile: {label} frame median {total}")
    frames = e.get("profiled_frames_ms") or []
    sums = e.get("profiled_stage_sums_ms") or []
    check(len(frames) == 3 and len(sums) == 3, f"profile: {label} 3 frames: {frames} {sums}")
    check(sorted(frames)[1] == total, f"profile: {label} median of {frames} is not {total}")
    for frame, stage_sum in zip(frames, sums):
        # The stages run from the frame's first mark to "finish"; the frame's
        # clock starts just before the first and stops just after "finish"
        # (a stall outside the stages is the frame's alone).
        check(finite_positive(frame) and 0.98 * frame - 1 <= stage_sum <= frame + 0.01,
              f"profile: {label} stages {stage_sum:.2f} ms against the frame {frame:.2f}")
check(doc and all("stages_ms" in e for e in doc["timing"]["entries"]),
      "profile: every entry profiled")
# Without --profile-frames nothing is profiled (the timed frames stay clean).
p0, doc0 = run("noprofile", ["--technique", "planar", "--rounds", "1", "--quiet"])
check(doc0 and not any("stages_ms" in e for e in doc0["timing"]["entries"]),
      "profile: no stages without --profile-frames")
p1 = subprocess.run([render, scene, "--technique", "none", "--image",
                     os.path.join(args.out, "bad.png"), "--stats",
                     os.path.join(args.out, "bad.json"), "--profile-frames", "-1"],
                    capture_output=True, text=True, timeout=120)
check(p1.returncode == 2 and "--profile-frames" in p1.stderr,
      f"profile: --profile-frames -1 is refused with status 2: {p1.returncode} {p1.stderr}")

# 3. The bench, timing only: one row per configuration plus none#2. The
# bench is a Python script that imports the vtkshadow module; under the
# sanitizers (tests/sanitize/run.sh product) that module is instrumented and
# cannot load into Debian's uninstrumented python3 ("ASan runtime does not
# come first"), so the sanitized run checks the tool's timing (1 and 2
# above) and this part runs in the normal build only.
def sanitized_build(bin_dir):
    cache = os.path.join(bin_dir, os.pardir, "CMakeCache.txt")
    try:
        with open(cache) as f:
            return any(line.startswith("VTKSHADOW_SANITIZE:BOOL=ON") for line in f)
    except OSError:
        return False


if sanitized_build(args.bin):
    print("cli.timing: the bench part runs in the normal build only (sanitized build)")
    print("cli.timing:", "FAILED (%d)" % len(failures) if failures else "ok")
    sys.exit(1 if failures else 0)
bench_out = os.path.join(args.out, "bench")
cmd = [sys.executable, os.path.join(args.source, "bench/vtkshadow_bench.py"),
       os.path.join(args.source, "scenes/basic/sphere-directional.json"), "--out", bench_out,
       "--timing-only", "--frames", "2", "--rounds", "2", "--warmup", "1",
       "--timing-scale", "0.2"]
p = subprocess.run(cmd, capture_output=True, text=True, timeout=1200)
check(p.returncode == 0, f"bench: status {p.returncode}: {p.stderr[-2000:]}")
sys.path.insert(0, os.path.join(args.source, "bench"))
import vtkshadow_bench  # noqa: E402

if p.returncode == 0:
    with open(os.path.join(bench_out, "bench.json")) as f:
        rows = json.load(f)
    expected = [(t, s) for t, s, _ in vtkshadow_bench.configs_for(True, "small")]
    got = [(r["technique"], r["settings"]) for r in rows]
    check(got == expected + [("none#2", "noise floor")], f"bench: rows {got}")
    check(all(finite_positive(r["ms_per_frame"]) and finite_positive(r["ratio"]) and
              r["ms_min"] <= r["ms_per_frame"] <= r["ms_max"] for r in rows),
          "bench: finite times and ratios in every row")
    floor = rows[-1]
    check(all(r["noise_floor"] == floor["ratio"] for r in rows), "bench: noise_floor column")
    check(next(r for r in rows if r["technique"] == "none")["ratio"] == 1, "bench: none is 1")
    with open(os.path.join(bench_out, "bench.csv")) as f:
        header = next(csv.reader(f))
    check("noise_floor" in header and "too_noisy" in header, f"bench: CSV header {header}")
    with open(os.path.join(bench_out, "summary.md")) as f:
        text = f.read()
    check("noise floor none#2 / none = " in text, "bench: the noise floor in summary.md")
    # Issue 14's three goals apply to sphere-directional (one light, one
    # receiver), each with a verdict (bench/bench_goals.py).
    check(all(r.get("scene_lights") == 1 and r.get("scene_receivers") == 1 for r in rows),
          "bench: scene_lights / scene_receivers 1 and 1 in every row")
    goal_lines = [l for l in text.splitlines() if l.startswith("- goal ")]
    check(len(goal_lines) == 3 and all(any(v in l for v in (": met (", ": missed by ",
                                                            ": too noisy ("))
                                       for l in goal_lines), f"bench: goal lines {goal_lines}")
    check(("WARNING: timing too noisy" in p.stdout) == bool(floor["too_noisy"]),
          "bench: the warning when too noisy")
p = subprocess.run([sys.executable, os.path.join(args.source, "bench/vtkshadow_bench.py"),
                    scene, "--out", bench_out, "--timing-only", "--rounds", "0"],
                   capture_output=True, text=True, timeout=60)
check(p.returncode == 2 and "--rounds" in p.stderr and "0" in p.stderr,
      f"bench --rounds 0: status {p.returncode}, {p.stderr.strip()[-300:]}")

print("cli.timing:", "FAILED (%d)" % len(failures) if failures else "ok")
sys.exit(1 if failures else 0)
