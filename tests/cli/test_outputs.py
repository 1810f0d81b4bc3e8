"""vtkshadow-render on the basic scene writes the image, a 16-bit visibility
with row 0 at the top, an 8-bit mask and the stats JSON, for each technique."""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "render"))
from png_io import read_png  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--bin", required=True)
ap.add_argument("--source", required=True)
ap.add_argument("--out", required=True)
args = ap.parse_args()
os.makedirs(args.out, exist_ok=True)
scene = os.path.join(args.source, "scenes/basic/sphere-plane.json")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


for technique in ("none", "vtk"):
    for light in (0, 1):
        base = os.path.join(args.out, f"{technique}-light{light}")
        run = subprocess.run(
            [os.path.join(args.bin, "vtkshadow-render"), scene, "--technique", technique,
             "--image", base + ".png", "--visibility", base + "-vis.png", "--mask",
             base + "-mask.png", "--stats", base + ".json", "--light", str(light),
             "--frames", "5", "--size", "320x240"], capture_output=True, text=True)
        check(run.returncode == 0, f"{technique} light {light}: status {run.returncode} {run.stderr}")
        if run.returncode != 0:
            continue
        check("visibility of light" in run.stderr, "progress output on stderr")
        image, image_type = read_png(base + ".png", components=True)
        check(image.shape == (240, 320, 3) and image_type == "unsigned char", f"image {image.shape}")
        vis, vis_type = read_png(base + "-vis.png", components=True)
        check(vis.shape == (240, 320, 1) and vis_type == "unsigned short", f"visibility {vis_type}")
        mask, mask_type = read_png(base + "-mask.png", components=True)
        check(mask_type == "unsigned char" and set(np.unique(mask)) <= {0, 255}, "mask is 0/255")
        # Row 0 at the top: the top rows see the sky (nothing), the bottom the floor.
        check(mask[:5].max() == 0 and mask[-5:].min() == 255, "row 0 of the mask is the top")
        check(vis[mask == 0].max() == 0, "visibility is 0 outside the mask")
        lit = vis[mask == 255]
        shadowed_fraction = float(np.mean(lit < 32768))
        if technique == "none" or light == 1:
            # No shadows, or VTK 9.1 casting none for a point light.
            check(shadowed_fraction == 0.0, f"{technique} light {light}: no shadow expected")
        else:
            check(0.005 < shadowed_fraction < 0.2, f"vtk light 0: shadow fraction {shadowed_fraction}")
        with open(base + ".json") as f:
            stats = json.load(f)
        for key in ("shadowed_ms", "unshadowed_ms"):
            t = stats[key]
            check(0 < t["min"] <= t["median"] <= t["max"], f"{key} ordered: {t}")
        check(stats["frames"] == 5 and stats["size"] == [320, 240], "stats echo the run")
        check((stats["shadow_map_bytes"] > 0) == (technique == "vtk"), "shadow-map memory")
        print(f"{technique} light {light}: shadowed {shadowed_fraction:.4f} of lit pixels, "
              f"{stats['shadowed_ms']['median']:.2f} ms vs {stats['unshadowed_ms']['median']:.2f} ms")

print("cli.outputs:", "FAILED" if failures else "ok")
sys.exit(1 if failures else 0)
