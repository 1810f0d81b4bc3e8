"""Generate the mesh files of the scene library (run with build/bin/vtkshadow-python).

    build/bin/vtkshadow-python scenes/meshes/make_meshes.py [OUTDIR]

Deterministic (no random numbers); each output stays well under 2 MB (binary
PLY, float32 coordinates). The outputs are committed next to this script.
"""
import math
import os
import sys

from vtkmodules.vtkCommonCore import vtkPoints, vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkImageData, vtkCellArray
from vtkmodules.vtkFiltersCore import (vtkContourFilter, vtkTriangleFilter, vtkGlyph3D,
                                       vtkCleanPolyData, vtkAppendPolyData, vtkPolyDataNormals)
from vtkmodules.vtkFiltersFlowPaths import vtkStreamTracer
from vtkmodules.vtkFiltersGeneral import vtkWarpScalar
from vtkmodules.vtkFiltersSources import (vtkArrowSource, vtkConeSource, vtkPlaneSource, vtkPointSource,
                                          vtkLineSource, vtkSphereSource)
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkCommonDataModel import vtkImplicitBoolean, vtkSphere
from vtkmodules.vtkImagingHybrid import vtkSampleFunction
from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOPLY import vtkPLYWriter

out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))


def triangles(poly):
    tri = vtkTriangleFilter()
    tri.SetInputData(poly)
    tri.PassLinesOff()
    tri.PassVertsOff()
    clean = vtkCleanPolyData()
    clean.SetInputConnection(tri.GetOutputPort())
    clean.Update()
    result = vtkPolyData()
    result.SetPoints(clean.GetOutput().GetPoints())
    result.SetPolys(clean.GetOutput().GetPolys())
    return result


def write(name, poly):
    poly = triangles(poly)
    path = os.path.join(out, name)
    w = vtkPLYWriter()
    w.SetFileName(path + ".tmp.ply")
    w.SetFileTypeToBinary()
    w.SetInputData(poly)
    if not w.Write():
        raise SystemExit("cannot write " + path)
    os.replace(path + ".tmp.ply", path)
    print("%s: %d triangles, %d bytes" % (path, poly.GetNumberOfPolys(), os.path.getsize(path)))


# 1. Isosurface of vtkRTAnalyticSource (the "Wavelet"), scaled to about 2 units.
src = vtkRTAnalyticSource()
src.SetWholeExtent(-20, 20, -20, 20, -20, 20)
src.SetCenter(0, 0, 0)
contour = vtkContourFilter()
contour.SetInputConnection(src.GetOutputPort())
contour.SetValue(0, 160.0)
contour.ComputeNormalsOff()
contour.Update()
iso = contour.GetOutput()
pts = iso.GetPoints()
for i in range(pts.GetNumberOfPoints()):
    x, y, z = pts.GetPoint(i)
    pts.SetPoint(i, x / 20.0, y / 20.0, z / 20.0 + 1.2)
write("isosurface.ply", iso)

# 2. Streamline tubes of a swirling analytic field (a vortex with updraft).
img = vtkImageData()
img.SetDimensions(21, 21, 11)
img.SetOrigin(-2, -2, 0)
img.SetSpacing(0.2, 0.2, 0.2)
vec = vtkFloatArray()
vec.SetNumberOfComponents(3)
vec.SetName("v")
for k in range(11):
    for j in range(21):
        for i in range(21):
            x, y, z = -2 + 0.2 * i, -2 + 0.2 * j, 0.2 * k
            vec.InsertNextTuple3(-y + 0.1 * x, x + 0.1 * y, 0.25)
img.GetPointData().SetVectors(vec)
seeds = vtkLineSource()
seeds.SetPoint1(0.3, 0, 0.2)
seeds.SetPoint2(1.6, 0, 0.2)
seeds.SetResolution(7)
tracer = vtkStreamTracer()
tracer.SetInputData(img)
tracer.SetSourceConnection(seeds.GetOutputPort())
tracer.SetMaximumPropagation(12)
tracer.SetIntegrationDirectionToForward()
tracer.SetIntegratorTypeToRungeKutta4()
tube = vtkTubeFilter()
tube.SetInputConnection(tracer.GetOutputPort())
tube.SetRadius(0.04)
tube.SetNumberOfSides(10)
tube.CappingOn()
tube.Update()
write("streamtubes.ply", tube.GetOutput())

# 3. 1,331 arrow glyphs of a rotational field on an 11x11x11 lattice.
lattice = vtkPolyData()
lp = vtkPoints()
dirs = vtkFloatArray()
dirs.SetNumberOfComponents(3)
dirs.SetName("dir")
for k in range(11):
    for j in range(11):
        for i in range(11):
            x, y, z = -1.5 + 0.3 * i, -1.5 + 0.3 * j, 0.3 + 0.25 * k
            lp.InsertNextPoint(x, y, z)
            dirs.InsertNextTuple3(-y, x, 0.5 * math.sin(z * 2.0))
lattice.SetPoints(lp)
lattice.GetPointData().SetVectors(dirs)
arrow = vtkArrowSource()
arrow.SetTipResolution(6)
arrow.SetShaftResolution(6)
glyph = vtkGlyph3D()
glyph.SetInputData(lattice)
glyph.SetSourceConnection(arrow.GetOutputPort())
glyph.SetVectorModeToUseVector()
glyph.SetScaleModeToDataScalingOff()
glyph.SetScaleFactor(0.22)
glyph.OrientOn()
glyph.Update()
write("arrow-glyphs.ply", glyph.GetOutput())

