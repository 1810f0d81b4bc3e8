"""Render test: the lit draw started from the depth pre-pass's depth
(early_depth, vtkShadowDepthSeed) gives the same image, and the policy
seeds where the measurement says it pays.

    test_depth_seed.py --bin BUILD/bin --out DIR --scene SCENE.json
        --technique T [--set KEY=VALUE]... [--size WxH]
        [--policy seeded|unseeded]

Without --policy: renders SCENE with early_depth=2 (every frame seeded) and
early_depth=0, and passes when the stats say the first was seeded and the
second not, and every pixel of the two colour images is the same. A seed
one step too near (the visible fragment then fails LEQUAL) or too far
behind a surface of the view shows here as differing pixels.

With --policy: renders with the default early_depth=1 over enough frames
for a measurement (one frame unseeded, one seeded, then the decision) and
passes when the last frame's depth_seeded is what --policy says and the
measured hidden fragments per pixel are on that side of the fitted
threshold (reported by the stats, vsh_depth_seed.h).
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import read_png  # noqa: E402


def render(args, out, label, extra, frames):
    image = os.path.join(out, f"{label}.png")
    stats = os.path.join(out, f"{label}.json")
    cmd = [os.path.join(args.bin, "vtkshadow-render"), args.scene, "--technique",
           args.technique, "--image", image, "--stats", stats, "--quiet",
           "--frames", str(frames), "--rounds", "1", "--warmup", "0", "--size", args.size]
    for kv in args.set + extra:
        cmd += ["--set", kv]
    subprocess.run(cmd, check=True, timeout=280)
    with open(stats) as f:
        technique_stats = json.load(f)["technique_stats"]
    colour, _ = read_png(image, components=True)
    return colour.astype(np.int64), technique_stats


def seed_stats(stats):
    # auto nests its sub-passes' stats: the first depth_seeded found.
    if isinstance(stats, dict):
        if "depth_seeded" in stats:
            return stats["depth_seeded"], stats["depth_seed_hidden_per_px"]
        for value in stats.values():
            found = seed_stats(value)
            if found:
                return found
    if isinstance(stats, list):
        for value in stats:
            found = seed_stats(value)
            if found:
                return found
    return None


def check_identity(args, out):
    # Two timed frames: the last stats frame (at the scene camera, after an
    # orbit frame) is then one raytrace traces, not a still frame it reuses
    # without a pre-pass (and so without a seed).
    seeded, seeded_stats = render(args, out, "always", ["early_depth=2"], 2)
    plain, plain_stats = render(args, out, "never", ["early_depth=0"], 2)
    failures = []
    if seed_stats(seeded_stats) is None or not seed_stats(seeded_stats)[0]:
        failures.append("early_depth=2: the lit draw was not seeded (depth_seeded false)")
    if seed_stats(plain_stats) and seed_stats(plain_stats)[0]:
        failures.append("early_depth=0: the lit draw was seeded")
    if seeded.shape != plain.shape:
        failures.append(f"image sizes differ: {seeded.shape} and {plain.shape}")
        return failures
    differ = int(np.count_nonzero(np.any(seeded != plain, axis=-1)))
    pixels = seeded.shape[0] * seeded.shape[1]
    print(f"{args.technique}: {differ} of {pixels} pixels differ between early_depth=2 and 0")
    if differ:
        failures.append(f"{differ} pixels differ (the seeded lit draw must be the same image)")
    return failures


def check_policy(args, out):
    _, stats = render(args, out, "policy", [], 4)
    found = seed_stats(stats)
    if found is None:
        return ["the stats have no depth_seeded"]
    seeded, hidden = found
    print(f"{args.technique}: depth_seeded {seeded}, {hidden:.4f} hidden fragments a pixel")
    want = args.policy == "seeded"
    failures = []
    if hidden < 0:
        failures.append("no measurement after 4 frames (depth_seed_hidden_per_px -1)")
    if seeded != want:
        failures.append(f"depth_seeded {seeded}, expected {want}")
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--technique", required=True)
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--size", default="400x300")
    parser.add_argument("--policy", choices=["seeded", "unseeded"])
    args = parser.parse_args()
    name = os.path.splitext(os.path.basename(args.scene))[0]
    label = args.technique + "".join("-" + kv for kv in args.set)
    out = os.path.join(args.out, f"{name}-{label}-{args.policy or 'identity'}")
    os.makedirs(out, exist_ok=True)
    failures = check_policy(args, out) if args.policy else check_identity(args, out)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
