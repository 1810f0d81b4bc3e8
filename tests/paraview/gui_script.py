"""Run inside the ParaView GUI (run_gui.sh): the plugin's view opens in the
GUI's layout with a sphere over a plane under ParaView's default lights (its
light kit) and saves a screenshot to $VTKSHADOW_GUI_SCREENSHOT. It also
writes $VTKSHADOW_GUI_POINTS, a JSON with the screenshot pixels of the middle
of the sphere's shadow from the key light and of lit floor beside it, which
run_gui.sh compares in the screenshot.

The points come from the lights and camera the renderer really used (read at
render time), not from what this script asked for: the light kit's lights
follow the camera.

The GUI exits with status 0 even when its --script raised, so any failure
here ends the process itself with status 1 after printing the traceback.
"""
import json
import math
import os
import traceback

RESOLUTION = [480, 360]
CENTER, RADIUS = [0.0, 0.0, 1.2], 0.5
FLOOR_HALF = 5.0  # the floor spans [-5, 5] x [-5, 5] at z = 0
HALF_WINDOW = 2  # run_gui.sh averages a (2*2+1)^2 window around each point


def say(text):
    """Straight to the process's stdout: the GUI passes Python's output on
    from its event loop, which os._exit would not let run."""
    os.write(1, (text.rstrip("\n") + "\n").encode())


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def scale(a, s):
    return [s * x for x in a]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(dot(a, a))
    return scale(a, 1.0 / n)


def world_light(light, camera):
    """A switched-on light in world coordinates for this frame. A headlight
    sits at the camera; a camera light's position and focal point are in the
    camera's frame, which the camera's light transform maps to the world."""
    if light.LightTypeIsHeadlight():
        kind = "headlight"
        position, focal = list(camera.GetPosition()), list(camera.GetFocalPoint())
    else:
        position, focal = list(light.GetPosition()), list(light.GetFocalPoint())
        kind = "scene light"
        if light.LightTypeIsCameraLight():
            kind = "camera light"
            m = camera.GetCameraLightTransformMatrix()
            # Affine matrix: w stays 1.
            position, focal = [list(m.MultiplyPoint(p + [1.0])[:3]) for p in (position, focal)]
    return {"kind": kind, "intensity": light.GetIntensity(), "positional": bool(light.GetPositional()),
            "position": position, "focal_point": focal}


def towards(light, q):
    """Direction from floor point q to `light` and how far the light is."""
    if light["positional"]:
        v = sub(light["position"], q)
        return v, math.sqrt(dot(v, v))
    return sub(light["position"], light["focal_point"]), math.inf


def lights_floor(light):
    """Whether the light reaches the floor's top (its normal is +z): the
    light kit's fill and back lights come from below it here."""
    if light["positional"]:
        return light["position"][2] > 0.0
    return towards(light, [0.0, 0.0, 0.0])[0][2] > 0.0


def clearance(q, direction, length):
    """How far the segment from q along `direction` (up to `length`) passes
    outside the sphere; negative when the sphere blocks it."""
    u = unit(direction)
    t = min(max(dot(sub(CENTER, q), u), 0.0), length)
    closest = add(q, scale(u, t))
    return math.sqrt(dot(sub(CENTER, closest), sub(CENTER, closest))) - RADIUS


def shadow_middle(light):
    """Where the light's ray through the sphere's centre meets the floor."""
    if light["positional"]:
        p = light["position"]
        return add(p, scale(sub(CENTER, p), p[2] / (p[2] - CENTER[2])))
    d = sub(light["focal_point"], light["position"])
    return add(CENTER, scale(d, -CENTER[2] / d[2]))


def on_floor(q, margin):
    return abs(q[0]) <= FLOOR_HALF - margin and abs(q[1]) <= FLOOR_HALF - margin


