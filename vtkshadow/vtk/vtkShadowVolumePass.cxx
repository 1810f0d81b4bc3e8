#include "vtkShadowVolumePass.h"
#include "vtkShadowSettings.h"
#include "vtkShadowStageProfile.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowFacingTest.h"
#include "vtkShadowFrame.h"
#include "vtkShadowImpostorProxies.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowScreenMask.h"
#include "vtkShadowVolumeOpacityMap.h"
#include "vtkShadowVolumeSides.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"
#include "vsh_rt_adaptive.h"
#include "vsh_silhouette.h"
#include "vsh_soft.h"
#include "vsh_soft_adaptive.h"
#include "vsh_transmit.h"
#include "vsh_volume.h"

#include "vtkShadowVolumeFS.h"
#include "vtkShadowVolumeVS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkShadowVolumePass);

namespace
{
constexpr int MaxLights = vtkShadowScreenMask::MaxLights;

// The renderer's actors that cast: the frame's Actors (from the renderer's
// props, not the render state's frustum-culled ones: a caster behind the
// camera still throws its shadow into the view) without NO_CAST and drawn
// as surfaces (vtkshadow::CastsAsSurface).
std::vector<vtkshadow::ShadowActor> CastingActors(const vtkshadow::ShadowFrame& frame)
{
  std::vector<vtkshadow::ShadowActor> actors;
  for (const vtkshadow::ShadowActor& a : frame.Actors)
  {
    if (vtkshadow::CastsAsSurface(a, vtkShadowPassBase::NO_CAST()))
    {
      actors.push_back(a);
    }
  }
  return actors;
}

// Whether the actor's whole surface is in the depth pre-pass: drawn as a
// surface, no face culled. Z-pass counting needs it (see DrawCaster).
bool SurfaceInDepth(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  return property->GetRepresentation() == VTK_SURFACE && !property->GetBackfaceCulling() &&
    !property->GetFrontfaceCulling();
}

// VTK 9.1 draws a surface with its edges through a geometry shader
// (vtkPolyDataEdgesGS.glsl) that moves each vertex 0.5 x LineWidth pixels
// outwards in x and y but keeps its depth, so that the edge lines fit inside
// the triangle. The drawn depth is then another plane: the difference is an
// affine function whose size at each moved vertex is the true plane's depth
// gradient times that move, so anywhere on the triangle it is at most
// 0.5 x LineWidth x |gradient|, a slope factor. A steep face drawn this way
// was shadowed on up to half its pixels by its own caps. The extra quarter
// pixel covers the rounding of the moved vertices.
float EdgesDepthTilt(double lineWidth)
{
  constexpr double roundingMargin = 0.25;
  return static_cast<float>(0.5 * std::max(lineWidth, 1.0) + roundingMargin);
}

// The caps lie on the caster's own faces, which its mapper may have drawn
// pushed back by VTK's coincident-topology offset (vtkMapper's
// ResolveCoincidentTopology; vedo turns it on for every mesh): depth +
// factor x |d depth / d pixel| + units x 1.6e-5 in its fragment shader
// (VTK 9.1's constant; later versions divide by 65000, a little less). The
// caps take the same offset on top of the sides' bias (its size: a cap
// pulled towards the camera must still pass a surface pushed either way),
// or a face whose cap does not lose the depth test to its own surface is
// shadowed whole (vedo's RandomHills: false shadows on 1.3 % of the frame).
void CoincidentOffset(vtkActor* actor, float& factor, float& units)
{
  factor = units = 0.0f;
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  if (!mapper || !property)
  {
    return;
  }
  // VTK 9.1's rule (vtkOpenGLPolyDataMapper::GetCoincidentParameters): the
  // triangles take the polygon offset in the global polygon-offset mode or
  // when the surface is drawn with its edges (vtkProperty::EdgeVisibility,
  // vedo's linewidth()); the edges are then drawn over every triangle again
  // with the line offset (units -4 by default, towards the camera). The
  // depth holds the nearer of the two, and the caps must reach past either.
  const bool edges = property->GetEdgeVisibility() && property->GetRepresentation() == VTK_SURFACE;
  double f = 0.0, u = 0.0;
  if (vtkMapper::GetResolveCoincidentTopology() == VTK_RESOLVE_POLYGON_OFFSET || edges)
  {
    mapper->GetCoincidentTopologyPolygonOffsetParameters(f, u);
    factor = static_cast<float>(std::abs(f));
    units = static_cast<float>(std::abs(u) * 1.6e-5);
  }
  if (edges)
  {
    mapper->GetCoincidentTopologyLineOffsetParameters(f, u);
    factor = std::max(factor, static_cast<float>(std::abs(f)));
    units = std::max(units, static_cast<float>(std::abs(u) * 1.6e-5));
    factor += EdgesDepthTilt(property->GetLineWidth());
  }
}

// Per-light counters of one frame, for --stats.
struct LightStats
{
  bool Casts = false;
  int ZPass = 0, ZFail = 0, Culled = 0;
  long long SilhouetteEdges = 0, Quads = 0, CapTriangles = 0;
  double FillPx = 0.0;
  double Cost = 0.0;
  // Samples of the volumes' faces that passed the depth test in the
  // previous frame this light was counted (GL_SAMPLES_PASSED; -1 unknown).
  long long SamplesPassed = -1;
  // Adaptive sampling: the first batch's size (0: not adaptive) and the
  // pixels that got all samples in the previous adaptive frame (-1 unknown).
  int Batch = 0;
  long long RefinedPx = -1;
};

// One GL_SAMPLES_PASSED query per light around its volume draws. Its result
// is read a frame later (when it is available), so the count never stalls
// the pipeline; a light whose query is still running skips a frame.
struct FillQuery
{
  GLuint Id = 0;
  bool Pending = false;
  long long Last = -1;

  // Takes last frame's result if the GPU has it (never waits), and makes
  // the query object on first use.
  void Collect()
  {
    if (this->Pending)
    {
      GLuint available = 0;
      glGetQueryObjectuiv(this->Id, GL_QUERY_RESULT_AVAILABLE, &available);
      if (available)
      {
        GLuint samples = 0;
        glGetQueryObjectuiv(this->Id, GL_QUERY_RESULT, &samples);
        this->Last = static_cast<long long>(samples);
        this->Pending = false;
      }
    }
    if (!this->Id)
    {
      glGenQueries(1, &this->Id);
    }
  }
};
}

