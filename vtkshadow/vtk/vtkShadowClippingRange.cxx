#include "vtkShadowClippingRange.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"

#include "vsh_bounds.h"
#include "vsh_camera.h"
#include "vsh_csm.h"
#include "vsh_vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
// Slack around the geometry's exact depth range: triangles drawn in float
// and rounding in the projection must not touch the planes.
constexpr double NearSlack = 0.98;
constexpr double FarSlack = 1.02;
// A prop whose box comes closer than this fraction of the far plane is
// measured on its triangles (the box is only a lower bound of its depth).
constexpr double RefineRatio = 1e-3;
// Meshes larger than this keep their box's depth (cost bound per frame).
constexpr vtkIdType MaxRefineCells = 4000000;

struct ViewFrame
{
  vsh_camera Camera;
  double Right[3], Up[3], Forward[3];
  double TanX, TanY; // half-extents of the frustum at depth 1
};

struct PropRange
{
  vtkProp* Prop;
  double Near, Far;
};

// Clip the convex polygon `in` (view coordinates, z = depth) to the side
// planes of the frustum and z >= zmin; returns the smallest depth left, or
// +inf when nothing is left.
double ClippedMinDepth(std::vector<std::array<double, 3>>& in, const ViewFrame& frame, double zmin)
{
  const double planes[5][4] = { { 0, 0, 1, -zmin }, { 1, 0, frame.TanX, 0 },
    { -1, 0, frame.TanX, 0 }, { 0, 1, frame.TanY, 0 }, { 0, -1, frame.TanY, 0 } };
  std::vector<std::array<double, 3>> out;
  for (const auto& p : planes)
  {
    out.clear();
    const size_t n = in.size();
    for (size_t i = 0; i < n; ++i)
    {
      const auto& a = in[i];
      const auto& b = in[(i + 1) % n];
      const double da = p[0] * a[0] + p[1] * a[1] + p[2] * a[2] + p[3];
      const double db = p[0] * b[0] + p[1] * b[1] + p[2] * b[2] + p[3];
      if (da >= 0)
      {
        out.push_back(a);
      }
      if ((da >= 0) != (db >= 0))
      {
        const double t = da / (da - db);
        out.push_back(
          { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]) });
      }
    }
    in.swap(out);
    if (in.empty())
    {
      return std::numeric_limits<double>::infinity();
    }
  }
  double lo = std::numeric_limits<double>::infinity();
  for (const auto& v : in)
  {
    lo = std::min(lo, v[2]);
  }
  return lo;
}

// The nearest visible depth of an actor's polygons (exact, per polygon);
// false when the actor has no polygonal input to measure.
bool TriangleNearDepth(vtkProp* prop, const ViewFrame& frame, double zmin, double& nearDepth)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  auto* poly = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!poly || !poly->GetPoints() || poly->GetNumberOfStrips() > 0 ||
    poly->GetNumberOfPolys() > MaxRefineCells)
  {
    return false;
  }
  // Points to view coordinates relative to the eye (the eye subtracted in
  // double before anything else keeps far-from-origin scenes exact).
  const double* m = actor->GetMatrix()->GetData();
  vtkPoints* points = poly->GetPoints();
  std::vector<std::array<double, 3>> view(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3], w[3];
    points->GetPoint(i, p);
    for (int r = 0; r < 3; ++r)
    {
      w[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3] -
        frame.Camera.position[r];
    }
    view[i] = { vsh_vec3_dot(w, frame.Right), vsh_vec3_dot(w, frame.Up),
      vsh_vec3_dot(w, frame.Forward) };
  }
  nearDepth = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 3>> polygon;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    polygon.clear();
    for (vtkIdType k = 0; k < n; ++k)
    {
      polygon.push_back(view[ids[k]]);
    }
    if (!polygon.empty())
    {
      nearDepth = std::min(nearDepth, ClippedMinDepth(polygon, frame, zmin));
    }
  }
  return true;
}

// Each visible prop's depth range: its bounding box clipped to the frustum.
std::vector<PropRange> BoxRanges(vtkRenderer* renderer, const ViewFrame& frame, double aspect)
{
  std::vector<PropRange> ranges;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    const double* b = prop->GetVisibility() && prop->GetUseBounds() ? prop->GetBounds() : nullptr;
    if (!b || !(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
    {
      continue;
    }
    vsh_bounds box;
    vsh_bounds_from_vtk(&box, b);
    if (!vsh_bounds_is_finite(&box))
    {
      continue;
    }
    // Far: beyond the box's farthest corner; near: a hair in front of the eye.
    double reach = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double d = std::max(std::fabs(box.min[a] - frame.Camera.position[a]),
        std::fabs(box.max[a] - frame.Camera.position[a]));
      reach += d * d;
    }
    reach = 2.0 * std::sqrt(reach) + 1e-300;
    const vsh_csm_depth_range_params depthParams = { &frame.Camera, aspect, reach * 1e-15, reach,
      &box };
    double range[2];
    if (vsh_csm_visible_depth_range(&depthParams, range) == VSH_CSM_OK)
    {
      ranges.push_back({ prop, range[0], range[1] });
    }
  }
  return ranges;
}
} // namespace

namespace vtkshadow
{
//------------------------------------------------------------------------------
bool VisibleClippingRange(vtkRenderer* renderer, double aspect, double out[2])
{
  vtkCamera* camera = renderer ? renderer->GetActiveCamera() : nullptr;
  if (!camera || camera->GetParallelProjection())
  {
    return false;
  }
  ViewFrame frame;
  camera->GetPosition(frame.Camera.position);
  camera->GetFocalPoint(frame.Camera.focal_point);
  camera->GetViewUp(frame.Camera.view_up);
  frame.Camera.view_angle = camera->GetViewAngle();
  if (vsh_camera_basis(&frame.Camera, frame.Right, frame.Up, frame.Forward) != 0 ||
    !(frame.Camera.view_angle > 0.0 && frame.Camera.view_angle < 180.0))
  {
    return false;
  }
  if (!(aspect > 0.0))
  {
    const int* size = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
    aspect = size && size[0] > 0 && size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 4.0;
  }
  frame.TanY = std::tan(vtkMath::RadiansFromDegrees(frame.Camera.view_angle) / 2.0);
  frame.TanX = frame.TanY * aspect;

  std::vector<PropRange> ranges = BoxRanges(renderer, frame, aspect);
  double far = 0.0;
  for (const PropRange& r : ranges)
  {
    far = std::max(far, r.Far);
  }
  if (ranges.empty() || !(far > 0.0))
  {
    return false;
  }
  // Boxes that reach the camera: their triangles say how close they come.
  double near = std::numeric_limits<double>::infinity();
  for (const PropRange& r : ranges)
  {
    double d = r.Near;
    if (d < RefineRatio * far && !TriangleNearDepth(r.Prop, frame, far * 1e-15, d))
    {
      d = r.Near;
    }
    near = std::min(near, d);
  }
  if (!std::isfinite(near))
  {
    return false; // boxes in view, but none of their triangles
  }
  out[1] = far * FarSlack;
  out[0] = std::max(near * NearSlack, out[1] * MinNearFarRatio);
  return true;
}

//------------------------------------------------------------------------------
void ResetClippingRange(vtkRenderer* renderer, double aspect)
{
  if (!renderer)
  {
    return;
  }
  double range[2];
  if (VisibleClippingRange(renderer, aspect, range))
  {
    renderer->GetActiveCamera()->SetClippingRange(range);
  }
  else
  {
    renderer->ResetCameraClippingRange();
  }
}
}
