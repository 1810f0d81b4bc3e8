"""The cost of a vtkVolume's shadow under csm and volume (the opacity shadow
map, docs/cascaded-shadow-maps.md, "Volumes"): frame time at 800x600 of
test_volume_casters.py's scene (floor, directional light straight down, a
20^3 volume of opacity 0.06 at unit 0.1) with the volume shown and hidden,
under the technique and under `none`, the camera orbiting a degree a frame
(so each frame renders again while the map is reused), and the map's own
computation (the stats' volume_map_ms, once per change of the volumes or
the light).

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_volume_map.py [csm volume]

Prints, per technique, the mean frame time of each configuration over
--frames frames after --warmup frames, interleaved --rounds times."""
import argparse
import json
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "python"))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "render"))

import float_render as fr  # noqa: E402
import translucent_scene as ts  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkVolume,  # noqa: E402
                                         vtkVolumeProperty)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper  # noqa: E402


def make_volume(points=20, spacing=0.1, alpha=0.06, unit=0.1):
    """test_volume_casters.py's volume: a box of constant scalar centred
    HEIGHT above the floor."""
    data = vtkImageData()
    data.SetDimensions(points, points, points)
    data.SetSpacing(spacing, spacing, spacing)
    half = 0.5 * (points - 1) * spacing
    data.SetOrigin(-half, -half, ts.HEIGHT - half)
    scalars = vtkFloatArray()
    scalars.SetNumberOfTuples(points ** 3)
    scalars.Fill(0.5)
    data.GetPointData().SetScalars(scalars)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, alpha)
    opacity.AddPoint(1.0, alpha)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0.0, 0.8, 0.5, 0.2)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetScalarOpacityUnitDistance(unit)
    mapper = vtkSmartVolumeMapper()
    mapper.SetInputData(data)
    v = vtkVolume()
    v.SetMapper(mapper)
    v.SetProperty(prop)
    return v


def timed(window, renderer, frames):
    """Mean seconds per frame over `frames` renders, orbiting a degree each."""
    start = time.perf_counter()
    for _ in range(frames):
        renderer.GetActiveCamera().Azimuth(1.0)
        window.Render()
    return (time.perf_counter() - start) / frames


def setup(technique, width, height):
    """(window, renderer, volume, pass or None) of the scene under
    `technique` ('none': no shadow pass)."""
    window = fr.new_window(width, height)
    renderer = fr.new_renderer(window)
    ts.caster_scene([])(renderer)
    volume = make_volume()
    renderer.AddVolume(volume)
    inner = None
    if technique != "none":
        inner = vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique)
        renderer.SetPass(inner)
    return window, renderer, volume, inner


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("techniques", nargs="*", default=["csm", "volume"])
    parser.add_argument("--size", default="800x600")
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--warmup", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    for technique in args.techniques:
        configs = {name: setup(name, width, height) for name in (technique, "none")}
        times = {}
        for name, (window, renderer, volume, _) in configs.items():
            for shown in (True, False):
                volume.SetVisibility(shown)
                timed(window, renderer, args.warmup)
                times[(name, shown)] = []
        for _ in range(args.rounds):
            for (name, shown), samples in times.items():
                window, renderer, volume, _ = configs[name]
                volume.SetVisibility(shown)
                samples.append(timed(window, renderer, args.frames))
        inner = configs[technique][3]
        stats = json.loads("{" + inner.GetStatsJSON(configs[technique][1]) + "}")
        print(f"{technique} at {width}x{height}, {args.rounds} x {args.frames} frames "
              f"(median of the rounds' means, ms/frame):")
        for (name, shown), samples in times.items():
            ms = 1000.0 * sorted(samples)[len(samples) // 2]
            print(f"  {name:8s} volume {'shown ' if shown else 'hidden'} {ms:8.1f}")
        print(f"  map: computed {stats.get('volume_maps_computed')} times, last "
              f"{stats.get('volume_map_ms', 0):.1f} ms ({stats.get('volume_map_samples')} "
              f"samples)")
        for window, _, _, _ in configs.values():
            window.Finalize()


if __name__ == "__main__":
    main()
