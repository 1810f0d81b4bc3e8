"""Soft shadows against an exact penumbra (issue 15; docs/harness.md,
"Lights with a size").

    test_soft.py --bin BUILD/bin --source SRC --out DIR

A sphere over a plane under two disk lights (radius 0.5 straight above,
0.35 to the side) and a sun of angular diameter 6 degrees. exact_penumbra
integrates, per pixel, the unoccluded fraction of each light (vsh_soft), and
the references rendered by vtkshadow-compare with those sizes must agree
with it in the penumbra:

- POV-Ray (area_light, 17 x 17 circular orient jitter) and Cycles (256
  samples at the pixel centre), seed 0: pen_mae, |pen_bias| and the 0.5
  contour distance within BOUNDS (each about twice the measured value);
- seed 1 renders again: each reference's own noise sigma (std of the
  difference of the two seeds / sqrt 2) below 1.5% in the plane's penumbra
  (on the sphere's own terminator Cycles' per-sample N.L is far noisier:
  3.6% measured there at 256 samples);
- the same scene with radius 0 and angle 0 (hard lights) equals the exact
  hard shadow (a step): mean error below 0.002 over the plane, i.e. only
  pixels the edge crosses differ, and so does radius 1e-4 (the limit),
  for POV-Ray and (1e-4, 64 samples) for Cycles, whose samples must all be
  at the pixel centre: no grey edge pixels (leak_pct + false_shadow_pct
  <= HARD_GREY_MAX; Blender's BOX filter spread them over the pixel).

Prints every figure; exits 1 when any bound fails. A missing POV-Ray or
Blender is an error of vtkshadow-compare (exit 1), not a skip.
"""
import argparse
import json
import os
import subprocess
import sys

import exact_cache

SCENE = {
    "description": "soft-shadow test: sphere over a plane, two disk lights and a sun with an angle",
    "size": [640, 480],
    "camera": {"position": [0, -7, 5], "focal_point": [0, 0, 0.4], "view_up": [0, 0, 1], "view_angle": 30},
    "lights": [
        {"type": "point", "position": [0, 0, 5], "radius": 0.5},
        {"type": "point", "position": [2.5, 1.5, 4], "radius": 0.35},
        {"type": "directional", "direction": [-1, -0.6, -2], "angle": 6},
    ],
    "objects": [
        {"sphere": {"center": [0, 0, 1.2], "radius": 0.5, "resolution": 256}},
        {"plane": {"origin": [-4, -4, 0], "point1": [4, -4, 0], "point2": [-4, 4, 0]}, "receiver": True},
    ],
}

# Measured at --scale 0.25 (160x120): POV-Ray pen_mae 0.0058 / 0.0061,
# Cycles 0.0067 / 0.0078 for the two disk lights (docs/harness.md). Bounds
# about twice that.
BOUNDS = {"pen_mae": 0.015, "abs_pen_bias": 0.006, "contour_05_px": 0.35}
NOISE_MAX = 0.015
HARD_MAE_MAX = 0.002
HARD_GREY_MAX = 0.05  # leak_pct + false_shadow_pct against the exact hard shadow

failures = []


def run(cmd):
    print("+", " ".join(cmd), flush=True)
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        print(r.stdout[-2000:], r.stderr[-4000:])
        failures.append("command failed: " + " ".join(cmd[:2]))
    return r


def compare(args, scene, out, seed):
    run([os.path.join(args.bin, "vtkshadow-compare"), scene, "--out", out, "--renderers",
         "povray,cycles", "--scale", "0.25", "--soft-samples", "256", "--povray-grid", "17",
         "--seed", str(seed), "--no-report"])


def exact(args, scene, k, vis, mask):
    r = exact_cache.run_exact(run, args.bin, "exact_penumbra", scene, k, vis, mask)
    try:
        return json.loads(r.stdout)
    except ValueError:
        failures.append("exact_penumbra gave no JSON")
        return None


