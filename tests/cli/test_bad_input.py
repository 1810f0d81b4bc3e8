"""vtkshadow-render on bad input: exit status 2, a message naming the file, the
field and the value, and no output file left behind.

Covers every bad scene in tests/scene/data/bad (the parser's rules, whose exact
messages tests/scene checks in C), the mesh problems only VTK's readers can
find (tests/cli/data), and bad command lines."""
import argparse
import glob
import os
import re
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--bin", required=True)
ap.add_argument("--source", required=True)
ap.add_argument("--out", required=True)
args = ap.parse_args()
os.makedirs(args.out, exist_ok=True)
render = os.path.join(args.bin, "vtkshadow-render")
good = os.path.join(args.source, "scenes/basic/sphere-plane.json")
failures = []
count = 0


def run_case(argv, expect_in_message, label, stats=True):
    global count
    count += 1
    outputs = [os.path.join(args.out, f"{label}.{ext}") for ext in
               ("image.png", "vis.png", "mask.png", "stats.json")]
    for p in outputs:
        if os.path.exists(p):
            os.remove(p)
    full = [render] + argv + ["--image", outputs[0], "--visibility", outputs[1],
                              "--mask", outputs[2], "--quiet"] + (
                                  ["--stats", outputs[3]] if stats else [])
    env = dict(os.environ)
    env.pop("DISPLAY", None)  # bad input must be caught before any rendering
    run = subprocess.run(full, capture_output=True, text=True, env=env, timeout=120)
    problems = []
    if run.returncode != 2:
        problems.append(f"exit status {run.returncode}, expected 2")
    for needle in expect_in_message:
        if needle not in run.stderr:
            problems.append(f"message lacks {needle!r}")
    left = [p for p in outputs if os.path.exists(p)]
    left += glob.glob(os.path.join(args.out, f"{label}.*.tmp*"))
    if left:
        problems.append(f"left output behind: {left}")
    if problems:
        failures.append(label)
        print(f"FAIL {label}: {'; '.join(problems)}\n  stderr: {run.stderr.strip()}")


# Every bad scene file of the parser's test suite.
bad_dir = os.path.join(args.source, "tests/scene/data/bad")
for path in sorted(glob.glob(os.path.join(bad_dir, "*.json"))):
    label = os.path.splitext(os.path.basename(path))[0]
    # The message starts with the file name, then the field (or the position).
    run_case([path, "--technique", "vtk"], [f"vtkshadow-render: {path}: "], "scene-" + label)
    count += 0

# Mesh problems found by VTK's readers: field objects[0].mesh and the path.
data = os.path.join(args.source, "tests/cli/data")
for name, needle in [("empty-mesh.json", "empty mesh"), ("corrupt-mesh.json", "invalid mesh"),
                     ("no-faces-mesh.json", "empty mesh")]:
    path = os.path.join(data, name)
    run_case([path, "--technique", "none"], [f"{path}: objects[0].mesh: ", needle, '(got "meshes/'],
             "mesh-" + name)

# Malformed mesh files, one per input class per format (tests/cli/data/
# make_bad_meshes.py): the scene that references one names it in objects[0].mesh.
sys.path.insert(0, data)
from make_bad_meshes import BAD_MESHES  # noqa: E402

scene_dir = os.path.join(args.out, "bad-mesh-scenes")
os.makedirs(scene_dir, exist_ok=True)
for name, (_, needle) in sorted(BAD_MESHES.items()):
    mesh = os.path.join(data, "meshes", "bad", name)
    scene = os.path.join(scene_dir, name + ".json")
    with open(scene, "w") as f:
        f.write('{"size": [64, 48], "camera": {"position": [2, -3, 2], "focal_point": [0, 0, 0], '
                '"view_up": [0, 0, 1], "view_angle": 45}, "lights": [{"type": "directional", '
                '"direction": [0, 0, -1]}], "objects": [{"mesh": "%s"}]}\n' % mesh)
    run_case([scene, "--technique", "none"],
             [f"vtkshadow-render: {scene}: objects[0].mesh: ", needle, f'(got "{mesh}"'],
             "bad-mesh-" + name)

# Bad command lines.
run_case([good, "--technique", "bogus"], ['unknown technique "bogus"'], "cli-technique")
run_case([good], ["missing --technique"], "cli-no-technique")
run_case([good, "--technique", "vtk", "--light", "3"], ["--light", "out of range", "3 lights"],
         "cli-light-range")
run_case([good, "--technique", "vtk", "--frames", "0"], ["--frames", '(got "0")'], "cli-frames")
run_case([good, "--technique", "vtk", "--size", "10x"], ["--size", '(got "10x")'], "cli-size")
run_case([good, "--technique", "vtk", "--bogus"], ['unknown option "--bogus"'], "cli-option")
run_case([os.path.join(args.out, "missing.json"), "--technique", "vtk"],
         ["missing.json"], "cli-missing-scene")
# Settings are checked by the named technique's pass (the registry's).
run_case([good, "--technique", "planar", "--set", "cascades=2"],
         ["technique planar has no setting", '"cascades=2'], "cli-set-other-technique")
