#include "vtkShadowReceiverPlane.h"

#include "vtkActor.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShadowActorFlags.h"
#include "vtkSmartPointer.h"

#include "vsh_mat4.h"
#include "vsh_plane.h"

#include <vector>

namespace vtkshadow
{
namespace
{
// The points of a poly data in world coordinates, appended to `world`.
void AppendWorldPoints(vtkPolyData* poly, const double m[16], std::vector<double>& world)
{
  if (!poly || !poly->GetPoints())
  {
    return;
  }
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    double p[3], w[3];
    poly->GetPoint(i, p);
    vsh_mat4_transform_point(m, p, w);
    world.insert(world.end(), w, w + 3);
  }
}
}

// The plane of a receiver actor's flat geometry in world coordinates, or
// false when the geometry is not flat (within 1e-6 of its size) or empty.
// The input is a poly data or, as ParaView's representations give it, a
// composite data set of poly data leaves.
bool ReceiverPlane(vtkActor* actor, double plane[4])
{
  vtkMapper* mapper = actor->GetMapper();
  vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  double m[16];
  vtkMatrix4x4::DeepCopy(m, actor->GetMatrix());
  std::vector<double> world;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      AppendWorldPoints(vtkPolyData::SafeDownCast(it->GetCurrentDataObject()), m, world);
    }
  }
  else
  {
    AppendWorldPoints(vtkPolyData::SafeDownCast(data), m, world);
  }
  if (world.size() < 9)
  {
    return false;
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
