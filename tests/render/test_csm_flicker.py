"""Render test: temporal stability of cascaded shadow maps (technique "csm")
along a camera path, as flicker_pct (docs/metrics.md).

The scene: test_planar's sphere over a floor, with the floor made long
(x -20..20, y -10..60) and a few more casters along it, lit by the same sun.
The camera translates sideways (+x, 0.12 a frame) and slightly forward
(+y, 0.05 a frame) over FRAMES frames, always looking the same way, so the
view frustum, and with it every cascade's fit, changes every frame.

For every frame the scene is written as JSON, loaded with vtkShadowScene and
measured with vtkShadowVisibility (the measurement of vtkshadow-render
--visibility: float renders, v = I_on / I_off) and compared with the exact
answer of that frame (exact_scene.trace_scene, shadows on every surface).
A pixel's error state is wrong = |v - v_exact| > 0.5; the compared pixels are
the exact valid pixels outside test_planar's exclude band (one pixel along
object and box-face edges, where triangles and analytic shapes differ; NOT
along the shadow boundary, where flicker lives). flicker_pct is the mean over
consecutive frame pairs of the percentage of pixels compared in both frames
whose state flips (vsh_flicker_pct). Printed per configuration, with the mean
wrong_pct and the figures with the 1-pixel shadow-boundary band excluded too.

Asserted, for csm with Stable on, at the origin and with the whole path moved
1e6 from the origin on every axis:
  * flicker_pct with the 1-pixel shadow-boundary band excluded (the --band 1
    convention of every wrong_pct bound of the render tests)
    <= --max-flicker-pct (default 0.05; measured 0.0015 at both places);
  * flicker_pct of all compared pixels <= --max-flicker-pct-all (default 0.3;
    measured 0.21). This one is about twice the per-frame wrong_pct (0.10):
    the camera moves ~12 px a frame on screen, so the few wrong pixels along
    the shadow edges (rasterised edge vs exact edge) land on other pixels in
    the next frame whatever the shadow map does.
Printed for comparison only: csm with Stable off, and technique "vtk".

  test_csm_flicker.py [--out DIR] [--frames 24] [--max-flicker-pct 0.05]
      [--max-flicker-pct-all 0.3] [--only stable|offset]
"""
import argparse
import json
import os
import sys
import time

import numpy as np
import vtkshadow
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_planar as tp  # noqa: E402
from exact_scene import trace_scene  # noqa: E402

SIZE = (640, 480)
DIRECTION = [-3, -2, -6]   # test_planar's sphere-floor sun


def path_scene(k):
    """Frame k of the path (a scene dict, camera moved)."""
    x = -1.4 + 0.12 * k
    y = -8.0 + 0.05 * k
    eye = [x, y, 5.0]
    return {
        "description": f"csm flicker path, frame {k}",
        "size": list(SIZE),
        "camera": {"position": eye, "focal_point": [x, y + 8.0, 0.5], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": DIRECTION}],
        "objects": [
            tp.sphere([0, 0, 1.2], 0.5),
            tp.floor(20, x0=-20, y0=-10, y1=60),
            tp.sphere([2.2, 3.0, 0.9], 0.6),
            {"box": {"min": [-2.6, 1.5, 0.0], "max": [-1.8, 2.1, 1.4]}, "name": "post"},
            tp.sphere([0.8, 9.0, 1.5], 1.0),
            {"box": {"min": [3.0, 14.0, 0.0], "max": [5.0, 14.6, 2.0]}, "name": "wall"},
        ],
    }


def visibility(path, technique):
    scene = vtkshadow.vtkShadowScene()
    if not scene.Load(path):
        sys.exit(scene.GetErrorMessage())
    vis = vtkshadow.vtkShadowVisibility()
    vis.SetScene(scene)
    vis.SetTechnique(technique)
    if not vis.Compute():
        sys.exit(f"{path}: {vis.GetErrorMessage()}")
    image = vis.GetVisibility()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w)[::-1].astype(np.float64)


def shadow_band(ref, valid):
    """vtkshadow-metrics --band 1 along the exact shadow boundary."""
    lit = valid & (ref >= 0.5)
    dark = valid & (ref < 0.5)

    def dilate(m):
        out = m.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                out |= np.roll(np.roll(m, dy, 0), dx, 1)
        return out
    return valid & ((lit & dilate(dark)) | (dark & dilate(lit)))


