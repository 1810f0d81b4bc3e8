// vtkShadowImpostors.cxx - the points and lines a mapper draws (see the
// header).
#include "vtkShadowImpostors.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkShadowCasterTriangles.h"
#include "vtkSmartPointer.h"

#include "vsh_impostor_proxy.h"
#include "vsh_mat4.h"
#include "vsh_raytrace.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_set>

namespace
{
// Calls visit(count, ids) for every cell of `cells`.
template <typename Visit>
void ForEachCell(vtkCellArray* cells, Visit visit)
{
  if (!cells)
  {
    return;
  }
  const vtkIdType* ids = nullptr;
  vtkIdType count = 0;
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    it->GetCurrentCell(count, ids);
    visit(count, ids);
  }
}

// The points drawn as GL points: verts' points, and with Representation
// Points every point a cell uses (each once, as the mapper's point
// primitives draw them over each other).
void AppendPoints(vtkPolyData* poly, bool allCells, std::vector<double>& out)
{
  vtkPoints* points = poly->GetPoints();
  std::vector<char> used(static_cast<size_t>(points->GetNumberOfPoints()), 0);
  auto mark = [&](vtkIdType count, const vtkIdType* ids)
  {
    for (vtkIdType k = 0; k < count; ++k)
    {
      if (ids[k] >= 0 && ids[k] < static_cast<vtkIdType>(used.size()))
      {
        used[static_cast<size_t>(ids[k])] = 1;
      }
    }
  };
  ForEachCell(poly->GetVerts(), mark);
  if (allCells)
  {
    ForEachCell(poly->GetLines(), mark);
    ForEachCell(poly->GetPolys(), mark);
    ForEachCell(poly->GetStrips(), mark);
  }
  for (size_t i = 0; i < used.size(); ++i)
  {
    if (used[i])
    {
      double p[3];
      points->GetPoint(static_cast<vtkIdType>(i), p);
      out.insert(out.end(), p, p + 3);
    }
  }
}

// Where AppendLines puts its runs: Impostors' LineVertices and Segments or
// FlatLineVertices and FlatSegments.
struct Runs
{
  std::vector<double>& Vertices;
  std::vector<unsigned int>& Segments;
};

// One polyline (or polygon edge) as a run of curve vertices.
void AppendRun(vtkPoints* points, vtkIdType count, const vtkIdType* ids, Runs out)
{
  if (count < 2 || out.Vertices.size() / 3 + count > std::numeric_limits<unsigned>::max())
  {
    return;
  }
  const auto first = static_cast<unsigned int>(out.Vertices.size() / 3);
  for (vtkIdType k = 0; k < count; ++k)
  {
    double p[3];
    points->GetPoint(ids[k], p);
    out.Vertices.insert(out.Vertices.end(), p, p + 3);
    if (k + 1 < count)
    {
      out.Segments.push_back(first + static_cast<unsigned int>(k));
    }
  }
}

// The lines drawn as GL lines: line cells, and with Representation
// Wireframe the edges of polygons and strips' triangles (an edge two
// polygons share once: one tube is drawn there, over itself).
void AppendLines(vtkPolyData* poly, bool wireframe, Runs out)
{
  vtkPoints* points = poly->GetPoints();
  const vtkIdType n = points->GetNumberOfPoints();
  ForEachCell(poly->GetLines(),
    [&](vtkIdType count, const vtkIdType* ids)
    {
      if (std::all_of(ids, ids + count, [&](vtkIdType id) { return id >= 0 && id < n; }))
      {
        AppendRun(points, count, ids, out);
      }
    });
  if (!wireframe)
  {
    return;
  }
  std::unordered_set<std::uint64_t> seen;
  auto edge = [&](vtkIdType a, vtkIdType b)
  {
    if (a < 0 || b < 0 || a >= n || b >= n || a == b)
    {
      return;
    }
    const auto key = (std::uint64_t(std::min(a, b)) << 32) ^ std::uint64_t(std::max(a, b));
    if (seen.insert(key).second)
    {
      const vtkIdType ids[2] = { a, b };
      AppendRun(points, 2, ids, out);
    }
  };
  ForEachCell(poly->GetPolys(),
    [&](vtkIdType count, const vtkIdType* ids)
    {
      for (vtkIdType k = 0; k < count && count > 1; ++k)
      {
        edge(ids[k], ids[(k + 1) % count]);
      }
    });
  ForEachCell(poly->GetStrips(),
    [&](vtkIdType count, const vtkIdType* ids)
    {
      for (vtkIdType k = 0; k + 1 < count; ++k)
      {
        edge(ids[k], ids[k + 1]);
        if (k + 2 < count)
        {
          edge(ids[k], ids[k + 2]);
        }
      }
    });
}

