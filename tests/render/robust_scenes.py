"""Scene pieces of the robustness suite (test_robust.py): hand-built VTK
scenes of white Lambertian actors (float_render.py) lit by one directional
light, and the variants real applications build (composite and glyph mappers,
user matrices, an overlay layer, translucent and unlit actors).

Row 0 of every image here is the TOP row.
"""
import numpy as np
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkMinimalStandardRandomSequence, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import (vtkConeSource, vtkCubeSource, vtkPlaneSource,
                                          vtkSphereSource)
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import float_render as fr

# Hand-built scenes render at this size (the scene-file cases at their own).
W, H = 480, 360

LIGHT = (3.0, 2.0, 6.0)             # directional, from here towards the origin
CAMERA = dict(position=(0.0, -9.0, 6.0), focal_point=(0.0, 0.0, 0.5))
SPHERES = [((-1.3, 0.2, 1.0), 0.5), ((0.1, 0.5, 1.5), 0.45), ((1.3, -0.3, 0.9), 0.4)]


def poly_actor(poly):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    actor = vtkActor()
    actor.SetMapper(mapper)
    return fr.lambertian(actor)


def sphere_poly(center, radius, res=48):
    s = vtkSphereSource()
    s.SetCenter(*center)
    s.SetRadius(radius)
    s.SetThetaResolution(res)
    s.SetPhiResolution(res)
    s.Update()
    return s.GetOutput()


def floor_poly(half=6.0, z=0.0):
    p = vtkPlaneSource()
    p.SetOrigin(-half, -half, z)
    p.SetPoint1(half, -half, z)
    p.SetPoint2(-half, half, z)
    p.Update()
    return p.GetOutput()


def add_floor(renderer, receiver=True, poly=None):
    floor = poly_actor(poly if poly is not None else floor_poly())
    if receiver:
        fr.mark_receiver(floor)
    renderer.AddActor(floor)
    return floor


def base(renderer, light=LIGHT, camera=CAMERA, positional=False):
    renderer.AddLight(fr.scene_light(light, positional=positional))
    fr.set_camera(renderer, **camera)


def coverage(build, width=W, height=H):
    """Pixels covered by the actors build(renderer) adds (lit by a headlight
    and fully ambient, so every covered pixel is bright)."""
    def covered(renderer):
        extra = build(renderer) or {}
        actors = renderer.GetActors()
        actors.InitTraversal()
        for _ in range(actors.GetNumberOfItems()):
            a = actors.GetNextActor()
            a.GetProperty().SetAmbient(1.0)
            a.GetProperty().SetOpacity(1.0)
            a.GetProperty().SetColor(1, 1, 1)
        return extra
    image, _ = fr.render_once(covered, width, height, False)
    return image > 1e-3


def dilate(mask, r=1):
    out = mask.copy()
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            out |= np.roll(np.roll(mask, dy, 0), dx, 1)
    return out


def glyph_input(n_side=22):
    rng = vtkMinimalStandardRandomSequence()
    rng.SetSeed(7)

    def rnd(lo, hi):
        rng.Next()
        return rng.GetRangeValue(lo, hi)
    points = vtkPoints()
    mag = vtkDoubleArray()
    mag.SetName("mag")
    direction = vtkDoubleArray()
    direction.SetName("dir")
    direction.SetNumberOfComponents(3)
    for i in range(n_side):
        for j in range(n_side):
            x = -2.6 + 5.2 * i / (n_side - 1)
            y = -2.0 + 4.0 * j / (n_side - 1)
            points.InsertNextPoint(x, y, rnd(0.9, 1.8))
            mag.InsertNextValue(rnd(0.0, 2.0))   # clamped to [0.4, 1.6] below
            d = (rnd(-1, 1), rnd(-1, 1), rnd(-1, 1))
            if i % 7 == 0:
                d = (-1.0, 0.0, 0.0)             # the special "flip x" branch
            direction.InsertNextTuple3(*d)
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.GetPointData().AddArray(mag)
    poly.GetPointData().AddArray(direction)
    return poly


def cone_source():
    cone = vtkConeSource()
    cone.SetResolution(12)
    cone.SetHeight(0.6)
    cone.SetRadius(0.18)
    return cone


