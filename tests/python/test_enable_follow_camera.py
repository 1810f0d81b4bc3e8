"""The lights enable_shadows adds follow the camera in every technique,
whatever the renderer's LightFollowCamera (issue 29; vedo turns it off).

A sphere on an empty renderer: enable_shadows adds vtkLightKit's key light
(a camera light) and a headlight as fill. One frame is drawn, then the
camera is moved (azimuth 140, elevation 35), and the next frame is compared
with the same steps on a renderer with LightFollowCamera on (VTK's default):
the sphere must be lit from the same side, its pixels' mean brightness
within 3 % and the brightness-weighted centre of its pixels within 2 px.
What it catches: a pass that leaves the key and fill at a fixed world
direction (`none`, and `auto`, which picks none for a lone sphere) or places
them once (`vtk`), so that the moved view shows the sphere's unlit back.
With a floor under the sphere the whole picture (the key light's shadow on
the floor) must match too. And the application's own camera light, which VTK leaves where it is
with LightFollowCamera off, is left there by every technique: each lights
the sphere as `none` (VTK's own passes) does; not checked for `vtk`, whose
vtkShadowMapBakerPass (VTK's code) places every camera light and headlight
whenever it bakes its maps.

Usage: test_enable_follow_camera.py [--technique NAME]"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "render"))

import vtkshadow  # noqa: E402
import float_render  # noqa: E402
import robust_scenes  # noqa: E402
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkLight  # noqa: E402

messages = vtkStringOutputWindow()  # the key light's notice, once per renderer
vtkOutputWindow.SetInstance(messages)
SIZE = 240
BACKGROUND = (0.2, 0.4, 0.8)  # no sphere pixel has this colour


def grab(window):
    """Render, and the picture as summed 8-bit RGB (H, W)."""
    window.Render()
    return float_render.read_window_rgb(window)


def moved_view(technique, follow, floor=False, own_light=False):
    """The picture after enable_shadows, one frame, and a camera move."""
    window = float_render.new_window(SIZE, SIZE)
    renderer = float_render.new_renderer(window)
    renderer.SetLightFollowCamera(follow)
    renderer.SetBackground(*BACKGROUND)
    renderer.AddActor(robust_scenes.poly_actor(robust_scenes.sphere_poly((0, 0, 1.2), 0.5, res=64)))
    if floor:
        robust_scenes.add_floor(renderer, receiver=False, poly=robust_scenes.floor_poly(half=3.0))
    if own_light:
        light = vtkLight()
        light.SetLightTypeToCameraLight()
        light.SetDirectionAngle(50, 10)
        renderer.AddLight(light)
    float_render.set_camera(renderer, (0, 8, 6), (0, 0, 1.2))
    renderer.ResetCamera()
    vtkshadow.enable_shadows(renderer, technique)
    grab(window)
    camera = renderer.GetActiveCamera()
    camera.Azimuth(140)
    camera.Elevation(35)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()
    image = grab(window)
    window.Finalize()
    return image


def lit_side(image):
    """Mean brightness of the sphere's pixels and their brightness-weighted
    centre (the lit side), the sphere being every pixel not the background."""
    sphere = np.abs(image - round(sum(BACKGROUND) * 255.0)) > 3.0
    ys, xs = np.nonzero(sphere)
    weights = image[sphere] + 1e-9
    centre = (float((xs * weights).sum() / weights.sum()), float((ys * weights).sum() / weights.sum()))
    return float(weights.mean()), centre, int(sphere.sum())


registry = vtkshadow.vtkShadowTechniqueRegistry
names = [registry.GetName(i) for i in range(registry.GetNumberOfTechniques())]
if "--technique" in sys.argv:
    names = [sys.argv[sys.argv.index("--technique") + 1]]
own_none = lit_side(moved_view("none", False, own_light=True))[0]
for name in names:
    on_mean, on_centre, on_px = lit_side(moved_view(name, True))
    off_mean, off_centre, off_px = lit_side(moved_view(name, False))
    shift = float(np.hypot(off_centre[0] - on_centre[0], off_centre[1] - on_centre[1]))
    ratio = off_mean / on_mean if on_mean > 0 else 0.0
    check(on_px > 5000 and abs(ratio - 1.0) <= 0.03 and shift <= 2.0,
          f"{name}: LightFollowCamera off lights the moved view as on: mean {off_mean:.1f} "
          f"against {on_mean:.1f} (ratio {ratio:.3f}), lit centre {shift:.1f} px apart "
          f"({off_px} and {on_px} sphere px)")
    gap = np.abs(moved_view(name, False, floor=True) - moved_view(name, True, floor=True))
    check(gap.mean() <= 3.0 and (gap > 24.0).mean() <= 0.005,
          f"{name}: with a floor, off and on give the same picture (mean difference "
          f"{gap.mean():.2f} of 765 levels, {100.0 * (gap > 24.0).mean():.2f} % px by more than 24)")
    if name == "vtk":
        continue  # VTK's own baker places every camera light when it bakes its maps
    own = lit_side(moved_view(name, False, own_light=True))[0]
    check(abs(own / own_none - 1.0) <= 0.03,
          f"{name}: the application's own camera light, LightFollowCamera off: mean {own:.1f}, "
          f"none {own_none:.1f}")
check("ERROR" not in (messages.GetOutput() or ""), "no VTK error")

finish()