// One (caster, light) volume on the GPU, rebuilt only when the light moved
// relative to the caster or the caster's mesh changed.
struct vtkShadowVolumePass::Volume
{
  double Light[4] = { 0, 0, 0, 0 }; // relative to the stored positions
  vtkMTimeType GeometryTime = 0;
  bool Valid = false;
  bool DarkCaps = false;    // closed caster: its facets facing away are dark
  bool Crossings = false;   // every face's prism: a translucent caster's count
  long long UsedFrame = -1; // the last frame this volume was counted
  size_t SideTriangles = 0, CapTriangles = 0;
  size_t SilhouetteEdges = 0, Quads = 0;
  vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* Program = nullptr;
  size_t Bytes = 0;

  void Release()
  {
    if (this->Buffer)
    {
      this->VAO->ReleaseGraphicsResources();
      this->Buffer->ReleaseGraphicsResources();
    }
  }
};

struct vtkShadowVolumePass::Internals
{
  vtkShadowScreenMask Opaque;
  // The translucent layer: translucent actors' own fragments, counted like
  // the opaque surfaces where they are the nearest (vtkShadowScreenMask).
  vtkShadowScreenMask Translucent;
  vtkShadowScreenMask* Counted = &this->Opaque; // the layer being counted
  vtkShadowScreenMask& Mask() { return *this->Counted; }
  // The mask `prop`'s fragments read.
  vtkShadowScreenMask& For(vtkProp* prop)
  {
    return this->Translucent.ReadBy(prop) ? this->Translucent : this->Opaque;
  }
  struct Caster
  {
    vtkShadowCasterGeometry Geometry;
    Volume Volumes[MaxLights];
    // A light with a size: one volume per sample point, so the samples
    // neither rebuild nor overwrite the hard volume of Volumes[light].
    std::vector<Volume> SoftVolumes[MaxLights];
    // The last frame in which a volume of light I had dark caps (the
    // caster is closed for that light: the facing test applies).
    long long ClosedFrame[MaxLights] = { -1, -1, -1, -1, -1, -1, -1, -1 };
    long long SeenFrame = -1;
  };
  // By (actor, instance): an actor drawn at two places (two assembly paths)
  // has a volume per place; the proxy of its spheres and tubes is at
  // (actor, -1 - instance), out of the facing test's reach (its lookup
  // starts at instance 0: VTK's impostors are not the proxy's facets).
  std::map<std::pair<vtkActor*, int>, std::unique_ptr<Caster>> Casters;
  // The actors whose shaders carry the facing test (UpdateFacingShaders).
  vtkshadow::FacingShaderSet FacingShaders;
  vtkshadow::ImpostorProxies Proxies;
  // The volumes' opacity shadow maps, multiplied into each layer's mask
  // after the stencil counts.
  vtkShadowVolumeOpacityMap VolumeMaps;
  // The sides drawn with their bias as a polygon offset (OffsetSides).
  vtkShadowVolumeSides Sides;
  static std::pair<vtkActor*, int> Key(const vtkshadow::ShadowActor& a)
  {
    return { a.Actor, a.Proxy ? -1 - a.Instance : a.Instance };
  }
  // The triangles a caster's volumes are built from.
  vtkShadowCasterGeometry& GeometryOf(const vtkshadow::ShadowActor& a)
  {
    return a.Proxy ? *a.Proxy : this->Casters[Key(a)]->Geometry;
  }
  long long FrameNumber = 0;
  LightStats Stats[MaxLights];
  FillQuery Queries[MaxLights];
  FillQuery RefineQueries[MaxLights]; // pixels marked for refinement
  // vsh_soft_batch_order for (SoftSamples, batch), computed when N changes.
  std::vector<int> Order;
  int OrderSamples = 0, OrderBatch = 0;
  int LightCount = 0;
  // The facing test's lights this frame: in view coordinates, with their
  // sizes where sampled.
  vtkshadow::FacingLights Facing;
  int Samples[MaxLights] = {}; // samples counted this frame per light (0: not counted)
  long long VolumeBuilds = 0;
  long long Instances = 0;
  bool Reported = false;
  vtkOpenGLState* State = nullptr;         // while counting a light
  vtkOpenGLRenderWindow* Window = nullptr; // while counting a light
};

// The frame in plain data: camera (relative to the eye, in double), lights
// and casters.
struct vtkShadowVolumePass::Frame
{
  explicit Frame(const vtkshadow::ShadowFrame& shared)
    : Shared(shared)
  {
  }
  const vtkshadow::ShadowFrame& Shared;
  int Size[2] = { 1, 1 }; // the viewport, at least a pixel each way
  double NearCorners[12]; // near-plane rectangle, relative to the eye
  // Per light: radius (positional) or angular diameter in degrees
  // (directional) when it is sampled (SoftSamples > 1), else 0.
  std::vector<double> LightSize;
  std::vector<vtkshadow::ShadowActor> Casters;
  // Translucent casters (opacity strictly between 0 and 1) and their opacity.
  std::vector<vtkshadow::ShadowActor> Translucent;
  std::vector<double> TranslucentOpacity;
  // The props this render state draws, sorted: z-pass counting needs the
  // caster's own surface in the depth buffer (see DrawCaster).
  std::vector<vtkProp*> Drawn;
};

//------------------------------------------------------------------------------
vtkShadowVolumePass::vtkShadowVolumePass()
  : Impl(new Internals)
{
  this->Impl->Translucent.SetTranslucentSurfaces(true);
  this->VolumesReceive = true;
}

//------------------------------------------------------------------------------
vtkShadowVolumePass::~vtkShadowVolumePass() = default;

