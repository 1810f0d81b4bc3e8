"""A tiny real user program for the installed package (tests/install/run.sh):
a sphere over a floor lit from straight above, vtkshadow.enable_shadows on
the renderer, one offscreen frame. Prints where vtkshadow was imported from
and the floor brightness under the sphere over the open floor's:

    /usr/bin/python3 shadow_program.py TECHNIQUE

It only reports; run.sh decides (csm: a shadow, none: no shadow).
"""
import sys

import vtkshadow
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCoordinate, vtkLight,
                                         vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL classes)

technique = sys.argv[1]
print("vtkshadow from", vtkshadow.__file__)

renderer = vtkRenderer()
for source in (vtkPlaneSource(), vtkSphereSource()):
    if isinstance(source, vtkPlaneSource):  # the floor: z = 0, 6 x 6
        source.SetOrigin(-3, -3, 0)
        source.SetPoint1(3, -3, 0)
        source.SetPoint2(-3, 3, 0)
    else:  # the sphere: radius 0.5, 1 above the floor's centre
        source.SetCenter(0, 0, 1)
        source.SetRadius(0.5)
        source.SetThetaResolution(48)
        source.SetPhiResolution(48)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
light = vtkLight()  # straight down: the shadow is centred on the origin
light.SetLightTypeToSceneLight()
light.SetPosition(0, 0, 10)
light.SetFocalPoint(0, 0, 0)
renderer.AddLight(light)
camera = renderer.GetActiveCamera()
camera.SetPosition(0, -6, 5)
camera.SetFocalPoint(0, 0, 0.3)
camera.SetViewUp(0, 0, 1)

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(320, 240)
window.AddRenderer(renderer)
vtkshadow.enable_shadows(renderer, technique=technique)
renderer.ResetCameraClippingRange()
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
image = grab.GetOutput()


def floor_brightness(x, y):
    """Mean RGB of the pixel where the floor point (x, y, 0) is drawn."""
    where = vtkCoordinate()
    where.SetCoordinateSystemToWorld()
    where.SetValue(x, y, 0)
    px, py = where.GetComputedDisplayValue(renderer)
    scalars = image.GetPointData().GetScalars()
    rgb = scalars.GetTuple(py * image.GetDimensions()[0] + px)[:3]
    return sum(rgb) / 3.0


under, open_floor = floor_brightness(0, 0), floor_brightness(1.2, 0)
print(f"{technique}: floor under the sphere {under:.1f}, open floor {open_floor:.1f}")
print(f"ratio {under / max(open_floor, 1.0):.3f}")
