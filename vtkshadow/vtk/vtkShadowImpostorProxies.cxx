// vtkShadowImpostorProxies.cxx - world-space proxies of the spheres and
// tubes an actor draws (see the header).
#include "vtkShadowImpostorProxies.h"

#include "vtkActor.h"
#include "vtkProperty.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowCasterTriangles.h"
#include "vtkShadowFrame.h"
#include "vtkShadowImpostors.h"
#include "vtkShadowPassBase.h"

#include "vsh_impostor_proxy.h"
#include "vsh_mat4.h"
#include "vsh_raytrace.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <set>

namespace
{
// The unit shapes, made once.
const vsh_proxy_shapes& Shapes()
{
  static const vsh_proxy_shapes shapes = []
  {
    vsh_proxy_shapes s;
    vsh_proxy_shapes_init(&s);
    return s;
  }();
  return shapes;
}

// World positions and triangles of the proxies being built.
struct ProxyMesh
{
  std::vector<double> Positions;
  std::vector<uint32_t> Triangles;
  // Sphere centres already placed: the vertices of wireframe edges repeat
  // (one run per edge), and two coincident spheres, welded, would join four
  // triangles at an edge (not closed any more).
  std::set<std::array<double, 3>> Centres;

  // Room for `vertices` more positions and `triangles` more triangles;
  // returns the first new vertex's index, or -1 past 32-bit indices.
  long long Grow(size_t vertices, size_t triangles)
  {
    const size_t base = this->Positions.size() / 3;
    if (base + vertices > std::numeric_limits<uint32_t>::max())
    {
      return -1;
    }
    this->Positions.resize(3 * (base + vertices));
    this->Triangles.resize(this->Triangles.size() + 3 * triangles);
    return static_cast<long long>(base);
  }

  void Sphere(const double centre[3], double radius)
  {
    const std::array<double, 3> key = { centre[0], centre[1], centre[2] };
    if (!(radius > 0.0) || !this->Centres.insert(key).second)
    {
      return;
    }
    const long long base = this->Grow(VSH_PROXY_SPHERE_VERTICES, VSH_PROXY_SPHERE_TRIANGLES);
    if (base >= 0)
    {
      vsh_proxy_sphere(&Shapes(), centre, radius, &this->Positions[3 * base],
        &this->Triangles[this->Triangles.size() - 3 * VSH_PROXY_SPHERE_TRIANGLES],
        static_cast<uint32_t>(base));
    }
  }

  // One flat quad (4 corners, counter-clockwise): two triangles, open (the
  // techniques count an open surface's shadow from both sides).
  void Quad(const double* corners)
  {
    const long long base = this->Grow(4, 2);
    if (base < 0)
    {
      return;
    }
    std::copy_n(corners, 12, &this->Positions[3 * base]);
    const auto b = static_cast<uint32_t>(base);
    const uint32_t triangles[6] = { b, b + 1, b + 2, b, b + 2, b + 3 };
    std::copy_n(triangles, 6, &this->Triangles[this->Triangles.size() - 6]);
  }

