"""Shadows across MPI ranks in pvbatch: the floor lives on rank 0, the sphere
that shadows it on the last rank, and the composited image must equal the
one-rank image.

    vtkshadow-pvbatch test_pv_ranks.py SCENE OUTDIR render TECHNIQUE [LAYOUT]
        renders the scene split over the ranks, writes OUTDIR/<ranks>-<technique>.png
        and OUTDIR/<ranks>-<technique>.json (the view's ShadowStatus);
        LAYOUT (the file names get -LAYOUT) puts, instead of the default split:
          empty      floor and sphere on rank 0, nothing on the last rank;
          offscreen  floor and sphere on rank 0, and on the last rank only a
                     sphere behind the camera (nothing of it on screen, its
                     shadow off the floor).
        A rank with nothing on screen must still join every reduction, or
        the ranks deadlock (run_ranks.sh runs these under a timeout);
    python3 test_pv_ranks.py compare REFERENCE.png IMAGE.png NONE.png SHADOW_PIXEL
        (run by the same pvbatch) checks IMAGE against REFERENCE: at most 0.1%
        of the pixels wrong outside a one-pixel band (a pixel is wrong when no
        reference pixel in its 3x3 neighbourhood is within 24 of it), and
        the shadow present (the shadow pixel darker than in NONE).
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def render(scene_path, out, technique, layout="split"):
    from paraview.simple import (CreateView, ProgrammableSource, Render, SaveScreenshot,
                                 Show)
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    import pv_scene

    ranks = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
    scene = pv_scene.load(scene_path)
    sphere = next(o["sphere"] for o in scene["objects"] if "sphere" in o)
    plane = next(o["plane"] for o in scene["objects"] if "plane" in o)
    view = CreateView("RenderViewWithShadows")
    view.ViewSize = [480, 360]
    # Every rank runs the source's script: rank 0 makes the floor, the last
    # rank the sphere (one rank: both); see LAYOUT above.
    if layout not in ("split", "empty", "offscreen"):
        sys.exit("test_pv_ranks.py: unknown layout %r (split, empty, offscreen)" % layout)
    cam = scene["camera"]["position"]
    behind = [cam[0], cam[1] - 6.0, cam[2]]  # the camera looks towards +y
    script = """
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkPlaneSource
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
c = vtkMultiProcessController.GetGlobalController()
rank, last = c.GetLocalProcessId(), c.GetNumberOfProcesses() - 1
layout = %r
parts = vtkAppendPolyData()
def sphere(center, radius):
    s = vtkSphereSource(); s.SetCenter(center); s.SetRadius(radius)
    s.SetThetaResolution(96); s.SetPhiResolution(96)
    parts.AddInputConnection(s.GetOutputPort())
if rank == 0:
    p = vtkPlaneSource(); p.SetOrigin(%r); p.SetPoint1(%r); p.SetPoint2(%r)
    parts.AddInputConnection(p.GetOutputPort())
if (rank == last) if layout == "split" else (rank == 0):
    sphere(%r, %r)
if layout == "offscreen" and rank == last:
    sphere(%r, 0.5)
if parts.GetNumberOfInputConnections(0):
    parts.Update()
    self.GetPolyDataOutput().ShallowCopy(parts.GetOutput())
""" % (layout, plane["origin"], plane["point1"], plane["point2"], sphere["center"],
       sphere["radius"], behind)
    source = ProgrammableSource(OutputDataSetType="vtkPolyData", Script=script)
    display = Show(source, view)
    display.AmbientColor = display.DiffuseColor = [0.9, 0.9, 0.9]
    scene_no_objects = dict(scene, objects=[])
    pv_scene.populate(view, scene_no_objects)
    view.ShadowTechnique = technique
    Render(view)
    if layout == "offscreen":
        # ParaView fits the camera to all the data on the first render: put
        # the scene's camera back so that the extra sphere is off screen.
        cam = scene["camera"]
        view.CameraPosition = cam["position"]
        view.CameraFocalPoint = cam["focal_point"]
        view.CameraViewUp = cam["view_up"]
    Render(view)
    name = "%d-%s" % (ranks, technique) + ("" if layout == "split" else "-" + layout)
    png = os.path.join(out, name + ".png")
    SaveScreenshot(png, view, ImageResolution=view.ViewSize)
    view.UpdatePropertyInformation()
    pixel = pv_scene.to_pixel(view, pv_scene.shadow_point(scene, sphere["center"]))
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump({"status": json.loads(view.GetProperty("ShadowStatus")[0]), "shadow_pixel": pixel}, f)
    print("%s: %s, shadow pixel %s" % (png, view.GetProperty("ShadowStatus")[0], pixel))


def read_rgb(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    a = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return a.astype(int)[::-1]


def compare(reference, image, none, pixel):
    import numpy as np
    import pv_scene
    ref, img = read_rgb(reference), read_rgb(image)
    if ref.shape != img.shape:
        sys.exit("%s is %s, %s is %s" % (image, img.shape, reference, ref.shape))
    h, w, _ = ref.shape
    padded = np.pad(ref, ((1, 1), (1, 1), (0, 0)), mode="edge")
    near = np.zeros((h, w), dtype=bool)
    for dy in range(3):
        for dx in range(3):
            diff = np.abs(padded[dy:dy + h, dx:dx + w] - img).max(axis=2)
            near |= diff <= 24
    wrong = 100.0 * (~near).sum() / near.size
    s_img = pv_scene.luminance(image, pixel)
    s_none = pv_scene.luminance(none, pixel)
    print("%s vs %s: %.3f%% wrong outside a one-pixel band; shadow pixel %.1f (none %.1f)" % (
        image, reference, wrong, s_img, s_none))
    ok = wrong <= 0.1 and s_img <= 0.6 * s_none
    if not ok:
        sys.exit("FAILED: %s" % image)


if __name__ == "__main__":
    if sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3], sys.argv[4], json.loads(sys.argv[5]))
    else:
        os.makedirs(sys.argv[2], exist_ok=True)
        render(sys.argv[1], sys.argv[2], sys.argv[4], *sys.argv[5:6])