//------------------------------------------------------------------------------
void vtkShadowVolumePass::SetUpFrame(const vtkRenderState* s, Frame& frame)
{
  const vtkshadow::ShadowFrame& shared = frame.Shared;
  frame.Size[0] = std::max(shared.Size[0], 1);
  frame.Size[1] = std::max(shared.Size[1], 1);
  vsh_volume_near_corners(shared.CameraRelative, frame.NearCorners);
  for (const vtkshadow::ShadowFrameLight& light : shared.Lights)
  {
    frame.LightSize.push_back(this->SoftSamples <= 1 ? 0.0 : light.Size);
  }
  frame.Casters = CastingActors(shared);
  // Points drawn as spheres and lines drawn as tubes: their closed proxies.
  this->Impl->Proxies.Append(shared, shared.Actors, frame.Casters);
  // Translucent actors cast as the opaque ones do (not NO_CAST, drawn as
  // surfaces); opacity 0 lets all the light through.
  for (const vtkshadow::ShadowActor& a : shared.Translucent)
  {
    const double opacity = vtkshadow::CasterOpacity(a.Actor);
    if (opacity > 0.0 && vtkshadow::CastsAsSurface(a, vtkShadowPassBase::NO_CAST()))
    {
      frame.Translucent.push_back(a);
      frame.TranslucentOpacity.push_back(opacity);
    }
  }
  frame.Drawn.assign(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
  std::sort(frame.Drawn.begin(), frame.Drawn.end());
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::LightsInViewCoordinates(vtkRenderer* renderer, const Frame& frame)
{
  this->Impl->Facing = vtkshadow::FacingLightsOf(renderer, frame.Shared, this->SoftSamples > 1);
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  Internals& impl = *this->Impl;
  ++impl.FrameNumber;
  vtkshadow::MarkStage("setup");
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  Frame frame(this->BeginFrame(s));
  // One value per light: a filter's colour comes out grey.
  this->NoteGreyFilters(frame.Shared);
  impl.VolumeMaps.Update(frame.Shared, window);
  this->NoteUncastVolumes(frame.Shared, &impl.VolumeMaps);
  this->SetUpFrame(s, frame);
  impl.LightCount = std::min(static_cast<int>(frame.Shared.Lights.size()), MaxLights);
  this->LightsInViewCoordinates(s->GetRenderer(), frame);
  for (auto& stats : impl.Stats)
  {
    stats = LightStats();
  }
  if (!this->CountLayer(s, window, frame, impl.Opaque))
  {
    if (!impl.Reported)
    {
      vtkErrorMacro("shadow volumes are off: "
        << (window ? impl.Opaque.GetError() : std::string("not an OpenGL render window")));
      impl.Reported = true;
    }
    this->RenderDelegate(s);
    return;
  }
  // Translucent surfaces receive on their own fragments: the same counts
  // against the nearest surface's depth, translucent ones included.
  const bool translucent = vtkShadowScreenMask::HasTranslucentProps(s);
  if (translucent && !this->CountLayer(s, window, frame, impl.Translucent))
  {
    vtkErrorMacro("shadow volumes (translucent layer): " << impl.Translucent.GetError());
  }
  this->ReleaseUnusedVolumes(window);
  vtkshadow::MarkStage("volume.stencil");
  impl.Opaque.Activate();
  impl.Translucent.Activate();
  this->RenderDelegateWithShaderHooks(s, &impl.Opaque);
  impl.Translucent.Deactivate();
  impl.Opaque.Deactivate();
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::CountLayer(const vtkRenderState* s, vtkOpenGLRenderWindow* window,
  const Frame& frame, vtkShadowScreenMask& layer)
{
  Internals& impl = *this->Impl;
  if (!window)
  {
    return false;
  }
  impl.Counted = &layer;
  // The depth pass draws with this pass's hooks registered too: a mapper
  // that first compiled its shader there without them would otherwise see
  // no newer shader stage in the main pass and keep the unhooked shader.
  this->PreRender(s);
  const bool depthOk = layer.RenderDepth(s, impl.LightCount);
  this->PostRender(s);
  vtkshadow::MarkStage("volume.prepass");
  vtkShaderProgram* program = depthOk
    ? window->GetShaderCache()->ReadyShaderProgram(vtkShadowVolumeVS, vtkShadowVolumeFS, "")
    : nullptr;
  impl.Sides.Ready(window, program, this->OffsetSides);
  impl.Instances = 0;
  std::fill(impl.Samples, impl.Samples + MaxLights, 0);
  for (int light = 0; light < impl.LightCount && program; ++light)
  {
    if (frame.Shared.Lights[light].Casts)
    {
      impl.Stats[light].Casts = true;
      this->CountLight(window, program, frame, light);
    }
  }
  if (program && !impl.VolumeMaps.Apply(window, layer, frame.Shared))
  {
    vtkErrorMacro("the volumes' opacity shadow maps did not draw");
  }
  impl.Counted = &impl.Opaque;
  this->UpdateFacingShaders();
  return depthOk;
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::UpdateFacingShaders()
{
  // The facing test's code goes only into the shaders of the actors that
  // are a closed caster of some light this frame (scivis/elevation, an open
  // caster, spent 1.9 ms of a 23.7 ms frame at 800x600 on the test in every
  // shader). The depth pre-pass before the volumes keeps the previous set's
  // shaders, which draw the same depth.
  // The entries' actors are not touched: an entry can outlive its actor
  // until the cache drops it, but only this frame's casters are closed this
  // frame.
  Internals& impl = *this->Impl;
  impl.FacingShaders.Begin();
  for (const auto& entry : impl.Casters)
  {
    for (int light = 0; this->FacingTest && light < impl.LightCount; ++light)
    {
      if (entry.second->ClosedFrame[light] == impl.FrameNumber)
      {
        impl.FacingShaders.Add(entry.first.first);
        break;
      }
    }
  }
  if (impl.FacingShaders.Commit())
  {
    this->BumpShaderTime();
  }
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::CountLight(
  vtkOpenGLRenderWindow* window, vtkShaderProgram* program, const Frame& frame, int light)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  impl.State = state;
  impl.Window = window;
  // A light with a size is sampled: N counts, each adding its share of lit
  // (vtkShadowScreenMask::AccumulateStencil); otherwise one count resolved.
  const int samples = frame.LightSize[light] > 0.0 ? this->SoftSamples : 1;
  impl.Samples[light] = samples;
  // The caller's winding (GL_CW while vtkPlanarReflectionPass draws a
  // mirrored world): DrawCaster sets its own per caster, and the delegate's
  // draw afterwards must see the caller's again, or the mappers' two-sided
  // lighting flips every normal of the mirrored scene.
  GLint frontFace = GL_CCW;
  glGetIntegerv(GL_FRONT_FACE, &frontFace);
  impl.Mask().BeginDraw(light);
  {
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    state->vtkglDisable(GL_SCISSOR_TEST);
    if (samples > 1)
    {
      impl.Mask().FillLight(light, 0.0f);
    }
    state->vtkglStencilMask(0xff);
    glClearStencil(0);
    state->vtkglClear(GL_STENCIL_BUFFER_BIT);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_BLEND);
    state->vtkglEnable(GL_STENCIL_TEST);
    // The far cap lies at infinity (w = 0): clamp its depth to the far
    // plane instead of clipping it. Not in VTK's state cache: restored below.
    glEnable(GL_DEPTH_CLAMP);
    FillQuery& query = impl.Queries[light];
    query.Collect();
    // Adaptive: the order puts the batch (centre and rim) first; otherwise
    // the spiral's order, the samples of before.
    const int batch =
      vsh_rt_adaptive_first(samples, this->Adaptive ? 1 : 0, VSH_SOFT_ADAPTIVE_BATCH);
    const std::vector<int>& order = this->SampleOrder(samples, batch);
    impl.Stats[light].Batch = batch < samples ? batch : 0;
    // The fill of the first (or only) count: a query cannot pause around
    // the accumulation quads of the samples.
    const bool measure = query.Id && !query.Pending;
    for (int j = 0; j < samples; ++j)
    {
      const bool refining = j >= batch;
      if (j == batch)
      {
        this->MarkRefined(light, vsh_soft_batch_levels(samples, batch, order.data()));
      }
      if (j > 0)
      {
        state->vtkglDisable(GL_SCISSOR_TEST);
        state->vtkglStencilMask(refining ? 0x7f : 0xff);
        state->vtkglClear(GL_STENCIL_BUFFER_BIT);
      }
      if (measure && j == 0)
      {
        glBeginQuery(GL_SAMPLES_PASSED, query.Id);
      }
      const int sample = order[static_cast<size_t>(j)];
      this->CountVolumes(program, frame, light, samples > 1 ? sample : -1, refining);
      if (measure && j == 0)
      {
        glEndQuery(GL_SAMPLES_PASSED);
        query.Pending = true;
      }
      state->vtkglDisable(GL_SCISSOR_TEST);
      if (samples > 1)
      {
        impl.Mask().AccumulateStencil(
          light, vtkShadowScreenMask::AccumulationLevels(sample, samples), refining ? 0x80 : 0);
      }
    }
    impl.Stats[light].SamplesPassed = query.Last;
    if (samples == 1)
    {
      impl.Mask().ResolveStencil(light);
    }
    if (!frame.Translucent.empty())
    {
      this->CountTranslucent(program, frame, light);
    }
    glDisable(GL_DEPTH_CLAMP);
    glFrontFace(static_cast<GLenum>(frontFace));
  }
  impl.Mask().EndDraw();
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::CountVolumes(vtkShaderProgram* program, const Frame& frame, int light,
  int sample, bool refining, const vtkshadow::ShadowActor* translucent)
{
  // The state of CountLight; the mask's accumulation between two samples
  // changed the stencil function and the bound program. Refining: the
  // counts go to the low 7 bits of the pixels marked in bit 7 (modulo 128
  // instead of 256), and the others reject every fragment.
  vtkOpenGLState* state = this->Impl->State;
  if (refining)
  {
    state->vtkglStencilFunc(GL_EQUAL, 0x80, 0x80);
    state->vtkglStencilMask(0x7f);
  }
  else
  {
    state->vtkglStencilFunc(GL_ALWAYS, 0, 0xff);
    state->vtkglStencilMask(0xff);
  }
  state->vtkglEnable(GL_SCISSOR_TEST);
  this->Impl->Window->GetShaderCache()->ReadyShaderProgram(program);
  program->SetUniformf("depthBias", static_cast<float>(this->DepthBias * std::ldexp(1.0, -24)));
  program->SetUniformf("slopeBias", static_cast<float>(this->SlopeBias));
  program->SetUniformf("maxSlopeBias", static_cast<float>(std::ldexp(1.0, -12)));
  program->SetUniformf("capFactor", 0.0f);
  program->SetUniformf("capUnits", 0.0f);
  if (translucent)
  {
    this->DrawCaster(program, frame, light, sample, *translucent, true);
    return;
  }
  for (const vtkshadow::ShadowActor& caster : frame.Casters)
  {
    this->DrawCaster(program, frame, light, sample, caster);
  }
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::CountTranslucent(vtkShaderProgram* program, const Frame& frame, int light)
{
  // After the opaque casters' channel is final: per translucent caster, the
  // crossings volume (every face's prism, z-fail: the caster is not in the
  // depth) counts at each pixel the caster's triangles between the surface
  // and the light (the light's centre for a sampled light), and the channel
  // is multiplied by (1 - opacity) per unit of that count
  // (docs/translucency.md). Each count starts from a zero stencil: the
  // opaque count is cleared once, and each multiplication takes its count
  // back to 0 (cleared again if it stopped early).
  vtkOpenGLState* state = this->Impl->State;
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglStencilMask(0xff);
  state->vtkglClear(GL_STENCIL_BUFFER_BIT);
  for (size_t c = 0; c < frame.Translucent.size(); ++c)
  {
    this->CountVolumes(program, frame, light, -1, false, &frame.Translucent[c]);
    // The draws keep the caster's scissor rectangle: the multiplication
    // touches only it.
    const double transmit = 1.0 - frame.TranslucentOpacity[c];
    const int maxSteps = vsh_transmit_steps(transmit);
    if (this->Impl->Mask().MultiplyStencilCount(light, static_cast<float>(transmit), maxSteps) >=
      maxSteps)
    {
      state->vtkglDisable(GL_SCISSOR_TEST);
      state->vtkglStencilMask(0xff);
      state->vtkglClear(GL_STENCIL_BUFFER_BIT);
    }
  }
}

//------------------------------------------------------------------------------
const std::vector<int>& vtkShadowVolumePass::SampleOrder(int samples, int batch)
{
  Internals& impl = *this->Impl;
  if (impl.OrderSamples != samples || impl.OrderBatch != batch)
  {
    // batch >= samples: the identity (vsh_soft_batch_order's), the spiral's
    // order of the non-adaptive path.
    impl.Order.assign(static_cast<size_t>(samples), 0);
    vsh_soft_batch_order(samples, batch, impl.Order.data());
    impl.OrderSamples = samples;
    impl.OrderBatch = batch;
  }
  return impl.Order;
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::MarkRefined(int light, int batchLevels)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = impl.State;
  // The pixels whose batch was all lit and stay so: stencil 0x40, then
  // the rest of the 255 levels there (all N samples lit reads exactly 1).
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglStencilMask(0xff);
  state->vtkglClear(GL_STENCIL_BUFFER_BIT);
  impl.Mask().MarkBatch(light, batchLevels, false, 0x40);
  impl.Mask().AccumulateStencil(light, 255 - batchLevels, 0x40);
  state->vtkglClear(GL_STENCIL_BUFFER_BIT);
  // Then the pixels to refine: stencil bit 7, counted once (the result is
  // read a frame later, when available, for --stats).
  FillQuery& query = impl.RefineQueries[light];
  query.Collect();
  const bool measure = query.Id && !query.Pending;
  if (measure)
  {
    glBeginQuery(GL_SAMPLES_PASSED, query.Id);
  }
  impl.Mask().MarkBatch(light, batchLevels, true, 0x80);
  if (measure)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    query.Pending = true;
  }
  impl.Stats[light].RefinedPx = query.Last;
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::ReleaseUnusedVolumes(vtkOpenGLRenderWindow* window)
{
  Internals& impl = *this->Impl;
  for (auto it = impl.Casters.begin(); it != impl.Casters.end();)
  {
    Internals::Caster& caster = *it->second;
    // The samples of a light counted hard (or not at all) this frame: a
    // sized light that turns hard or stops casting frees its N volumes.
    for (int light = 0; light < MaxLights; ++light)
    {
      if (impl.Samples[light] <= 1 || caster.SeenFrame != impl.FrameNumber)
      {
        for (Volume& volume : caster.SoftVolumes[light])
        {
          volume.Release();
        }
        caster.SoftVolumes[light].clear();
      }
    }
    // Forget casters that left the scene.
    if (caster.SeenFrame != impl.FrameNumber)
    {
      caster.Geometry.ReleaseGraphicsResources(window);
      it = impl.Casters.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
vtkShadowVolumePass::Volume* vtkShadowVolumePass::UpdateVolume(
  const vtkshadow::ShadowActor& shadowActor, int light, int sample, const double lightWorld[4],
  bool crossings)
{
  Internals& impl = *this->Impl;
  vtkActor* actor = shadowActor.Actor;
  auto& caster = impl.Casters[impl.Key(shadowActor)];
  if (!caster)
  {
    caster.reset(new Internals::Caster);
  }
  vtkShadowCasterGeometry& geometry = impl.GeometryOf(shadowActor);
  if (caster->SeenFrame != impl.FrameNumber)
  {
    if (!shadowActor.Proxy)
    {
      geometry.Update(actor);
    }
    caster->SeenFrame = impl.FrameNumber;
    impl.Instances += geometry.GetNumberOfInstances();
  }
  const vsh_mesh_topology* topology = geometry.GetTopology();
  double lightStored[4];
  if (!topology || !geometry.WorldToStored(shadowActor.Matrix, lightWorld, lightStored))
  {
    return nullptr;
  }
  std::vector<Volume>& soft = caster->SoftVolumes[light];
  if (sample >= 0 && soft.size() != static_cast<size_t>(this->SoftSamples))
  {
    for (size_t i = static_cast<size_t>(this->SoftSamples); i < soft.size(); ++i)
    {
      soft[i].Release();
    }
    soft.resize(static_cast<size_t>(this->SoftSamples));
  }
  Volume& volume = sample >= 0 ? soft[static_cast<size_t>(sample)] : caster->Volumes[light];
  if (volume.Valid && volume.GeometryTime == geometry.GetBuildTime() &&
    volume.Crossings == crossings && std::equal(lightStored, lightStored + 4, volume.Light))
  {
    volume.UsedFrame = impl.FrameNumber;
    caster->ClosedFrame[light] = volume.DarkCaps ? impl.FrameNumber : caster->ClosedFrame[light];
    return &volume;
  }
  vsh_volume built;
  if ((crossings ? vsh_volume_build_crossings(topology, lightStored, &built)
                 : vsh_volume_build(topology, lightStored, &built)) != VSH_MESH_OK)
  {
    return nullptr;
  }
  ++impl.VolumeBuilds;
  const size_t triangles = built.side_triangles + built.cap_triangles;
  std::vector<float> data(12 * triangles);
  for (size_t i = 0; i < data.size(); ++i)
  {
    data[i] = static_cast<float>(built.vertices[i]);
  }
  volume.SideTriangles = built.side_triangles;
  volume.CapTriangles = built.cap_triangles;
  volume.SilhouetteEdges = built.silhouette_edges;
  volume.Quads = built.silhouette_quads;
  volume.DarkCaps = built.dark_caps != 0;
  volume.Crossings = crossings;
  volume.UsedFrame = impl.FrameNumber;
  caster->ClosedFrame[light] = volume.DarkCaps ? impl.FrameNumber : caster->ClosedFrame[light];
  vsh_volume_free(&built);
  if (!volume.Buffer)
  {
    volume.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    volume.Buffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    volume.VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  if (!data.empty())
  {
    volume.Buffer->Upload(data, vtkOpenGLBufferObject::ArrayBuffer);
  }
  volume.Bytes = data.size() * sizeof(float);
  volume.Program = nullptr;
  std::copy_n(lightStored, 4, volume.Light);
  volume.GeometryTime = geometry.GetBuildTime();
  volume.Valid = true;
  return &volume;
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::CountsZPass(const Frame& frame, const vtkshadow::ShadowActor& caster,
  const Volume& volume, const double bounds[6], const double lightRelative[4], bool crossings) const
{
  double size = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    size = std::max(size, bounds[2 * k + 1] - bounds[2 * k]);
  }
  const double eye[3] = { 0, 0, 0 };
  // Z-pass counts no caps: a ray from the eye enters a volume through its
  // sides or through the caster itself, which then hides what lies behind.
  // A caster the state does not draw (the mirror in the mirrored world of
  // vtkPlanarReflectionPass: it casts there, as it does in the real world,
  // but is not drawn) lets the ray in through its cap uncounted, so its
  // volume is counted z-fail (a wall mirror's shadow on the reflected floor
  // was inverted: reflection_mae 0.16 against POV-Ray). So does a caster
  // drawn as lines or points, or with culled faces: its surface has holes
  // in the depth (an open caster with culled back faces, seen from behind:
  // 15.6 % of the pixels off in z-pass, 0.07 % in z-fail).
  // A proxy of spheres or tubes is not what the depth holds (VTK's
  // impostors are): z-fail.
  const bool drawn = std::binary_search(frame.Drawn.begin(), frame.Drawn.end(), caster.Root) &&
    SurfaceInDepth(caster.Actor) && !caster.Proxy;
  // A translucent caster's crossings are always counted z-fail: it is not in
  // the depth pre-pass. With OpenZFail, so is a caster that is not closed
  // (both sides' volumes) when the camera sees one of its faces from the
  // side that faces away from the light: there the prisms of its faces
  // reach towards the eye and z-pass counts their far faces against the
  // surface's own depth. A floor seen from above under a light above stays
  // z-pass, without caps to draw.
  // The per-face test last, only when nothing cheaper has decided.
  if (this->ForceZFail || !drawn || crossings ||
    vsh_volume_zpass_safe(eye, frame.NearCorners, bounds, lightRelative, 1e-3 * size) != 1)
  {
    return false;
  }
  return volume.DarkCaps || this->UnlitCaps || !this->OpenZFail ||
    !this->SeenUnlit(frame, caster, volume);
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::SeenUnlit(
  const Frame& frame, const vtkshadow::ShadowActor& caster, const Volume& volume) const
{
  // The eye in the volume's own (shifted model) coordinates, as the light
  // it was built for.
  double eyeWorld[4];
  vtkshadow::EyeHomogeneous(frame.Shared, eyeWorld);
  vtkShadowCasterGeometry& geometry = this->Impl->GeometryOf(caster);
  double eyeStored[4];
  if (!geometry.GetTopology() || !geometry.WorldToStored(caster.Matrix, eyeWorld, eyeStored))
  {
    return true;
  }
  return vsh_silhouette_seen_unlit(geometry.GetTopology(), volume.Light, eyeStored) != 0;
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::DrawCaster(vtkShaderProgram* program, const Frame& frame, int light,
  int sample, const vtkshadow::ShadowActor& caster, bool crossings)
{
  Internals& impl = *this->Impl;
  LightStats& stats = impl.Stats[light];
  double lightWorld[4];
  std::copy_n(frame.Shared.Lights[light].Homogeneous, 4, lightWorld);
  if (sample >= 0)
  {
    // Sample `sample` of the light's disk turned to face the caster's
    // centre, as planar's samples (docs/soft-shadows.md): a caster centred
    // on the light keeps the centre.
    double centre[3], point[4];
    for (int i = 0; i < 3; ++i)
    {
      centre[i] = 0.5 * (caster.Bounds[2 * i] + caster.Bounds[2 * i + 1]);
    }
    if (vsh_soft_sample_light(
          lightWorld, frame.LightSize[light], centre, sample, this->SoftSamples, 0.0, point) == 0)
    {
      std::copy_n(point, 4, lightWorld);
    }
  }
  Volume* volume = this->UpdateVolume(caster, light, sample, lightWorld, crossings);
  if (!volume || volume->SideTriangles + volume->CapTriangles == 0)
  {
    return;
  }
  // Camera-relative bounds and light for the planning tests.
  double bounds[6],
    lightRelative[4] = { lightWorld[0], lightWorld[1], lightWorld[2], lightWorld[3] };
  std::copy_n(caster.Bounds, 6, bounds);
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] -= frame.Shared.Eye[k];
    bounds[2 * k + 1] -= frame.Shared.Eye[k];
    lightRelative[k] -= lightWorld[3] * frame.Shared.Eye[k];
  }
  int rect[4];
  if (!vsh_volume_screen_rect(
        frame.Shared.CameraRelative, bounds, lightRelative, frame.Size[0], frame.Size[1], rect))
  {
    ++stats.Culled;
    return;
  }
  const bool zpass = this->CountsZPass(frame, caster, *volume, bounds, lightRelative, crossings);
  // Model (shifted) -> world -> relative to the eye -> clip, in double.
  double modelRelative[16], mcdc[16], transposed[16];
  impl.GeometryOf(caster).GetModelRelativeMatrix(caster.Matrix, frame.Shared.Eye, modelRelative);
  vsh_mat4_multiply(frame.Shared.CameraRelative, modelRelative, mcdc);
  vsh_mat4_transpose(mcdc, transposed);
  float mcdcF[16];
  for (int i = 0; i < 16; ++i)
  {
    mcdcF[i] = static_cast<float>(transposed[i]);
  }
  program->SetUniformMatrix4x4("volumeMCDC", mcdcF);
  // A mirroring matrix turns every volume inside out: keep "front" meaning
  // "entering" so its counts add to the other casters' instead of cancelling.
  glFrontFace(vsh_mat4_determinant(modelRelative) < 0.0 ? GL_CW : GL_CCW);
  vtkOpenGLState* state = impl.State;
  state->vtkglScissor(rect[0], rect[1], rect[2], rect[3]);
  if (zpass)
  {
    state->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    state->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  }
  else
  {
    state->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    state->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
  }
  if (volume->Program != program)
  {
    volume->VAO->ShaderProgramChanged();
    volume->VAO->Bind();
    volume->VAO->AddAttributeArray(
      program, volume->Buffer, "vertexMC", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
    volume->Program = program;
  }
  volume->VAO->Bind();
  // z-fail counts every cap. z-pass needs none of a closed caster's; of an
  // open caster's (with UnlitCaps) only those of the faces seen from their
  // unlit side: the leaving ones (DrawFaces).
  const bool leavingCaps = zpass && !volume->DarkCaps && this->UnlitCaps;
  const int caps = zpass && !leavingCaps ? 0 : static_cast<int>(3 * volume->CapTriangles);
  this->DrawFaces(
    program, mcdcF, static_cast<int>(3 * volume->SideTriangles), caps, leavingCaps, caster.Actor);
  volume->VAO->Release();

  (zpass ? stats.ZPass : stats.ZFail) += 1;
  stats.SilhouetteEdges += static_cast<long long>(volume->SilhouetteEdges);
  stats.Quads += static_cast<long long>(volume->Quads);
  stats.CapTriangles += zpass && !leavingCaps ? 0 : static_cast<long long>(volume->CapTriangles);
  const double fill = static_cast<double>(rect[2]) * rect[3];
  stats.FillPx += fill;
  const vsh_volume_cost_input cost = { volume->Quads, volume->CapTriangles, zpass ? 0 : 1, fill,
    2.0 };
  stats.Cost += vsh_volume_cost(&cost);
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::DrawFaces(vtkShaderProgram* program, const float volumeMCDC[16],
  int sides, int caps, bool leavingCaps, vtkActor* actor)
{
  Internals& impl = *this->Impl;
  // The caps carry the caster's coincident-topology offset (CoincidentOffset)
  // on top of the bias: the biased shader's terms, which a polygon offset
  // cannot add (it clamps its whole sum). Without one, their bias is the
  // sides'.
  float capFactor = 0.0f, capUnits = 0.0f;
  CoincidentOffset(caps > 0 ? actor : nullptr, capFactor, capUnits);
  const bool sidesBias = caps > 0 && capFactor == 0.0f && capUnits == 0.0f;
  // Caps with the sides' bias go with the sides: in their range when both
  // faces count, else (the leaving ones) in a second draw of the sides'
  // program, culled. All others go through the biased shader below.
  const bool capsInSidesRange = sidesBias && !leavingCaps;
  const bool capsAfterSides = sidesBias && leavingCaps && impl.Sides.Program();
  const int range = sides + (capsInSidesRange ? caps : 0);
  if (impl.Sides.Program())
  {
    impl.Sides.Draw(impl.Window, volumeMCDC, 0, range, this->DepthBias, this->SlopeBias);
    if (capsAfterSides)
    {
      impl.Sides.Draw(impl.Window, volumeMCDC, sides, caps, this->DepthBias, this->SlopeBias, true);
    }
    impl.Window->GetShaderCache()->ReadyShaderProgram(program);
  }
  else
  {
    glDrawArrays(GL_TRIANGLES, 0, range);
  }
  if (caps == 0 || capsInSidesRange || capsAfterSides)
  {
    return;
  }
  // The caps in the biased shader, the leaving ones alone when asked.
  if (leavingCaps)
  {
    impl.State->vtkglEnable(GL_CULL_FACE);
    impl.State->vtkglCullFace(GL_FRONT);
  }
  program->SetUniformf("capFactor", capFactor);
  program->SetUniformf("capUnits", capUnits);
  glDrawArrays(GL_TRIANGLES, sides, caps);
  program->SetUniformf("capFactor", 0.0f);
  program->SetUniformf("capUnits", 0.0f);
  if (leavingCaps)
  {
    impl.State->vtkglCullFace(GL_BACK);
    impl.State->vtkglDisable(GL_CULL_FACE);
  }
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  const bool ok = this->Impl->For(prop).PreReplaceShaderValues(fragmentShader, prop);
  if (fragmentShader.find("vshScreenPrepare") != std::string::npos &&
    this->Impl->FacingShaders.Has(prop))
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec",
      std::string("//VTK::Light::Dec\n") + vtkshadow::FacingShaderCode("vshFacing"), false);
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  this->ReceiveVolumeShadows(fragmentShader, prop);
  vtkShadowScreenMask& mask = this->Impl->For(prop);
  if (fragmentShader.find("vshFacingPrepare") == std::string::npos)
  {
    return mask.PostReplaceShaderValues(fragmentShader, this->GetResidualLight());
  }
  return mask.PostReplaceShaderValues(fragmentShader, this->GetResidualLight(),
    "vshFacingCombine(%d, vertexVC.xyz, vshScreenLit(%d))",
    "vshScreenPrepare(); vshFacingPrepare(vertexVC.xyz);");
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  this->SetVolumeShadowParameters(program);
  Internals& impl = *this->Impl;
  impl.For(prop).SetShaderParameters(program);
  if (program->IsUniformUsed("vshFacingLights"))
  {
    vtkshadow::SetFacingUniforms(program, "vshFacing", this->ClosedCasterLights(prop), impl.Facing);
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkShadowVolumePass::ClosedCasterLights(vtkProp* prop) const
{
  const Internals& impl = *this->Impl;
  auto* actor = vtkActor::SafeDownCast(prop);
  int bits = 0;
  if (!this->FacingTest || !actor)
  {
    return 0;
  }
  // Every instance of the actor: they share its mesh, so its closedness.
  for (auto it = impl.Casters.lower_bound({ actor, 0 });
       it != impl.Casters.end() && it->first.first == actor; ++it)
  {
    for (int light = 0; light < impl.LightCount; ++light)
    {
      if (it->second->ClosedFrame[light] == impl.FrameNumber)
      {
        bits |= 1 << light;
      }
    }
  }
  return bits;
}

//------------------------------------------------------------------------------
bool vtkShadowVolumePass::CastsExactly(vtkActor* actor)
{
  // A front-culled closed caster shows the inside its dark caps fill
  // (against raytrace, a sphere over a floor: 17.6 % of the pixels off).
  // Actors drawn as a wireframe or points cast nothing in any exact
  // technique (vtkshadow::CastsAsSurface), so they are exact here too.
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  return property && !property->GetFrontfaceCulling();
}

//------------------------------------------------------------------------------
vtkIdType vtkShadowVolumePass::GetNumberOfVolumeBuilds() const
{
  return static_cast<vtkIdType>(this->Impl->VolumeBuilds);
}

//------------------------------------------------------------------------------
long long vtkShadowVolumePass::GetMemoryBytes() const
{
  long long bytes = this->Impl->Opaque.GetMemoryBytes() + this->Impl->Translucent.GetMemoryBytes();
  for (const auto& entry : this->Impl->Casters)
  {
    bytes += entry.second->Geometry.GetNumberOfBytes();
    for (const Volume& volume : entry.second->Volumes)
    {
      bytes += static_cast<long long>(volume.Bytes);
    }
    for (const std::vector<Volume>& soft : entry.second->SoftVolumes)
    {
      for (const Volume& volume : soft)
      {
        bytes += static_cast<long long>(volume.Bytes);
      }
    }
  }
  return bytes + this->GetVolumeReceiverMemoryBytes();
}

//------------------------------------------------------------------------------
std::string vtkShadowVolumePass::GetStatsJSON(vtkRenderer*) const
{
  const Internals& impl = *this->Impl;
  std::ostringstream out;
  out << "\"volume_builds\": " << impl.VolumeBuilds << ", \"caster_instances\": " << impl.Instances
      << ", \"instancing\": \"per instance\", \"fill\": \"scissor area\", "
      << "\"sides_offset\": " << (impl.Sides.Program() ? "true" : "false") << ", "
      << impl.Proxies.StatsJSON() << ", " << impl.VolumeMaps.StatsJSON() << ", "
      << this->VolumeReceiverStatsJSON() << ", " << this->DepthSeedStatsJSON() << ", \"lights\": [";
  for (int light = 0; light < impl.LightCount; ++light)
  {
    const LightStats& s = impl.Stats[light];
    out << (light ? ", " : "") << "{\"casts\": " << (s.Casts ? "true" : "false")
        << ", \"zpass\": " << s.ZPass << ", \"zfail\": " << s.ZFail << ", \"culled\": " << s.Culled
        << ", \"silhouette_edges\": " << s.SilhouetteEdges << ", \"volume_quads\": " << s.Quads
        << ", \"cap_triangles\": " << s.CapTriangles
        << ", \"fill_px\": " << static_cast<long long>(s.FillPx)
        << ", \"fill_samples_passed\": " << s.SamplesPassed
        << ", \"cost\": " << static_cast<long long>(s.Cost)
        << ", \"soft_samples\": " << impl.Samples[light] << ", \"soft_batch\": " << s.Batch
        << ", \"refined_px\": " << s.RefinedPx << "}";
  }
  out << "]";
  return out.str();
}

//------------------------------------------------------------------------------
// The settings, once (vtkShadowSettings.h).
const vtkshadow::Settings& vtkShadowVolumePass::SettingsTable()
{
  using P = vtkShadowVolumePass;
  using vtkshadow::Row;
  static const vtkshadow::Settings table(&vtkShadowPassBase::SettingsTable(),
    {
      Row("depth_bias", vtkshadow::Closed(0, 1e6), &P::SetDepthBias, &P::GetDepthBias,
        "depth bias of the volume faces in 2^-24 of the depth range"),
      Row("slope_bias", vtkshadow::Closed(0, 16), &P::SetSlopeBias, &P::GetSlopeBias,
        "fraction of the depth's slope per pixel added to depth_bias"),
      Row("force_zfail", vtkshadow::Flag(), &P::SetForceZFail, &P::GetForceZFail,
        "count every volume with z-fail, never z-pass"),
      Row("open_zfail", vtkshadow::Flag(), &P::SetOpenZFail, &P::GetOpenZFail,
        "without unlit_caps: count the volumes of casters that are not closed z-fail where their "
        "unlit side is seen"),
      Row("unlit_caps", vtkshadow::Flag(), &P::SetUnlitCaps, &P::GetUnlitCaps,
        "count casters that are not closed z-pass, with the caps of the faces seen from their "
        "unlit side (open_zfail then does not apply)"),
      Row("facing_test", vtkshadow::Flag(), &P::SetFacingTest, &P::GetFacingTest,
        "darken the facets of closed casters that face away from a light"),
      Row("offset_sides", vtkshadow::Flag(), &P::SetOffsetSides, &P::GetOffsetSides,
        "bias the volumes' sides by a clamped polygon offset (depth and stencil tested before "
        "shading) instead of a depth the fragment shader writes"),
      Row("soft_samples", vtkshadow::Integers(1, 255), &P::SetSoftSamples, &P::GetSoftSamples,
        "samples of a light with a size (docs/soft-shadows.md)"),
      Row("adaptive", vtkshadow::Flag(), &P::SetAdaptive, &P::GetAdaptive,
        "the rest of the samples only near a penumbra"),
    });
  return table;
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  impl.Opaque.ReleaseGraphicsResources(w);
  impl.Translucent.ReleaseGraphicsResources(w);
  impl.VolumeMaps.ReleaseGraphicsResources(w);
  for (FillQuery& query : impl.RefineQueries)
  {
    if (query.Id && w)
    {
      glDeleteQueries(1, &query.Id);
    }
    query = FillQuery();
  }
  for (FillQuery& query : impl.Queries)
  {
    if (query.Id && w)
    {
      glDeleteQueries(1, &query.Id);
    }
    query = FillQuery();
  }
  impl.Proxies.ReleaseGraphicsResources(w);
  for (auto& entry : impl.Casters)
  {
    entry.second->Geometry.ReleaseGraphicsResources(w);
    for (Volume& volume : entry.second->Volumes)
    {
      volume.Release();
    }
    for (std::vector<Volume>& soft : entry.second->SoftVolumes)
    {
      for (Volume& volume : soft)
      {
        volume.Release();
      }
    }
  }
  impl.Casters.clear();
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkShadowVolumePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Casters: " << this->Impl->Casters.size() << "\n";
}
