#include "vtkShadowEmbreeScene.h"

#include "vsh_rt_classify.h"

#include "vsh_mat4.h"
#include "vsh_raytrace.h"
#include "vtkActor.h"
#include "vtkShadowCasterTriangles.h"
#include "vtkShadowImpostors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace
{
double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void OnEmbreeError(void* user, RTCError code, const char* message)
{
  auto* error = static_cast<std::string*>(user);
  *error = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
    (message ? message : "(no message)");
}

// The cofactor matrix of the actor's 3x3: proportional to its inverse
// transpose, so it maps object normals to world normals (up to length and,
// for mirroring matrices, sign; the tracer normalizes and orients them).
void Cofactors(const double m[16], double out[9])
{
  auto a = [&](int r, int c) { return m[4 * r + c]; };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      out[3 * r + c] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
    }
  }
}

// Commits `geometry` and hands it to `scene` (which keeps it).
void CommitInto(RTCScene scene, RTCGeometry geometry)
{
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
}

// What an impostor instance points its triangle lookup at: nothing.
const std::vector<float> NoVertices;
const std::vector<unsigned int> NoIndices;

// Fills a FLOAT4 (x y z radius) vertex buffer of `count` vertices from
// data-coordinate positions: placed by `matrix`, relative to `centre`, each
// with the world radius of `pixels` at its place. Returns the largest radius.
double FillImpostorVertices(const double* data, size_t count, const double matrix[16],
  const double centre[3], const vtkShadowEmbreeScene::Camera& camera, double pixels, float* out)
{
  double largest = 0;
  for (size_t i = 0; i < count; ++i)
  {
    double world[3];
    vsh_mat4_transform_point(matrix, data + 3 * i, world);
    const double radius =
      vsh_rt_impostor_radius(camera.Projection, camera.View, camera.Width, pixels, world);
    largest = std::max(largest, radius);
    for (int r = 0; r < 3; ++r)
    {
      out[4 * i + r] = static_cast<float>(world[r] - centre[r]);
    }
    out[4 * i + 3] = static_cast<float>(radius);
  }
  return largest;
}
}

struct vtkShadowEmbreeScene::Mesh
{
  RTCScene Scene = nullptr;
  vtkMTimeType DataTime = 0;
  double Shift[3] = { 0, 0, 0 };
  double Radius = 0; // in data units, about Shift
  long long Triangles = 0;
  std::vector<float> Vertices; // kept for the tracer's double-precision landing
  std::vector<unsigned int> Indices;
  // Its spheres and tubes (vtkShadowImpostors), in data coordinates: the
  // top levels size and place them (AddImpostors).
  vtkshadow::Impostors Drawn;
  vtkMTimeType ImpostorTime = 0;
  int Version = 0;
  bool Seen = false;

  // Whether it puts anything in the top levels.
  bool Used() const { return this->Triangles > 0 || !this->Drawn.Empty(); }

  ~Mesh()
  {
    if (this->Scene)
    {
      rtcReleaseScene(this->Scene);
    }
  }
};

//------------------------------------------------------------------------------
vtkShadowEmbreeScene::vtkShadowEmbreeScene() = default;

//------------------------------------------------------------------------------
vtkShadowEmbreeScene::~vtkShadowEmbreeScene()
{
  this->Meshes.clear();
  for (RTCScene scene : this->ImpostorScenes)
  {
    rtcReleaseScene(scene);
  }
  if (this->Visible)
  {
    rtcReleaseScene(this->Visible);
  }
  if (this->Casters)
  {
    rtcReleaseScene(this->Casters);
  }
  if (this->Device)
  {
    rtcReleaseDevice(this->Device);
  }
}

//------------------------------------------------------------------------------
long long vtkShadowEmbreeScene::GetNumberOfTriangles() const
{
  long long n = 0;
  for (const auto& entry : this->Meshes)
  {
    n += entry.second->Triangles;
  }
  return n;
}