run_case([good, "--technique", "csm", "--set", "cascades=9"],
         ["technique csm", '"cascades=9'], "cli-set-out-of-range")
run_case([good, "--technique", "csm", "--set", "bogus=1"], ['"bogus=1'], "cli-set-unknown")
# Planar mirrors (docs/reflections.md): --reflections and --image-light.
mirror = os.path.join(args.source, "scenes/mirror/sphere-mirror-floor.json")
run_case([mirror, "--technique", "planar", "--reflections", "yes"],
         ["--reflections", "auto, on, off or no-shadows", '(got "yes")'], "cli-reflections-word")
run_case([mirror, "--technique", "planar", "--reflections", "ON"],
         ["--reflections", '(got "ON")'], "cli-reflections-case")
run_case([mirror, "--technique", "planar", "--reflections", ""],
         ["--reflections"], "cli-reflections-empty")
# no value: the next option (run_case's --image) is taken as it, and refused
run_case([mirror, "--technique", "planar", "--reflections"],
         ["--reflections", '(got "--image")'], "cli-reflections-missing")
run_case([mirror, "--technique", "planar", "--image-light", "-1"],
         ["--image-light", '(got "-1")'], "cli-image-light-negative")
run_case([mirror, "--technique", "planar", "--image-light", "1x"],
         ["--image-light", '(got "1x")'], "cli-image-light-junk")
run_case([mirror, "--technique", "planar", "--image-light", "1"],
         ["--image-light", "out of range"], "cli-image-light-range")

# The interleaved timing's options: each bad value names the option and the
# value; the timing options without --stats are refused.
TIMING_CASES = [
    (["--rounds", "0"], ["--rounds", '(got "0")'], "cli-rounds-zero"),
    (["--rounds", "x"], ["--rounds", '(got "x")'], "cli-rounds-junk"),
    (["--warmup", "-1"], ["--warmup", '(got "-1")'], "cli-warmup"),
    (["--frames", "100001"], ["--frames", '(got "100001")'], "cli-frames-big"),
    (["--noise-tolerance", "0"], ["--noise-tolerance", '(got "0")'], "cli-noise-zero"),
    (["--noise-tolerance", "1"], ["--noise-tolerance", '(got "1")'], "cli-noise-one"),
    (["--noise-tolerance", "nan"], ["--noise-tolerance", '(got "nan")'], "cli-noise-nan"),
    (["--time-also", "bogus"], ["--time-also", '"bogus"', "unknown technique"], "cli-also-tech"),
    (["--time-also", "csm:bogus=1"], ["--time-also", '"csm:bogus=1"', 'no setting "bogus"'],
     "cli-also-key"),
    (["--time-also", "csm:cascades=9"], ["--time-also", '"csm:cascades=9"'], "cli-also-range"),
    (["--time-also", "csm:cascades"], ["--time-also", '(got "csm:cascades")'], "cli-also-form"),
    (["--time-also", "csm:"], ["--time-also", '(got "csm:")'], "cli-also-empty"),
    (["--time-also", "csm:cascades=2,"], ["--time-also", '(got "csm:cascades=2,")'],
     "cli-also-comma"),
    (["--time-also", "none"], ["--time-also", '"none"', "timed twice"], "cli-also-none"),
    (["--time-also", "vtk"], ["--time-also", '"vtk"', "timed twice"], "cli-also-main"),
    (["--time-also", "csm", "--time-also", "csm"], ["--time-also", '"csm"', "timed twice"],
     "cli-also-twice"),
]
for extra, needles, label in TIMING_CASES:
    run_case([good, "--technique", "vtk"] + extra, needles, label)
for option, value in (("--rounds", "3"), ("--time-also", "csm"), ("--fail-if-noisy", None)):
    run_case([good, "--technique", "vtk", option] + ([value] if value else []),
             [option, "only with --stats"], "cli-no-stats" + option, stats=False)

# How many cases ran: a moved data directory, an empty glob or a lost table
# entry must not pass as "0 failed". tests/scene/data/bad held 77 bad scenes
# when this was written (only ever grows); every one of them runs, plus the 3
# mesh cases, every malformed mesh, the 17 command lines above, the timing
# cases and the 3 timing options without --stats.
bad_scenes = len(glob.glob(os.path.join(bad_dir, "*.json")))
if bad_scenes < 77:
    failures.append("scene-count")
    print(f"FAIL: {bad_scenes} bad scenes in {bad_dir}, expected at least 77")
expected = bad_scenes + 3 + len(BAD_MESHES) + 17 + len(TIMING_CASES) + 3
if count != expected:
    failures.append("count")
    print(f"FAIL ran {count} cases, expected {expected}")
if len(BAD_MESHES) < 47:
    failures.append("mesh-table")
    print(f"FAIL only {len(BAD_MESHES)} malformed mesh cases, expected at least 47")
print(f"cli.bad_input: {count} cases ({bad_scenes} bad scenes, {len(BAD_MESHES)} malformed meshes), "
      f"{len(failures)} failed")
sys.exit(1 if failures else 0)
