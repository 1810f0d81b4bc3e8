"""Render test for scenes with a wide depth range (scenes/hard/near-far-*):
vtkshadow-render's visibility of light 0 against the exact answer ray-cast by
exact_scene.py, outside a one-pixel band along every exact edge and outside
the spheres' tessellated terminator (tessellated_terminator).

VTK's own clipping range keeps the near plane at 1/1000 of the far plane,
which clipped everything closer than about 20 in near-far-1e5 (96% of the
pixels wrong for every technique, `none` included). The clipping range now
comes from the visible geometry (vtkShadowScene::ResetCameraClippingRange).

  test_depth_range.py --bin BUILD/bin --out DIR --scene SCENE.json
      --technique T --reference all|planar|none --max-wrong-pct P
      [--size WxH] [--near-object K] [--set KEY=VALUE]...

--reference none: the unshadowed answer (what `none` must match exactly);
planar: shadows only on receiver planes (what planar promises); all: every
object shadows every other. --near-object K additionally requires that the
renderer's mask covers at least 99% of the exact lit pixels of object K (the
object nearest the camera, the one a too-far near plane clips away).
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import read_png, write_png  # noqa: E402
from exact_scene import edge_band, trace_scene  # noqa: E402


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        sys.exit(f"{os.path.basename(cmd[0])} failed with status {r.returncode}")


def tessellated_terminator(scene, exact):
    """Pixels of spheres near their terminator, where a facet of the
    renderer's UV sphere (its `resolution` segments around, half as many
    rings) may face away from the light while the exact sphere faces it: its
    normal is within about pi / resolution of the exact one on either axis,
    so within 2 pi / resolution, with margin. Such a facet is dark on the
    triangles (a ray from it enters the solid; the facing test of planar and
    volume says so), lit on the exact sphere."""
    band = np.zeros(exact["object"].shape, bool)
    for k, o in enumerate(scene["objects"]):
        if "sphere" in o:
            tolerance = np.sin(2.0 * np.pi / o["sphere"].get("resolution", 64))
            band |= (exact["object"] == k) & (np.abs(exact["light_cos"]) < tolerance)
    return band


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--scene", required=True)
    ap.add_argument("--technique", required=True)
    ap.add_argument("--reference", required=True, choices=["all", "planar", "none"])
    ap.add_argument("--max-wrong-pct", type=float, required=True)
    ap.add_argument("--size")
    ap.add_argument("--near-object", type=int)
    ap.add_argument("--set", action="append", default=[], help="technique setting KEY=VALUE")
    args = ap.parse_args()
    with open(args.scene) as f:
        scene = json.load(f)
    width, height = scene["size"]
    size_args = []
    if args.size:
        width, height = (int(v) for v in args.size.split("x"))
        size_args = ["--size", args.size]
    for setting in args.set:
        size_args += ["--set", setting]
    os.makedirs(args.out, exist_ok=True)
    name = (f"{os.path.splitext(os.path.basename(args.scene))[0]}-{args.technique}"
            f"-{args.reference}-{width}x{height}" + "".join("-" + s for s in args.set))
    base = os.path.join(args.out, name)

    run([os.path.join(args.bin, "vtkshadow-render"), args.scene, "--technique", args.technique,
         "--image", base + "-image.png", "--visibility", base + "-visibility.png",
         "--mask", base + "-mask.png", "--quiet"] + size_args)

    exact = trace_scene(scene, 0, width, height, shadows=args.reference)
    valid = exact["valid"]
    exclude = edge_band(exact["object"]) | edge_band(valid.astype(int)) | \
        edge_band(exact["face"] + 8 * (exact["object"] + 1))
    if args.reference != "none":
        exclude |= edge_band(exact["blocked"].astype(int))
    exclude |= tessellated_terminator(scene, exact)
    write_png(base + "-exact.png", np.round(exact["visibility"] * 65535), 16)
    write_png(base + "-exact-mask.png", valid * 255, 8)
    write_png(base + "-exclude.png", exclude * 255, 8)
    run([os.path.join(args.bin, "vtkshadow-metrics"), "--reference", base + "-exact.png",
         "--mask", base + "-exact-mask.png", "--test", base + "-visibility.png",
         "--exclude", base + "-exclude.png", "--band", "1",
         "--heatmap", base + "-error.png", "--json", base + "-metrics.json"])
    with open(base + "-metrics.json") as f:
        metrics = json.load(f)

    mask = read_png(base + "-mask.png") > 127
    outside = ~exclude
    agreement = 100.0 * np.mean(mask[outside] == valid[outside])
    print(f"{name}: wrong_pct {metrics['wrong_pct']:.4f}  vis_mae {metrics['vis_mae']:.5f}  "
          f"false_shadow_pct {metrics['false_shadow_pct']:.4f}  "
          f"false_light_pct {metrics['false_light_pct']:.4f}  compared "
          f"{metrics['compared_pixels']}  mask agreement {agreement:.4f}%")
    failed = False
    if metrics["compared_pixels"] < 0.2 * width * height:
        print(f"FAIL: only {metrics['compared_pixels']} pixels compared")
        failed = True
    if agreement < 99.5:
        print(f"FAIL: mask agreement {agreement:.4f}% < 99.5%")
        failed = True
    if metrics["wrong_pct"] > args.max_wrong_pct:
        print(f"FAIL: wrong_pct {metrics['wrong_pct']:.4f} > {args.max_wrong_pct}")
        failed = True
    if args.near_object is not None:
        near = valid & (exact["object"] == args.near_object) & outside
        seen = 100.0 * np.mean(mask[near]) if near.any() else 0.0
        print(f"object {args.near_object} (nearest): {int(near.sum())} exact lit pixels, "
              f"{seen:.2f}% of them in the rendered mask")
        if not near.any() or seen < 99.0:
            print("FAIL: the nearest object is missing (clipped by the near plane?)")
            failed = True
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
