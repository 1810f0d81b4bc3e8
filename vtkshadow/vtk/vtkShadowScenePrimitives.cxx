// vtkShadowScenePrimitives.cxx - impostor actors and the volume blob of a
// scene file (vtkShadowScenePrimitives.h).
#include "vtkShadowScenePrimitives.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "vsh_scene.h"

#include <algorithm>
#include <cmath>

namespace vtkshadow
{

vtkSmartPointer<vtkPolyData> NewImpostorPolyData(const vsh_object& object)
{
  const vtkIdType n = static_cast<vtkIdType>(object.position_count);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, object.positions + 3 * i);
  }
  vtkNew<vtkCellArray> cells;
  if (object.kind == VSH_OBJECT_POLYLINE)
  {
    cells->InsertNextCell(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      cells->InsertCellPoint(i);
    }
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      cells->InsertNextCell(1, &i);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (object.kind == VSH_OBJECT_POLYLINE)
  {
    data->SetLines(cells);
  }
  else
  {
    data->SetVerts(cells);
  }
  return data;
}

vtkSmartPointer<vtkActor> NewImpostorActor(
  const vsh_object& object, vtkPolyData* data, double pixelScale)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* p = actor->GetProperty();
  const float pixels = static_cast<float>(object.pixels * pixelScale);
  if (object.kind == VSH_OBJECT_POLYLINE)
  {
    p->RenderLinesAsTubesOn();
    p->SetLineWidth(pixels);
  }
  else
  {
    p->RenderPointsAsSpheresOn();
    p->SetPointSize(pixels);
  }
  return actor;
}

namespace
{
// Extinction profile max(0, 1 - d / radius) on samples^3 points spanning the
// blob's box (the field is 0 on the box's faces, so clamping is harmless).
vtkSmartPointer<vtkImageData> BlobField(const vsh_object& object)
{
  const int n = object.samples;
  const double spacing = 2.0 * object.radius / (n - 1);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(spacing, spacing, spacing);
  image->SetOrigin(object.center[0] - object.radius, object.center[1] - object.radius,
    object.center[2] - object.radius);
  vtkNew<vtkFloatArray> field;
  field->SetName("profile");
  field->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i, ++id)
      {
        const double d[3] = { -object.radius + i * spacing, -object.radius + j * spacing,
          -object.radius + k * spacing };
        const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        field->SetValue(id, static_cast<float>(std::max(0.0, 1.0 - r / object.radius)));
      }
    }
  }
  image->GetPointData()->SetScalars(field);
  return image;
}
}

vtkSmartPointer<vtkVolume> NewBlobVolume(const vsh_object& object, const double color[3])
{
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputData(BlobField(object));
  // Opacity at unit distance u = radius for profile s: a step ds keeps
  // (1 - a)^(ds / u) = exp(-density * s * ds) when a = 1 - exp(-density s u).
  // Tabulated finely enough that the piecewise-linear curve is within 1e-3.
  vtkNew<vtkPiecewiseFunction> opacity;
  const int steps = 64;
  for (int i = 0; i <= steps; ++i)
  {
    const double s = static_cast<double>(i) / steps;
    opacity->AddPoint(s, 1.0 - std::exp(-object.density * object.radius * s));
  }
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, color[0], color[1], color[2]);
  colors->AddRGBPoint(1.0, color[0], color[1], color[2]);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(colors);
  property->SetScalarOpacityUnitDistance(object.radius);
  property->SetInterpolationTypeToLinear();
  property->ShadeOff();
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  return volume;
}

} // namespace vtkshadow
