"""Render test: the visibility image of a sphere over a plane against the exact
answer computed here by ray casting the analytic sphere and plane.

Runs vtkshadow-render on a scene this test writes, computes the exact
visibility, and measures the error with vtkshadow-metrics, outside a one-pixel
band along every exact edge (shadow boundary, silhouettes, mask boundary):
the renderer draws tessellated triangles, the reference analytic shapes.

  test_visibility.py --bin BUILD/bin --out DIR --technique vtk --size 512x512
      --light directional (--max-wrong-pct P | --expect-wrong-pct LO HI)
      [--reference unshadowed] [--beats OTHER [--by 10]]

--beats OTHER: measure technique OTHER the same way too, and require its
wrong_pct to be at least --by times ours (and above 0).
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import read_png, write_png  # noqa: E402
from exact_scene import edge_band, render_exact  # noqa: E402

LIGHTS = {
    "directional": {"type": "directional", "direction": [-3, -2, -6]},
    "point": {"type": "point", "position": [3, 2, 6]},
    "spot": {"type": "spot", "position": [3, 2, 6], "focal_point": [0, 0, 0], "cone_angle": 30},
}


def sphere_over_plane(light, width, height):
    return {
        "description": "render test: sphere over a plane",
        "size": [width, height],
        "camera": {"position": [0, -8, 5], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [LIGHTS[light]],
        "objects": [
            {"sphere": {"center": [0, 0, 1.2], "radius": 0.5, "resolution": 256}},
            {"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0], "point2": [-5, 5, 0]},
             "receiver": True},
        ],
    }


def measure(args, technique, width, height):
    """Render with `technique`, compare with the exact answer; returns
    (metrics, mask agreement in percent)."""
    name = f"{technique}-{args.light}-{width}x{height}"
    scene = sphere_over_plane(args.light, width, height)
    scene_path = os.path.join(args.out, name + ".json")
    with open(scene_path, "w") as f:
        json.dump(scene, f, indent=1)

    vis_path = os.path.join(args.out, name + "-visibility.png")
    mask_path = os.path.join(args.out, name + "-mask.png")
    run = subprocess.run(
        [os.path.join(args.bin, "vtkshadow-render"), scene_path, "--technique", technique,
         "--image", os.path.join(args.out, name + "-image.png"), "--visibility", vis_path,
         "--mask", mask_path, "--quiet"], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        sys.exit(f"vtkshadow-render failed with status {run.returncode}")

    exact, valid, obj = render_exact(scene, 0, width, height)
    if args.reference == "unshadowed":
        exact = valid.astype(float)
    exclude = edge_band(obj) | edge_band(valid.astype(int))
    ref_path = os.path.join(args.out, name + "-exact.png")
    ref_mask_path = os.path.join(args.out, name + "-exact-mask.png")
    exclude_path = os.path.join(args.out, name + "-exclude.png")
    write_png(ref_path, np.round(exact * 65535), 16)
    write_png(ref_mask_path, valid * 255, 8)
    write_png(exclude_path, exclude * 255, 8)

    metrics_json = os.path.join(args.out, name + "-metrics.json")
    run = subprocess.run(
        [os.path.join(args.bin, "vtkshadow-metrics"), "--reference", ref_path, "--mask",
         ref_mask_path, "--test", vis_path, "--exclude", exclude_path, "--band", "1",
         "--heatmap", os.path.join(args.out, name + "-error.png"), "--json", metrics_json],
        capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        sys.exit(f"vtkshadow-metrics failed with status {run.returncode}")
    with open(metrics_json) as f:
        metrics = json.load(f)

    # The measured mask must agree with the exact set of lit-facing pixels.
    mask = read_png(mask_path) > 127
    outside = ~exclude
    agreement = 100.0 * np.mean(mask[outside] == valid[outside])
    print(f"{name}: wrong_pct {metrics['wrong_pct']:.4f}  vis_mae {metrics['vis_mae']:.5f}  "
          f"edge_px {metrics['edge_px']:.3f}  false_shadow_pct {metrics['false_shadow_pct']:.4f}  "
          f"false_light_pct {metrics['false_light_pct']:.4f}  "
          f"wrong_of_shadow_pct {metrics['wrong_of_shadow_pct']:.4f}  "
          f"compared {metrics['compared_pixels']}  mask agreement {agreement:.4f}%")
    return metrics, agreement


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--technique", required=True)
    ap.add_argument("--size", required=True)
    ap.add_argument("--light", default="directional", choices=sorted(LIGHTS))
    ap.add_argument("--reference", default="shadowed", choices=["shadowed", "unshadowed"])
    ap.add_argument("--max-wrong-pct", type=float)
    ap.add_argument("--expect-wrong-pct", type=float, nargs=2)
    ap.add_argument("--beats", metavar="TECHNIQUE",
                    help="also measure TECHNIQUE; its wrong_pct must be at least --by times ours")
    ap.add_argument("--by", type=float, default=10.0)
    ap.add_argument("--min-valid-agreement", type=float, default=99.9)
    args = ap.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    os.makedirs(args.out, exist_ok=True)
    metrics, agreement = measure(args, args.technique, width, height)
    failed = False
    if metrics["compared_pixels"] < 0.2 * width * height:
        print(f"FAIL: only {metrics['compared_pixels']} pixels compared")
        failed = True
    if agreement < args.min_valid_agreement:
        print(f"FAIL: mask agreement {agreement:.4f}% < {args.min_valid_agreement}%")
        failed = True
    if args.max_wrong_pct is not None and metrics["wrong_pct"] > args.max_wrong_pct:
        print(f"FAIL: wrong_pct {metrics['wrong_pct']:.4f} > {args.max_wrong_pct}")
        failed = True
    if args.expect_wrong_pct is not None:
        lo, hi = args.expect_wrong_pct
        if not lo <= metrics["wrong_pct"] <= hi:
            print(f"FAIL: wrong_pct {metrics['wrong_pct']:.4f} outside the recorded [{lo}, {hi}]")
            failed = True
    if args.beats:
        # A ratio, not a recorded value of the other technique: the claim is
        # about ours. The other must show a real error (> 0), else "beats by
        # a factor" means nothing.
        other, _ = measure(args, args.beats, width, height)
        ours, theirs = metrics["wrong_pct"], other["wrong_pct"]
        ok = theirs > 0 and theirs >= args.by * ours
        print(f"{args.technique} wrong_pct {ours:.4f} vs {args.beats} {theirs:.4f}: "
              f"{'x%.1f' % (theirs / ours) if ours > 0 else 'ours is 0'} "
              f"(need >= x{args.by:g}: {'ok' if ok else 'FAIL'})")
        failed |= not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
