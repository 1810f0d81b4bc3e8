#include "vtkShadowReceiverPlane.h"

#include "vtkActor.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShadowActorFlags.h"

#include "vsh_mat4.h"
#include "vsh_plane.h"

#include <vector>

namespace vtkshadow
{
// The plane of a receiver actor's flat geometry in world coordinates, or
// false when the geometry is not flat (within 1e-6 of its size) or empty.
bool ReceiverPlane(vtkActor* actor, double plane[4])
{
  vtkMapper* mapper = actor->GetMapper();
  auto* poly = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
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
  // Largest fan triangle's normal, flat within 1e-6 of the points' size.
  return vsh_plane_fit_points(world.data(), world.size() / 3, 1e-6, plane) == VSH_PLANE_OK;
}

//------------------------------------------------------------------------------
ReceiverPlaneCache::Entry& ReceiverPlaneCache::Get(vtkActor* actor)
{
  Entry& entry = this->Entries[actor];
  const vtkMTimeType t = std::max(actor->GetMatrix()->GetMTime(), vtkshadow::MeshTime(actor));
  if (t > entry.Time || entry.Time == 0)
  {
    entry.Time = t;
    entry.Flat = ReceiverPlane(actor, entry.Plane);
    entry.Reported = false;
  }
  return entry;
}
}
