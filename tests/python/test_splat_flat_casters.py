"""Shadows of vtkPointGaussianMapper's splats and of plain points and lines
(issue 32; docs/enable-shadows.md, "Points, lines and splats"), in the scene
and with the measure of test_impostor_casters.py (an opaque floor, a light
straight down, an oblique camera, 400x300; the shadow area against a
control drawn by the same technique, 0.6-1.6x; none and NO_CAST cast
nothing; the pass's stats count the shapes):

(d) 20 splats, ScaleArray values s in [0.5, 1], ScaleFunction s -> s / 2,
    ScaleFactor 0.6 (radius 0.3 s, world units), Emissive (the default);
    5 of them with opacity 0.2 (OpacityArray): against sphere meshes of
    radius 0.3 s at the 15 others;
(e) plain points, point size 18: against the camera-facing squares 18
    pixels wide at each point's depth, built here from the camera's
    projection of the points (not the library's rule);
(f) the splats' mapper with ScaleFactor 0 (VTK draws points then), point
    size 18: the same squares;
(g) a plain polyline of 48 points, width 16: against bands 16 pixels wide
    across each segment's direction on screen (from its projected ends);
(h) what casts nothing: the polyline and the points one pixel wide (the
    shadow area is the floor's own), and a sphere with EdgeVisibility and
    line width 4 darkens no pixel of its surface beyond what it darkens
    without its edges (they do not shadow their own surface; the edges'
    own pixels are left out: each technique shades drawn lines its way);
(i) a sphere mesh drawn as points (size 8) or as a wireframe (width 3), and
    the splats alone, cast a shadow; auto's reason for the light is never
    "nothing casts shadows".

Usage: test_splat_flat_casters.py [raytrace|csm|auto|volume|planar]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import numpy as np  # noqa: E402
import float_render as fr  # noqa: E402
import test_impostor_casters as ic  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import (  # noqa: E402
    vtkCellArray, vtkPiecewiseFunction, vtkPolyData)
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkCamera  # noqa: E402
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPointGaussianMapper  # noqa: E402

TECHNIQUE = ic.TECHNIQUE
SPLAT_FACTOR = 0.6  # radius = SPLAT_FACTOR * ScaleFunction(s), the function s / 2
QUAD_TRIANGLES = 2


def splat_scales():
    return np.linspace(0.5, 1.0, len(ic.cloud()))


def splat_opaque():
    """Which splats have opacity 1 (the others 0.2: they cast nothing)."""
    return np.arange(len(ic.cloud())) % 4 != 3


def splat_radii():
    return SPLAT_FACTOR * splat_scales() / 2.0


def splats(scale_factor=SPLAT_FACTOR, point_size=1.0):
    """The cloud as a vtkPointGaussianMapper's splats (verts)."""
    def build(renderer):
        data = ic.poly_data(ic.cloud(), "verts")
        for name, values in (("scale", splat_scales()),
                             ("opacity", np.where(splat_opaque(), 1.0, 0.2))):
            array = vtkFloatArray()
            array.SetName(name)
            for v in values:
                array.InsertNextValue(v)
            data.GetPointData().AddArray(array)
        mapper = vtkOpenGLPointGaussianMapper()
        mapper.SetInputData(data)
        mapper.ScalarVisibilityOff()
        mapper.SetScaleArray("scale")
        function = vtkPiecewiseFunction()
        function.AddPoint(0.0, 0.0)
        function.AddPoint(2.0, 1.0)
        mapper.SetScaleFunction(function)
        mapper.SetScaleFactor(scale_factor)
        mapper.SetOpacityArray("opacity")
        actor = fr.lambertian(vtkActor())
        actor.SetMapper(mapper)
        actor.GetProperty().SetPointSize(point_size)
        renderer.AddActor(actor)
        return actor
    return build


