"""What the exact-penumbra tests of the soft techniques share
(test_soft_planar.py, test_soft_csm.py): the scene of test_soft.py with the
lights' sizes set, one vtkshadow-render run of a technique with a setting,
exact_penumbra's figures for its visibility, and the failure list each
script reports from.
"""
import json
import os
import subprocess

import exact_cache
from test_soft import SCENE

SIZE = "160x120"
failures = []


def run(cmd):
    """Runs cmd; a non-zero status is a failure (output printed)."""
    print("+", " ".join(cmd), flush=True)
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        print(r.stdout[-2000:], r.stderr[-4000:])
        failures.append("command failed: " + " ".join(cmd[:4]))
    return r


def scene_with(out, name, size):
    """test_soft.py's scene with every light's radius / angle set to size
    (None: as it is), written to OUT/NAME.json."""
    scene = json.loads(json.dumps(SCENE))
    if size is not None:
        for light in scene["lights"]:
            light["radius" if "radius" in light else "angle"] = size
    path = os.path.join(out, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def render(bindir, scene, technique, setting, k, stem, stats=False):
    """vtkshadow-render of light k with --set SETTING (a string, or a list of
    them): (visibility, mask, image) paths STEM_vis.png, STEM_mask.png,
    STEM.png; with stats, also STEM.json (--stats, one timed frame)."""
    vis, mask, image = stem + "_vis.png", stem + "_mask.png", stem + ".png"
    sets = ["--stats", stem + ".json", "--frames", "1", "--rounds", "1", "--warmup", "1"] \
        if stats else []
    for one in ([setting] if isinstance(setting, str) else setting):
        sets += ["--set", one]
    run([os.path.join(bindir, "vtkshadow-render"), scene, "--technique", technique] + sets +
        ["--light", str(k), "--size", SIZE, "--visibility", vis, "--mask", mask,
         "--image", image, "--quiet"])
    return vis, mask, image


def exact(bindir, scene, k, vis, mask):
    """exact_penumbra's JSON figures of a visibility image, or None (the
    exact image from the run's cache, exact_cache.py)."""
    r = exact_cache.run_exact(run, bindir, "exact_penumbra", scene, k, vis, mask)
    try:
        return json.loads(r.stdout)
    except ValueError:
        failures.append("exact_penumbra gave no JSON")
        return None


def same_bytes(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def check_hard(bindir, out, technique, hard_mae_max, extra=()):
    """The hard case of a sampled technique (setting soft_samples): radius /
    angle 0 (with soft_samples 16) renders the same bytes as the sized scene
    with soft_samples=1 (both the hard path), and a size of 1e-6 with N = 16
    equals the exact hard shadow (mean error within hard_mae_max over the
    plane). `extra`: more settings for every render (csm: soft=2).
    Failures go to `failures`."""
    hard = scene_with(out, "hard", 0)
    soft = scene_with(out, "soft", None)
    tiny = scene_with(out, "tiny", 1e-6)
    for k in range(len(SCENE["lights"])):
        _, _, a = render(bindir, hard, technique, ["soft_samples=16"] + list(extra), k,
                         os.path.join(out, "hard_light%d" % k))
        _, _, b = render(bindir, soft, technique, ["soft_samples=1"] + list(extra), k,
                         os.path.join(out, "n1_light%d" % k))
        same = os.path.exists(a) and os.path.exists(b) and same_bytes(a, b)
        print("light %d: radius 0 and soft_samples=1 render the same bytes: %s" % (k, same))
        if not same:
            failures.append("light %d: soft_samples=1 is not the hard path" % k)
        vis, mask, _ = render(bindir, tiny, technique, ["soft_samples=16"] + list(extra), k,
                              os.path.join(out, "tiny_light%d" % k))
        m = exact(bindir, hard, k, vis, mask)
        print("size 1e-6, N=16, light %d against the exact hard shadow: %s" % (k, m))
        if not m or not m["mae"] <= hard_mae_max:
            failures.append("size 1e-6 light %d: not the hard shadow (%s)" % (k, m))


# The adaptive tests' small occluder (test_soft_adaptive.py,
# test_soft_planar_adaptive.py): a sphere of radius 0.08 halfway to light 0,
# whose blocked blob of the light can fall between a fixed batch's points.
# Non-adaptive N = 64 must stay within PEN_MAE_MAX of the exact penumbra;
# adaptive within SMALL_MAE_MAX, a regression bound, not a quality goal.
PEN_MAE_MAX = 0.02
SMALL_MAE_MAX = 0.05


def small_occluder_scene(out):
    """The small-occluder scene, written to OUT/small.json."""
    scene = json.loads(json.dumps(SCENE))
    scene["objects"][0]["sphere"]["center"] = [0, 0, 2.5]
    scene["objects"][0]["sphere"]["radius"] = 0.08
    path = os.path.join(out, "small.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def check_small_occluder(args, render):
    """The failure mode of a fixed batch: renders the small-occluder scene's
    light 0 at N = 64 adaptive and not with the test's render(args, scene,
    n, adaptive, k, tag) (exact()'s dict first in what it returns), prints
    and bounds the figures."""
    path = small_occluder_scene(args.out)
    adaptive = render(args, path, 64, 1, 0, "small")[0]
    plain = render(args, path, 64, 0, 0, "small")[0]
    if not adaptive or not plain or plain["pen_pixels"] < 20:
        failures.append("small occluder: no penumbra measured")
        return
    print("small occluder, N=64, light 0: pen_mae adaptive %g (bias %g), non-adaptive %g (bias %g)"
          % (adaptive["pen_mae"], adaptive["pen_bias"], plain["pen_mae"], plain["pen_bias"]))
    if not plain["pen_mae"] <= PEN_MAE_MAX:
        failures.append("small occluder: non-adaptive pen_mae %g > %g" % (plain["pen_mae"], PEN_MAE_MAX))
    if not adaptive["pen_mae"] <= SMALL_MAE_MAX:
        failures.append("small occluder: adaptive pen_mae %g > %g"
                        % (adaptive["pen_mae"], SMALL_MAE_MAX))


def verdict(test_name):
    """Print every failure (or that all bounds were met); the exit status."""
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("%s: all bounds met" % test_name)
    return 0


def parse_args():
    """--bin BUILD/bin --out DIR (created) of every soft harness test."""
    import argparse
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    return args
