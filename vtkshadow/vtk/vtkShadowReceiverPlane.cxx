#include "vtkShadowReceiverPlane.h"

#include "vtkActor.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShadowActorFlags.h"

#include "vsh_mat4.h"

#include <algorithm>
#include <cmath>
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
  // The normal of the largest triangle fanned from point 0 (robust for
  // slivers and collinear leading points).
  const double* o = world.data();
  double best[3] = { 0, 0, 0 }, bestLength = 0.0;
  for (size_t i = 1; i + 1 < world.size() / 3; ++i)
  {
    const double a[3] = { world[3 * i] - o[0], world[3 * i + 1] - o[1], world[3 * i + 2] - o[2] };
    const double b[3] = { world[3 * i + 3] - o[0], world[3 * i + 4] - o[1],
      world[3 * i + 5] - o[2] };
    const double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > bestLength)
    {
      bestLength = length;
      std::copy_n(n, 3, best);
    }
  }
  if (!(bestLength > 0.0))
  {
    return false;
  }
  double size = 0.0;
  for (size_t i = 0; i < world.size() / 3; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      size = std::max(size, std::abs(world[3 * i + a] - o[a]));
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    plane[a] = best[a] / bestLength;
  }
  plane[3] = -(plane[0] * o[0] + plane[1] * o[1] + plane[2] * o[2]);
  for (size_t i = 0; i < world.size() / 3; ++i)
  {
    const double* p = &world[3 * i];
    const double d = plane[0] * (p[0] - o[0]) + plane[1] * (p[1] - o[1]) + plane[2] * (p[2] - o[2]);
    if (std::abs(d) > 1e-6 * size)
    {
      return false;
    }
  }
  return true;
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