// Calls visit(id) for each point vtkOpenGLPointGaussianMapper draws: the
// points of its verts in order (repeats too), every point without verts.
template <typename Visit>
void ForEachSplatPoint(vtkPolyData* poly, Visit visit)
{
  const vtkIdType n = poly->GetNumberOfPoints();
  if (poly->GetNumberOfVerts() == 0)
  {
    for (vtkIdType id = 0; id < n; ++id)
    {
      visit(id);
    }
    return;
  }
  ForEachCell(poly->GetVerts(),
    [&](vtkIdType count, const vtkIdType* ids)
    {
      for (vtkIdType k = 0; k < count; ++k)
      {
        if (ids[k] >= 0 && ids[k] < n)
        {
          visit(ids[k]);
        }
      }
    });
}

// A splat's value of `array` as vtkOpenGLPointGaussianMapper reads it: the
// component asked for, the magnitude when it is out of range, the only one
// of a single-component array.
double SplatValue(vtkDataArray* array, vtkIdType id, int component)
{
  const int n = array->GetNumberOfComponents();
  if (n == 1)
  {
    return array->GetComponent(id, 0);
  }
  if (component >= 0 && component < n)
  {
    return array->GetComponent(id, component);
  }
  double sum = 0.0;
  for (int c = 0; c < n; ++c)
  {
    const double v = array->GetComponent(id, c);
    sum += v * v;
  }
  return std::sqrt(sum);
}

// The mapper's named point array of `poly`, or nullptr.
vtkDataArray* SplatArray(vtkPolyData* poly, const char* name)
{
  return name ? poly->GetPointData()->GetArray(name) : nullptr;
}

// The splats a vtkPointGaussianMapper draws (vtkOpenGLPointGaussianMapper:
// each point of its verts, every point without verts), as spheres: the
// radius is ScaleFactor times the ScaleArray's value (1 without one) put
// through ScaleFunction when there is one (the mapper's table samples that
// function); those whose opacity (OpacityArray through
// ScalarOpacityFunction, 1 without) is below 0.5 are left out.
void AppendSplats(vtkPointGaussianMapper* mapper, vtkPolyData* poly, vtkshadow::Impostors& out)
{
  vtkDataArray* scales = SplatArray(poly, mapper->GetScaleArray());
  vtkDataArray* opacities = SplatArray(poly, mapper->GetOpacityArray());
  vtkPiecewiseFunction* scaleFunction =
    mapper->GetScaleArray() ? mapper->GetScaleFunction() : nullptr;
  vtkPiecewiseFunction* opacityFunction =
    mapper->GetOpacityArray() ? mapper->GetScalarOpacityFunction() : nullptr;
  vtkPoints* points = poly->GetPoints();
  auto splat = [&](vtkIdType id)
  {
    double opacity =
      opacities ? SplatValue(opacities, id, mapper->GetOpacityArrayComponent()) : 1.0;
    opacity = opacityFunction ? opacityFunction->GetValue(opacity) : opacity;
    double size = scales ? SplatValue(scales, id, mapper->GetScaleArrayComponent()) : 1.0;
    size = scaleFunction ? scaleFunction->GetValue(size) : size;
    // A negative radius flips the triangle: the same disc.
    const double radius = std::fabs(size * mapper->GetScaleFactor());
    if (opacity >= 0.5 && radius > 0.0 && std::isfinite(radius))
    {
      double p[3];
      points->GetPoint(id, p);
      out.Splats.insert(out.Splats.end(), p, p + 3);
      out.SplatRadii.push_back(radius);
    }
  };
  ForEachSplatPoint(poly, splat);
}

