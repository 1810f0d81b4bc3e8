"""A typical VTK science script, as a new user writes it (issue 19): the
wavelet source, a contour coloured by its scalars, gradient arrow glyphs, an
outline with lighting off, cube axes, a scalar bar, a text label, a volume
beside them, a composite dataset and a floor plane. build() returns the
actors by role so tests can hide or inspect them."""
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkMaskPoints
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersModeling import vtkOutlineFilter
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkImagingCore import vtkImageShiftScale
from vtkmodules.vtkImagingCore import vtkImageCast
from vtkmodules.vtkImagingGeneral import vtkImageGradient
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingAnnotation import vtkCubeAxesActor, vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkGlyph3DMapper,
                                         vtkPolyDataMapper, vtkTextActor, vtkVolume,
                                         vtkVolumeProperty)
from vtkmodules.vtkRenderingOpenGL2 import vtkCompositePolyDataMapper2
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper
from vtkmodules.vtkCommonTransforms import vtkTransform
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

FLOOR_Z = -14.0


def build(renderer):
    roles = {}
    wavelet = vtkRTAnalyticSource()  # 21^3 samples over [-10, 10]^3, scalars RTData
    wavelet.Update()
    low, high = wavelet.GetOutput().GetScalarRange()

    lut = vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetTableRange(low, high)
    lut.Build()

    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 0.5 * (low + high))
    contour.ComputeScalarsOn()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(low, high)
    roles["contour"] = vtkActor()
    roles["contour"].SetMapper(mapper)

    # Gradient arrows on a sparse set of the wavelet's points.
    gradient = vtkImageGradient()
    gradient.SetDimensionality(3)
    gradient.SetInputConnection(wavelet.GetOutputPort())
    gradient.Update()
    image = gradient.GetOutput()
    image.GetPointData().SetActiveVectors(image.GetPointData().GetScalars().GetName())
    sparse = vtkMaskPoints()
    sparse.SetInputData(image)
    sparse.SetOnRatio(97)
    sparse.GenerateVerticesOn()
    glyphs = vtkGlyph3DMapper()
    glyphs.SetInputConnection(sparse.GetOutputPort())
    arrow = vtkArrowSource()  # kept: a temporary source would be freed
    roles["arrow"] = arrow
    glyphs.SetSourceConnection(arrow.GetOutputPort())
    glyphs.SetOrientationArray(image.GetPointData().GetScalars().GetName())
    glyphs.OrientOn()
    glyphs.SetScaleFactor(2.5)
    glyphs.ScalingOff()
    glyphs.ScalarVisibilityOff()
    roles["glyphs"] = vtkActor()
    roles["glyphs"].SetMapper(glyphs)
    roles["glyphs"].GetProperty().SetColor(0.9, 0.9, 0.9)

    outline = vtkOutlineFilter()
    outline.SetInputConnection(wavelet.GetOutputPort())
    outline_mapper = vtkPolyDataMapper()
    outline_mapper.SetInputConnection(outline.GetOutputPort())
    roles["outline"] = vtkActor()
    roles["outline"].SetMapper(outline_mapper)
    roles["outline"].GetProperty().LightingOff()
    roles["outline"].GetProperty().SetColor(1, 1, 0)

    # A composite dataset: two spheres in one vtkMultiBlockDataSet.
    blocks = vtkMultiBlockDataSet()
    for i, centre in enumerate(((-15.0, -4.0, -9.0), (-15.0, 6.0, -6.0))):
        sphere = vtkSphereSource()
        sphere.SetCenter(*centre)
        sphere.SetRadius(3.0)
        sphere.SetThetaResolution(32)
        sphere.SetPhiResolution(16)
        sphere.Update()
        blocks.SetBlock(i, sphere.GetOutput())
    composite = vtkCompositePolyDataMapper2()
    composite.SetInputDataObject(blocks)
    roles["composite"] = vtkActor()
    roles["composite"].SetMapper(composite)
    roles["composite"].GetProperty().SetColor(0.3, 0.8, 0.4)

    # The volume beside them (x + 34), a plain volume rendering of the wavelet.
    cast = vtkImageShiftScale()
    cast.SetInputConnection(wavelet.GetOutputPort())
    cast.SetShift(-low)
    cast.SetScale(255.0 / (high - low))
    cast.SetOutputScalarTypeToUnsignedChar()
    volume_mapper = vtkSmartVolumeMapper()
    volume_mapper.SetInputConnection(cast.GetOutputPort())
    colours = vtkColorTransferFunction()
    colours.AddRGBPoint(0, 0.2, 0.2, 1.0)
    colours.AddRGBPoint(255, 1.0, 0.3, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0, 0.0)
    opacity.AddPoint(120, 0.0)
    opacity.AddPoint(255, 0.6)
    volume_property = vtkVolumeProperty()
    volume_property.SetColor(colours)
    volume_property.SetScalarOpacity(opacity)
    roles["volume"] = vtkVolume()
    roles["volume"].SetMapper(volume_mapper)
    roles["volume"].SetProperty(volume_property)
    roles["volume"].SetPosition(34.0, 0.0, 0.0)

    floor = vtkPlaneSource()
    floor.SetOrigin(-40, -30, FLOOR_Z)
    floor.SetPoint1(60, -30, FLOOR_Z)
    floor.SetPoint2(-40, 40, FLOOR_Z)
    floor.SetResolution(20, 14)
    floor_mapper = vtkPolyDataMapper()
    floor_mapper.SetInputConnection(floor.GetOutputPort())
    roles["floor"] = vtkActor()
    roles["floor"].SetMapper(floor_mapper)
    roles["floor"].GetProperty().SetColor(0.85, 0.85, 0.8)

    for name in ("contour", "glyphs", "outline", "composite", "floor"):
        renderer.AddActor(roles[name])
    renderer.AddVolume(roles["volume"])

    axes = vtkCubeAxesActor()
    axes.SetBounds(wavelet.GetOutput().GetBounds())
    axes.SetCamera(renderer.GetActiveCamera())
    roles["axes"] = axes
    renderer.AddActor(axes)

    # 2D overlays, on the background (left and top), away from the 3D scene.
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("RTData")
    bar.SetPosition(0.02, 0.64)
    bar.SetWidth(0.08)
    bar.SetHeight(0.3)
    roles["bar"] = bar
    renderer.AddViewProp(bar)
    text = vtkTextActor()
    text.SetInput("wavelet: contour, gradient, volume")
    text.GetTextProperty().SetFontSize(16)
    text.SetDisplayPosition(150, 440)
    roles["text"] = text
    renderer.AddViewProp(text)

    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(8, 4, -6)
    camera.SetPosition(8, -95, 45)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    renderer.SetBackground(0.05, 0.05, 0.1)
    return roles
