// vtkCascadedShadowMapPassInternals.h - the state vtkCascadedShadowMapPass
// shares between its two source files: the pass itself
// (vtkCascadedShadowMapPass.cxx: plan, bake, forward lookups) and the
// screen-space resolve (vtkCascadedShadowMapResolve.cxx).
#ifndef vtkCascadedShadowMapPassInternals_h
#define vtkCascadedShadowMapPassInternals_h

#include "vtkCascadedShadowMapPass.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowClipSpaceRects.h"
#include "vtkShadowFrame.h"
#include "vtkShadowImpostorProxies.h"
#include "vtkShadowScreenMask.h"
#include "vtkShadowVolumeOpacityMap.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTimeStamp.h"

#include "vsh_csm.h"
#include "vsh_csm_plan.h"
#include "vsh_csm_sampled.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkMultiProcessController;
class vtkOpenGLRenderWindow;

namespace vtkshadow
{
// Row-major double -> column-major float (GL's order).
inline void ToFloatTransposed(const double m[16], float out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[c * 4 + r] = static_cast<float>(m[r * 4 + c]);
    }
  }
}

/**
 * What the pass keeps from frame to frame for one world: the atlas, what
 * each of its tiles holds, and the casters' content key. A mirror's
 * reflection is another world (other casters' matrices, other lights): with
 * one set, each world's bake overwrote the other's tiles every frame.
 */
struct CascadedHeldMaps
{
  vtkSmartPointer<vtkTextureObject> Atlas;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FBO;
  int AtlasSize[2] = { 0, 0 };
  int TileGrid[2] = { 1, 1 };
  int RenderedResolution = 0; // texels per tile edge of the held maps
  // What each atlas tile holds: the view it was rendered with (relative to
  // the camera position then), so a later frame can reuse it.
  std::vector<vsh_csm_held_map> Rendered;
  // The casters' state by content (actors, matrix values, mesh times): a
  // new stamp only when it differs from the last frame's, so a matrix set
  // back to the same values (vtkPlanarReflectionPass restores every actor's
  // after its mirrored draw, which moves the matrices' MTime) keeps the maps.
  unsigned long long CasterKey = 0;
  vtkTimeStamp CasterStamp;
  // SOFT_SAMPLED: what the sample slots hold (the lights' sample frames and
  // slots); when it changes every slot is baked again.
  unsigned long long SampleKey = 0;
  // Translucent casters (docs/translucency.md), in the atlas's layout and
  // allocated only while the scene has one: per texel their nearest depth
  // (32-bit float depth) and the product of (1 - opacity) over their
  // surfaces in front of the opaque map (16-bit float).
  vtkSmartPointer<vtkTextureObject> TranslucentDepth;
  vtkSmartPointer<vtkTextureObject> Transmit;
  bool TransmitAllocated = false;

  long long Bytes() const
  {
    return (this->TransmitAllocated ? 10LL : 4LL) * this->AtlasSize[0] * this->AtlasSize[1];
  }
};

/**
 * (Re)allocate `texture` as a depth atlas of width x height, compared with
 * LEQUAL and filtered linearly (the hardware 2x2 comparison): the maps'
 * atlas and the translucent casters' nearest depths.
 */
void AllocateDepthAtlas(
  vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width, int height);

/**
 * GLSL statements that set `target(I)` ("%d" stands for I) to the shadow
 * factor of lights first..first+count-1 of `plan` (mapper numbering), from
 * posVC, normalVC, depth and fade in scope. Lights the surface faces away
 * from get `away` without a lookup: the forward path passes "1.0" (the
 * mapper's terms are 0 there, so nothing changes), the screen resolve "0.0"
 * (its normal comes from the depth, and a surface facing away from a light
 * is not lit by it).
 */
std::string CascadedLookupCode(const vsh_csm_tile_plan& plan, int first, int count,
  const std::string& target, float margin, const std::string& away,
  const int* sampleFirst = nullptr);

/**
 * The resolve's statements for lights first..first+3 over a kind of screen
 * tile: `codes` holds each light's VSH_CSM_SCREEN_* (vsh_csm_screen.h):
 * lit without a lookup, one cascade's lookup with its map index compiled
 * in, or the per-pixel code of CascadedLookupCode.
 */
std::string CascadedTileLookupCode(
  const vsh_csm_tile_plan& plan, int first, const int codes[4], const int* sampleFirst = nullptr);
}

// One frame's inputs: the shared frame (vtkShadowFrame.h) and what the pass
// derives from it: the plain scene the core plans from, and what the bake
// needs (the caster actors).
struct vtkCascadedShadowMapPass::Frame
{
  explicit Frame(const vtkshadow::ShadowFrame& shared)
    : Shared(shared)
  {
  }
  const vtkshadow::ShadowFrame& Shared;
  std::vector<vtkshadow::ShadowActor> Casters;
  // Translucent actors that cast (TranslucentShadowActors, CastsAsSurface):
  // drawn into the transmittance maps, not the depth maps.
  std::vector<vtkshadow::ShadowActor> Translucent;
  vtkMTimeType CasterTime = 0;       // changes when a caster moves, changes or leaves
  std::vector<vsh_csm_light> Lights; // switched on, in the mappers' numbering
  vsh_csm_scene Scene{};             // its `lights` point into Lights
  vsh_csm_settings Settings{};
};