//------------------------------------------------------------------------------
vtkShadowEmbreeScene::Mesh* vtkShadowEmbreeScene::UpdateMesh(vtkActor* actor)
{
  std::unique_ptr<Mesh>& slot = this->Meshes[actor];
  if (!slot)
  {
    slot.reset(new Mesh);
  }
  Mesh& mesh = *slot;
  mesh.Seen = true;
  const vtkMTimeType impostorTime = vtkshadow::ImpostorTime(actor);
  if (!mesh.Scene || impostorTime != mesh.ImpostorTime)
  {
    // Spheres and tubes: a copy of the data, sized per frame (cheap to
    // redo; the property's point size and representation count too).
    vtkshadow::ExtractImpostors(actor, mesh.Drawn);
    mesh.ImpostorTime = impostorTime;
    ++mesh.Version;
  }
  const vtkMTimeType dataTime = vtkshadow::CasterDataTime(actor);
  if (mesh.Scene && dataTime == mesh.DataTime)
  {
    return mesh.Used() ? &mesh : nullptr;
  }
  const auto start = std::chrono::steady_clock::now();
  mesh.DataTime = dataTime;
  if (mesh.Scene)
  {
    rtcReleaseScene(mesh.Scene);
    mesh.Scene = nullptr;
  }
  mesh.Triangles = 0;
  vtkshadow::CasterTriangles triangles;
  vtkshadow::ExtractCasterTriangles(actor, triangles);
  const size_t vertexCount = triangles.Vertices.size() / 3;
  const size_t triangleCount = triangles.Indices.size() / 3;
  mesh.Scene = rtcNewScene(this->Device);
  // Robust: watertight edges, so no shadow ray slips between two triangles.
  // The context filter: the tracer's transmittance through translucent
  // casters (Embree needs the flag on every instanced scene too).
  rtcSetSceneFlags(mesh.Scene,
    static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
  if (triangleCount > 0)
  {
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
    auto* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), triangleCount));
    if (vertices && indices)
    {
      std::memcpy(vertices, triangles.Vertices.data(), triangles.Vertices.size() * sizeof(float));
      std::memcpy(indices, triangles.Indices.data(), triangles.Indices.size() * sizeof(unsigned));
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(mesh.Scene, geometry);
    rtcReleaseGeometry(geometry);
    mesh.Triangles = static_cast<long long>(triangleCount);
  }
  rtcCommitScene(mesh.Scene);
  std::copy_n(triangles.Shift, 3, mesh.Shift);
  mesh.Vertices = triangles.Vertices;
  mesh.Indices.assign(triangles.Indices.begin(), triangles.Indices.end());
  double r2 = 0;
  for (size_t i = 0; i < vertexCount; ++i)
  {
    const float* v = &triangles.Vertices[3 * i];
    r2 = std::max(r2, double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
  }
  mesh.Radius = std::sqrt(r2);
  ++mesh.Version;
  ++this->MeshBuilds;
  this->MeshBuildSeconds += SecondsSince(start);
  return mesh.Used() ? &mesh : nullptr;
}

//------------------------------------------------------------------------------
void vtkShadowEmbreeScene::CollectTriangles(std::vector<double>& triangles,
  std::vector<unsigned char>& flags, std::vector<int>& placements) const
{
  triangles.clear();
  flags.clear();
  placements.clear();
  for (size_t k = 0; k < this->Parts.size(); ++k)
  {
    const Part& part = this->Parts[k];
    const Instance& inst = part.Placed;
    if (!inst.Vertices || !inst.Indices || inst.Impostors)
    {
      continue;
    }
    const unsigned char flag = !part.Casts ? 0
      : part.Translucent                   ? VSH_RT_CLASSIFY_TRANSLUCENT
                                           : VSH_RT_CLASSIFY_CASTS;
    const std::vector<unsigned int>& indices = *inst.Indices;
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
    {
      for (int v = 0; v < 3; ++v)
      {
        const float* p = &(*inst.Vertices)[3 * size_t(indices[t + v])];
        for (int r = 0; r < 3; ++r)
        {
          const double* m = &inst.Transform[4 * r];
          triangles.push_back(m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3]);
        }
      }
      flags.push_back(flag);
      placements.push_back(static_cast<int>(k));
    }
  }
}

