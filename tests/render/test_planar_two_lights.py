"""Render test: with two lights, each planar shadow removes that light's
contribution and nothing else.

Scene: test_planar.py's "two-lights" (a sphere over a receiver floor, light 0
directional, light 1 a point light; the two shadows overlap in part).

1. Visibility of each light (vtkshadow-render --technique planar --light 0|1)
   against the exact planar answer, exactly as test_planar.py does
   (wrong_pct <= 0.02 outside the one-pixel bands and wrong_of_shadow_pct <= 1,
   the floors of tests/render/render_bounds.cmake: planar measures 0; masks
   agree >= 99.9 %).
2. Colour: three float renders of white Lambertian surfaces (no ambient, no
   specular; vtkShadowScene.Populate(renderer, True, onlyLight)) through a
   vtkFramebufferPass with a Float32 colour target, read back as floats, the
   same way vtkShadowVisibility measures one light:
     I_both  both lights, the technique under test (planar);
     I_0     light 0 only, no shadows ("none");
     I_1     light 1 only, no shadows.
   On floor pixels (outside one-pixel bands along the exact shadow boundaries
   and object / mask edges) where the exact answer has
     - light 0 blocked, light 1 not:  |I_both - I_1| <= 1 % of I_1
     - light 1 blocked, light 0 not:  |I_both - I_0| <= 1 % of I_0
     - both blocked (the overlap):    I_both <= 1 % of (I_0 + I_1), i.e. darker
       than either single-light region (no diffuse light from either)
     - neither blocked:               |I_both - (I_0 + I_1)| <= 1 % (sanity)
   each on every such pixel (at most 0.05 % of them may miss, the same
   tolerance as wrong_pct).

  test_planar_two_lights.py --bin BUILD/bin --out DIR [--technique planar]

--technique none validates the measurement before planar exists: then the
shadow regions must hold I_both = I_0 + I_1 instead (the test says so and
checks that).
"""
import argparse
import os
import sys

import numpy as np
import vtkshadow
from vtkmodules.vtkCommonCore import VTK_FLOAT
from vtkmodules.vtkRenderingCore import vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import (vtkFramebufferPass, vtkOpenGLRenderer,
                                            vtkTextureObject)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_scene import edge_band  # noqa: E402
import test_planar  # noqa: E402

REL = 0.01          # "within 1 %"
MAX_MISS_PCT = 0.05  # share of region pixels allowed to miss


def render_float(scene_path, technique, only_light, width, height):
    """Summed RGB of a float render (H, W), row 0 at the top."""
    sc = vtkshadow.vtkShadowScene()
    if not sc.Load(scene_path):
        sys.exit(sc.GetErrorMessage())
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    renderer = vtkOpenGLRenderer()
    window.AddRenderer(renderer)
    if not sc.Populate(renderer, True, only_light):
        sys.exit("Populate failed")
    tech = vtkshadow.vtkShadowTechnique()
    tech.SetName(technique)
    if not tech.IsValid():
        sys.exit(f"unknown technique {technique!r} (known: "
                 f"{vtkshadow.vtkShadowTechnique.GetKnownTechniques()})")
    capture = vtkFramebufferPass()
    capture.SetColorFormat(vtkTextureObject.Float32)
    capture.SetDepthFormat(vtkTextureObject.Fixed32)
    capture.SetDelegatePass(tech.CreatePass())
    renderer.SetPass(capture)
    window.Render()
    tex = capture.GetColorTexture()
    if tex is None or tex.GetWidth() != width or tex.GetHeight() != height:
        sys.exit("no float colour texture to read back")
    window.MakeCurrent()
    pbo = tex.Download()
    rgba = np.zeros((height, width, 4), np.float32)
    if not pbo.Download2D(VTK_FLOAT, rgba, [width, height], 4, [0, 0]):
        sys.exit("could not download the float colour texture")
    capture.ReleaseGraphicsResources(window)
    renderer.SetPass(None)
    window.Finalize()
    return rgba[::-1, :, :3].astype(np.float64).sum(axis=2)


