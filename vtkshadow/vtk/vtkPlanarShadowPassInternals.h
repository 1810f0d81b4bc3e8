// vtkPlanarShadowPassInternals.h - the state vtkPlanarShadowPass shares
// between its two source files: the pass itself (vtkPlanarShadowPass.cxx:
// receivers, casters, the hard mask, the lighting hooks) and the sampled
// area lights (vtkPlanarShadowSoft.cxx: soft pairs, their accumulation and
// the adaptive sample counts).
#ifndef vtkPlanarShadowPassInternals_h
#define vtkPlanarShadowPassInternals_h

#include "vtkPlanarShadowPass.h"
#include "vtkProp.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowClipSpaceQuad.h"
#include "vtkShadowFacingTest.h"
#include "vtkShadowFrame.h"
#include "vtkShadowImpostorProxies.h"
#include "vtkShadowReceiverPlane.h"
#include "vtkWeakPointer.h"

#include "vsh_planar.h"
#include "vsh_planar_plan.h"

#include <algorithm>
#include <map>
#include <memory>
#include <vector>

class vtkInformation;
class vtkOpenGLFramebufferObject;
class vtkTextureObject;

namespace vtkshadow
{
namespace planar
{
// (receiver, light) pairs per frame: one mask bit each.
constexpr int MaxPairs = VSH_PLANAR_MAX_PAIRS;
constexpr int MaxExplicitPlanes = 8;
// Soft pairs per frame: one channel each of the RGBA16F accumulation.
constexpr int MaxSoftPairs = 4;
// Pairs per frame with a transmittance channel (translucent casters): one
// channel each of another RGBA16F texture.
constexpr int MaxTransmitPairs = 4;

// Whether a caster's world bounds lie in the plane (within 1e-6 of their size).
inline bool LiesInPlane(const vtkshadow::ShadowActor& caster, const double plane[4])
{
  return vsh_planar_bounds_in_plane(caster.Bounds, plane) != 0;
}
}
}

struct vtkPlanarShadowPass::Internals
{
  struct ExplicitPlane
  {
    double Origin[3];
    double Normal[3];
  };
  struct Caster
  {
    vtkShadowCasterGeometry Geometry;
    vtkMTimeType SeenFrame = 0;
  };

  std::vector<vtkWeakPointer<vtkActor>> ReceiverActors;
  std::vector<ExplicitPlane> Planes;
  vtkshadow::ReceiverPlaneCache ReceiverPlanes;
  std::map<vtkActor*, std::unique_ptr<Caster>> Casters;
  // Proxies of the points drawn as spheres and lines drawn as tubes.
  vtkshadow::ImpostorProxies Proxies;
  vtkMTimeType Frame = 0;

  vtkTextureObject* Mask = nullptr;
  vtkOpenGLFramebufferObject* FBO = nullptr;
  // Stencil for silhouette fans (winding numbers), and a screen quad.
  unsigned int Stencil = 0;
  int StencilSize[2] = { 0, 0 };
  vtkShadowClipSpaceQuad Quad; // over the whole viewport (DrawViewportQuad)
  int MaskSize[2] = { 0, 0 };
  int MaskChannels = 4; // 32-bit channels: 1 up to 32 pairs, else 4
  int MaskOrigin[2] = { 0, 0 };
  // Where the mask may hold bits: the pixel box written by the last frame
  // (everything after an allocation, whose content is undefined). Only that
  // box is cleared: on a software rasterizer a full-screen clear of the
  // mask costs about as much as a shadow pair's fill.
  int DirtyBox[4] = { 0, 0, 0, 0 };
  bool DirtyAll = true;
  vsh_planar_rect Written; // this frame's writes, in NDC
  // Sampled area lights: the shadowed fraction of up to four soft pairs
  // (one channel each), the pair bit of each channel (-1: none), and
  // whether the receivers' shaders have the soft lookup compiled in.
  vtkTextureObject* Soft = nullptr;
  int SoftSize[2] = { 0, 0 };
  int SoftPair[vtkshadow::planar::MaxSoftPairs] = { -1, -1, -1, -1 };
  bool SoftShader = false;
  bool SoftWarned = false;
  // Adaptive sample counts: the sample order of SoftOrderSamples (the batch
  // first when SoftOrderAdaptive), the batch's read-back and mark (one byte
  // per pixel, uploaded to SoftMark), and per soft pair of the last frame
  // its light, refined pixels and the box they were drawn in.
  std::vector<int> SoftOrder;
  int SoftOrderSamples = 0;
  bool SoftOrderAdaptive = false;
  vtkTextureObject* SoftMark = nullptr;
  std::vector<float> SoftReadback;
  std::vector<unsigned char> SoftMarkBytes;
  struct PairStats
  {
    int Light;
    long Refined;
    long BoxPixels;
  };
  std::vector<PairStats> SoftStats;
  bool SoftAdaptive = false; // in the last frame
  // Translucent casters: per pair with a channel, the product of (1 -
  // opacity) over the projected translucent triangles covering each pixel
  // (1 elsewhere), the pair bit of each channel (-1: none), and whether the
  // receivers' shaders have the transmittance lookup compiled in.
  vtkTextureObject* Transmit = nullptr;
  int TransmitSize[2] = { 0, 0 };
  int TransmitPair[vtkshadow::planar::MaxTransmitPairs] = { -1, -1, -1, -1 };
  bool TransmitShader = false;
  bool TransmitWarned = false;