//------------------------------------------------------------------------------
double vtkShadowEmbreeScene::GetLargestRadius() const
{
  double largest = 0;
  for (const Part& part : this->Parts)
  {
    largest = std::max(largest, part.Placed.Radius);
  }
  return largest;
}

//------------------------------------------------------------------------------
bool vtkShadowEmbreeScene::GetTriangle(
  unsigned int id, unsigned int primitive, double v[3][3]) const
{
  if (id >= this->Instances.size())
  {
    return false;
  }
  const Instance& inst = this->Instances[id];
  if (3 * size_t(primitive) + 2 >= inst.Indices->size())
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    const float* p = &(*inst.Vertices)[3 * size_t((*inst.Indices)[3 * size_t(primitive) + k])];
    for (int r = 0; r < 3; ++r)
    {
      const double* m = &inst.Transform[4 * r];
      v[k][r] = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<double> vtkShadowEmbreeScene::PlacementKey(
  const std::vector<Actor>& actors, const Camera& camera)
{
  // What the top levels depend on: which meshes (and their versions), where,
  // and who casts; with points or lines, the camera their radii are for.
  std::vector<double> key;
  bool impostors = false;
  for (const Actor& a : actors)
  {
    auto it = this->Meshes.find(a.Prop);
    if (it == this->Meshes.end() || !it->second->Used())
    {
      continue;
    }
    key.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(a.Prop)));
    key.push_back(it->second->Version);
    key.push_back(a.Casts ? 1 : 0);
    key.push_back(a.CastsImpostors ? 1 : 0);
    key.push_back(a.Opacity);
    key.insert(key.end(), a.Transmit, a.Transmit + 3);
    key.insert(key.end(), a.Matrix, a.Matrix + 16);
    impostors = impostors || !it->second->Drawn.Empty();
  }
  this->WorldKeySize = key.size();
  if (impostors)
  {
    key.insert(key.end(), camera.Projection, camera.Projection + 16);
    key.insert(key.end(), camera.View, camera.View + 16);
    key.push_back(camera.Width);
  }
  return key;
}

//------------------------------------------------------------------------------
void vtkShadowEmbreeScene::Attach(
  const Actor& a, bool casts, RTCScene scene, const float transform[12], const Instance& instance)
{
  const bool translucent = a.Opacity < 1.0;
  this->Parts.push_back({ instance, casts, translucent });
  this->ImpostorParts += instance.Impostors ? 1 : 0;
  if (instance.Impostors && !translucent)
  {
    this->ImpostorSlack = std::max(this->ImpostorSlack, instance.Slack);
  }
  for (RTCScene top : { this->Visible, this->Casters })
  {
    // A translucent actor is not in the depth pass (nothing lands on it)
    // and casts a partial shadow only.
    if ((top == this->Casters && !casts) || (top == this->Visible && translucent))
    {
      continue;
    }
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geometry, scene);
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, transform);
    rtcCommitGeometry(geometry);
    if (top == this->Visible)
    {
      rtcAttachGeometryByID(top, geometry, static_cast<unsigned int>(this->Instances.size()));
    }
    else
    {
      rtcAttachGeometryByID(top, geometry, static_cast<unsigned int>(this->CasterOpacity.size()));
      this->CasterOpacity.push_back(static_cast<float>(translucent ? a.Opacity : 1.0));
      for (int k = 0; k < 3; ++k)
      {
        this->CasterTransmit.push_back(static_cast<float>(translucent ? a.Transmit[k] : 0.0));
      }
      this->TranslucentCasters = this->TranslucentCasters || translucent;
      this->TintedCasters = this->TintedCasters || (translucent && a.Tinted);
    }
    rtcReleaseGeometry(geometry);
  }
  if (!translucent)
  {
    this->Instances.push_back(instance);
  }
}