def flicker_pct(states, masks):
    """vsh_flicker_pct: mean over consecutive pairs of the percentage of
    pixels valid in both whose state differs (pairs with none skipped)."""
    pcts = []
    for k in range(1, len(states)):
        both = masks[k - 1] & masks[k]
        n = int(both.sum())
        if n:
            pcts.append(100.0 * np.sum(both & (states[k - 1] != states[k])) / n)
    return float(np.mean(pcts)) if pcts else 0.0, pcts


def techniques():
    stable = vtkshadow.vtkShadowTechnique()
    stable.SetName("csm")
    stable.SetOption("stable", 1)
    unstable = vtkshadow.vtkShadowTechnique()
    unstable.SetName("csm")
    unstable.SetOption("stable", 0)
    vtk = vtkshadow.vtkShadowTechnique()
    vtk.SetName("vtk")
    return {"csm stable": stable, "csm unstable": unstable, "vtk": vtk,
            "csm stable +1e6": stable}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(os.getcwd(), "csm_flicker"))
    ap.add_argument("--frames", type=int, default=24)
    ap.add_argument("--max-flicker-pct", type=float, default=0.05)
    ap.add_argument("--max-flicker-pct-all", type=float, default=0.3)
    ap.add_argument("--only", choices=["stable", "offset"],
                    help="only Stable csm at the origin (and the comparisons), or only +1e6")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    techs = techniques()
    if args.only == "stable":
        names = ["csm stable", "csm unstable", "vtk"]
    elif args.only == "offset":
        names = ["csm stable +1e6"]
    else:
        names = list(techs)
    asserted = {"csm stable", "csm stable +1e6"}

    states = {n: [] for n in names}
    states_b = {n: [] for n in names}
    masks, masks_b, wrong = {}, {}, {n: [] for n in names}
    shadow_px = []
    for k in range(args.frames):
        base = path_scene(k)
        variants = {}
        if any(not n.endswith("+1e6") for n in names):
            variants["origin"] = base
        if any(n.endswith("+1e6") for n in names):
            variants["offset"] = tp.moved(base, offset=1e6)
        for where, scene in variants.items():
            path = os.path.join(args.out, f"frame{k:02d}-{where}.json")
            with open(path, "w") as f:
                json.dump(scene, f, indent=1)
            trace = trace_scene(scene, 0, SIZE[0], SIZE[1], "all")
            ref, valid = trace["visibility"], trace["valid"]
            compared = valid & ~tp.exclude_band(trace)
            compared_b = compared & ~shadow_band(ref, valid)
            masks.setdefault(where, []).append(compared)
            masks_b.setdefault(where, []).append(compared_b)
            if where == "origin":
                shadow_px.append(int(np.sum(compared & (ref < 0.5))))
            for n in names:
                if (where == "offset") != n.endswith("+1e6"):
                    continue
                v = visibility(path, techs[n])
                err = np.abs(v - ref) > 0.5
                states[n].append(err & compared)
                states_b[n].append(err & compared_b)
                wrong[n].append(100.0 * np.sum(err & compared) / max(int(compared.sum()), 1))

    failed = False
    if shadow_px:
        print(f"exact shadow px per frame: min {min(shadow_px)} max {max(shadow_px)}")
        if min(shadow_px) < 2000:
            print("FAIL: the path must keep >= 2000 exact shadow px in every frame")
            failed = True
    for n in names:
        where = "offset" if n.endswith("+1e6") else "origin"
        f, pairs = flicker_pct(states[n], masks[where])
        fb, _ = flicker_pct(states_b[n], masks_b[where])
        line = (f"{n}: flicker_pct {f:.4f} (max pair {max(pairs):.4f})  with the shadow-boundary "
                f"band excluded {fb:.4f}  wrong_pct mean {np.mean(wrong[n]):.4f} max "
                f"{np.max(wrong[n]):.4f}  frames {args.frames}")
        if n in asserted:
            ok = fb <= args.max_flicker_pct and f <= args.max_flicker_pct_all
            line += (f"  (bounds: banded <= {args.max_flicker_pct}, all <= "
                     f"{args.max_flicker_pct_all}: {'ok' if ok else 'FAIL'})")
            failed |= not ok
        print(line)
    print(f"time {time.time() - start:.1f} s")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
