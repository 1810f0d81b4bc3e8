#!/usr/bin/env python3
"""Run one third-party example program UNMODIFIED with vtkshadow injected.

  run_example.py --example FILE --technique T[:KEY=VALUE,...] --out PREFIX
                 [--size 400x300] [--frames 3] [--sabotage hide|error|crash|light]

T may carry technique settings, passed to enable_shadows by name (e.g.
raytrace:classify=0).

The example file is executed with runpy (cwd = its folder, sys.argv =
[FILE]) after the toolkit has been patched:

- vedo: every Plotter is made offscreen; Plotter.show() runs as usual and
  then, the first time it is called, the capture below happens and the
  process ends (os._exit: animations and later show() calls never run).
- plain VTK: vtkRenderWindowInteractor (in vtkmodules.vtkRenderingCore,
  vtkmodules.all and vtk) is replaced by a Python subclass whose Start()
  does the capture; vtkRenderWindow by one that renders offscreen.

The capture: VTK's error/warning display is switched on (vedo switches it
off) and sent to a vtkStringOutputWindow from the start;
vtkshadow.enable_shadows(r, technique=T) on every renderer of the window;
the window forced to --size; a first Render(), then --frames timed
Render() calls; the frame (RGB) and depth are read; then every prop is
hidden for one frame to read the background, and restored.

Python's, numpy's and VTK's random generators are seeded (0) first, so
that examples drawing random data draw the same under every technique.

Writes PREFIX.png (the frame), PREFIX.npz (rgb, fg: the foreground =
depth < 1 or colour differs from the background frame by more than 8/255)
and PREFIX.json (status, times, VTK errors and warnings issued after
enable_shadows, the technique's stats, counts of props). Exit status 0
when the capture happened, 3 when the example ended without showing
anything, other codes for exceptions and crashes.

--sabotage is for the corpus' negative controls only: `hide` hides the
largest actor after enabling, `error` issues a VTK error, `crash` aborts,
`light` darkens every surface's diffuse
reflection to 60 percent (as a wrong light would).
"""
import argparse
import json
import os
import runpy
import sys
import time

import numpy as np

import vtkmodules.all  # noqa: F401  (every VTK class, as an example would get)
from vtkmodules.vtkCommonCore import vtkObject, vtkOutputWindow, vtkStringOutputWindow

ARGS = None
LOG = vtkStringOutputWindow()
STATE = {"done": False}


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--example", required=True)
    ap.add_argument("--technique", required=True)
    ap.add_argument("--out", required=True, help="output prefix (PREFIX.png/.npz/.json)")
    ap.add_argument("--size", default="400x300")
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--sabotage", choices=["hide", "error", "crash", "light"])
    args = ap.parse_args()
    args.size = tuple(int(v) for v in args.size.split("x"))
    return args


def vtk_messages(text):
    """(errors, warnings) among VTK's messages in `text`."""
    errors, warnings = [], []
    for block in text.split("\n\n"):
        block = block.strip()
        if not block:
            continue
        if "ERROR" in block:
            errors.append(block[:400])
        elif "Warning" in block or "WARNING" in block:
            warnings.append(block[:400])
    return errors, warnings


def read_rgb(window):
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
    w, h = window.GetSize()
    arr = vtkUnsignedCharArray()
    window.GetPixelData(0, 0, w - 1, h - 1, 0, arr)
    rgb = np.frombuffer(memoryview(arr), dtype=np.uint8).copy()
    return rgb.reshape(h, w, 3)[::-1]


def read_depth(window):
    from vtkmodules.vtkCommonCore import vtkFloatArray
    w, h = window.GetSize()
    arr = vtkFloatArray()
    window.GetZbufferData(0, 0, w - 1, h - 1, arr)
    z = np.frombuffer(memoryview(arr), dtype=np.float32).copy()
    return z.reshape(h, w)[::-1]


def renderers_of(window):
    found = []
    coll = window.GetRenderers()
    coll.InitTraversal()
    for _ in range(coll.GetNumberOfItems()):
        found.append(coll.GetNextItem())
    return found


def props_of(renderer):
    found = []
    coll = renderer.GetViewProps()
    coll.InitTraversal()
    for _ in range(coll.GetNumberOfItems()):
        found.append(coll.GetNextProp())
    return found