//------------------------------------------------------------------------------
void vtkShadowEmbreeScene::AddMeshInstance(const Actor& a, const Mesh& mesh)
{
  // Stored positions (data - Shift) -> world -> relative to the centre,
  // composed in double and rounded to float once.
  const double* m = a.Matrix;
  float xfm[12];
  Instance instance;
  for (int r = 0; r < 3; ++r)
  {
    // The same placement in double, unrounded: the tracer computes the
    // surface point on it (a far floor seen at a grazing angle moves by
    // thousands of units for the float rounding of its translation).
    double t = m[4 * r + 3] - this->Centre[r];
    for (int c = 0; c < 3; ++c)
    {
      t += m[4 * r + c] * mesh.Shift[c];
      xfm[4 * r + c] = static_cast<float>(m[4 * r + c]);
      instance.Transform[4 * r + c] = m[4 * r + c];
    }
    xfm[4 * r + 3] = static_cast<float>(t);
    instance.Transform[4 * r + 3] = t;
  }
  instance.Vertices = &mesh.Vertices;
  instance.Indices = &mesh.Indices;
  Cofactors(m, instance.Normal);
  double scale = 0;
  for (int c = 0; c < 3; ++c)
  {
    scale = std::max(scale, std::hypot(m[c], m[4 + c], m[8 + c]));
  }
  instance.Radius = mesh.Radius * scale;
  this->Attach(a, a.Casts, mesh.Scene, xfm, instance);
}

//------------------------------------------------------------------------------
void vtkShadowEmbreeScene::AddCapsule(const float a[4], const float b[4])
{
  // Relative to the centre, the float radius grown by 1e-6 of itself and
  // a float epsilon of the position's magnitude: what Embree holds, covered.
  for (const float* ball : { a, b })
  {
    const double magnitude = std::fabs(ball[0]) + std::fabs(ball[1]) + std::fabs(ball[2]);
    for (int r = 0; r < 3; ++r)
    {
      this->ImpostorCapsules.push_back(ball[r]);
    }
    this->ImpostorCapsules.push_back(
      double(ball[3]) * (1.0 + 1e-6) + magnitude * double(std::numeric_limits<float>::epsilon()));
  }
}

//------------------------------------------------------------------------------
double vtkShadowEmbreeScene::AddSpheres(
  RTCScene scene, const Actor& a, const vtkshadow::Impostors& drawn, const Camera& camera)
{
  // Points drawn as spheres (sized for the camera) and splats (their own
  // world radius): one geometry of FLOAT4 (x y z radius) vertices.
  const size_t points = drawn.Points.size() / 3, splats = drawn.SplatRadii.size();
  if (points + splats == 0)
  {
    return 0;
  }
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), points + splats));
  double largest = 0;
  if (vertices)
  {
    largest = FillImpostorVertices(
      drawn.Points.data(), points, a.Matrix, this->Centre, camera, drawn.PointSize, vertices);
    float* out = vertices + 4 * points;
    for (size_t i = 0; i < splats; ++i, out += 4)
    {
      double world[3];
      vsh_mat4_transform_point(a.Matrix, &drawn.Splats[3 * i], world);
      for (int r = 0; r < 3; ++r)
      {
        out[r] = static_cast<float>(world[r] - this->Centre[r]);
      }
      out[3] = static_cast<float>(drawn.SplatRadii[i]);
      largest = std::max(largest, drawn.SplatRadii[i]);
    }
    for (size_t i = 0; i < points + splats; ++i)
    {
      const float* v = vertices + 4 * i;
      this->AddCapsule(v, v);
    }
  }
  CommitInto(scene, geometry);
  return largest;
}

