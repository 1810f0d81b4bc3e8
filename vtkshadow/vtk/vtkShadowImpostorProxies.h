// vtkShadowImpostorProxies.h - triangle proxies of the points and lines
// VTK draws as screen-space shapes (vtkShadowImpostors), for the techniques
// that cast triangles (csm, planar, volume): closed icospheres and tubes
// for RenderPointsAsSpheres, RenderLinesAsTubes and vtkPointGaussianMapper's
// splats, where raytrace casts true spheres and round curves
// (vtkShadowEmbreeScene), and the very quads raytrace casts for plain
// points and lines. Pixel-sized ones take the radius VTK draws
// (vsh_rt_impostor_radius: half the drawn pixel width at the point's
// depth), splats their world radius, so every technique casts what VTK
// draws.
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

// Whether the actor draws any of those shapes (ImpostorKinds: its property,
// mapper and cell counts): the test that keeps the proxies free for every
// other actor.
bool DrawsImpostors(vtkActor* actor);

// The world radius VTK draws `pixels` wide at world point `p` with the
// frame's camera (vsh_rt_impostor_radius).
double ImpostorRadius(const ShadowFrame& frame, double pixels, const double p[3]);

// The actor's world bounds grown by the largest radius its shapes can have
// inside them (the radius at the box corner farthest along the view of the
// point size plus the line width, or the largest splat radius). False when
// the actor draws none (DrawsImpostors).
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