def describe_prop(prop):
    """'surface', 'flat', 'lines', 'volume', 'image', '2d' or 'other'."""
    if prop.IsA("vtkVolume"):
        return "volume"
    if prop.IsA("vtkImageSlice") or prop.IsA("vtkImageActor"):
        return "image"
    if prop.IsA("vtkActor2D") or not prop.IsA("vtkProp3D"):
        return "2d"
    if not prop.IsA("vtkActor") or prop.GetMapper() is None:
        return "other"
    data = prop.GetMapper().GetInput()
    if data is None or not data.IsA("vtkPolyData"):
        return "other"
    if data.GetNumberOfPolys() + data.GetNumberOfStrips() == 0:
        return "lines"
    b = prop.GetBounds()
    ext = sorted(abs(b[2 * i + 1] - b[2 * i]) for i in range(3))
    return "flat" if ext[0] <= 1e-6 * max(ext[2], 1e-30) else "surface"


def count_props(renderers):
    counts = {}
    for r in renderers:
        for p in props_of(r):
            if not p.GetVisibility():
                continue
            kind = describe_prop(p)
            counts[kind] = counts.get(kind, 0) + 1
    return counts


def sabotage(kind, renderers):
    if kind == "hide":
        actors = [p for r in renderers for p in props_of(r)
                  if p.GetVisibility() and describe_prop(p) in ("surface", "flat")]
        if actors:
            def size(a):
                b = a.GetBounds()
                return sum((b[2 * i + 1] - b[2 * i]) ** 2 for i in range(3))
            max(actors, key=size).VisibilityOff()
    elif kind == "error":
        from vtkmodules.vtkIOImage import vtkPNGReader
        reader = vtkPNGReader()
        reader.SetFileName("/nonexistent/sabotage.png")
        reader.Update()
    elif kind == "crash":
        os.abort()
    elif kind == "light":  # the shading changes as a wrong light would change it
        for r in renderers:
            for p in props_of(r):
                if p.IsA("vtkActor") and describe_prop(p) in ("surface", "flat"):
                    prop = p.GetProperty()
                    prop.SetDiffuse(0.6 * prop.GetDiffuse())


def timed_renders(window, n):
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        window.Render()
        times.append(1000.0 * (time.perf_counter() - t0))
    return times


def background_frame(window, renderers):
    hidden = [p for r in renderers for p in props_of(r) if p.GetVisibility()]
    for p in hidden:
        p.VisibilityOff()
    window.Render()
    rgb = read_rgb(window)
    for p in hidden:
        p.VisibilityOn()
    return rgb


def technique_spec(spec):
    """TECH[:KEY=VALUE[,KEY=VALUE]...] -> (TECH, {KEY: number or text})."""
    name, _, rest = spec.partition(":")
    options = {}
    for item in filter(None, rest.split(",")):
        key, eq, value = item.partition("=")
        if not eq or not key:
            raise SystemExit("run_example.py: --technique %r: %r is not KEY=VALUE" % (spec, item))
        try:
            options[key] = int(value)
        except ValueError:
            try:
                options[key] = float(value)
            except ValueError:
                options[key] = value
    return name, options


def enable_all(renderers, technique):
    import vtkshadow
    name, options = technique_spec(technique)
    techs = []
    for r in renderers:
        techs.append(vtkshadow.enable_shadows(r, technique=name, **options))
    return techs