//------------------------------------------------------------------------------
double vtkShadowEmbreeScene::AddTubes(
  RTCScene scene, const Actor& a, const vtkshadow::Impostors& drawn, const Camera& camera)
{
  if (drawn.Segments.empty())
  {
    return 0;
  }
  // Round: cones between spheres at the vertices, a tube whose joints
  // close (VTK's own wide-line tubes leave wedges at sharp bends).
  const size_t lineVertices = drawn.LineVertices.size() / 3;
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), lineVertices));
  auto* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(geometry,
    RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned int), drawn.Segments.size()));
  double largest = 0;
  if (vertices && indices)
  {
    largest = FillImpostorVertices(drawn.LineVertices.data(), lineVertices, a.Matrix, this->Centre,
      camera, drawn.LineWidth, vertices);
    std::copy(drawn.Segments.begin(), drawn.Segments.end(), indices);
    for (unsigned int first : drawn.Segments)
    {
      this->AddCapsule(vertices + 4 * size_t(first), vertices + 4 * (size_t(first) + 1));
    }
  }
  CommitInto(scene, geometry);
  return largest;
}

//------------------------------------------------------------------------------
size_t vtkShadowEmbreeScene::AddFlatQuads(
  RTCScene scene, const Actor& a, const vtkshadow::Impostors& drawn, const Camera& camera)
{
  // Plain points and lines: the flat squares and bands VTK draws, as quads
  // (Embree's flat curves face each ray, a shadow ray too: not the band
  // facing the camera).
  std::vector<double> corners;
  vtkshadow::AppendFlatQuads(
    drawn, a.Matrix, camera.Projection, camera.View, camera.Width, corners);
  const size_t quads = corners.size() / 12;
  if (quads == 0)
  {
    return 0;
  }
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_QUAD);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * quads));
  auto* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned int), quads));
  if (vertices && indices)
  {
    for (size_t i = 0; i < corners.size(); ++i)
    {
      vertices[i] = static_cast<float>(corners[i] - this->Centre[i % 3]);
    }
    for (size_t i = 0; i < 4 * quads; ++i)
    {
      indices[i] = static_cast<unsigned int>(i);
    }
    for (size_t q = 0; q < quads; ++q)
    {
      // The quad's bounding ball: its centre, to its farthest corner.
      const float* v = vertices + 12 * q;
      float ball[4] = { 0, 0, 0, 0 };
      for (int c = 0; c < 4; ++c)
      {
        for (int r = 0; r < 3; ++r)
        {
          ball[r] += 0.25f * v[3 * c + r];
        }
      }
      for (int c = 0; c < 4; ++c)
      {
        const float d[3] = { v[3 * c] - ball[0], v[3 * c + 1] - ball[1], v[3 * c + 2] - ball[2] };
        ball[3] = std::max(ball[3], std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      }
      this->AddCapsule(ball, ball);
    }
  }
  CommitInto(scene, geometry);
  return quads;
}

