"""What points drawn as spheres cost each technique (docs/enable-shadows.md,
"Points as spheres, lines as tubes"): COUNT random points (default 20000,
seed 1) drawn with RenderPointsAsSpheres, point size 4, over a floor, a
directional light straight down, 400x300. raytrace casts Embree spheres;
csm, planar and volume cast triangle proxies that are rebuilt whenever the
camera moves (their radius is a pixel width). Per technique: the median
time of Render after the camera turned 2 degrees (FRAMES frames), and of
Render with nothing changed. One process per technique, one after the
other: on a shared machine the times are only as steady as its load.

Usage: xvfb-run -a build/bin/vtkshadow-python bench/bench_impostors.py [COUNT]"""
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "render"))

FRAMES = 5
TECHNIQUES = ("none", "raytrace", "csm", "planar", "volume")


def cloud(count):
    """COUNT points as verts cells."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    xyz = np.random.default_rng(1).uniform([-3, -3, 0.5], [3, 3, 2], (count, 3))
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    cells = vtkCellArray()
    ids = np.arange(count, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(np.arange(count + 1, dtype=np.int64), deep=True),
                  numpy_to_vtkIdTypeArray(ids, deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetVerts(cells)
    return data


def run_one(technique, count):
    """(median moving-camera frame, still frame) in seconds."""
    import float_render as fr
    import vtkshadow
    from vtkmodules.vtkFiltersSources import vtkPlaneSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    window = fr.new_window(400, 300)
    renderer = fr.new_renderer(window)
    floor = vtkPlaneSource()
    floor.SetOrigin(-6, -6, 0)
    floor.SetPoint1(6, -6, 0)
    floor.SetPoint2(-6, 6, 0)
    floor.Update()
    actors = []
    for data in (floor.GetOutput(), cloud(count)):
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(data)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
        actors.append(actor)
    actors[1].GetProperty().SetRenderPointsAsSpheres(True)
    actors[1].GetProperty().SetPointSize(4)
    renderer.AddLight(fr.scene_light((0.0, 0.0, 10.0), (0.0, 0.0, 0.0)))
    fr.set_camera(renderer, (7.0, -7.0, 6.0), (0, 0, 0.6), view_angle=30, clipping=(1.0, 40.0))
    renderer.SetPass(vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique))
    window.Render()
    moving = []
    for _ in range(FRAMES):
        renderer.GetActiveCamera().Azimuth(2)
        start = time.perf_counter()
        window.Render()
        moving.append(time.perf_counter() - start)
    start = time.perf_counter()
    window.Render()
    still = time.perf_counter() - start
    window.Finalize()
    return statistics.median(moving), still


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--one":
        print("%.4f %.4f" % run_one(sys.argv[2], int(sys.argv[3])))
        sys.exit(0)
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    print(f"{count} points as spheres (size 4), 400x300; seconds per Render")
    print("technique  camera moving  still")
    for name in TECHNIQUES:
        out = subprocess.run([sys.executable, __file__, "--one", name, str(count)],
                             capture_output=True, text=True, check=True).stdout.split()
        print(f"{name:10} {float(out[-2]):13.3f}  {float(out[-1]):.3f}")
