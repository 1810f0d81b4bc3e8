"""Interleaved frame times of technique variants in ONE window (a stop-gap
until vtkshadow-render --stats and the benches interleave, issue 14 item 1).

  tests/gl-run.sh build/bin/vtkshadow-python bench/probe_interleaved.py \
      [--rounds 4] [--frames 15] [--warmup 3] [--size 800x600] SCENE \
      LABEL=TECHNIQUE[:key=value,...] ...

Every variant renders the same camera orbit as vtkshadow-render; variants
alternate in blocks inside the process, the order rotated each round. The
first variant is the reference: for each variant the script prints the
median frame time over all timed frames, and the median and spread
(min..max) over rounds of (variant round median / reference round median).
List the reference twice (e.g. none=none none2=none) to see the noise floor.
Besides wall-clock, it reports process CPU time per frame (every llvmpipe
thread), which a machine loaded by other jobs disturbs less.
"""
import argparse
import json
import math
import statistics
import sys
import time

import vtkshadow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow


def place_camera(renderer, scene, i, frames):
    camera = renderer.GetActiveCamera()
    scene.ConfigureCamera(camera)
    phase = 2.0 * math.pi * i / max(frames, 2)
    camera.Azimuth(5.0 * math.sin(phase))
    camera.Elevation(2.0 * math.cos(phase) - 2.0)
    camera.OrthogonalizeViewUp()
    vtkshadow.vtkShadowScene.ResetCameraClippingRange(renderer)


def parse_variant(text):
    label, _, spec = text.partition("=")
    name, _, opts = spec.partition(":")
    options = []
    for item in filter(None, opts.split(",")):
        k, _, v = item.partition("=")
        options.append((k, float(v)))
    return label, name, options


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("variants", nargs="+")
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--frames", type=int, default=15)
    ap.add_argument("--warmup", type=int, default=3)
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--json")
    a = ap.parse_args()
    w, h = (int(v) for v in a.size.split("x"))
    scene = vtkshadow.vtkShadowScene()
    if not scene.Load(a.scene):
        sys.exit(scene.GetErrorMessage())
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetSize(w, h)
    window.AddRenderer(renderer)
    scene.Populate(renderer)
    variants = []
    for text in a.variants:
        label, name, options = parse_variant(text)
        t = vtkshadow.vtkShadowTechnique()
        t.SetName(name)
        for k, v in options:
            if not t.SetOption(k, v):
                sys.exit(f"{label}: bad option {k}={v}")
        variants.append((label, t, t.CreatePass()))
    times = {label: [] for label, _, _ in variants}
    rounds = {label: [] for label, _, _ in variants}
    cpu = {label: [] for label, _, _ in variants}
    stats = {}
    for r in range(a.rounds):
        order = variants[r % len(variants):] + variants[:r % len(variants)]
        for label, t, p in order:
            renderer.SetPass(p)
            for i in range(a.warmup):
                place_camera(renderer, scene, i, a.frames)
                window.Render()
            window.WaitForCompletion()
            block = []
            c0 = time.process_time()
            for i in range(a.frames):
                place_camera(renderer, scene, i, a.frames)
                t0 = time.perf_counter()
                window.Render()
                window.WaitForCompletion()
                block.append(1e3 * (time.perf_counter() - t0))
            cpu[label].append(1e3 * (time.process_time() - c0) / a.frames)
            times[label] += block
            rounds[label].append(statistics.median(block))
            stats[label] = p.GetStatsJSON(renderer)
    ref = variants[0][0]
    out = {}
    print(f"# {a.scene} {a.size} rounds={a.rounds} frames={a.frames}")
    for label, _, _ in variants:
        ratios = [x / y for x, y in zip(rounds[label], rounds[ref])]
        cratios = [x / y for x, y in zip(cpu[label], cpu[ref])]
        out[label] = {"ms": statistics.median(times[label]), "ratio": statistics.median(ratios),
                      "ratio_min": min(ratios), "ratio_max": max(ratios),
                      "cpu_ms": statistics.median(cpu[label]),
                      "cpu_ratio": statistics.median(cratios), "cpu_ratio_min": min(cratios),
                      "cpu_ratio_max": max(cratios), "stats": stats[label]}
        print(f"{label:>10} wall {out[label]['ms']:7.1f} ms ratio {out[label]['ratio']:.3f} "
              f"({min(ratios):.2f}..{max(ratios):.2f})  cpu {out[label]['cpu_ms']:7.1f} ms "
              f"ratio {out[label]['cpu_ratio']:.3f} ({min(cratios):.2f}..{max(cratios):.2f})")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)
    for _, _, p in variants:
        p.ReleaseGraphicsResources(window)


if __name__ == "__main__":
    main()