//------------------------------------------------------------------------------
void vtkShadowEmbreeScene::AddImpostors(const Actor& a, const Mesh& mesh, const Camera& camera)
{
  // In world units relative to the centre, not instanced from data
  // coordinates: VTK draws a sphere round and its size in pixels whatever
  // the actor's scale, so the radius cannot go through the actor's matrix.
  const vtkshadow::Impostors& drawn = mesh.Drawn;
  RTCScene scene = rtcNewScene(this->Device);
  rtcSetSceneFlags(scene,
    static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
  // The flat quads need no slack: VTK's depth lies on them.
  const double largest =
    std::max(this->AddSpheres(scene, a, drawn, camera), this->AddTubes(scene, a, drawn, camera));
  const size_t quads = this->AddFlatQuads(scene, a, drawn, camera);
  rtcCommitScene(scene);
  this->ImpostorScenes.push_back(scene);
  this->ImpostorCount += static_cast<long long>(
    drawn.Points.size() / 3 + drawn.SplatRadii.size() + drawn.Segments.size() + quads);
  // An identity placement: the positions already are in the frame.
  Instance instance;
  const float xfm[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
  for (int k = 0; k < 12; ++k)
  {
    instance.Transform[k] = xfm[k];
  }
  for (int k = 0; k < 9; ++k)
  {
    instance.Normal[k] = k % 4 == 0 ? 1.0 : 0.0;
  }
  instance.Radius = largest;
  instance.Vertices = &NoVertices;
  instance.Indices = &NoIndices;
  instance.Impostors = scene;
  instance.Slack = largest;
  this->Attach(a, a.CastsImpostors, scene, xfm, instance);
}

//------------------------------------------------------------------------------
bool vtkShadowEmbreeScene::BuildTopLevel(
  const std::vector<Actor>& actors, const double eye[3], const Camera& camera)
{
  const auto start = std::chrono::steady_clock::now();
  // The top levels' origin: the eye (see Update), so a visible point's
  // float coordinates are as precise as its distance from the camera allows.
  std::copy_n(eye, 3, this->Centre);
  for (RTCScene* top : { &this->Visible, &this->Casters })
  {
    if (*top)
    {
      rtcReleaseScene(*top);
    }
    *top = rtcNewScene(this->Device);
  }
  for (RTCScene scene : this->ImpostorScenes)
  {
    rtcReleaseScene(scene);
  }
  this->ImpostorScenes.clear();
  this->ImpostorCount = 0;
  rtcSetSceneFlags(this->Casters, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  this->Instances.clear();
  this->Parts.clear();
  this->ImpostorParts = 0;
  this->ImpostorSlack = 0;
  this->ImpostorCapsules.clear();
  this->CasterOpacity.clear();
  this->CasterTransmit.clear();
  this->TranslucentCasters = false;
  this->TintedCasters = false;
  for (const Actor& a : actors)
  {
    auto it = this->Meshes.find(a.Prop);
    if (it == this->Meshes.end())
    {
      continue;
    }
    const Mesh& mesh = *it->second;
    const bool translucent = a.Opacity < 1.0;
    if (mesh.Triangles > 0 && !(translucent && !a.Casts))
    {
      this->AddMeshInstance(a, mesh);
    }
    if (!mesh.Drawn.Empty() && !(translucent && !a.CastsImpostors))
    {
      this->AddImpostors(a, mesh, camera);
    }
  }
  rtcCommitScene(this->Visible);
  rtcCommitScene(this->Casters);
  ++this->TopCommits;
  this->TopSeconds += SecondsSince(start);
  return this->Error.empty();
}

//------------------------------------------------------------------------------
bool vtkShadowEmbreeScene::Update(
  const std::vector<Actor>& actors, const double eye[3], double nearDistance, const Camera& camera)
{
  this->Error.clear();
  if (!this->Device)
  {
    this->Device = rtcNewDevice(nullptr);
    if (!this->Device)
    {
      this->Error = "Embree: rtcNewDevice failed (error " +
        std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")";
      return false;
    }
    rtcSetDeviceErrorFunction(this->Device, &OnEmbreeError, &this->Error);
  }
  for (auto& entry : this->Meshes)
  {
    entry.second->Seen = false;
  }
  for (const Actor& a : actors)
  {
    this->UpdateMesh(a.Prop);
  }
  // Actors gone from the frame: their meshes go too.
  for (auto it = this->Meshes.begin(); it != this->Meshes.end();)
  {
    it = it->second->Seen ? std::next(it) : this->Meshes.erase(it);
  }
  // A camera move keeps the top levels while their origin stays within the
  // near distance of the eye (vsh_rt_frame_usable); further away, points
  // near the camera would lose float precision (and their shadow rays start
  // too far off the surface), so the origin moves to the eye. With points
  // or lines, every camera change rebuilds them (PlacementKey).
  std::vector<double> placement = this->PlacementKey(actors, camera);
  const double toEye[3] = { eye[0] - this->Centre[0], eye[1] - this->Centre[1],
    eye[2] - this->Centre[2] };
  // Where things are in the world, whatever the camera sizes impostors at.
  std::vector<double> world(placement.begin(), placement.begin() + this->WorldKeySize);
  if (world != this->World)
  {
    this->World.swap(world);
    ++this->WorldCommits;
  }
  if (!this->Visible || placement != this->Placement || !vsh_rt_frame_usable(toEye, nearDistance))
  {
    this->Placement.swap(placement);
    this->BuildTopLevel(actors, eye, camera);
  }
  return this->Error.empty();
}