def splat_spheres():
    """The control of (d): sphere meshes at the opaque splats."""
    return ic.sphere_meshes_of([(p, r) for p, r, keep in
                                zip(ic.cloud(), splat_radii(), splat_opaque()) if keep])


def plain(cell, size):
    """The cloud (cell 'verts') or the polyline ('line'), drawn plain with
    point size / line width `size`."""
    def build(renderer):
        actor = ic.add(renderer, ic.poly_data(ic.cloud() if cell == "verts" else ic.polyline(),
                                              cell))
        actor.GetProperty().SetPointSize(size)
        actor.GetProperty().SetLineWidth(size)
        return actor
    return build


def camera():
    """The scenes' camera, for the controls."""
    c = vtkCamera()
    c.SetPosition(*ic.EYE)
    c.SetFocalPoint(*ic.FOCAL)
    c.SetViewUp(0, 0, 1)
    c.SetViewAngle(ic.VIEW_ANGLE)
    c.SetClippingRange(1.0, 40.0)
    return c


def eye_axes():
    """The camera's right and up vectors in world coordinates."""
    m = camera().GetViewTransformMatrix()
    return (np.array([m.GetElement(0, k) for k in range(3)]),
            np.array([m.GetElement(1, k) for k in range(3)]))


def screen(p):
    """p's pixel position (x, y) in the W x H window."""
    m = camera().GetCompositeProjectionTransformMatrix(ic.W / ic.H, -1, 1)
    h = [sum(m.GetElement(r, k) * (list(p) + [1.0])[k] for k in range(4)) for r in range(4)]
    return np.array([(h[0] / h[3] + 1) * ic.W / 2, (h[1] / h[3] + 1) * ic.H / 2])


def quads(corners):
    """Poly data of the quads in `corners` (4 world points each)."""
    points, cells = vtkPoints(), vtkCellArray()
    for quad in corners:
        cells.InsertNextCell(4)
        for c in quad:
            cells.InsertCellPoint(points.InsertNextPoint(*c))
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetPolys(cells)
    return data


def squares(size):
    """Squares `size` pixels wide facing the camera at the cloud's points."""
    right, up = eye_axes()
    corners = []
    for p in ic.cloud():
        h = ic.impostor_radius(p, size)
        corners.append([p + h * (sx * right + sy * up)
                        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))])
    return quads(corners)


def bands(size):
    """Bands `size` pixels wide across each segment of the polyline on
    screen: the direction between its projected ends, turned a quarter."""
    right, up = eye_axes()
    line = ic.polyline()
    corners = []
    for a, b in zip(line[:-1], line[1:]):
        d = screen(b) - screen(a)
        across = (-d[1] * right + d[0] * up) / np.linalg.norm(d)
        ra, rb = ic.impostor_radius(a, size), ic.impostor_radius(b, size)
        corners.append([a - ra * across, b - rb * across, b + rb * across, a + ra * across])
    return quads(corners)


def shadow_alone(name, build):
    """(h): `build` casts nothing (the shadow area is the floor's own)."""
    floor_alone = ic.render(ic.scene(), None)
    off = ic.render(ic.scene(build), None)
    mask = ic.covered(off, floor_alone)
    area = ic.shadow_area(ic.scene(build), TECHNIQUE, mask, off)
    own = ic.shadow_area(ic.scene(), TECHNIQUE, mask, floor_alone)
    print(f"{name}: {TECHNIQUE} shadow area {area} px, the floor alone {own} px")
    check(area <= own, f"{name}: casts nothing ({area} px, the floor alone {own})")


def sphere_actor(renderer, theta, phi):
    """A sphere mesh (radius 1 at (0, 0, 1.4), theta x phi) in `renderer`."""
    s = vtkSphereSource()
    s.SetCenter(0.0, 0.0, 1.4)
    s.SetRadius(1.0)
    s.SetThetaResolution(theta)
    s.SetPhiResolution(phi)
    s.Update()
    return ic.add(renderer, s.GetOutput())