  // Per-frame values for SetShaderParameters.
  std::map<vtkProp*, int> ReceiverIndex;
  // The facing test: per closed opaque caster the bits of the lights it
  // gets the test for (those this pass casts), and the lights' inputs.
  std::map<vtkProp*, int> FacingBits;
  // FacingBits' actors: only their shaders carry the facing test's code
  // (NoteClosedCasters).
  vtkshadow::FacingShaderSet FacingShaders;
  vtkshadow::FacingLights Facing;
  int LightCount = 0;
  int PlaneCount = 0;
  float PlaneVC[4 * vtkshadow::planar::MaxExplicitPlanes] = {};
  int PlaneReceiver[vtkshadow::planar::MaxExplicitPlanes] = {};
  float PlaneTolerance[vtkshadow::planar::MaxExplicitPlanes] = {};
  std::vector<vtkProp*> Receiving; // sorted (from the map)
  // Receivers by their property keys, and the frame's props and the actors
  // they draw through prop paths (sorted): a prop the mapper draws that is
  // none of them is an inner actor drawing for an outer one whose property
  // keys it shares (vtkLODActor's and ParaView's vtkPVLODActor's Device): it
  // receives as the outer actor does. (The parts of an assembly share its
  // keys too, but each is known and receives as itself.)
  std::map<vtkInformation*, vtkProp*> ReceiverByKeys;
  std::vector<vtkProp*> FrameProps;
  bool EveryoneReceives = false;
  std::vector<vtkWeakPointer<vtkActor>> Detected; // in the last frame
  int DetectedParts = 0;                          // flat parts receiving, last frame

  // The actors added with AddReceiverActor() that still exist.
  std::vector<vtkActor*> AddedActors() const
  {
    std::vector<vtkActor*> added;
    for (const auto& r : this->ReceiverActors)
    {
      if (r)
      {
        added.push_back(r);
      }
    }
    return added;
  }

  // The receiver an actor draws for: itself, or the outer actor of an
  // inner one (see ReceiverByKeys).
  vtkProp* Outer(vtkProp* prop) const
  {
    if (!prop || this->ReceiverIndex.count(prop) ||
      std::binary_search(this->FrameProps.begin(), this->FrameProps.end(), prop))
    {
      return prop;
    }
    auto it = this->ReceiverByKeys.find(prop->GetPropertyKeys());
    return it == this->ReceiverByKeys.end() ? prop : it->second;
  }

  bool CanReceive(vtkProp* prop) const
  {
    prop = this->Outer(prop);
    return this->EveryoneReceives ||
      std::binary_search(this->Receiving.begin(), this->Receiving.end(), prop);
  }
};

// The frame: the shared inputs (viewport, camera, lights, actors) and what
// the planning stages derive from them for the drawing stages.
struct vtkPlanarShadowPass::Frame
{
  explicit Frame(const vtkshadow::ShadowFrame& shared)
    : Shared(shared)
  {
  }
  const vtkshadow::ShadowFrame& Shared;
  // Switched-on lights in the mappers' numbering, as the core plans them.
  std::vector<vsh_planar_light> Lights;
  // Receivers: an actor (nullptr for an explicit plane) and its plane, 4
  // doubles per receiver.
  std::vector<vtkActor*> Receivers;
  std::vector<double> Planes;
  // Per receiver, how far above its plane a caster point must be to cast
  // onto it: 0, or for a flat part of a mesh the part's own rounding, so
  // the mesh's points on the part do not shadow the part they make up.
  std::vector<double> CasterLift;
  std::vector<vtkshadow::ShadowActor> Casters;
  // Translucent casters (opacity strictly between 0 and 1) and their opacity.
  std::vector<vtkshadow::ShadowActor> Translucent;
  std::vector<double> TranslucentOpacity;
};

// A closed caster drawn as its silhouette fans, counted in the stencil.
struct vtkPlanarShadowPass::Fan
{
  vtkShadowCasterGeometry* Geometry;
  float MCDC[16];
  double Light[4]; // in the caster's model coordinates
};

#endif
