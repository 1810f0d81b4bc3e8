"""Shadow volumes on meshes from live pipelines (issue 29): techniques whose
hooks draw the depth pre-pass (volume, and csm's screen resolve) must draw
every caster into it, also those whose mappers bind buffer textures (cell
normals, flat shading, cell scalars: vtkBooleanOperationPolyDataFilter and
isosurface output, a lego surface coloured by cells), which VTK's mappers
get through their input connection.

What it catches: screen-mask samplers with no texture unit of their own in
the pre-pass share one with the mapper's samplerBuffer; then the draw
fails (GL_INVALID_OPERATION), the caster is missing from the depth, and
volume draws false shadows and darkens lit surfaces: 5.9 % (boolean),
6.5 % (isosurface, auto too: it picks volume) and 26.6 % (lego) of the
valid pixels differ from raytrace, csm screen from forward 5.8 % (lego).

Per mesh, visibility (float renders, tests/render/float_render.py) of
volume and auto at max_error 0 (which then picks an exact technique)
against raytrace, and csm with resolve=screen against csm forward: at most
1 % of the valid pixels may disagree (|v_a - v_b| > 0.5). A mesh drawn as a
wireframe shows only its lines: raytrace, volume and auto cast no shadow of
its triangles (vtkshadow::CastsAsSurface; before, they drew the solid
shadow of a surface nothing on screen shows: 1,000+ px here), and agree.

Usage: test_volume_live_pipeline.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "render"))

import vtkshadow  # noqa: E402
import float_render as fr  # noqa: E402
import robust_scenes  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData  # noqa: E402
from vtkmodules.vtkFiltersCore import (vtkContourFilter, vtkPointDataToCellData,  # noqa: E402
                                       vtkPolyDataNormals, vtkThreshold)
from vtkmodules.vtkFiltersGeneral import vtkBooleanOperationPolyDataFilter  # noqa: E402
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402

import numpy as np  # noqa: E402

W, H = 400, 300
MAX_PCT = 1.0


def two_spheres(operation, resolution):
    """Two overlapping spheres through vtkBooleanOperationPolyDataFilter."""
    op = vtkBooleanOperationPolyDataFilter()
    op.SetOperation(operation)
    for port, x in ((0, -0.35), (1, 0.35)):
        sphere = vtkSphereSource()
        sphere.SetCenter(x, 0, 1.2)
        sphere.SetRadius(0.8)
        sphere.SetThetaResolution(resolution)
        sphere.SetPhiResolution(resolution)
        op.SetInputConnection(port, sphere.GetOutputPort())
    return op


def boolean():
    """Two spheres intersected, cell normals added, flat shading (vedo's
    boolean example)."""
    op = two_spheres(vtkBooleanOperationPolyDataFilter.VTK_INTERSECTION, 40)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(op.GetOutputPort())
    normals.ComputeCellNormalsOn()
    return normals, {"flat": True}


def wireframe():
    """The two spheres' union drawn as a wireframe (vedo's boolean example,
    "plus"): volumes are not exact for it (lines leave no surface between
    them), so auto must not pick volume."""
    return two_spheres(vtkBooleanOperationPolyDataFilter.VTK_UNION, 24), {"wireframe": True}


def isosurface():
    """The wavelet's isosurface with cell normals only."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 180)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(contour.GetOutputPort())
    normals.ComputePointNormalsOff()
    normals.ComputeCellNormalsOn()
    return normals, {"scale": 0.06, "z": 1.2}


def lego():
    """Voxels of a distance field between two values, as a surface coloured
    by cell scalars (vedo's legosurface in numpy2volume1)."""
    n = 24
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(-1.2, -1.2, 0.2)
    image.SetSpacing(2.4 / (n - 1), 2.4 / (n - 1), 2.4 / (n - 1))
    x, y, z = np.mgrid[:n, :n, :n]
    c = (n - 1) / 2.0
    field = (((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2) / c ** 2).ravel(order="F")
    array = numpy_to_vtk(field.astype(np.float32), deep=1)
    array.SetName("distance")
    image.GetPointData().SetScalars(array)
    threshold = vtkThreshold()
    threshold.SetInputData(image)
    threshold.SetLowerThreshold(0.55)
    threshold.SetUpperThreshold(1.0)
    threshold.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "distance")
    surface = vtkGeometryFilter()
    surface.SetInputConnection(threshold.GetOutputPort())
    cells = vtkPointDataToCellData()
    cells.SetInputConnection(surface.GetOutputPort())
    return cells, {"flat": True, "cell_scalars": True}


def scene(mesh):
    source, options = mesh()

    def build(renderer):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        if options.get("cell_scalars"):
            mapper.SetScalarModeToUseCellData()
            mapper.SetScalarRange(0.55, 1.0)
        else:
            mapper.ScalarVisibilityOff()
        caster = fr.lambertian(vtkActor())
        caster.SetMapper(mapper)
        if options.get("flat"):
            caster.GetProperty().SetInterpolationToFlat()
        if options.get("wireframe"):
            caster.GetProperty().SetRepresentationToWireframe()
        if "scale" in options:
            caster.SetScale(options["scale"])
            caster.SetPosition(0, 0, options["z"])
        renderer.AddActor(caster)
        robust_scenes.add_floor(renderer, receiver=False, poly=robust_scenes.floor_poly(3.0))
        renderer.AddLight(fr.scene_light((1.5, -1.0, 3.0)))
        fr.set_camera(renderer, (2.5, -6.0, 4.5), (0, 0, 0.8), clipping=(1.0, 30.0))
    return build


def render(build, technique, options=None):
    """(float image, the pass's stats) of the scene under `technique`."""
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    build(renderer)
    if technique == "off":
        inner = vtkRenderStepsPass()
    else:
        t = vtkshadow.vtkShadowTechnique()
        t.SetName(technique)
        for key, value in (options or {}).items():
            t.SetOption(key, value)
        inner = t.CreatePass()
    capture = fr.FloatCapture(renderer, inner)
    window.Render()
    window.Render()
    image = capture.read()
    stats = inner.GetStatsJSON(renderer) if technique != "off" else ""
    capture.release()
    window.Finalize()
    return image, stats


for mesh in (boolean, isosurface, lego, wireframe):
    build = scene(mesh)
    off, _ = render(build, "off")
    vis, stats = {}, {}
    for label, technique, options in (("raytrace", "raytrace", None), ("volume", "volume", None),
                                      ("csm forward", "csm", {"resolve": 0}),
                                      ("csm screen", "csm", {"resolve": 1}),
                                      ("auto", "auto", {"max_error": 0})):
        image, stats[label] = render(build, technique, options)
        vis[label] = fr.visibility(image, off)
    shadowed = int(fr.shadowed(*vis["raytrace"]).sum())
    pairs = (("volume", "raytrace"), ("auto", "raytrace"), ("csm screen", "csm forward"))
    if mesh is wireframe:
        for label in ("raytrace", "volume", "auto"):
            n = int(fr.shadowed(*vis[label]).sum())
            check(n < 50, f"wireframe: {label} casts no shadow of its triangles ({n} px "
                  "shadowed, fewer than 50)")
    else:
        check(shadowed > 1000, f"{mesh.__name__}: raytrace shows a shadow ({shadowed} px)")
    for a, b in pairs:
        pct, n, missed = fr.compare_visibility(*vis[a], *vis[b])
        check(100.0 - pct <= MAX_PCT,
              f"{mesh.__name__}: {a} against {b}: {100.0 - pct:.3f} % of {n} px differ "
              f"(at most {MAX_PCT} %)")

finish()