def to_pixel(camera, world):
    """Column and row (from the top) of a world point in a RESOLUTION image
    seen by `camera`. A renderer of its own: during ParaView's magnified
    (tiled) screenshot the view's renderer has a tile's camera and size."""
    from vtkmodules.vtkRenderingCore import vtkCamera, vtkRenderer, vtkRenderWindow
    window, renderer, copy = vtkRenderWindow(), vtkRenderer(), vtkCamera()
    window.SetOffScreenRendering(1)  # never rendered: only its size is used
    window.SetSize(RESOLUTION)
    window.AddRenderer(renderer)
    copy.DeepCopy(camera)
    renderer.SetActiveCamera(copy)
    renderer.SetWorldPoint(world[0], world[1], world[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return [int(math.floor(x)), RESOLUTION[1] - 1 - int(math.floor(y))]


def measure(frame):
    """The shadow and lit points for a frame recorded by on_render."""
    camera, lights = frame["camera"], frame["lights"]
    reaching = [l for l in lights if lights_floor(l)]
    # The key light: the strongest one that reaches the floor and casts
    # shadows (the pass casts none from the headlight: they hide behind the
    # caster).
    casting = [l for l in reaching if l["kind"] != "headlight"]
    if not casting:
        raise RuntimeError("no light but the headlight reaches the floor: %s" % lights)
    key = max(casting, key=lambda l: l["intensity"])
    eye = list(camera.GetPosition())

    def seen(q):
        v = sub(eye, q)
        return clearance(q, v, math.sqrt(dot(v, v)))

    shadow = shadow_middle(key)
    if not on_floor(shadow, RADIUS) or seen(shadow) < RADIUS / 4:
        raise RuntimeError("the shadow's middle %s is off the floor or hidden by the sphere "
                           "(clearance %.2f): change the camera" % (shadow, seen(shadow)))
    # Lit floor beside it at the same depth: along the camera's right, well
    # clear (a radius) of every light's shadow and of the sphere's silhouette.
    right = cross(sub(list(camera.GetFocalPoint()), eye), list(camera.GetViewUp()))
    right = unit([right[0], right[1], 0.0])
    for k in (3, -3, 4, -4, 5, -5, 6, -6):
        lit = add(shadow, scale(right, k * RADIUS))
        if (on_floor(lit, RADIUS) and seen(lit) >= RADIUS
                and all(clearance(lit, *towards(l, lit)) >= RADIUS for l in reaching)):
            break
    else:
        raise RuntimeError("no lit floor point beside the shadow at %s" % shadow)
    points = {"shadow": {"world": shadow}, "lit": {"world": lit}}
    for p in points.values():
        p["pixel"] = to_pixel(camera, p["world"])
        col, row = p["pixel"]
        if not (HALF_WINDOW <= col < RESOLUTION[0] - HALF_WINDOW
                and HALF_WINDOW <= row < RESOLUTION[1] - HALF_WINDOW):
            raise RuntimeError("%s lands outside the screenshot at %s" % (p["world"], p["pixel"]))
    points.update(resolution=RESOLUTION, half_window=HALF_WINDOW, key_light=key, lights=lights,
                  camera={"position": eye, "focal_point": list(camera.GetFocalPoint()),
                          "view_up": list(camera.GetViewUp()), "view_angle": camera.GetViewAngle()})
    return points


def main():
    from paraview.simple import (AssignViewToLayout, CreateView, GetLayout, Plane, Render,
                                 SaveScreenshot, Show, Sphere)
    import paraview.simple
    from vtkmodules.vtkRenderingCore import vtkCamera

    # Keep the camera set below: the first render would otherwise fit it to
    # the whole floor and the sphere would be a few pixels wide.
    paraview.simple._DisableFirstRenderCameraReset()
    view = CreateView("RenderViewWithShadows")
    AssignViewToLayout(view=view, layout=GetLayout())
    view.ShadowTechnique = "csm"
    Show(Sphere(Center=CENTER, Radius=RADIUS), view)
    Show(Plane(Origin=[-FLOOR_HALF, -FLOOR_HALF, 0], Point1=[FLOOR_HALF, -FLOOR_HALF, 0],
               Point2=[-FLOOR_HALF, FLOOR_HALF, 0]), view)
    view.CameraPosition = [0, -8, 5]
    view.CameraFocalPoint = [0, 0, 0.5]
    view.CameraViewUp = [0, 0, 1]

    # The lights and camera of each untiled frame, as the renderer had them.
    # Tiles of a magnified screenshot narrow the camera; their pose and
    # lights are those of the untiled frames.
    frames = []

    def on_render(renderer, event):
        if list(renderer.GetRenderWindow().GetTileScale()) != [1, 1]:
            return
        camera = vtkCamera()
        camera.DeepCopy(renderer.GetActiveCamera())
        lights = []
        collection = renderer.GetLights()
        collection.InitTraversal()
        for _ in range(collection.GetNumberOfItems()):
            light = collection.GetNextItem()
            if light.GetSwitch():
                lights.append(world_light(light, camera))
        frames.append({"camera": camera, "lights": lights})

    view.GetRenderer().AddObserver("EndEvent", on_render)
    Render(view)
    SaveScreenshot(os.environ["VTKSHADOW_GUI_SCREENSHOT"], view, ImageResolution=RESOLUTION)
    if not frames:
        raise RuntimeError("the view's renderer rendered no untiled frame")
    points = measure(frames[-1])
    say("gui_script.py: key light %s, shadow middle %s at pixel %s, lit floor %s at pixel %s" % (
        points["key_light"], points["shadow"]["world"], points["shadow"]["pixel"],
        points["lit"]["world"], points["lit"]["pixel"]))
    with open(os.environ["VTKSHADOW_GUI_POINTS"], "w") as f:
        json.dump(points, f, indent=1)


try:
    main()
except BaseException:
    say(traceback.format_exc())
    os._exit(1)
