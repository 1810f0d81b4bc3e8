"""enable_shadows on a typical VTK pipeline (issue 19), with every registered
technique: no VTK error, the 2D overlays and the volume drawn as without
shadows, the floor under the casters darker (not for techniques that cast
nothing), residual_light between the hard shadow and no shadow, the floor
found as a plane receiver, the key light added once and only to a renderer
without lights, and bad settings refused without changing anything.

Usage: test_enable_shadows.py SOURCE_DIR [--technique NAME]"""
import ctypes
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))

import vtkshadow  # noqa: E402
import robust_techniques  # noqa: E402
import typical_pipeline  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow  # noqa: E402
from vtkmodules.vtkCommonCore import vtkInformation  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkLight, vtkRenderWindow, vtkRenderer,  # noqa: E402
                                         vtkWindowToImageFilter)

failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


messages = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(messages)
seen = 0


def new_messages():
    global seen
    text = messages.GetOutput() or ""
    new, seen = text[seen:], len(text)
    return new


WIDTH, HEIGHT = 640, 480
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(WIDTH, HEIGHT)
renderer = vtkRenderer()
window.AddRenderer(renderer)
roles = typical_pipeline.build(renderer)
THREE_D = ("contour", "glyphs", "outline", "composite", "floor", "volume", "axes")


def grab():
    window.Render()
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.SetInputBufferTypeToRGB()
    capture.ReadFrontBufferOff()
    capture.Update()
    image = capture.GetOutput()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(HEIGHT, WIDTH, 3)
    return rgb.astype(np.float64)


def luminance(rgb):
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def render(hidden=()):
    for name in hidden:
        roles[name].VisibilityOff()
    rgb = grab()
    for name in hidden:
        roles[name].VisibilityOn()
    return rgb


def differs(a, b, levels=8.0):
    return np.abs(a - b).max(axis=2) > levels


# ---------------------------------------------------------------------------
# Lights, decided at the first frame: a renderer with no light gets
# vtkLightKit's key light (+ headlight fill), once; one with its own light is
# left alone; key_light=False too. (The lights changing later:
# test_enable_light_changes.py.)
technique = vtkshadow.enable_shadows(renderer, "none")
check(renderer.GetLights().GetNumberOfItems() == 0 and technique.GetAddedKeyLight() is None,
      "no light is added before the first frame")
grab()
text = new_messages()
check(technique.GetAddedKeyLight() is not None, "a key light was added to a renderer without lights")
check("key light" in technique.GetLightMessage() and text.count("key light") == 1,
      "said so once: " + technique.GetLightMessage()[:80])
key = technique.GetAddedKeyLight()
check(key.LightTypeIsCameraLight() and abs(key.GetIntensity() - 0.75) < 1e-12,
      "the key light is vtkLightKit's: a camera light at intensity 0.75")
check(renderer.GetLights().GetNumberOfItems() == 2, "key light + headlight fill")
again = vtkshadow.enable_shadows(renderer, "none")
grab()
check(again.GetAddedKeyLight() is key and renderer.GetLights().GetNumberOfItems() == 2
      and "key light" not in new_messages(),
      "enable_shadows again: the same key light, not added twice, nothing said")

other = vtkRenderer()
own = vtkLight()
own.SetLightTypeToSceneLight()
own.SetPosition(1, 2, 3)
other.AddLight(own)
window.AddRenderer(other)
t = vtkshadow.enable_shadows(other, "auto")
window.Render()
check(other.GetLights().GetNumberOfItems() == 1 and t.GetAddedKeyLight() is None
      and t.GetLightMessage() == "", "a scene light of the user's: nothing added")
bare = vtkRenderer()
window.AddRenderer(bare)
t = vtkshadow.enable_shadows(bare, "auto", key_light=False)
window.Render()
check(t.GetAddedKeyLight() is None and t.GetLightMessage() == ""
      and all(light.LightTypeIsHeadlight() for light in bare.GetLights()),
      f"key_light=False adds nothing ({bare.GetLights().GetNumberOfItems()} light: VTK's headlight)")