def capture(window, how):
    """Enable shadows on every renderer of `window`, render, save, end."""
    if STATE["done"]:
        return
    STATE["done"] = True
    vtkObject.GlobalWarningDisplayOn()
    before = LOG.GetOutput() or ""
    import vtkshadow
    result = {"example": ARGS.example, "technique": ARGS.technique, "injected_at": how,
              "status": "ok", "vtkshadow_module": os.path.dirname(vtkshadow.__file__)}
    window.SetOffScreenRendering(1)
    window.SetSize(*ARGS.size)
    renderers = renderers_of(window)
    techs = enable_all(renderers, ARGS.technique)
    if ARGS.sabotage:
        sabotage(ARGS.sabotage, renderers)
    t0 = time.perf_counter()
    window.Render()
    result["first_frame_ms"] = 1000.0 * (time.perf_counter() - t0)
    times = timed_renders(window, ARGS.frames)
    result["frame_ms"] = times
    result["frame_ms_median"] = float(np.median(times))
    rgb = read_rgb(window)
    depth = read_depth(window)
    result["stats"] = [json.loads(t.GetStatsJSON(r) or "{}") for t, r in zip(techs, renderers)]
    result["light_message"] = [t.GetLightMessage() or "" for t in techs]
    result["detected_receivers"] = sum(t.GetNumberOfDetectedReceivers() for t in techs)
    result["props"] = count_props(renderers)
    result["renderers"] = len(renderers)
    bg = background_frame(window, renderers)
    fg = (depth < 1.0) | (np.abs(rgb.astype(np.int16) - bg).max(axis=2) > 8)
    after = (LOG.GetOutput() or "")[len(before):]
    result["errors_before"], result["warnings_before"] = vtk_messages(before)
    result["errors"], result["warnings"] = vtk_messages(after)
    save(rgb, fg, result)


def save(rgb, fg, result):
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    np.savez_compressed(ARGS.out + ".npz", rgb=rgb, fg=fg)
    h, w, _ = rgb.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(rgb[::-1].reshape(-1, 3).copy()))
    writer = vtkPNGWriter()
    writer.SetFileName(ARGS.out + ".png")
    writer.SetInputData(image)
    writer.Write()
    with open(ARGS.out + ".json", "w") as f:
        json.dump(result, f, indent=1)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


def patch_vedo():
    try:
        import vedo
    except ImportError:
        return
    vedo.settings.default_backend = "vtk"
    plotter_init = vedo.Plotter.__init__
    plotter_show = vedo.Plotter.show

    def init(self, *a, **kw):
        kw["offscreen"] = True
        kw.pop("qt_widget", None)
        kw.pop("wx_widget", None)
        plotter_init(self, *a, **kw)
        vtkObject.GlobalWarningDisplayOn()

    def show(self, *a, **kw):
        kw["interactive"] = False
        out = plotter_show(self, *a, **kw)
        if self.window is not None:
            capture(self.window, "vedo.Plotter.show")
        return out

    vedo.Plotter.__init__ = init
    vedo.Plotter.show = show


def patch_vtk():
    import vtkmodules.vtkRenderingCore as core
    import vtkmodules.all as everything
    base_interactor = core.vtkRenderWindowInteractor
    base_window = core.vtkRenderWindow

    class Interactor(base_interactor):
        def Initialize(self):
            pass

        def Start(self):
            capture(self.GetRenderWindow(), "vtkRenderWindowInteractor.Start")

    class Window(base_window):
        def __init__(self, *a):
            self.SetOffScreenRendering(1)

    modules = [core, everything]
    try:
        import vtk
        modules.append(vtk)
    except ImportError:
        pass
    for m in modules:
        m.vtkRenderWindowInteractor = Interactor
        m.vtkRenderWindow = Window


def seed_randomness():
    """Examples that draw random data draw the same in every run (the
    techniques are compared frame to frame)."""
    import random
    from vtkmodules.vtkCommonCore import vtkMath
    random.seed(0)
    np.random.seed(0)
    vtkMath.RandomSeed(0)
    try:
        import vedo  # vedo's own helpers use numpy's and Python's generators
    except ImportError:
        pass


def main():
    global ARGS
    ARGS = parse_args()
    LOG.SetInstance(LOG)
    vtkOutputWindow.SetInstance(LOG)
    patch_vtk()
    patch_vedo()
    example = os.path.abspath(ARGS.example)
    ARGS.out = os.path.abspath(ARGS.out)
    os.chdir(os.path.dirname(example))
    sys.path.insert(0, os.path.dirname(example))
    sys.argv = [example]
    seed_randomness()
    runpy.run_path(example, run_name="__main__")
    # the example ended without show()/Start(): nothing captured
    with open(ARGS.out + ".json", "w") as f:
        json.dump({"example": ARGS.example, "technique": ARGS.technique,
                   "status": "no-show"}, f)
    sys.stdout.flush()
    os._exit(3)


if __name__ == "__main__":
    main()
