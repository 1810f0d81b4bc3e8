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

    roles["contour"] = contour_actor(wavelet, lut, low, high)
    roles["arrow"], roles["glyphs"] = gradient_arrows(wavelet)
    roles["outline"] = outline_actor(wavelet)
    roles["composite"] = composite_actor()
    roles["volume"] = volume_beside(wavelet, low, high)
    roles["floor"] = floor_actor()

    for name in ("contour", "glyphs", "outline", "composite", "floor"):
        renderer.AddActor(roles[name])
    renderer.AddVolume(roles["volume"])

    axes = vtkCubeAxesActor()
    axes.SetBounds(wavelet.GetOutput().GetBounds())
    axes.SetCamera(renderer.GetActiveCamera())
    roles["axes"] = axes
    renderer.AddActor(axes)

    roles["bar"], roles["text"] = overlays(lut)
    renderer.AddViewProp(roles["bar"])
    renderer.AddViewProp(roles["text"])

    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(8, 4, -6)
    camera.SetPosition(8, -95, 45)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    renderer.SetBackground(0.05, 0.05, 0.1)
    return roles


def contour_actor(wavelet, lut, low, high):
    """A contour of the wavelet, coloured by its scalars."""
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 0.5 * (low + high))
    contour.ComputeScalarsOn()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(low, high)
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def gradient_arrows(wavelet):
    """Gradient arrows on a sparse set of the wavelet's points: (the arrow
    source, kept: a temporary source would be freed; the glyph actor)."""
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
    arrow = vtkArrowSource()
    glyphs.SetSourceConnection(arrow.GetOutputPort())
    glyphs.SetOrientationArray(image.GetPointData().GetScalars().GetName())
    glyphs.OrientOn()
    glyphs.SetScaleFactor(2.5)
    glyphs.ScalingOff()
    glyphs.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(glyphs)
    actor.GetProperty().SetColor(0.9, 0.9, 0.9)
    return arrow, actor


def outline_actor(wavelet):
    """The wavelet's outline, lighting off."""
    outline = vtkOutlineFilter()
    outline.SetInputConnection(wavelet.GetOutputPort())
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(outline.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().LightingOff()
    actor.GetProperty().SetColor(1, 1, 0)
    return actor


def composite_actor():
    """A composite dataset: two spheres in one vtkMultiBlockDataSet."""
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
    actor = vtkActor()
    actor.SetMapper(composite)
    actor.GetProperty().SetColor(0.3, 0.8, 0.4)
    return actor


def volume_beside(wavelet, low, high):
    """The volume beside them (x + 34), a plain volume rendering of the wavelet."""
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
    volume = vtkVolume()
    volume.SetMapper(volume_mapper)
    volume.SetProperty(volume_property)
    volume.SetPosition(34.0, 0.0, 0.0)
    return volume


def floor_actor():
    """The floor plane under everything, at FLOOR_Z."""
    floor = vtkPlaneSource()
    floor.SetOrigin(-40, -30, FLOOR_Z)
    floor.SetPoint1(60, -30, FLOOR_Z)
    floor.SetPoint2(-40, 40, FLOOR_Z)
    floor.SetResolution(20, 14)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(floor.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.85, 0.8)
    return actor


def overlays(lut):
    """2D overlays, on the background (left and top), away from the 3D
    scene: (scalar bar, text label)."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("RTData")
    bar.SetPosition(0.02, 0.64)
    bar.SetWidth(0.08)
    bar.SetHeight(0.3)
    text = vtkTextActor()
    text.SetInput("wavelet: contour, gradient, volume")
    text.GetTextProperty().SetFontSize(16)
    text.SetDisplayPosition(150, 440)
    return bar, text