window.RemoveRenderer(other)
window.RemoveRenderer(bare)
new_messages()

# Bad settings: an exception, and the renderer keeps its pass and lights.
before = renderer.GetPass()
for args, kwargs, kind in ((("bogus",), {}, ValueError),
                           (("csm",), {"max_error": 0.5}, ValueError),
                           (("auto",), {"residual_light": 1.5}, ValueError),
                           (("auto",), {"residual_light": float("nan")}, ValueError),
                           (("planar",), {"cascades": 2}, ValueError)):
    try:
        vtkshadow.enable_shadows(renderer, *args, **kwargs)
        raised = None
    except Exception as error:  # noqa: BLE001
        raised = error
    check(isinstance(raised, kind) and renderer.GetPass() is before
          and renderer.GetLights().GetNumberOfItems() == 2,
          f"enable_shadows{args} {kwargs} refused: {raised}")
try:
    vtkshadow.enable_shadows(None)
    raised = None
except TypeError as error:
    raised = error
check(raised is not None, f"no renderer: TypeError ({raised})")
new_messages()

# ---------------------------------------------------------------------------
# Baselines without shadows.
none = render()
check("ERROR" not in new_messages(), "the pipeline renders without shadows with no VTK error")
none_nofloor = render(("floor",))
none_novolume = render(("volume",))
overlay_only = render(THREE_D)
background = np.array(renderer.GetBackground()) * 255.0
overlay = np.abs(overlay_only - background).max(axis=2) > 24.0
volume_px = differs(none, none_novolume)
check(overlay.sum() > 500, f"the overlays cover {overlay.sum()} px")
check(volume_px.sum() > 2000, f"the volume covers {volume_px.sum()} px")
floor_none = differs(none, none_nofloor)
L_none = luminance(none)

registry = vtkshadow.vtkShadowTechniqueRegistry
names = [registry.GetName(i) for i in range(registry.GetNumberOfTechniques())]
if "--technique" in sys.argv:
    names = [sys.argv[sys.argv.index("--technique") + 1]]
floor_index = renderer.GetActors().IsItemPresent(roles["floor"]) - 1

for name in names:
    casts = robust_techniques.profile(name).casts
    t = vtkshadow.enable_shadows(renderer, name)
    image = render()
    image_nofloor = render(("floor",))
    text = new_messages()
    check("ERROR" not in text, f"{name}: no VTK error" + (f" ({text.strip()[:300]})" if "ERROR" in text else ""))
    # 2D overlays and the volume as without shadows.
    bad = differs(image, none, 2.0) & overlay
    check(100.0 * bad.sum() / overlay.sum() <= 0.5,
          f"{name}: overlays intact ({bad.sum()} of {overlay.sum()} px differ)")
    drawn = differs(image, none_novolume) & volume_px
    check(100.0 * drawn.sum() / volume_px.sum() >= 80.0,
          f"{name}: the volume is drawn ({drawn.sum()} of {volume_px.sum()} px)")
    # The floor where both renders show it.
    floor = floor_none & differs(image, image_nofloor)
    L = luminance(image)
    shadowed = floor & (L_none - L > 20.0)
    pct = 100.0 * shadowed.sum() / max(floor.sum(), 1)
    mean_drop = float(np.mean((L_none - L)[floor])) if floor.any() else 0.0
    if casts:
        check(floor.sum() > 20000 and pct >= 2.0 and mean_drop > 1.0,
              f"{name}: the floor is darker under the casters: {pct:.2f} % of {floor.sum()} "
              f"floor px shadowed, mean drop {mean_drop:.2f} levels")
        # residual_light 0.5: half of the key light left in the shadows.
        t = vtkshadow.enable_shadows(renderer, name, residual_light=0.5)
        half = luminance(render())
        new_messages()
        gap = (L_none - L)[shadowed]
        kept = ((half - L)[shadowed] / gap).mean() if shadowed.any() else 0.0
        check(0.3 <= kept <= 0.7, f"{name}: residual_light 0.5 keeps {kept:.2f} of the light "
                                  f"the shadow took (want about 0.5)")
    else:
        check(pct <= 0.1 and abs(mean_drop) < 0.5,
              f"{name}: no shadow ({pct:.3f} % floor px darker, mean drop {mean_drop:.3f})")
    stats = t.GetStatsJSON(renderer)
    if name in ("planar", "auto"):
        check(t.GetNumberOfDetectedReceivers() == 1 and t.GetDetectedReceiver(0) is roles["floor"],
              f"{name}: the floor detected as the plane receiver")
        check(f'"detected_receivers": [{floor_index}]' in stats,
              f"{name}: stats name the detected floor (actor {floor_index}): {stats[:200]}")

