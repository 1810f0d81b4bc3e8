"""enable_shadows decides about the key light at each frame, from the lights
the renderer has then, not at the call (issue 29: vedo's Plotter() is made,
enable_shadows called, and vedo's show() adds the scene's lights later; the
key and fill were added on top of them and the floor washed out).

Every technique, a sphere over a floor (LightFollowCamera off, as in vedo,
but for the last case),
sums of RGB compared with a reference made by calling enable_shadows after
the application's lights are in place (mean difference <= 3 of 765 levels,
at most 0.5 % of the pixels by more than 24):

- light added after the call: enable_shadows on an empty renderer, then a
  scene light, then the first frame; no key light may be left;
- light added after a frame: the key and fill were added at the first
  frame; the scene light comes, and the next frame drops them;
- lights removed: the application's lights go again, the key and fill come
  back (reference: enable_shadows on an empty renderer);
- own headlight: a headlight of the application, dimmed to be the fill at
  the first frame, gets its own intensity back once a scene light comes;
- key_light=False after a frame with the key light: the key and fill go
  (reference: key_light=False from the start, VTK's automatic headlight).

Usage: test_enable_light_changes.py [--technique NAME]"""
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

messages = vtkStringOutputWindow()  # the key light's notices
vtkOutputWindow.SetInstance(messages)
SIZE = 200


def scene(follow):
    """A sphere over a floor (white Lambertian), the camera above the floor."""
    window = float_render.new_window(SIZE, SIZE)
    renderer = float_render.new_renderer(window)
    renderer.SetLightFollowCamera(follow)
    renderer.AddActor(robust_scenes.poly_actor(robust_scenes.sphere_poly((0, 0, 1.2), 0.5)))
    robust_scenes.add_floor(renderer, receiver=False, poly=robust_scenes.floor_poly(half=3.0))
    float_render.set_camera(renderer, (0, -8, 6), (0, 0, 0.6))
    return window, renderer


def scene_light():
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(1, -1, 3)
    light.SetFocalPoint(0, 0, 0)
    light.SetColor(0.4, 0.6, 1.0)
    return light


def headlight():
    light = vtkLight()
    light.SetLightTypeToHeadlight()
    return light


def frame(window):
    window.Render()
    return float_render.read_window_rgb(window)


def picture(technique, before=(), after=(), frame_between=False, remove_all=False, follow=False):
    """`before` lights added, enable_shadows, (a frame,) `after` lights added
    (or every light removed), the picture; and the renderer."""
    window, renderer = scene(follow)
    for light in before:
        renderer.AddLight(light)
    vtkshadow.enable_shadows(renderer, technique)
    if frame_between:
        frame(window)
    if remove_all:
        renderer.RemoveAllLights()
    for light in after:
        renderer.AddLight(light)
    return frame(window), renderer


def same(a, b):
    gap = np.abs(a - b)
    return gap.mean() <= 3.0 and (gap > 24.0).mean() <= 0.005, \
        f"mean difference {gap.mean():.2f} of 765 levels, {100.0 * (gap > 24.0).mean():.2f} % px by more than 24"


def key_lights(renderer):
    return sum(1 for light in renderer.GetLights() if light.LightTypeIsCameraLight())


registry = vtkshadow.vtkShadowTechniqueRegistry
names = [registry.GetName(i) for i in range(registry.GetNumberOfTechniques())]
if "--technique" in sys.argv:
    names = [sys.argv[sys.argv.index("--technique") + 1]]
def said():
    """The VTK messages since the last call."""
    global seen
    text = messages.GetOutput() or ""
    new, seen = text[seen:], len(text)
    return new


seen = 0
for name in names:
    reference, _ = picture(name, before=[scene_light()])
    said()
    image, renderer = picture(name, after=[scene_light()])
    ok, how = same(image, reference)
    check(ok and renderer.GetLights().GetNumberOfItems() == 1 and "key light" not in said(),
          f"{name}: scene light added after the call, before the first frame: as if added before, "
          f"no key light said ({how}; {renderer.GetLights().GetNumberOfItems()} light(s))")
    image, renderer = picture(name, after=[scene_light()], frame_between=True)
    ok, how = same(image, reference)
    check(ok and renderer.GetLights().GetNumberOfItems() == 1,
          f"{name}: scene light added after a frame: key and fill dropped ({how}; "
          f"{renderer.GetLights().GetNumberOfItems()} light(s))")
    empty, _ = picture(name)
    image, renderer = picture(name, before=[scene_light()], frame_between=True, remove_all=True)
    ok, how = same(image, empty)
    check(ok and key_lights(renderer) == 1,
          f"{name}: the application's lights removed: key and fill back ({how})")
    # LightFollowCamera on: with it off VTK leaves the application's headlight
    # where it was last placed, by its first frame here, nowhere in the reference.
    reference, _ = picture(name, before=[headlight(), scene_light()], follow=True)
    own = headlight()
    image, renderer = picture(name, before=[own], after=[scene_light()], frame_between=True,
                              follow=True)
    ok, how = same(image, reference)
    check(ok and own.GetIntensity() == 1.0 and renderer.GetLights().GetNumberOfItems() == 2,
          f"{name}: the application's headlight back at its own intensity "
          f"({own.GetIntensity():.2f}) when a scene light comes ({how})")
    # key_light=False after a frame with the key light: it goes, as the fill.
    window, renderer = scene(False)
    vtkshadow.enable_shadows(renderer, name)
    frame(window)
    t = vtkshadow.enable_shadows(renderer, name, key_light=False)
    image = frame(window)
    bare_window, bare = scene(False)
    vtkshadow.enable_shadows(bare, name, key_light=False)
    ok, how = same(image, frame(bare_window))
    check(ok and t.GetAddedKeyLight() is None and key_lights(renderer) == 0,
          f"{name}: key_light=False removes the key and fill added before ({how})")
check("ERROR" not in (messages.GetOutput() or ""), "no VTK error")

finish()