  void Tube(const double a[3], double ra, const double b[3], double rb, int turn)
  {
    if (!(ra > 0.0) || !(rb > 0.0))
    {
      return;
    }
    const long long base = this->Grow(VSH_PROXY_TUBE_VERTICES, VSH_PROXY_TUBE_TRIANGLES);
    if (base < 0)
    {
      return;
    }
    if (!vsh_proxy_tube(&Shapes(), a, ra, b, rb, turn, &this->Positions[3 * base],
          &this->Triangles[this->Triangles.size() - 3 * VSH_PROXY_TUBE_TRIANGLES],
          static_cast<uint32_t>(base)))
    {
      // A segment of no length: its end spheres cover it.
      this->Positions.resize(3 * static_cast<size_t>(base));
      this->Triangles.resize(this->Triangles.size() - 3 * VSH_PROXY_TUBE_TRIANGLES);
    }
  }
};

// `count` data points placed by `matrix`, with the radius of `pixels` at
// each.
void PlacePoints(const vtkshadow::ShadowFrame& frame, const double matrix[16], const double* data,
  size_t count, double pixels, std::vector<double>& world, std::vector<double>& radii)
{
  world.resize(3 * count);
  radii.resize(count);
  for (size_t i = 0; i < count; ++i)
  {
    vsh_mat4_transform_point(matrix, data + 3 * i, &world[3 * i]);
    radii[i] = vtkshadow::ImpostorRadius(frame, pixels, &world[3 * i]);
  }
}

// The proxies of everything `drawn` holds: a sphere per point and per
// splat, a truncated cone per segment and a sphere per line vertex (round
// joints and ends, as raytrace's round curves have), a quad per flat point
// or segment.
void BuildMesh(const vtkshadow::ShadowFrame& frame, const double matrix[16],
  const vtkshadow::Impostors& drawn, ProxyMesh& mesh)
{
  std::vector<double> world, radii;
  for (size_t i = 0; i < drawn.SplatRadii.size(); ++i)
  {
    double centre[3];
    vsh_mat4_transform_point(matrix, &drawn.Splats[3 * i], centre);
    mesh.Sphere(centre, drawn.SplatRadii[i]);
  }
  std::vector<double> corners;
  vtkshadow::AppendFlatQuads(drawn, matrix, frame.Projection, frame.View, frame.Size[0], corners);
  for (size_t q = 0; q + 11 < corners.size(); q += 12)
  {
    mesh.Quad(&corners[q]);
  }
  PlacePoints(
    frame, matrix, drawn.Points.data(), drawn.Points.size() / 3, drawn.PointSize, world, radii);
  for (size_t i = 0; i < radii.size(); ++i)
  {
    mesh.Sphere(&world[3 * i], radii[i]);
  }
  if (drawn.Segments.empty())
  {
    return;
  }
  PlacePoints(frame, matrix, drawn.LineVertices.data(), drawn.LineVertices.size() / 3,
    drawn.LineWidth, world, radii);
  for (size_t i = 0; i < radii.size(); ++i)
  {
    mesh.Sphere(&world[3 * i], radii[i]);
  }
  int turn = 0;
  for (unsigned int s : drawn.Segments)
  {
    // Alternate ring turns: collinear neighbours' rings never coincide.
    mesh.Tube(&world[3 * s], radii[s], &world[3 * (s + 1)], radii[s + 1], turn++);
  }
}
}

namespace vtkshadow
{
struct ImpostorProxies::Entry
{
  Impostors Drawn;
  vtkMTimeType DrawnTime = 0;
  bool Extracted = false;
  // The camera, viewport, placement and data the proxies were built for.
  std::vector<double> Key;
  vtkShadowCasterGeometry Geometry;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  bool Empty = true;
  long long Seen = -1;
};

//------------------------------------------------------------------------------
bool DrawsImpostors(vtkActor* actor)
{
  return ImpostorKinds(actor) != 0;
}

//------------------------------------------------------------------------------
double ImpostorRadius(const ShadowFrame& frame, double pixels, const double p[3])
{
  return vsh_rt_impostor_radius(frame.Projection, frame.View, frame.Size[0], pixels, p);
}

//------------------------------------------------------------------------------
bool ImpostorBounds(const ShadowFrame& frame, const ShadowActor& actor, double bounds[6])
{
  const int kinds = ImpostorKinds(actor.Actor);
  if (!kinds)
  {
    return false;
  }
  vtkProperty* property = actor.Actor->GetProperty();
  const double pixels = (kinds & (SPHERES | FLAT_POINTS) ? property->GetPointSize() : 0.0) +
    (kinds & (TUBES | FLAT_LINES) ? property->GetLineWidth() : 0.0);
  // Splats: their largest radius; the others' radius grows linearly with
  // the depth: the largest is at a corner.
  double largest = 0.0, splats[2];
  if (SplatRadiusRange(actor.Actor, splats))
  {
    largest = splats[1];
  }
  for (int c = 0; c < 8 && pixels > 0.0; ++c)
  {
    const double corner[3] = { actor.Bounds[c & 1], actor.Bounds[2 + ((c >> 1) & 1)],
      actor.Bounds[4 + ((c >> 2) & 1)] };
    largest = std::max(largest, ImpostorRadius(frame, pixels, corner));
  }
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] = actor.Bounds[2 * k] - largest;
    bounds[2 * k + 1] = actor.Bounds[2 * k + 1] + largest;
  }
  return true;
}

//------------------------------------------------------------------------------
ImpostorProxies::ImpostorProxies() = default;

//------------------------------------------------------------------------------
ImpostorProxies::~ImpostorProxies() = default;

