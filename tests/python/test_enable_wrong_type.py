"""enable_shadows given something that is not a vtkRenderer (issue 29): a
TypeError that says what to pass, and nothing changed.

- an object holding a vtkRenderer in `.renderer` (vedo's and PyVista's
  Plotter): "pass plotter.renderer" (it is not taken on the caller's behalf:
  such a plotter may hold several renderers, `.renderer` being the current
  one, and the technique returned belongs to one renderer);
- a vtkRenderWindow: pass one of its renderers (and the window's renderer
  keeps its pass);
- a technique name in the renderer's place: the renderer comes first;
- None, a number, another VTK object: what was given and what is needed.

What it catches: a string, a number or a plotter raising AttributeError
('... has no attribute IsA'), and a TypeError for a window that does not
say what to pass.

Usage: test_enable_wrong_type.py"""
import sys

import vtkshadow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory overrides)
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderWindow, vtkRenderer

failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


class Plotter:
    """What vedo's (and PyVista's) Plotter looks like to enable_shadows."""

    def __init__(self):
        self.renderer = vtkRenderer()
        self.renderers = [self.renderer]


window = vtkRenderWindow()
in_window = vtkRenderer()
window.AddRenderer(in_window)
plotter = Plotter()
cases = [
    (plotter, ("plotter.renderer",)),
    (window, ("GetRenderers()", "vtkRenderWindow")),
    ("csm", ("renderer comes first", "technique='csm'")),
    (None, ("None", "vtkRenderer")),
    (42, ("int", "vtkRenderer")),
    (vtkActor(), ("vtkOpenGLActor", "vtkRenderer")),
]
for given, wanted in cases:
    try:
        vtkshadow.enable_shadows(given, "csm")
        raised = None
    except Exception as error:  # noqa: BLE001
        raised = error
    text = str(raised)
    check(isinstance(raised, TypeError) and all(w in text for w in wanted),
          f"enable_shadows({type(given).__name__}): {type(raised).__name__}: {text}")
check(in_window.GetPass() is None and plotter.renderer.GetPass() is None
      and plotter.renderer.GetLights().GetNumberOfItems() == 0,
      "nothing changed: no pass, no light")
technique = vtkshadow.enable_shadows(plotter.renderer, "csm")
check(plotter.renderer.GetPass() is not None and technique.GetRenderer() is plotter.renderer,
      "plotter.renderer is taken")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
