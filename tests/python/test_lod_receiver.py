"""A receiver drawn through an inner actor (vtkLODActor draws with its
Device actor, sharing its property keys; ParaView's vtkPVLODActor does the
same): planar must still shadow it. What it catches: the mapper asks the
pass about the Device; a pass that knows only the outer actor as a receiver
leaves the floor under the sphere lit (no planar shadow in ParaView).

The floor under the sphere (the light's ray through its centre) must be at
most 30% as bright as without shadows, a lit floor point within 5%; a plain
vtkActor floor is the control (the same figures).

Usage: test_lod_receiver.py"""
import sys

import vtkshadow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory overrides)
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingLOD import vtkLODActor

failures = []


def scene(floor_class):
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(320, 240)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    plane = vtkPlaneSource()
    plane.SetOrigin(-4, -4, 0)
    plane.SetPoint1(4, -4, 0)
    plane.SetPoint2(-4, 4, 0)
    sphere = vtkSphereSource()
    sphere.SetCenter(0, 0, 1.5)
    sphere.SetRadius(0.7)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(48)
    for source, cls in ((plane, floor_class), (sphere, vtkActor)):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = cls()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(0)
    light.SetPosition(0, 0, 1)  # straight down: the shadow's middle is (0, 0, 0)
    light.SetFocalPoint(0, 0, 0)
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -9, 7)
    camera.SetFocalPoint(0, 0, 0.5)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    return window, renderer


def luminance_at(window, renderer, world):
    renderer.SetWorldPoint(world[0], world[1], world[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    image = grab.GetOutput()
    scalars = image.GetPointData().GetScalars()
    w = image.GetDimensions()[0]
    total = 0.0
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            i = (int(round(y)) + dy) * w + int(round(x)) + dx
            total += sum(scalars.GetComponent(i, c) for c in range(3)) / 3.0
    return total / 9.0


def measure(floor_class, technique):
    window, renderer = scene(floor_class)
    if technique != "none":
        shadows = vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique)
        renderer.SetPass(shadows)
    window.Render()
    window.Render()
    return luminance_at(window, renderer, (0, 0, 0)), luminance_at(window, renderer, (3, 2.5, 0))


for floor_class in (vtkActor, vtkLODActor):
    base_shadow, base_lit = measure(floor_class, "none")
    shadow, lit = measure(floor_class, "planar")
    name = floor_class.__name__
    print("%s floor: shadow %.1f (none %.1f), lit %.1f (none %.1f)" % (
        name, shadow, base_shadow, lit, base_lit))
    if not base_shadow > 40:
        failures.append("%s: the floor is not lit without shadows (%.1f)" % (name, base_shadow))
    if not shadow <= 0.3 * base_shadow:
        failures.append("%s: no planar shadow under the sphere (%.1f vs %.1f)" % (
            name, shadow, base_shadow))
    if not abs(lit - base_lit) <= 0.05 * base_lit:
        failures.append("%s: lit floor changed (%.1f vs %.1f)" % (name, lit, base_lit))

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok: planar shadows a vtkActor and a vtkLODActor receiver alike")