//------------------------------------------------------------------------------
bool ImpostorProxies::Build(const ShadowFrame& frame, const ShadowActor& actor, Entry& entry)
{
  const vtkMTimeType drawnTime = ImpostorTime(actor.Actor);
  if (!entry.Extracted || drawnTime != entry.DrawnTime)
  {
    ExtractImpostors(actor.Actor, entry.Drawn);
    entry.DrawnTime = drawnTime;
    entry.Extracted = true;
  }
  std::vector<double> key(frame.Projection, frame.Projection + 16);
  key.insert(key.end(), frame.View, frame.View + 16);
  key.insert(key.end(), actor.Matrix, actor.Matrix + 16);
  key.push_back(frame.Size[0]);
  key.push_back(static_cast<double>(drawnTime));
  if (key == entry.Key)
  {
    return !entry.Empty;
  }
  entry.Key.swap(key);
  ++this->Builds;
  ProxyMesh mesh;
  BuildMesh(frame, actor.Matrix, entry.Drawn, mesh);
  entry.Empty = mesh.Triangles.empty();
  if (entry.Empty)
  {
    return false;
  }
  // Stored relative to the centre of their bounds, as a mapper's triangles
  // are, so float keeps precision far from the origin.
  CasterTriangles triangles;
  for (int k = 0; k < 3; ++k)
  {
    entry.Bounds[2 * k] = std::numeric_limits<double>::max();
    entry.Bounds[2 * k + 1] = std::numeric_limits<double>::lowest();
  }
  for (size_t i = 0; i < mesh.Positions.size(); ++i)
  {
    const int k = static_cast<int>(i % 3);
    entry.Bounds[2 * k] = std::min(entry.Bounds[2 * k], mesh.Positions[i]);
    entry.Bounds[2 * k + 1] = std::max(entry.Bounds[2 * k + 1], mesh.Positions[i]);
  }
  for (int k = 0; k < 3; ++k)
  {
    triangles.Shift[k] = 0.5 * (entry.Bounds[2 * k] + entry.Bounds[2 * k + 1]);
  }
  triangles.Vertices.resize(mesh.Positions.size());
  for (size_t i = 0; i < mesh.Positions.size(); ++i)
  {
    triangles.Vertices[i] = static_cast<float>(mesh.Positions[i] - triangles.Shift[i % 3]);
  }
  triangles.Indices.assign(mesh.Triangles.begin(), mesh.Triangles.end());
  entry.Geometry.Load(triangles);
  return true;
}

//------------------------------------------------------------------------------
void ImpostorProxies::Append(const ShadowFrame& frame, const std::vector<ShadowActor>& actors,
  std::vector<ShadowActor>& casters)
{
  ++this->Frame;
  for (const ShadowActor& actor : actors)
  {
    if (!DrawsImpostors(actor.Actor) || HasFlag(actor, vtkShadowPassBase::NO_CAST()))
    {
      continue;
    }
    auto& entry = this->Entries[{ actor.Actor, actor.Instance }];
    if (!entry)
    {
      entry.reset(new Entry);
    }
    entry->Seen = this->Frame;
    if (this->Build(frame, actor, *entry))
    {
      ShadowActor proxy = actor;
      vsh_mat4_identity(proxy.Matrix);
      std::copy_n(entry->Bounds, 6, proxy.Bounds);
      proxy.Proxy = &entry->Geometry;
      casters.push_back(proxy);
    }
  }
  // Actors that left (or stopped drawing spheres and tubes); Append runs
  // while the pass renders, with its context current.
  for (auto it = this->Entries.begin(); it != this->Entries.end();)
  {
    if (it->second->Seen != this->Frame)
    {
      it->second->Geometry.ReleaseGraphicsResources(nullptr);
      it = this->Entries.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
long long ImpostorProxies::GetNumberOfTriangles() const
{
  long long triangles = 0;
  for (const auto& entry : this->Entries)
  {
    triangles += entry.second->Empty ? 0 : entry.second->Geometry.GetNumberOfTriangles();
  }
  return triangles;
}

//------------------------------------------------------------------------------
std::string ImpostorProxies::StatsJSON() const
{
  return "\"impostor_proxies\": {\"triangles\": " + std::to_string(this->GetNumberOfTriangles()) +
    ", \"builds\": " + std::to_string(this->Builds) + "}";
}

//------------------------------------------------------------------------------
void ImpostorProxies::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& entry : this->Entries)
  {
    entry.second->Geometry.ReleaseGraphicsResources(window);
  }
  this->Entries.clear();
}
}