GLYPH_RANGE = (0.4, 1.6)
GLYPH_SCALE = 0.9


def caster_poly():
    cube = vtkCubeSource()
    cube.SetXLength(1.2)
    cube.SetYLength(0.5)
    cube.SetZLength(0.8)
    cube.Update()
    return cube.GetOutput()


def user_matrix():
    t = vtkTransform()
    t.Translate(0.2, 0.4, 0.3)
    t.RotateWXYZ(33.0, 1.0, 2.0, 0.5)
    t.Scale(1.1, 0.9, 1.3)
    m = vtkMatrix4x4()
    m.DeepCopy(t.GetMatrix())
    return m


def transformed_actor(poly):
    actor = poly_actor(poly)
    actor.SetUserMatrix(user_matrix())
    actor.SetScale(1.5, 0.7, 1.2)
    actor.SetOrientation(20.0, 35.0, 10.0)
    actor.SetPosition(-0.4, -0.2, 1.3)
    actor.SetOrigin(0.1, 0.05, -0.1)
    return actor


def pretransformed(poly, actor):
    t = vtkTransform()
    t.SetMatrix(actor.GetMatrix())
    f = vtkTransformPolyDataFilter()
    f.SetInputData(poly)
    f.SetTransform(t)
    f.Update()
    return f.GetOutput()


def floor_tilt():
    t = vtkTransform()
    t.Translate(0.0, 0.0, -0.3)
    t.RotateX(12.0)
    t.RotateY(-8.0)
    m = vtkMatrix4x4()
    m.DeepCopy(t.GetMatrix())
    return m


VIEWPORT_CAMERAS = [
    dict(position=(0.0, -9.0, 6.0), focal_point=(0.0, 0.0, 0.5)),
    dict(position=(7.0, -5.0, 4.0), focal_point=(-0.3, 0.2, 0.4)),
]


def populate_spheres(renderer, camera):
    base(renderer, camera=camera)
    add_floor(renderer)
    for center, r in SPHERES:
        renderer.AddActor(poly_actor(sphere_poly(center, r)))


def overlay_renderer(window):
    over = fr.new_renderer(window, layer=1)
    quad = vtkPlaneSource()
    quad.SetOrigin(0, 0, 0)
    quad.SetPoint1(1, 0, 0)
    quad.SetPoint2(0, 1, 0)
    actor = poly_actor(_update(quad))
    actor.GetProperty().LightingOff()
    actor.GetProperty().SetColor(1.0, 0.2, 0.1)
    over.AddActor(actor)
    cam = over.GetActiveCamera()
    cam.ParallelProjectionOn()
    cam.SetPosition(0, 0, 10)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(0, 1, 0)
    cam.SetParallelScale(4.0)     # the unit quad covers a small patch
    cam.SetClippingRange(1, 20)
    return over


def _update(src):
    src.Update()
    return src.GetOutput()


def sphere_floor(renderer):
    base(renderer)
    add_floor(renderer)
    center, r = SPHERES[1]
    renderer.AddActor(poly_actor(sphere_poly(center, 0.7)))


def translucent_box():
    cube = vtkCubeSource()
    cube.SetCenter(2.6, 2.2, 0.6)
    cube.SetXLength(1.0)
    cube.SetYLength(1.0)
    cube.SetZLength(1.2)
    actor = poly_actor(_update(cube))
    actor.GetProperty().SetOpacity(0.4)
    return actor


def unlit_cube(lit):
    cube = vtkCubeSource()
    cube.SetCenter(-2.2, 1.0, 1.2)
    cube.SetXLength(0.8)
    cube.SetYLength(0.8)
    cube.SetZLength(0.8)
    actor = poly_actor(_update(cube))
    if not lit:
        actor.GetProperty().LightingOff()
    return actor


def unlit_plate(lit, receiver):
    plate = poly_actor(floor_poly(0.8, 0.0))
    plate.SetPosition(2.4, -1.6, 0.5)
    if not lit:
        plate.GetProperty().LightingOff()
    if receiver:
        fr.mark_receiver(plate)
    return plate