def write_scene(path, scene):
    with open(path, "w") as f:
        json.dump(scene, f)


def check_soft(args, scene_path, outs):
    for renderer in ("povray", "cycles"):
        for k in range(len(SCENE["lights"])):
            d0 = os.path.join(outs[0], "exact", renderer)
            d1 = os.path.join(outs[1], "exact", renderer)
            vis, mask = (os.path.join(d0, "light%d_%s.png" % (k, n)) for n in ("visibility", "mask"))
            m = exact(args, scene_path, k, vis, mask)
            r = run([os.path.join(args.bin, "exact_penumbra"), "--noise", vis,
                     os.path.join(d1, "light%d_visibility.png" % k), mask, scene_path, str(k)])
            noise = json.loads(r.stdout) if r.returncode == 0 else {"sigma": 1}
            print("soft %s light %d: %s noise %s" % (renderer, k, m, noise))
            if not m or m["pen_pixels"] < 100:
                failures.append("%s light %d: no penumbra measured" % (renderer, k))
                continue
            for key, bound in BOUNDS.items():
                value = abs(m["pen_bias"]) if key == "abs_pen_bias" else m[key]
                if not value <= bound:
                    failures.append("%s light %d: %s %g > %g" % (renderer, k, key, value, bound))
            if not noise["sigma"] <= NOISE_MAX:
                failures.append("%s light %d: noise %g > %g" % (renderer, k, noise["sigma"], NOISE_MAX))


def check_hard(args, out, size):
    scene = json.loads(json.dumps(SCENE))
    for light in scene["lights"]:
        light["radius" if "radius" in light else "angle"] = size
    path = os.path.join(out, "hard-%g.json" % size)
    write_scene(path, scene)
    cout = os.path.join(out, "hard-%g" % size)
    # Size 1e-4 also renders Cycles with 64 samples: all at the pixel centre,
    # so the edge stays a step. Blender's BOX filter (always 1 px wide) made
    # the edges grey: leak_pct 4.2-7.9 and false_shadow_pct 0.21-0.37 per
    # light, 0 and 0 with the Gaussian (HARD_GREY_MAX).
    renderers = ["povray", "cycles"] if size > 0 else ["povray"]
    run([os.path.join(args.bin, "vtkshadow-compare"), path, "--out", cout, "--renderers",
         ",".join(renderers), "--soft-samples", "64", "--scale", "0.25", "--no-report"])
    hard = os.path.join(out, "hard-exact.json")
    scene0 = json.loads(json.dumps(SCENE))
    for light in scene0["lights"]:
        light["radius" if "radius" in light else "angle"] = 0
    write_scene(hard, scene0)
    for renderer in renderers:
        stem = os.path.join(cout, "hard-%g" % size, renderer)
        for k in range(len(SCENE["lights"])):
            m = exact(args, hard, k, os.path.join(stem, "light%d_visibility.png" % k),
                      os.path.join(stem, "light%d_mask.png" % k))
            print("hard (size %g) %s light %d: %s" % (size, renderer, k, m))
            if not m or not m["mae"] <= HARD_MAE_MAX:
                failures.append("size %g %s light %d: not the hard shadow (%s)" % (size, renderer, k, m))
            elif not m["leak_pct"] + m["false_shadow_pct"] <= HARD_GREY_MAX:
                failures.append("size %g %s light %d: grey edge pixels (%s)" % (size, renderer, k, m))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    scene_path = os.path.join(args.out, "exact.json")
    write_scene(scene_path, SCENE)
    outs = [os.path.join(args.out, "seed%d" % s) for s in (0, 1)]
    for seed, out in enumerate(outs):
        compare(args, scene_path, out, seed)
    check_soft(args, scene_path, outs)
    check_hard(args, args.out, 0)
    check_hard(args, args.out, 1e-4)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("harness.soft: all bounds met")
    return 0


if __name__ == "__main__":
    sys.exit(main())