struct vtkCascadedShadowMapPass::Internals
{
  double SplitFractions[VSH_CSM_MAX_CASCADES] = { 0 };
  std::map<vtkActor*, std::unique_ptr<vtkShadowCasterGeometry>> Casters;
  // Proxies of the points drawn as spheres and lines drawn as tubes.
  vtkshadow::ImpostorProxies Proxies;
  // The held maps of the world being drawn (vtkShadowPassBase::SetWorldKey)
  // and, parked by key, those of the other worlds (a mirror's reflection).
  vtkshadow::CascadedHeldMaps Held;
  int HeldWorld = 0;
  std::map<int, vtkshadow::CascadedHeldMaps> Parked;
  int FrameMapsRendered = 0; // in every world since world 0 was last drawn
  // This frame's maps and, per light in the mappers' numbering, their kind
  // and range of tiles (the shader's uniforms).
  vsh_csm_plan Plan{};
  float LightVC[VSH_CSM_MAX_LIGHTS][3] = { { 0 } };
  // Per light (direction to the light, 0) or (position, 1), view coordinates.
  float ToLightVC[VSH_CSM_MAX_LIGHTS][4] = { { 0 } };
  float ViewToWorld[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  float PixelSize[2] = { 0, 0 }; // world size of a pixel: [0] + [1] * view depth
  // PCSS: per light (mappers' numbering) its size term (vsh_pcss_light_term:
  // tan(angle / 2) or the radius; 0 hard), whether this frame compiles PCSS
  // in, and the raw-depth binding of the atlas (sampler object, unit).
  float SoftTerm[VSH_CSM_MAX_LIGHTS] = { 0 };
  bool PCSS = false;
  // SOFT_SAMPLED: per light its size (radius or angular diameter, 0 hard),
  // sample frame, first atlas slot of its sample maps (-1: hard; sample k
  // of its map j is slot SampleFirst + k count + j), the derived sample
  // maps (slots from Plan.tiles.tile_count on), the disk samples, and the
  // per-sample terms the shader rebuilds each sample's matrix from.
  float SampleSize[VSH_CSM_MAX_LIGHTS] = { 0 };
  vsh_csm_sample_frame SampleFrame[VSH_CSM_MAX_LIGHTS];
  int SampleFirst[VSH_CSM_MAX_LIGHTS];
  int SampleSlots = 0;
  bool Sampled = false;
  std::vector<vsh_csm_tile> SampleTiles;
  float SampleDisk[VSH_CSM_MAX_SAMPLES][2];
  // Adaptive: slot k of a light's samples holds disk sample SampleOrder[k]
  // (the batch of SampleBatch first; identity and 0 when not adaptive),
  // recomputed only when OrderSamples (its N) changes.
  std::vector<int> SampleOrder;
  int OrderSamples = 0;
  int SampleBatch = 0;
  float SampleU[VSH_CSM_MAX_LIGHTS][3];
  float SampleV[VSH_CSM_MAX_LIGHTS][3];
  float TileShear[VSH_CSM_MAX_TILES][4];
  double ShearTexels = 0.0; // how far a sample map's lookups move from the base map's
  unsigned int RawSampler = 0;
  int RawUnit = -1;
  float FadeStart = 0.0f;
  float MaxDistance = 0.0f;
  std::string ShaderSignature; // kinds, filter: what the generated code depends on
  // This frame has translucent casters: their maps are baked and read
  // (VSH_TRANSMIT).
  bool Transmit = false;
  // The screen-space resolve: the mask, whether this frame uses it, the
  // resolve shader per mask texture (lights 0-3, 4-7), and whether the
  // depth pre-pass is running (the mask's textures are not bound then).
  std::unique_ptr<vtkShadowScreenMask> Mask;
  bool Screen = false;
  // The volumes' opacity shadow maps, multiplied into the mask after the
  // resolve: a frame they cover takes the screen resolve.
  vtkShadowVolumeOpacityMap VolumeMaps;
  bool PrePass = false;
  bool ScreenFailed = false;
  std::string ResolveSource[2];
  // The CHOOSE rule's measurement: fragment-shader invocations of the
  // pre-pass (what forward lookups would run for: the main pass rasterizes
  // the same triangles) per covered pixel (what the resolve runs for), from
  // queries on a screen frame; -1 before the first. Re-measured every 64
  // frames.
  unsigned int Queries[2] = { 0, 0 };
  unsigned int FragmentQuery = 0; // the GL query target that counts fragments
  double Overdraw = -1.0;
  int FramesSinceMeasure = 0;
  bool Measuring = false;
  // TileCull: the pre-pass depth read back, its per-tile ranges and the
  // pixels it covers, and per mask texture the kinds of tile to draw (the
  // resolve source compiled for each, its range of rectangles).
  struct TileGroup
  {
    std::string Source;
    int First = 0;
    int Count = 0;
  };
  std::vector<float> DepthRead, TileMin, TileMax;
  long long CoveredPixels = 0;
  bool TilesPlanned = false;
  std::vector<TileGroup> Groups[2];
  vtkShadowClipSpaceRects Rects[2];
  // Ranks sharing the image (vtkShadowRankReduction): bounds and maps
  // reduced over them.
  vtkSmartPointer<vtkMultiProcessController> Controller;
  std::vector<float> ReduceScratch;
};

#endif
