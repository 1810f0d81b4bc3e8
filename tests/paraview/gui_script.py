"""Run inside the ParaView GUI (run_gui.sh): the plugin's view opens in the
GUI's layout and renders shadows; the screenshot goes to
$VTKSHADOW_GUI_SCREENSHOT. Any failure leaves no screenshot."""
import os

from paraview.simple import (AssignViewToLayout, CreateView, GetLayout, Plane, Render,
                             SaveScreenshot, Show, Sphere)

view = CreateView("RenderViewWithShadows")
AssignViewToLayout(view=view, layout=GetLayout())
view.ShadowTechnique = "csm"
Show(Sphere(Center=[0, 0, 1.2], Radius=0.5), view)
Show(Plane(Origin=[-5, -5, 0], Point1=[5, -5, 0], Point2=[-5, 5, 0]), view)
view.CameraPosition = [0, -8, 5]
view.CameraFocalPoint = [0, 0, 0.5]
view.CameraViewUp = [0, 0, 1]
Render(view)
SaveScreenshot(os.environ["VTKSHADOW_GUI_SCREENSHOT"], view, ImageResolution=[480, 360])
