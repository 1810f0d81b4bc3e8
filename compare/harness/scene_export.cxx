// scene_export.cxx - building the ExportScene from the loaded scene.
#include "scene_export.h"

#include "harness_files.h"

#include "vsh_scene.h"
#include "vtkShadowScene.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace vsh_harness
{

bool ContentKey(const vsh_scene* s, const std::string& path, std::string& key, std::string& err)
{
  std::string bytes;
  if (!ReadFile(path, bytes))
  {
    err = path + ": cannot read";
    return false;
  }
  key = "scene " + MD5Hex(bytes) + "\n";
  for (size_t i = 0; i < s->object_count; ++i)
    if (s->objects[i].kind == VSH_OBJECT_MESH)
    {
      std::string mb;
      if (!ReadFile(s->objects[i].mesh_resolved_path, mb))
      {
        err = path + ": cannot read a mesh file of objects[" + std::to_string(i) + "]";
        return false;
      }
      key += "mesh " + std::to_string(i) + " " + MD5Hex(mb) + "\n";
    }
  return true;
}

namespace
{

// Camera: x' = (x - camera position) * scale, scale a power of two bringing
// the focal distance to about 10 (exact, see ExportScene).
void ExportCamera(const vsh_camera& c, ExportScene& ex)
{
  double dist = 0;
  for (int i = 0; i < 3; ++i)
    dist += (c.focal_point[i] - c.position[i]) * (c.focal_point[i] - c.position[i]);
  dist = std::sqrt(dist);
  ex.scale = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(10.0 / dist))));
  for (int i = 0; i < 3; ++i)
  {
    ex.anchor[i] = c.position[i];
    ex.eye[i] = 0;
    ex.focal[i] = (c.focal_point[i] - c.position[i]) * ex.scale;
    ex.up[i] = c.view_up[i];
  }
  ex.view_angle = c.view_angle;
}

// One object's points, normals and triangles; grows the bounds lo/hi.
void ExportPolyData(
  vtkPolyData* pd, const ExportScene& ex, ExportObject& eo, double lo[3], double hi[3])
{
  vtkPoints* pts = pd->GetPoints();
  vtkDataArray* nrm = pd->GetPointData()->GetNormals();
  if (!nrm)
    nrm = pd->GetPointData()->GetArray("Normals");
  const vtkIdType np = pts ? pts->GetNumberOfPoints() : 0;
  eo.points.resize(3 * np);
  eo.normals.resize(3 * np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3], n[3] = { 0, 0, 1 };
    pts->GetPoint(i, p);
    if (nrm)
      nrm->GetTuple(i, n);
    for (int j = 0; j < 3; ++j)
    {
      eo.points[3 * i + j] = (p[j] - ex.anchor[j]) * ex.scale;
      eo.normals[3 * i + j] = n[j];
      lo[j] = std::min(lo[j], eo.points[3 * i + j]);
      hi[j] = std::max(hi[j], eo.points[3 * i + j]);
    }
  }
  vtkCellArray* polys = pd->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
  {
    // The loader gives triangles; fan anything larger, exactly as VTK draws it.
    for (vtkIdType t = 1; t + 1 < ids->GetNumberOfIds(); ++t)
    {
      eo.triangles.push_back(static_cast<uint32_t>(ids->GetId(0)));
      eo.triangles.push_back(static_cast<uint32_t>(ids->GetId(t)));
      eo.triangles.push_back(static_cast<uint32_t>(ids->GetId(t + 1)));
    }
  }
}

ExportLight ExportOneLight(const vsh_light& L, const ExportScene& ex)
{
  ExportLight el;
  el.type = L.type == VSH_LIGHT_DIRECTIONAL ? 0 : L.type == VSH_LIGHT_POINT ? 1 : 2;
  el.cone = L.cone_angle;
  // Directions do not scale; lengths do (a similarity transform).
  el.size = el.type == 0 ? L.angle : L.radius * ex.scale;
  if (el.type == 0)
  {
    double n = std::sqrt(L.direction[0] * L.direction[0] + L.direction[1] * L.direction[1] +
      L.direction[2] * L.direction[2]);
    // Far outside the scene: POV-Ray's parallel shadow rays stop at the
    // plane through the light position.
    const double far = 10.0 * (ex.bounds_diagonal + 1.0);
    for (int j = 0; j < 3; ++j)
    {
      el.axis[j] = L.direction[j] / n;
      el.position[j] = ex.bounds_center[j] - far * el.axis[j];
    }
    return el;
  }
  double ax[3], n = 0;
  for (int j = 0; j < 3; ++j)
  {
    el.position[j] = (L.position[j] - ex.anchor[j]) * ex.scale;
    ax[j] = el.type == 2 ? L.focal_point[j] - L.position[j] : (j == 2 ? -1.0 : 0.0);
    n += ax[j] * ax[j];
  }
  n = std::sqrt(n);
  for (int j = 0; j < 3; ++j)
    el.axis[j] = ax[j] / n;
  return el;
}

// A volume in the normalized frame; grows the bounds lo/hi by its box.
ExportVolume ExportOneVolume(const vsh_object& o, const ExportScene& ex, double lo[3], double hi[3])
{
  ExportVolume v;
  v.radius = o.radius * ex.scale;
  v.density = o.density / ex.scale; // an optical depth is density * length
  v.casts = o.casts != 0;
  for (int j = 0; j < 3; ++j)
  {
    v.center[j] = (o.center[j] - ex.anchor[j]) * ex.scale;
    lo[j] = std::min(lo[j], v.center[j] - v.radius);
    hi[j] = std::max(hi[j], v.center[j] + v.radius);
  }
  return v;
}

} // namespace

bool BuildExport(vtkShadowScene* vs, const vsh_scene* s, int w, int h, ExportScene& ex)
{
  ex.width = w;
  ex.height = h;
  ExportCamera(s->camera, ex);
  double lo[3] = { 1e308, 1e308, 1e308 }, hi[3] = { -1e308, -1e308, -1e308 };
  for (int o = 0; o < vs->GetNumberOfObjects(); ++o)
  {
    vtkPolyData* pd = vs->GetObjectPolyData(o);
    if (!pd)
      return false;
    ExportObject eo;
    eo.casts = vs->GetObjectCasts(o);
    vs->GetObjectColor(o, eo.color);
    eo.mirror = vs->GetObjectMirror(o);
    eo.opacity = vs->GetObjectOpacity(o);
    eo.filter = vs->GetObjectFilter(o);
    ex.has_mirror = ex.has_mirror || eo.mirror > 0;
    ex.tinted = ex.tinted || (eo.opacity < 1 && eo.filter > 0);
    ExportPolyData(pd, ex, eo, lo, hi);
    if (!eo.triangles.empty())
      ex.objects.push_back(std::move(eo));
  }
  for (size_t i = 0; i < s->object_count; ++i)
    if (s->objects[i].kind == VSH_OBJECT_VOLUME)
      ex.volumes.push_back(ExportOneVolume(s->objects[i], ex, lo, hi));
  double diag = 0;
  for (int j = 0; j < 3; ++j)
  {
    ex.bounds_center[j] = 0.5 * (lo[j] + hi[j]);
    diag += (hi[j] - lo[j]) * (hi[j] - lo[j]);
  }
  ex.bounds_diagonal = std::sqrt(diag);
  for (size_t k = 0; k < s->light_count; ++k)
    ex.lights.push_back(ExportOneLight(s->lights[k], ex));
  return true;
}

} // namespace vsh_harness