def edged_sphere(edges):
    def build(renderer):
        actor = sphere_actor(renderer, 24, 16)
        actor.GetProperty().SetEdgeVisibility(edges)
        actor.GetProperty().SetLineWidth(4.0)
    return build


def represented(representation, size):
    """(i): a sphere mesh drawn as points (size `size`) or as a wireframe
    (width `size`): VTK shows only those."""
    def build(renderer):
        actor = sphere_actor(renderer, 16, 10)
        actor.GetProperty().SetRepresentation(representation)
        actor.GetProperty().SetPointSize(size)
        actor.GetProperty().SetLineWidth(size)
    return build


def casts_something(name, build):
    """(i): `build` casts a shadow; under auto, its light's reason is not
    "nothing casts shadows"."""
    floor_alone = ic.render(ic.scene(), None)
    off = ic.render(ic.scene(build), None)
    area = ic.shadow_area(ic.scene(build), TECHNIQUE, ic.covered(off, floor_alone), off)
    reason = fr.render_technique(ic.scene(build), TECHNIQUE, ic.W, ic.H,
                                 lambda renderer, inner: inner.GetLightReason(0)
                                 if TECHNIQUE == "auto" else "")[1]
    print(f"{name}: {TECHNIQUE} shadow area {area} px; {reason!r}")
    check(area > 300, f"{name}: casts a shadow ({area} px > 300)")
    if TECHNIQUE == "auto":
        check("nothing casts" not in reason, f"{name}: auto knows it casts ({reason!r})")


def darkened(build):
    """Pixels whose visibility is below 0.5 (the sphere's too), and the
    unshadowed render."""
    off = ic.render(ic.scene(build), None)
    v, valid = fr.visibility(ic.render(ic.scene(build), TECHNIQUE), off)
    return valid & (v < 0.5), off


def edges_darken():
    """(h)'s edges: the pixels the sphere with edges has darkened that the
    one without has not, outside the edges' own pixels (those are drawn
    over the surface and lit, or not, as the technique shades lines), and
    the darkened pixels without edges."""
    with_edges, off_edges = darkened(edged_sphere(True))
    without, off = darkened(edged_sphere(False))
    drawn = ic.covered(off_edges, off)
    return int((with_edges & ~without & ~drawn).sum()), int(without.sum())


def main():
    opaque = int(splat_opaque().sum())
    ic.compare("splats (ScaleFactor 0.6, scale function s / 2)", splats(), splat_spheres,
               opaque, triangles=ic.proxy_triangles(opaque, 0))
    count = len(ic.cloud())
    ic.compare("plain points (size 18)", plain("verts", ic.POINT_SIZE),
               lambda: squares(ic.POINT_SIZE), count, triangles=QUAD_TRIANGLES * count)
    ic.compare("splats with ScaleFactor 0 (points, size 18)", splats(0.0, ic.POINT_SIZE),
               lambda: squares(ic.POINT_SIZE), count, triangles=QUAD_TRIANGLES * count)
    segments = len(ic.polyline()) - 1
    ic.compare("plain polyline (width 16)", plain("line", ic.LINE_WIDTH),
               lambda: bands(ic.LINE_WIDTH), segments, triangles=QUAD_TRIANGLES * segments)
    shadow_alone("plain polyline, width 1", plain("line", 1.0))
    shadow_alone("plain points, size 1", plain("verts", 1.0))
    casts_something("sphere drawn as points (size 8)", represented(0, 8.0))
    casts_something("sphere drawn as a wireframe (width 3)", represented(1, 3.0))
    casts_something("splats alone", splats())
    extra, without = edges_darken()
    print(f"sphere with EdgeVisibility (width 4): {extra} px darkened off its edges that are "
          f"not without them ({without} px darkened without)")
    check(without > 500 and extra <= 0.005 * without,
          f"edges shadow nothing of their surface ({extra} px <= 0.5 % of {without})")
    finish()


if __name__ == "__main__":
    main()
