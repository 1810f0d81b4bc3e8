"""A library scene (scenes/*.json) as ParaView sources in a view, and the
measurements the ParaView tests share: where a world point lands in the
screenshot, and the mean luminance of a small window there.

Only what the ParaView tests need of the scene format: spheres, planes and
boxes, the camera, and the scene's directional lights (ParaView's light kit
is switched off so the scene's own lights are the only ones).
"""
import json

from paraview.simple import (AddLight, Box, Plane, Show, Sphere)
from vtkmodules.vtkIOImage import vtkPNGReader


def load(path):
    with open(path) as f:
        return json.load(f)


def populate(view, scene):
    """Sources, lights and camera of `scene` in `view`; returns the sources."""
    sources = []
    for obj in scene["objects"]:
        if "sphere" in obj:
            s = obj["sphere"]
            res = int(s.get("resolution", 64))
            src = Sphere(Center=s["center"], Radius=s["radius"],
                         ThetaResolution=res, PhiResolution=res)
        elif "plane" in obj:
            p = obj["plane"]
            src = Plane(Origin=p["origin"], Point1=p["point1"], Point2=p["point2"])
        elif "box" in obj:
            b = obj["box"]
            lo, hi = b["min"], b["max"]
            src = Box(Center=[(lo[i] + hi[i]) / 2 for i in range(3)],
                      XLength=hi[0] - lo[0], YLength=hi[1] - lo[1], ZLength=hi[2] - lo[2])
        else:
            continue
        display = Show(src, view)
        display.AmbientColor = display.DiffuseColor = obj.get("color", [0.8, 0.8, 0.8])
        sources.append(src)
    view.UseLight = 0  # no light kit: the scene's lights only
    for light in scene["lights"]:
        if light["type"] != "directional":
            continue
        d = light["direction"]
        l = AddLight(view=view)
        l.Type = "Directional"
        l.Coords = "Scene"
        l.Position = [-d[0], -d[1], -d[2]]
        l.FocalPoint = [0.0, 0.0, 0.0]
        l.Intensity = 1.0
    cam = scene["camera"]
    view.CameraPosition = cam["position"]
    view.CameraFocalPoint = cam["focal_point"]
    view.CameraViewUp = cam["view_up"]
    view.CameraViewAngle = cam.get("view_angle", 30)
    view.OrientationAxesVisibility = 0
    return sources


def shadow_point(scene, caster_center):
    """Where the first directional light's ray through `caster_center`
    meets the plane z = 0 (the floor of the library's basic scenes)."""
    d = next(l["direction"] for l in scene["lights"] if l["type"] == "directional")
    t = -caster_center[2] / d[2]
    return [caster_center[0] + t * d[0], caster_center[1] + t * d[1], 0.0]


def to_pixel(view, world):
    """Pixel (column, row from the top) of a world point in the view."""
    renderer = view.GetRenderer()
    renderer.SetWorldPoint(world[0], world[1], world[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    height = view.ViewSize[1]
    return int(round(x)), int(round(height - 1 - y))


def luminance(png, pixel, half=3):
    """Mean luminance (0..255) of the (2*half+1)^2 window around `pixel`."""
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    comps = image.GetNumberOfScalarComponents()
    data = image.GetPointData().GetScalars()
    total, n = 0.0, 0
    for row in range(pixel[1] - half, pixel[1] + half + 1):
        for col in range(pixel[0] - half, pixel[0] + half + 1):
            if not (0 <= row < h and 0 <= col < w):
                raise SystemExit("%s: pixel %s is outside the %dx%d image" % (png, pixel, w, h))
            index = (h - 1 - row) * w + col  # VTK images start at the bottom
            rgb = [data.GetComponent(index, c) for c in range(min(3, comps))]
            total += 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
            n += 1
    return total / n

