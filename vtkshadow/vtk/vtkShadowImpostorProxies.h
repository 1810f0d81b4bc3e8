// vtkShadowImpostorProxies.h - closed triangle proxies of the spheres and
// tubes VTK draws for RenderPointsAsSpheres and RenderLinesAsTubes, for the
// techniques that cast triangles (csm, planar, volume). raytrace casts true
// spheres and round curves (vtkShadowEmbreeScene); these meshes stand in
// for them at the same radius (vsh_rt_impostor_radius: half the drawn pixel
// width at the point's depth), so every technique casts what VTK draws.
//
// The radius is in pixels, so the proxies are world-space meshes of the
// current camera: rebuilt when the camera, the viewport, the actor's
// placement, its property or its data change. Their shapes and their size
// rule (the proxy's mean silhouette area is the sphere's) are the core's
// (vsh_impostor_proxy.h).
#ifndef vtkShadowImpostorProxies_h
#define vtkShadowImpostorProxies_h

#include "vtkShadowActorFlags.h" // for ShadowActor

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkActor;
class vtkWindow;

namespace vtkshadow
{
struct ShadowFrame;

// Whether the actor's property asks for spheres or tubes at all
// (RenderPointsAsSpheres, or RenderLinesAsTubes with a width above 1): the
// test that keeps the proxies free for every other actor.
bool DrawsImpostors(vtkActor* actor);

// The world radius VTK draws `pixels` wide at world point `p` with the
// frame's camera (vsh_rt_impostor_radius).
double ImpostorRadius(const ShadowFrame& frame, double pixels, const double p[3]);

// The actor's world bounds grown by the largest radius its spheres and
// tubes can have inside them (the radius at the box corner farthest along
// the view, its width the larger of point size and line width). False when
// the actor draws no spheres or tubes (DrawsImpostors).
bool ImpostorBounds(const ShadowFrame& frame, const ShadowActor& actor, double bounds[6]);

// One pass's proxies (their GPU copies live in its context).
class ImpostorProxies
{
public:
  ImpostorProxies();
  ~ImpostorProxies();

  // Appends to `casters` a proxy caster for each of `actors` that draws
  // spheres or tubes and is not marked NO_CAST: the same Actor, Root and
  // Instance, an identity Matrix (the proxy is in world coordinates), the
  // proxy's world Bounds and Proxy pointing at its triangles. Proxies of
  // actors no longer listed are dropped. Nothing is built (and nothing
  // appended) when no actor draws spheres or tubes.
  void Append(const ShadowFrame& frame, const std::vector<ShadowActor>& actors,
    std::vector<ShadowActor>& casters);

  // Triangles of the last Append's proxies, and proxy rebuilds so far.
  long long GetNumberOfTriangles() const;
  long long GetNumberOfBuilds() const { return this->Builds; }
  // Both as the passes' stats entry: "impostor_proxies": {...}.
  std::string StatsJSON() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  ImpostorProxies(const ImpostorProxies&) = delete;
  void operator=(const ImpostorProxies&) = delete;

  struct Entry;
  bool Build(const ShadowFrame& frame, const ShadowActor& actor, Entry& entry);
  std::map<std::pair<vtkActor*, int>, std::unique_ptr<Entry>> Entries;
  long long Frame = 0;
  long long Builds = 0;
};
}

#endif