// The actor's vtkPolyData input and property, or false.
bool DrawnInput(vtkActor* actor, vtkPolyData*& poly, vtkProperty*& property)
{
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  poly = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  property = actor ? actor->GetProperty() : nullptr;
  return poly && poly->GetPoints() && property && !vtkGlyph3DMapper::SafeDownCast(mapper);
}

// The extremes of `function` over [lo, hi]: at the ends or at a node in
// between (piecewise linear between its nodes).
void FunctionRange(vtkPiecewiseFunction* function, double lo, double hi, double range[2])
{
  range[0] = range[1] = function->GetValue(lo);
  auto take = [&](double x)
  {
    const double v = function->GetValue(x);
    range[0] = std::min(range[0], v);
    range[1] = std::max(range[1], v);
  };
  take(hi);
  double node[4];
  for (int i = 0; i < function->GetSize(); ++i)
  {
    function->GetNodeValue(i, node);
    if (node[0] > lo && node[0] < hi)
    {
      take(node[0]);
    }
  }
}
}

//------------------------------------------------------------------------------
vtkMTimeType vtkshadow::ImpostorTime(vtkActor* actor)
{
  vtkMTimeType t = CasterDataTime(actor);
  if (vtkProperty* property = actor ? actor->GetProperty() : nullptr)
  {
    t = std::max(t, property->GetMTime());
  }
  // The splats' scale and opacity functions are not part of the mapper's
  // time.
  if (auto* gaussian = vtkPointGaussianMapper::SafeDownCast(actor ? actor->GetMapper() : nullptr))
  {
    for (vtkPiecewiseFunction* f :
      { gaussian->GetScaleFunction(), gaussian->GetScalarOpacityFunction() })
    {
      t = std::max(t, f ? f->GetMTime() : 0);
    }
  }
  return t;
}

//------------------------------------------------------------------------------
int vtkshadow::ImpostorKinds(vtkActor* actor)
{
  vtkPolyData* poly = nullptr;
  vtkProperty* property = nullptr;
  if (!DrawnInput(actor, poly, property))
  {
    return 0;
  }
  const double pointSize = property->GetPointSize();
  if (auto* gaussian = vtkPointGaussianMapper::SafeDownCast(actor->GetMapper()))
  {
    if (poly->GetNumberOfPoints() == 0)
    {
      return 0;
    }
    return gaussian->GetScaleFactor() != 0.0 ? SPLATS : (pointSize > 1.0 ? FLAT_POINTS : 0);
  }
  const int representation = property->GetRepresentation();
  const bool cellPoints = representation == VTK_POINTS && poly->GetNumberOfCells() > 0;
  int kinds = 0;
  if (poly->GetNumberOfVerts() > 0 || cellPoints)
  {
    kinds |= property->GetRenderPointsAsSpheres() ? SPHERES : (pointSize > 1.0 ? FLAT_POINTS : 0);
  }
  const bool lines = representation != VTK_POINTS &&
    (poly->GetNumberOfLines() > 0 ||
      (representation == VTK_WIREFRAME &&
        poly->GetNumberOfPolys() + poly->GetNumberOfStrips() > 0));
  if (lines && property->GetLineWidth() > 1.0)
  {
    kinds |= property->GetRenderLinesAsTubes() ? TUBES : FLAT_LINES;
  }
  return kinds;
}

