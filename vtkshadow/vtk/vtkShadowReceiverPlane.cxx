#include "vtkShadowReceiverPlane.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShadowActorFlags.h"

#include "vsh_mat4.h"
#include "vsh_plane.h"

#include <algorithm>
#include <cfloat>
#include <vector>

namespace vtkshadow
{
// The plane of a receiver actor's flat geometry in world coordinates, or
// false when the geometry is not flat (within 1e-6 of its size) or empty.
bool ReceiverPlane(vtkActor* actor, double plane[4], bool* surface)
{
  vtkMapper* mapper = actor->GetMapper();
  // A polydata drawn as itself: glyph mappers take points too, but draw
  // shapes at them, which are not the points' plane.
  auto* poly = mapper && mapper->IsA("vtkPolyDataMapper")
    ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0))
    : nullptr;
  if (surface)
  {
    *surface = poly && (poly->GetNumberOfPolys() > 0 || poly->GetNumberOfStrips() > 0);
  }
  if (!poly || !poly->GetPoints() || poly->GetNumberOfPoints() < 3)
  {
    return false;
  }
  double m[16];
  vtkMatrix4x4::DeepCopy(m, actor->GetMatrix());
  std::vector<double> world(3 * poly->GetNumberOfPoints());
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    double p[3];
    poly->GetPoint(i, p);
    vsh_mat4_transform_point(m, p, &world[3 * i]);
  }
  // Largest fan triangle's normal, flat within 1e-6 of the points' size
  // and the rounding of float storage (a float floor far from the origin).
  const double stored = poly->GetPoints()->GetDataType() == VTK_FLOAT ? FLT_EPSILON : 0.0;
  return vsh_plane_fit_stored_points(world.data(), world.size() / 3, 1e-6, stored, plane) ==
    VSH_PLANE_OK;
}

//------------------------------------------------------------------------------
ReceiverPlaneCache::Entry& ReceiverPlaneCache::Get(vtkActor* actor)
{
  Entry& entry = this->Entries[actor];
  const vtkMTimeType t = std::max(actor->GetMatrix()->GetMTime(), vtkshadow::MeshTime(actor));
  if (t > entry.Time || entry.Time == 0)
  {
    entry.Time = t;
    entry.Flat = ReceiverPlane(actor, entry.Plane, &entry.Surface);
    entry.Reported = false;
  }
  return entry;
}

//------------------------------------------------------------------------------
ReceiverChoice ChooseReceivers(const std::vector<vtkActor*>& actors,
  const std::vector<vtkActor*>& added, vtkInformationIntegerKey* receiverKey, bool detect,
  ReceiverPlaneCache& cache)
{
  ReceiverChoice choice;
  for (vtkActor* actor : actors)
  {
    if (HasFlag(actor, receiverKey) || std::find(added.begin(), added.end(), actor) != added.end())
    {
      choice.Receivers.push_back(actor);
    }
  }
  if (!choice.Receivers.empty() || !detect)
  {
    return choice;
  }
  for (vtkActor* actor : actors)
  {
    vtkInformation* keys = actor->GetPropertyKeys();
    if (keys && keys->Has(receiverKey))
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