# 4. Elevation surface: z = f(x, y) on a 120x120 grid.
plane = vtkPlaneSource()
plane.SetOrigin(-3, -3, 0)
plane.SetPoint1(3, -3, 0)
plane.SetPoint2(-3, 3, 0)
plane.SetResolution(119, 119)
plane.Update()
surf = plane.GetOutput()
sp = surf.GetPoints()
for i in range(sp.GetNumberOfPoints()):
    x, y, _ = sp.GetPoint(i)
    z = (0.9 * math.exp(-((x - 0.8) ** 2 + (y - 0.5) ** 2) / 0.6)
         + 0.6 * math.exp(-((x + 1.2) ** 2 + (y + 0.9) ** 2) / 0.3)
         + 0.15 * math.sin(2.0 * x) * math.cos(1.5 * y))
    sp.SetPoint(i, x, y, z)
write("elevation.ply", surf)

# 5. 7x7 cone glyphs tilted in a swirl, standing on the floor (bases at z ~ 0.15).
lattice = vtkPolyData()
lp = vtkPoints()
dirs = vtkFloatArray()
dirs.SetNumberOfComponents(3)
dirs.SetName("dir")
for j in range(7):
    for i in range(7):
        x, y = -1.5 + 0.5 * i, -1.5 + 0.5 * j
        lp.InsertNextPoint(x, y, 0.35)
        dirs.InsertNextTuple3(-0.5 * y, 0.5 * x, 1.0)
lattice.SetPoints(lp)
lattice.GetPointData().SetVectors(dirs)
# Tapered closed casters: the cone tips are thinner than a shadow-map texel
# over part of their length (auto's taper term, docs/auto.md).
cone = vtkConeSource()
cone.SetResolution(24)
cone.SetHeight(1.0)
cone.SetRadius(0.25)
cone.CappingOn()
glyph = vtkGlyph3D()
glyph.SetInputData(lattice)
glyph.SetSourceConnection(cone.GetOutputPort())
glyph.SetVectorModeToUseVector()
glyph.SetScaleModeToDataScalingOff()
glyph.SetScaleFactor(0.5)
glyph.OrientOn()
glyph.Update()
write("cone-glyphs.ply", glyph.GetOutput())

# 6. Tube around a helix (3 turns, radius 1, pitch 0.6), 20 sides, capped.
# A coarse (20-sided) closed tube: its terminator strip of facets facing away
# from a light is several pixels wide (docs/shadow-volumes.md, The terminator).
hp = vtkPoints()
lines = vtkCellArray()
m = 360
lines.InsertNextCell(m + 1)
for i in range(m + 1):
    t = 3 * 2 * math.pi * i / m
    hp.InsertNextPoint(math.cos(t), math.sin(t), 0.35 + 0.6 * t / (2 * math.pi))
    lines.InsertCellPoint(i)
hel = vtkPolyData()
hel.SetPoints(hp)
hel.SetLines(lines)
tube = vtkTubeFilter()
tube.SetInputData(hel)
tube.SetRadius(0.12)
tube.SetNumberOfSides(20)
tube.CappingOn()
tube.Update()
write("helix-tube.ply", tube.GetOutput())

# 7. Open casters: a bowl (a sphere cut 20 degrees above its equator, tilted)
# and blobs (an isosurface of four spheres' union cut by the sampling box at
# the bottom). The camera sees into the bowl: faces seen from the side
# turned away from the light (docs/shadow-volumes.md, z-fail for casters
# that are not closed).
bowl_src = vtkSphereSource()
bowl_src.SetThetaResolution(40)
bowl_src.SetPhiResolution(40)
bowl_src.SetStartPhi(70)
bowl_src.SetEndPhi(180)
bowl_src.SetRadius(0.9)
bowl_move = vtkTransform()
bowl_move.Translate(-0.6, 0.3, 1.1)
bowl_move.RotateX(25)
bowl_tf = vtkTransformPolyDataFilter()
bowl_tf.SetTransform(bowl_move)
bowl_tf.SetInputConnection(bowl_src.GetOutputPort())
bowl_tf.Update()
write("open-bowl.ply", bowl_tf.GetOutput())

union = vtkImplicitBoolean()
union.SetOperationTypeToUnion()
for centre in ((0, 0, 0), (0.7, 0.2, 0.3), (-0.5, 0.6, -0.2), (0.2, -0.7, 0.4)):
    ball = vtkSphere()
    ball.SetCenter(*centre)
    ball.SetRadius(0.55)
    union.AddFunction(ball)
field = vtkSampleFunction()
field.SetImplicitFunction(union)
field.SetModelBounds(-1.2, 1.2, -1.2, 1.2, -0.4, 1.2)
field.SetSampleDimensions(48, 48, 40)
blobs = vtkContourFilter()
blobs.SetInputConnection(field.GetOutputPort())
blobs.SetValue(0, 0.0)
blobs_move = vtkTransform()
blobs_move.Translate(0.9, -0.3, 1.0)
blobs_tf = vtkTransformPolyDataFilter()
blobs_tf.SetTransform(blobs_move)
blobs_tf.SetInputConnection(blobs.GetOutputPort())
blobs_tf.Update()
write("open-blobs.ply", blobs_tf.GetOutput())
