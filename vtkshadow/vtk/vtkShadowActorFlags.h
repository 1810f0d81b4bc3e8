// vtkShadowActorFlags.h - which actors take part in shadows (plain actors
// and the parts of assemblies, each with the matrix it is drawn with), and
// the integer shadow flags they carry in their property keys
// (vtkShadowPassBase::RECEIVER(), NO_CAST()); shared by every pass and the
// C API.
#ifndef vtkShadowActorFlags_h
#define vtkShadowActorFlags_h

#include "vtkActor.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkProp.h"

#include <algorithm>
#include <functional>
#include <vector>

class vtkRenderState;
class vtkRenderer;
class vtkShadowCasterGeometry;

namespace vtkshadow
{
// True when `prop` carries `key` with a non-zero value.
inline bool HasFlag(vtkProp* prop, vtkInformationIntegerKey* key)
{
  vtkInformation* info = prop->GetPropertyKeys();
  return info && info->Has(key) && info->Get(key) != 0;
}

// Set `key` on an actor, creating its property keys when it has none.
inline void SetFlag(vtkActor* actor, vtkInformationIntegerKey* key, int value)
{
  if (!actor->GetPropertyKeys())
  {
    vtkNew<vtkInformation> keys;
    actor->SetPropertyKeys(keys);
  }
  actor->GetPropertyKeys()->Set(key, value);
  actor->Modified();
}

// When the actor's mesh last changed: its mapper or the mapper's input.
// (Not the actor's own MTime: VTK's pass machinery bumps it when it gives
// actors property keys. The placement is ShadowActor::Matrix, compared by
// value.)
inline vtkMTimeType MeshTime(vtkActor* actor)
{
  vtkMTimeType t = actor->GetMapper()->GetMTime();
  if (vtkDataObject* data = actor->GetMapper()->GetInputDataObject(0, 0))
  {
    t = std::max(t, data->GetMTime());
  }
  return t;
}

// An actor that takes part in the shadows of a frame: the end of a prop
// path (the prop itself for a plain actor, a part of a vtkAssembly or a
// vtkPropAssembly otherwise), placed where VTK draws it.
struct ShadowActor
{
  vtkActor* Actor;
  // The renderer's prop the path starts at (Actor itself for a plain actor).
  vtkProp* Root;
  // Data -> world, row major: the actor's own matrix, or the path's composed
  // one, which VTK pokes into the part while it draws it.
  double Matrix[16];
  double Bounds[6]; // world bounds, VTK order
  // Earlier entries of the same list with the same Actor (a part used by two
  // assemblies, or twice in one): caches that depend on the placement key
  // on (Actor, Instance).
  int Instance;
  // Set for the proxy of the spheres and tubes Actor draws
  // (vtkShadowImpostorProxies): a pass draws these world-space triangles
  // (Matrix is the identity) instead of the actor's own.
  vtkShadowCasterGeometry* Proxy = nullptr;
};

// Calls visit(actor, matrix) for every visible actor with a mapper that
// `root` draws, with the data -> world matrix (row major) it is drawn with:
// a plain actor with its own matrix; a vtkAssembly, a vtkPropAssembly or any
// other prop with assembly paths (InitPathTraversal / GetNextPath) for each
// path ending in an actor, with that path's composed matrix, as their
// RenderOpaqueGeometry pokes it. Every pass finds casters and receivers
// through this one traversal (ShadowActors below).
void ForEachPathActor(vtkProp* root, const std::function<void(vtkActor*, const double*)>& visit);

// The render state's actors that can cast or receive: visible, with a
// mapper, opaque (translucent geometry neither blocks nor shows shadows
// here) and with initialised bounds, found by ForEachPathActor. VTK's
// frustum culler has dropped the props outside the view from this list:
// right for what the frame draws, wrong for casters (see the overload below).
std::vector<ShadowActor> ShadowActors(const vtkRenderState* s);

// The renderer's actors that can cast or receive, from its props rather than
// the render state's frustum-culled ones: a caster behind the camera (or
// beside the view) still throws its shadow into the view.
std::vector<ShadowActor> ShadowActors(vtkRenderer* renderer);

// The renderer's translucent actors whose property's opacity is below 1
// (CasterOpacity), from its props as above: what raytrace and csm let cast
// a partial shadow (docs/translucency.md). Actors translucent only through a
// texture's or their scalars' alpha (opacity 1) are in neither list. Every
// other technique leaves translucent actors out.
std::vector<ShadowActor> TranslucentShadowActors(vtkRenderer* renderer);

// The actor's property opacity clamped to [0, 1] (1 without a property or
// for NaN: opaque).
double CasterOpacity(vtkActor* actor);

// What one crossing of a translucent actor's surface lets through per
// colour channel, the core's rule (vsh_transmit_crossing): its opacity,
// vtkShadowPassBase::FILTER() (own keys, else its root prop's; clamped to
// [0, 1], 0 when absent or NaN) and its property's diffuse colour. Returns
// whether the crossing is tinted (a filter above 0 and channels that
// differ), i.e. whether grey visibility would be wrong for it.
bool CasterTransmit(const ShadowActor& actor, double transmit[3]);

// Whether one of `translucent` (TranslucentShadowActors, a frame's
// Translucent) casts (not `noCast`, drawn as a surface) a tinted shadow
// (CasterTransmit): techniques with one value per light draw it grey, auto
// gives its lights raytrace.
bool HasTintingCaster(
  const std::vector<ShadowActor>& translucent, vtkInformationIntegerKey* noCast);

// Whether the renderer shows a vtkVolume (volume rendering): raytrace casts
// its shadow (vtkShadowVolumeCasters), the other techniques say per light
// that they do not, and auto gives its lights raytrace.
bool HasVisibleVolumes(vtkRenderer* renderer);

// The property keys that decide `key` for a shadow actor: its own when they
// carry the key, else its root prop's (VTK's assemblies hand their keys to
// their parts while drawing them, so marking the assembly marks every part);
// nullptr when neither carries it.
vtkInformation* FlagKeys(const ShadowActor& a, vtkInformationIntegerKey* key);

// True when the shadow actor's deciding keys (FlagKeys) set `key` non-zero.
inline bool HasFlag(const ShadowActor& a, vtkInformationIntegerKey* key)
{
  vtkInformation* keys = FlagKeys(a, key);
  return keys && keys->Get(key) != 0;
}

// True when the shadow actor casts with its triangles: not marked with
// `noCast` (vtkShadowPassBase::NO_CAST) and drawn as a surface. An actor
// drawn as a wireframe or as points shows only lines or points a few pixels
// wide: the solid shadow of its triangles would come from nothing on
// screen, so it casts none (csm's maps hold the lines VTK rasterizes). The
// points and lines VTK draws (vtkShadowImpostors: spheres, tubes, and plain
// squares and bands wider than a pixel) and vtkPointGaussianMapper's splats
// cast whatever the representation: raytrace as Embree spheres, curves and
// quads, csm, planar and volume as proxies (vtkShadowImpostorProxies).
bool CastsAsSurface(const ShadowActor& a, vtkInformationIntegerKey* noCast);
}

#endif
