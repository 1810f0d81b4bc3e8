// vtkShadowImpostors.cxx - the points and lines a mapper draws (see the
// header).
#include "vtkShadowImpostors.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkGlyph3DMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkShadowCasterTriangles.h"
#include "vtkSmartPointer.h"

#include <algorithm>
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

// One polyline (or polygon edge) as a run of curve vertices.
void AppendRun(vtkPoints* points, vtkIdType count, const vtkIdType* ids, vtkshadow::Impostors& out)
{
  if (count < 2 || out.LineVertices.size() / 3 + count > std::numeric_limits<unsigned>::max())
  {
    return;
  }
  const auto first = static_cast<unsigned int>(out.LineVertices.size() / 3);
  for (vtkIdType k = 0; k < count; ++k)
  {
    double p[3];
    points->GetPoint(ids[k], p);
    out.LineVertices.insert(out.LineVertices.end(), p, p + 3);
    if (k + 1 < count)
    {
      out.Segments.push_back(first + static_cast<unsigned int>(k));
    }
  }
}

// The lines drawn as GL lines: line cells, and with Representation
// Wireframe the edges of polygons and strips' triangles (an edge two
// polygons share once: one tube is drawn there, over itself).
void AppendLines(vtkPolyData* poly, bool wireframe, vtkshadow::Impostors& out)
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
}

//------------------------------------------------------------------------------
vtkMTimeType vtkshadow::ImpostorTime(vtkActor* actor)
{
  vtkMTimeType t = CasterDataTime(actor);
  if (vtkProperty* property = actor ? actor->GetProperty() : nullptr)
  {
    t = std::max(t, property->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
bool vtkshadow::ExtractImpostors(vtkActor* actor, Impostors& out)
{
  out = Impostors();
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  auto* poly = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!poly || !poly->GetPoints() || vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  const int representation = property ? property->GetRepresentation() : VTK_SURFACE;
  if (!property)
  {
    return false;
  }
  out.PointSize = property->GetPointSize();
  out.LineWidth = property->GetLineWidth();
  // The solids only: the mapper's DrawingSpheres / DrawingTubes (tubes need
  // a width above 1, else it draws plain lines).
  if (property->GetRenderPointsAsSpheres())
  {
    AppendPoints(poly, representation == VTK_POINTS, out.Points);
  }
  if (property->GetRenderLinesAsTubes() && out.LineWidth > 1.0 && representation != VTK_POINTS)
  {
    AppendLines(poly, representation == VTK_WIREFRAME, out);
  }
  return !out.Empty();
}