# The C API's one call on the same renderer (the pointer from the wrapping).
capi = ctypes.CDLL(os.path.join(os.path.dirname(os.path.abspath(vtkshadow.__file__)), "..", "..",
                                "..", "libvtkshadow.so"))
capi.vtkshadow_enable_shadows.restype = ctypes.c_void_p
capi.vtkshadow_enable_shadows.argtypes = (ctypes.c_void_p, ctypes.c_char_p, ctypes.c_double,
                                          ctypes.c_char_p, ctypes.c_size_t)
capi.vtkshadow_technique_detected_receiver_count.argtypes = (ctypes.c_void_p,)
capi.vtkshadow_technique_light_message.restype = ctypes.c_char_p
capi.vtkshadow_technique_light_message.argtypes = (ctypes.c_void_p,)
capi.vtkshadow_technique_free.argtypes = (ctypes.c_void_p,)
address = int(renderer.__this__[1:].split("_")[0], 16)
error = ctypes.create_string_buffer(1024)
handle = capi.vtkshadow_enable_shadows(address, b"planar", -1.0, error, len(error))
check(handle is not None, f"C: vtkshadow_enable_shadows(renderer, planar) ({error.value})")
if handle:
    c_image = luminance(render())
    check(capi.vtkshadow_technique_detected_receiver_count(handle) == 1
          and b"key light" in capi.vtkshadow_technique_light_message(handle)
          and renderer.GetLights().GetNumberOfItems() == 2,
          "C: the floor detected, the key light and fill kept")
    check(np.mean((L_none - c_image)[floor_none] > 20.0) > 0.01, "C: the floor is shadowed")
    capi.vtkshadow_technique_free(handle)
check(capi.vtkshadow_enable_shadows(address, b"csm", 0.5, error, len(error)) is None
      and b"max_error" in error.value, f"C: csm has no max_error: {error.value}")
new_messages()

# Explicit marks override detection: the floor marked, or opted out.
info = vtkInformation()
roles["floor"].SetPropertyKeys(info)
info.Set(vtkshadow.vtkShadowPassBase.RECEIVER(), 1)
roles["floor"].Modified()
t = vtkshadow.enable_shadows(renderer, "planar")
marked = luminance(render())
check(t.GetNumberOfDetectedReceivers() == 0 and '"shadow_pairs": 1' in t.GetStatsJSON(renderer),
      "a marked floor receives, nothing is detected: " + t.GetStatsJSON(renderer))
info.Set(vtkshadow.vtkShadowPassBase.RECEIVER(), 0)
roles["floor"].Modified()
opted_out = luminance(render())
check(t.GetNumberOfDetectedReceivers() == 0 and '"shadow_pairs": 0' in t.GetStatsJSON(renderer)
      and np.abs(opted_out - L_none)[floor_none].max() <= 2.0,
      "RECEIVER() = 0 on the floor: not detected, no shadow")
check(np.mean((L_none - marked)[floor_none] > 20.0) > 0.01, "the marked floor is shadowed")
check("ERROR" not in new_messages(), "no VTK error with marks")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