//------------------------------------------------------------------------------
bool vtkshadow::SplatRadiusRange(vtkActor* actor, double range[2])
{
  if (!(ImpostorKinds(actor) & SPLATS))
  {
    return false;
  }
  auto* mapper = vtkPointGaussianMapper::SafeDownCast(actor->GetMapper());
  auto* poly = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  vtkDataArray* scales = SplatArray(poly, mapper->GetScaleArray());
  double values[2] = { 1.0, 1.0 };
  if (scales)
  {
    const int component =
      scales->GetNumberOfComponents() == 1 ? 0 : mapper->GetScaleArrayComponent();
    scales->GetRange(values, component < scales->GetNumberOfComponents() ? component : -1);
  }
  if (vtkPiecewiseFunction* f = mapper->GetScaleArray() ? mapper->GetScaleFunction() : nullptr)
  {
    FunctionRange(f, values[0], values[1], values);
  }
  const double factor = mapper->GetScaleFactor();
  const double a = std::fabs(values[0] * factor), b = std::fabs(values[1] * factor);
  // A range across 0 holds radius 0.
  range[0] = values[0] * values[1] <= 0.0 ? 0.0 : std::min(a, b);
  range[1] = std::max(a, b);
  return true;
}

//------------------------------------------------------------------------------
void vtkshadow::AppendFlatQuads(const Impostors& drawn, const double matrix[16],
  const double projection[16], const double view[16], int width, std::vector<double>& corners)
{
  double quad[12];
  auto place = [&](const double* data, double pixels, double world[3])
  {
    vsh_mat4_transform_point(matrix, data, world);
    return vsh_rt_impostor_radius(projection, view, width, pixels, world);
  };
  for (size_t i = 0; i + 2 < drawn.FlatPoints.size(); i += 3)
  {
    double p[3];
    const double half = place(&drawn.FlatPoints[i], drawn.PointSize, p);
    if (vsh_flat_square(view, p, half, quad))
    {
      corners.insert(corners.end(), quad, quad + 12);
    }
  }
  for (unsigned int s : drawn.FlatSegments)
  {
    double a[3], b[3];
    const double ra = place(&drawn.FlatLineVertices[3 * size_t(s)], drawn.LineWidth, a);
    const double rb = place(&drawn.FlatLineVertices[3 * (size_t(s) + 1)], drawn.LineWidth, b);
    if (vsh_flat_band(projection, view, a, ra, b, rb, quad))
    {
      corners.insert(corners.end(), quad, quad + 12);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkshadow::ExtractImpostors(vtkActor* actor, Impostors& out)
{
  out = Impostors();
  const int kinds = ImpostorKinds(actor);
  if (!kinds)
  {
    return false;
  }
  vtkPolyData* poly = nullptr;
  vtkProperty* property = nullptr;
  DrawnInput(actor, poly, property);
  out.PointSize = property->GetPointSize();
  out.LineWidth = property->GetLineWidth();
  const int representation = property->GetRepresentation();
  if (auto* gaussian = vtkPointGaussianMapper::SafeDownCast(actor->GetMapper()))
  {
    // Its points are the splats (or the verts' points), whatever the
    // representation.
    if (kinds & SPLATS)
    {
      AppendSplats(gaussian, poly, out);
    }
    else
    {
      ForEachSplatPoint(poly,
        [&](vtkIdType id)
        {
          double p[3];
          poly->GetPoint(id, p);
          out.FlatPoints.insert(out.FlatPoints.end(), p, p + 3);
        });
    }
    return !out.Empty();
  }
  if (kinds & (SPHERES | FLAT_POINTS))
  {
    AppendPoints(
      poly, representation == VTK_POINTS, (kinds & SPHERES) ? out.Points : out.FlatPoints);
  }
  if (kinds & TUBES)
  {
    AppendLines(poly, representation == VTK_WIREFRAME, { out.LineVertices, out.Segments });
  }
  else if (kinds & FLAT_LINES)
  {
    AppendLines(poly, representation == VTK_WIREFRAME, { out.FlatLineVertices, out.FlatSegments });
  }
  return !out.Empty();
}
