#include "vtkShadowReceiverPlane.h"

#include "vtkActor.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShadowActorFlags.h"
#include "vtkSmartPointer.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"

#include "vsh_bounds.h"
#include "vsh_flat_parts.h"
#include "vsh_mat4.h"
#include "vsh_plane.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace vtkshadow
{
namespace
{
// The poly data a polydata mapper draws as itself: its input, or, as
// ParaView's representations give it, the poly data leaves of a composite
// data set. Glyph mappers take points too, but draw shapes at them, which
// are not the points' plane, so they give nothing.
std::vector<vtkPolyData*> DrawnPolyData(vtkMapper* mapper)
{
  std::vector<vtkPolyData*> leaves;
  if (!mapper || !mapper->IsA("vtkPolyDataMapper"))
  {
    return leaves;
  }
  vtkDataObject* data = mapper->GetInputDataObject(0, 0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* poly = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        leaves.push_back(poly);
      }
    }
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    leaves.push_back(poly);
  }
  return leaves;
}
}

// The plane of a receiver actor's flat geometry in world coordinates, or
// false when the geometry is not flat (within 1e-6 of its size) or empty.
bool ReceiverPlane(vtkActor* actor, const double m[16], double plane[4], bool* surface)
{
  const std::vector<vtkPolyData*> leaves = DrawnPolyData(actor->GetMapper());
  std::vector<double> world;
  bool hasSurface = false;
  bool floatStorage = false;
  for (vtkPolyData* poly : leaves)
  {
    hasSurface = hasSurface || poly->GetNumberOfPolys() > 0 || poly->GetNumberOfStrips() > 0;
    if (!poly->GetPoints())
    {
      continue;
    }
    floatStorage = floatStorage || poly->GetPoints()->GetDataType() == VTK_FLOAT;
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
    {
      double p[3], w[3];
      poly->GetPoint(i, p);
      vsh_mat4_transform_point(m, p, w);
      world.insert(world.end(), w, w + 3);
    }
  }
  if (surface)
  {
    *surface = hasSurface;
  }
  if (world.size() < 9)
  {
    return false;
  }
  // Largest fan triangle's normal, flat within 1e-6 of the points' size
  // and the rounding of float storage (a float floor far from the origin).
  const double stored = floatStorage ? FLT_EPSILON : 0.0;
  return vsh_plane_fit_stored_points(world.data(), world.size() / 3, 1e-6, stored, plane) ==
    VSH_PLANE_OK;
}

namespace
{
// Every polygon (fanned) and strip of `cells` as triangles, indices offset
// by `base`; false when there are more than `limit` in all.
bool AppendTriangles(
  vtkCellArray* cells, bool strips, long long base, std::vector<long long>& triangles, size_t limit)
{
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 2; k < n; ++k)
    {
      // A strip's odd triangles are wound the other way round.
      const bool flip = strips && (k % 2 == 1);
      const vtkIdType a = strips ? ids[k - 2] : ids[0];
      const vtkIdType b = flip ? ids[k] : ids[k - 1];
      const vtkIdType c = flip ? ids[k - 1] : ids[k];
      triangles.insert(triangles.end(), { base + a, base + b, base + c });
    }
    if (triangles.size() > 3 * limit)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
std::vector<FlatPart> FlatParts(vtkActor* actor, const double m[16])
{
  // Sorting the triangles once per mesh change is cheap up to millions;
  // beyond, a mesh that is not flat as a whole is left without parts.
  const size_t limit = 4u << 20;
  std::vector<double> world;
  std::vector<long long> triangles;
  vsh_bounds box;
  vsh_bounds_init_empty(&box);
  for (vtkPolyData* poly : DrawnPolyData(actor->GetMapper()))
  {
    if (!poly->GetPoints())
    {
      continue;
    }
    const long long base = static_cast<long long>(world.size() / 3);
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
    {
      double p[3], w[3];
      poly->GetPoint(i, p);
      vsh_mat4_transform_point(m, p, w);
      world.insert(world.end(), w, w + 3);
      vsh_bounds_add_point(&box, w);
    }
    if (!AppendTriangles(poly->GetPolys(), false, base, triangles, limit) ||
      !AppendTriangles(poly->GetStrips(), true, base, triangles, limit))
    {
      return {};
    }
  }
  vsh_flat_part found[6];
  const int n = vsh_flat_parts(world.data(), world.size() / 3, triangles.data(),
    triangles.size() / 3, 1e-4, 1e-5, 0.05, found, 6);
  double largest = 0.0; // the largest absolute coordinate, for float rounding
  for (int k = 0; k < 3 && !vsh_bounds_is_empty(&box); ++k)
  {
    largest = std::max({ largest, std::abs(box.min[k]), std::abs(box.max[k]) });
  }
  const double diagonal = vsh_bounds_diagonal_length(&box);
  std::vector<FlatPart> parts;
  for (int i = 0; i < n; ++i)
  {
    // On the part: within the grouping's tolerance and the rounding of
    // float points far from the origin.
    parts.push_back(
      { { found[i].plane[0], found[i].plane[1], found[i].plane[2], found[i].plane[3] },
        found[i].area, 1e-5 * diagonal + 4.0 * FLT_EPSILON * largest });
  }
  return parts;
}

//------------------------------------------------------------------------------
const std::vector<FlatPart>& ReceiverPlaneCache::GetParts(const ShadowActor& actor)
{
  Entry& entry = this->Get(actor);
  if (!entry.PartsDone)
  {
    entry.Parts =
      entry.Flat || !entry.Surface ? std::vector<FlatPart>() : FlatParts(actor.Actor, actor.Matrix);
    entry.PartsDone = true;
  }
  return entry.Parts;
}

//------------------------------------------------------------------------------
ReceiverPlaneCache::Entry& ReceiverPlaneCache::Get(const ShadowActor& actor)
{
  Entry& entry = this->Entries[{ actor.Actor, actor.Instance }];
  const vtkMTimeType t = vtkshadow::MeshTime(actor.Actor);
  if (t > entry.Time || entry.Time == 0 ||
    !std::equal(actor.Matrix, actor.Matrix + 16, entry.Matrix))
  {
    entry.Time = t;
    std::copy_n(actor.Matrix, 16, entry.Matrix);
    entry.Flat = ReceiverPlane(actor.Actor, actor.Matrix, entry.Plane, &entry.Surface);
    entry.Reported = false;
    entry.PartsDone = false;
  }
  return entry;
}

//------------------------------------------------------------------------------
ReceiverChoice ChooseReceivers(const std::vector<ShadowActor>& actors,
  const std::vector<vtkActor*>& added, vtkInformationIntegerKey* receiverKey, bool detect,
  ReceiverPlaneCache& cache)
{
  ReceiverChoice choice;
  for (const ShadowActor& actor : actors)
  {
    if (HasFlag(actor, receiverKey) ||
      std::find(added.begin(), added.end(), actor.Actor) != added.end())
    {
      choice.Receivers.push_back(actor);
    }
  }
  if (!choice.Receivers.empty() || !detect)
  {
    return choice;
  }
  for (const ShadowActor& actor : actors)
  {
    if (FlagKeys(actor, receiverKey))
    {
      continue; // RECEIVER() = 0: opted out
    }
    const ReceiverPlaneCache::Entry& entry = cache.Get(actor);
    if (entry.Flat && entry.Surface)
    {
      choice.Receivers.push_back(actor);
    }
  }
  choice.Detected = !choice.Receivers.empty();
  return choice;
}
}