def check_region(label, sel, measured, expected, rel, failures):
    n = int(sel.sum())
    if n == 0:
        failures.append(f"{label}: empty region (scene geometry?)")
        return f"{label}: 0 px"
    err = np.abs(measured[sel] - expected[sel]) / np.maximum(expected[sel], 1e-12)
    miss = 100.0 * np.mean(err > rel)
    if miss > MAX_MISS_PCT:
        failures.append(f"{label}: {miss:.3f} % of {n} px off by more than {100 * rel:g} %")
    return f"{label}: {n} px, max rel err {err.max():.4f}, median {np.median(err):.5f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--technique", default="planar")
    args = ap.parse_args()
    case = "two-lights"
    scene = test_planar.CASES[case][0]()
    width, height = scene["size"]
    reference = "planar" if args.technique != "none" else "unshadowed"
    failed = False
    traces = []
    for light in (0, 1):
        f, trace, _ = test_planar.run_case(
            args.bin, args.out, case, scene, light, args.technique, reference,
            0.02, 99.9, test_planar.CASES[case][1], max_wrong_of_shadow_pct=1.0)
        failed |= f
        # The planar answer for the colour check, whatever the reference above.
        from exact_scene import trace_scene
        traces.append(trace_scene(scene, light, width, height, "planar"))

    scene_path = os.path.join(args.out, f"{case}.json")
    i_both = render_float(scene_path, args.technique, -1, width, height)
    i_0 = render_float(scene_path, "none", 0, width, height)
    i_1 = render_float(scene_path, "none", 1, width, height)
    np.savez_compressed(os.path.join(args.out, f"{case}-{args.technique}-float.npz"),
                        both=i_both, only0=i_0, only1=i_1)

    t0, t1 = traces
    floor = t0["receiver"]
    band = (test_planar.exclude_band(t0) | test_planar.exclude_band(t1)
            | edge_band(t0["blocked"].astype(int)) | edge_band(t1["blocked"].astype(int)))
    # Both lights reach the surface (valid for both), away from every edge.
    base = floor & t0["valid"] & t1["valid"] & ~band
    b0, b1 = t0["blocked"], t1["blocked"]
    only_in_0 = base & b0 & ~b1   # light 0's shadow, lit by light 1
    only_in_1 = base & b1 & ~b0
    overlap = base & b0 & b1
    lit = base & ~b0 & ~b1
    failures = []
    total = i_0 + i_1
    figures = [check_region("lit by both", lit, i_both, total, REL, failures)]
    if args.technique == "none":
        # Validation mode: no shadows, so every region holds I_0 + I_1.
        figures += [check_region(f"{name} (unshadowed)", sel, i_both, total, REL, failures)
                    for name, sel in (("shadow 0", only_in_0), ("shadow 1", only_in_1),
                                      ("overlap", overlap))]
    else:
        figures.append(check_region("shadow of light 0 = light 1 alone", only_in_0, i_both, i_1,
                                    REL, failures))
        figures.append(check_region("shadow of light 1 = light 0 alone", only_in_1, i_both, i_0,
                                    REL, failures))
        n = int(overlap.sum())
        if n == 0:
            failures.append("overlap: empty region (scene geometry?)")
        else:
            ratio = i_both[overlap] / total[overlap]
            darker = (i_both[overlap] < np.minimum(i_0[overlap], i_1[overlap]))
            miss = 100.0 * np.mean((ratio > REL) | ~darker)
            figures.append(f"overlap: {n} px, max I_both/(I_0+I_1) {ratio.max():.4f}")
            if miss > MAX_MISS_PCT:
                failures.append(f"overlap: {miss:.3f} % of {n} px not dark "
                                f"(I_both > 1 % of I_0 + I_1 or not below either light alone)")
    print(f"{case}-{args.technique} colour: " + "; ".join(figures))
    for msg in failures:
        print("FAIL: " + msg)
    sys.exit(1 if failed or failures else 0)


if __name__ == "__main__":
    main()
