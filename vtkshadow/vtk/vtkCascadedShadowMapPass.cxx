#include "vtkCascadedShadowMapPass.h"
#include "vtkShadowSettings.h"
#include "vtkShadowStageProfile.h"

#include "vtkActor.h"
#include "vtkCascadedShadowMapPassInternals.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowRankReduction.h"
#include "vtkShadowScreenMask.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include "vsh_bounds.h"
#include "vsh_camera.h"
#include "vsh_csm.h"
#include "vsh_csm_plan.h"
#include "vsh_mat4.h"
#include "vsh_pcss.h"

#include "vtkShadowMapDepthFS.h"
#include "vtkShadowMapDepthVS.h"
#include "vtkShadowMapLightFS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCascadedShadowMapPass);

using vtkshadow::ToFloatTransposed;

namespace
{
// Free one world's atlas (the objects stay, to be allocated again).
void ReleaseHeld(vtkshadow::CascadedHeldMaps& held, vtkWindow* w)
{
  if (held.Atlas)
  {
    held.Atlas->ReleaseGraphicsResources(w);
  }
  if (held.FBO)
  {
    held.FBO->ReleaseGraphicsResources(w);
  }
  for (vtkTextureObject* texture : { held.TranslucentDepth.Get(), held.Transmit.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(w);
    }
  }
  held.TransmitAllocated = false;
  held.AtlasSize[0] = held.AtlasSize[1] = 0;
  held.Rendered.clear();
}

constexpr int MaxLights = VSH_CSM_MAX_LIGHTS;
constexpr int MaxTiles = VSH_CSM_MAX_TILES;
}

namespace vtkshadow
{
// (vtkCascadedShadowMapPassInternals.h)
void AllocateDepthAtlas(
  vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width, int height)
{
  texture->SetContext(window);
  texture->ReleaseGraphicsResources(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetDepthTextureCompare(true);
  texture->SetDepthTextureCompareFunction(vtkTextureObject::Lequal);
  texture->AllocateDepth(width, height, vtkTextureObject::Float32);
  // The setters above change nothing the second time, so the texture
  // object's time is older than its last SendParameters and the new GL
  // texture would never get the depth compare mode: every lookup would
  // then read as shadowed (found by the robustness suite: auto re-sizing
  // its maps after a window resize).
  texture->Modified();
}
}

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass::vtkCascadedShadowMapPass()
  : CascadeCount(0)
  , RatioPerCascade(8.0)
  , SplitScheme(PRACTICAL)
  , SplitLambda(0.75)
  , Stable(true)
  , MapResolution(2048)
  , MaxTexelPixels(0.0)
  , MemoryBudget(256LL << 20)
  , BiasScale(1.0)
  , Filter(HARDWARE_2X2)
  , PCFSize(3)
  , PoissonRadius(1.5)
  , BlendBand(0.1)
  , MaxShadowDistance(0.0)
  , FadeFraction(0.1)
  , DebugCascades(false)
  , Resolve(FORWARD)
  , TapTexelPixels(4.0)
  , TileCull(true)
  , NumberOfTilesCulled(0)
  , Soft(SOFT_PCSS)
  , PCSSBlockerTaps(16)
  , PCSSFilterTaps(24)
  , PCSSMaxTexels(48.0)
  , UsedPCSS(false)
  , SoftSamples(16)
  , UsedSampled(false)
  , Adaptive(false)
  , UsedScreenResolve(false)
  , UsedResolution(0)
  , NumberOfMapsRendered(0)
  , NumberOfMapsReused(0)
  , TotalMapsRendered(0)
  , Impl(new Internals)
{
  this->VolumesReceive = true;
}

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass::~vtkCascadedShadowMapPass() = default;

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::CopySettings(vtkCascadedShadowMapPass* o)
{
  if (!o || o == this)
  {
    return;
  }
  this->CascadeCount = o->CascadeCount;
  this->RatioPerCascade = o->RatioPerCascade;
  this->SplitScheme = o->SplitScheme;
  this->SplitLambda = o->SplitLambda;
  std::copy_n(o->Impl->SplitFractions, VSH_CSM_MAX_CASCADES, this->Impl->SplitFractions);
  this->Stable = o->Stable;
  this->MapResolution = o->MapResolution;
  this->MaxTexelPixels = o->MaxTexelPixels;
  this->MemoryBudget = o->MemoryBudget;
  this->BiasScale = o->BiasScale;
  this->Filter = o->Filter;
  this->PCFSize = o->PCFSize;
  this->PoissonRadius = o->PoissonRadius;
  this->BlendBand = o->BlendBand;
  this->MaxShadowDistance = o->MaxShadowDistance;
  this->FadeFraction = o->FadeFraction;
  this->DebugCascades = o->DebugCascades;
  this->Resolve = o->Resolve;
  this->TapTexelPixels = o->TapTexelPixels;
  this->TileCull = o->TileCull;
  this->Soft = o->Soft;
  this->PCSSBlockerTaps = o->PCSSBlockerTaps;
  this->PCSSFilterTaps = o->PCSSFilterTaps;
  this->PCSSMaxTexels = o->PCSSMaxTexels;
  this->SoftSamples = o->SoftSamples;
  this->Adaptive = o->Adaptive;
  this->CastHeadlightShadows = o->CastHeadlightShadows;
  this->SkippedLights = o->SkippedLights;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::SetController(vtkMultiProcessController* controller)
{
  if (this->Impl->Controller != controller)
  {
    this->Impl->Controller = controller;
    // Maps of one rank are not the reduced ones, in any world.
    this->Impl->Held.Rendered.clear();
    for (auto& parked : this->Impl->Parked)
    {
      parked.second.Rendered.clear();
    }
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkCascadedShadowMapPass::GetController() const
{
  return this->Impl->Controller;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::SetSplitFraction(int i, double fraction)
{
  if (i >= 0 && i < VSH_CSM_MAX_CASCADES && this->Impl->SplitFractions[i] != fraction)
  {
    this->Impl->SplitFractions[i] = fraction;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapPass::GetSplitFraction(int i) const
{
  return (i >= 0 && i < VSH_CSM_MAX_CASCADES) ? this->Impl->SplitFractions[i] : 0.0;
}

//------------------------------------------------------------------------------
int vtkCascadedShadowMapPass::GetNumberOfCascades(int light) const
{
  const vsh_csm_tile_plan& tiles = this->Impl->Plan.tiles;
  return (light >= 0 && light < tiles.light_count && tiles.kind[light] == VSH_CSM_CASCADES)
    ? tiles.count[light]
    : 0;
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapPass::GetCascadeFar(int light, int cascade) const
{
  if (cascade < 0 || cascade >= this->GetNumberOfCascades(light))
  {
    return 0.0;
  }
  const vsh_csm_tile_plan& tiles = this->Impl->Plan.tiles;
  return tiles.tiles[tiles.first[light] + cascade].far_depth;
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapPass::GetCascadeTexelPixels(int light, int cascade) const
{
  if (cascade < 0 || cascade >= this->GetNumberOfCascades(light))
  {
    return 0.0;
  }
  const vsh_csm_tile_plan& tiles = this->Impl->Plan.tiles;
  return tiles.tiles[tiles.first[light] + cascade].texel_px;
}

//------------------------------------------------------------------------------
long long vtkCascadedShadowMapPass::GetMemoryBytes() const
{
  const long long mask =
    this->UsedScreenResolve && this->Impl->Mask ? this->Impl->Mask->GetMemoryBytes() : 0;
  long long atlases = this->Impl->Held.Bytes();
  for (const auto& parked : this->Impl->Parked)
  {
    atlases += parked.second.Bytes();
  }
  return atlases + mask + this->GetVolumeReceiverMemoryBytes();
}

//------------------------------------------------------------------------------
long long vtkCascadedShadowMapPass::GetWorldsMemoryBytes() const
{
  const Internals& impl = *this->Impl;
  long long bytes = impl.HeldWorld != 0 ? impl.Held.Bytes() : 0;
  for (const auto& parked : impl.Parked)
  {
    bytes += parked.first != 0 ? parked.second.Bytes() : 0;
  }
  return bytes;
}

//------------------------------------------------------------------------------
// Park the held maps of the world drawn last and take out those of the world
// this frame draws (empty the first time: it bakes them).
void vtkCascadedShadowMapPass::SelectWorld(int world)
{
  Internals& impl = *this->Impl;
  if (world == impl.HeldWorld)
  {
    return;
  }
  std::swap(impl.Parked[impl.HeldWorld], impl.Held);
  auto it = impl.Parked.find(world);
  if (it != impl.Parked.end())
  {
    std::swap(impl.Held, it->second);
    impl.Parked.erase(it);
  }
  impl.HeldWorld = world;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::ReleaseWorlds(vtkWindow* w, int first)
{
  Internals& impl = *this->Impl;
  first = std::max(first, 1);
  if (impl.HeldWorld >= first)
  {
    this->SelectWorld(0);
  }
  for (auto it = impl.Parked.begin(); it != impl.Parked.end();)
  {
    if (it->first >= first)
    {
      ReleaseHeld(it->second, w);
      it = impl.Parked.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
// The frame, stage by stage: gather the scene, plan the maps (depth range ->
// resolution -> tiles fitted per light kind, in the C core), allocate the
// atlas, select the maps an earlier frame can stand in for, bake the rest,
// then render the scene through the delegate with the shadow lookups.
void vtkCascadedShadowMapPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->NumberOfMapsRendered = 0;
  vtkshadow::MarkStage("setup");
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkCascadedShadowMapPass needs an OpenGL render window");
    return;
  }
  this->SelectWorld(this->WorldKey);
  // World 0 starts each frame (a mirror's world is drawn after it).
  this->Impl->FrameMapsRendered = this->WorldKey == 0 ? 0 : this->Impl->FrameMapsRendered;
  Frame frame(this->BeginFrame(s));
  // One transmittance per texel: a filter's colour comes out grey.
  this->NoteGreyFilters(frame.Shared);
  this->Impl->VolumeMaps.Update(frame.Shared, window);
  this->GatherScene(frame);
  this->PlanMaps(frame);
  this->PlanSamples(frame);
  this->Impl->Screen = this->ChooseScreenResolve(frame);
  // Only the screen resolve multiplies the volumes' maps in.
  this->NoteUncastVolumes(frame.Shared, this->Impl->Screen ? &this->Impl->VolumeMaps : nullptr);
  ++this->Impl->FramesSinceMeasure;
  this->UsedScreenResolve = this->Impl->Screen;
  this->UpdateShaderState(frame);
  const int resolution = this->AllocateAtlas(window);
  std::vector<int> bake;
  this->SelectReusable(frame, resolution, bake);
  this->BuildSampleTiles(bake);
  vtkshadow::MarkStage("csm.plan");
  this->BakeMaps(window, frame, bake, resolution);
  if (this->WorldKey == 0)
  {
    // A mirrored world leaves its mirror out: only the scene itself says
    // which casters are gone.
    this->ReleaseRemovedCasters(window, frame);
  }
  vtkshadow::MarkStage("csm.maps");

  // The scene, with every receiver's lighting reading the maps (forward) or
  // the mask the resolve wrote from them (screen).
  this->Impl->Held.Atlas->Activate();
  if (this->Impl->Transmit)
  {
    this->Impl->Held.TranslucentDepth->Activate();
    this->Impl->Held.Transmit->Activate();
  }
  this->BindRawAtlas(window);
  if (this->Impl->Screen)
  {
    this->RenderScreenResolved(s, window, frame);
  }
  else
  {
    this->RenderDelegateWithShaderHooks(s);
  }
  this->UnbindRawAtlas(window);
  if (this->Impl->Transmit)
  {
    this->Impl->Held.Transmit->Deactivate();
    this->Impl->Held.TranslucentDepth->Deactivate();
  }
  this->Impl->Held.Atlas->Deactivate();
}

namespace
{
// FNV-1a over the casters' identity, matrix values and mesh times, in
// order, and the translucent ones' opacities: equal for an unchanged set of
// casters (a caster leaving changes it).
unsigned long long CasterContentKey(const std::vector<vtkshadow::ShadowActor>& casters,
  const std::vector<vtkshadow::ShadowActor>& translucent)
{
  unsigned long long h = 1469598103934665603ULL;
  auto mix = [&h](const void* data, size_t n)
  {
    const unsigned char* b = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i)
    {
      h = (h ^ b[i]) * 1099511628211ULL;
    }
  };
  // Each list with its count; a translucent caster with its opacity (its
  // transmittance maps change with it).
  auto mixList = [&mix](const std::vector<vtkshadow::ShadowActor>& list, bool opacities)
  {
    for (const vtkshadow::ShadowActor& caster : list)
    {
      const vtkMTimeType mesh = vtkshadow::MeshTime(caster.Actor);
      mix(&caster.Actor, sizeof(caster.Actor));
      mix(caster.Matrix, sizeof(caster.Matrix));
      mix(&mesh, sizeof(mesh));
      if (caster.Proxy)
      {
        // Spheres and tubes: rebuilt with the camera, not with the mesh.
        const vtkMTimeType built = caster.Proxy->GetBuildTime();
        mix(&built, sizeof(built));
      }
      if (opacities)
      {
        const double opacity = vtkshadow::CasterOpacity(caster.Actor);
        mix(&opacity, sizeof(opacity));
      }
    }
    const size_t count = list.size();
    mix(&count, sizeof(count));
  };
  mixList(casters, false);
  mixList(translucent, true);
  return h;
}
}

//------------------------------------------------------------------------------
// Casters and receivers (every visible opaque actor receives), the camera,
// the lights, and the settings: the plain inputs of the plan.
void vtkCascadedShadowMapPass::GatherScene(Frame& frame)
{
  const vtkshadow::ShadowFrame& shared = frame.Shared;
  vsh_csm_scene& scene = frame.Scene;
  scene.aspect = shared.Aspect;
  scene.viewport_height = shared.Size[1];

  vsh_bounds_init_empty(&scene.casters);
  vsh_bounds_init_empty(&scene.receivers);
  // Receivers are what the frame draws (the render state's frustum-culled
  // list); casters come from the renderer's props, because a caster behind
  // the camera or beside the view still throws its shadow into it.
  for (const vtkshadow::ShadowActor& shadowActor : shared.Drawn)
  {
    vsh_bounds ab;
    vsh_bounds_from_vtk(&ab, shadowActor.Bounds);
    vsh_bounds_merge(&scene.receivers, &ab);
  }
  for (const vtkshadow::ShadowActor& shadowActor : shared.Actors)
  {
    if (!vtkshadow::HasFlag(shadowActor, vtkShadowPassBase::NO_CAST()))
    {
      vsh_bounds ab;
      vsh_bounds_from_vtk(&ab, shadowActor.Bounds);
      frame.Casters.push_back(shadowActor);
      vsh_bounds_merge(&scene.casters, &ab);
    }
  }
  // Points drawn as spheres and lines as tubes cast their proxies (the
  // actor's own triangles, if any, are cast above as before).
  const size_t meshes = frame.Casters.size();
  this->Impl->Proxies.Append(shared, shared.Actors, frame.Casters);
  for (size_t i = meshes; i < frame.Casters.size(); ++i)
  {
    vsh_bounds ab;
    vsh_bounds_from_vtk(&ab, frame.Casters[i].Bounds);
    vsh_bounds_merge(&scene.casters, &ab);
  }
  // Translucent casters are casters to the plan too (the maps' depth range
  // reaches them, and a screen tile near one is not lit for certain); only
  // those drawn as surfaces cast, as under raytrace. Every translucent
  // actor receives on its own fragments (the forward lookups), so the maps
  // cover it as a receiver.
  for (const vtkshadow::ShadowActor& shadowActor : shared.Translucent)
  {
    vsh_bounds ab;
    vsh_bounds_from_vtk(&ab, shadowActor.Bounds);
    vsh_bounds_merge(&scene.receivers, &ab);
    if (vtkshadow::CastsAsSurface(shadowActor, vtkShadowPassBase::NO_CAST()))
    {
      frame.Translucent.push_back(shadowActor);
      vsh_bounds_merge(&scene.casters, &ab);
    }
  }
  this->Impl->Transmit = !frame.Translucent.empty();
  // The actors' placement by value, not their own MTime (VTK's pass
  // machinery gives actors property keys during the first frame, which
  // bumps it) nor their matrices' (set back to equal values by a mirror).
  const unsigned long long key = CasterContentKey(frame.Casters, frame.Translucent);
  if (key != this->Impl->Held.CasterKey || this->Impl->Held.CasterStamp.GetMTime() == 0)
  {
    this->Impl->Held.CasterKey = key;
    this->Impl->Held.CasterStamp.Modified();
  }
  frame.CasterTime = this->Impl->Held.CasterStamp.GetMTime();
  scene.caster_count = static_cast<int>(frame.Casters.size() + frame.Translucent.size());
  // Across ranks: every rank plans from everyone's casters and receivers, so
  // the light matrices, the tiles and the reuse decisions agree.
  vtkMultiProcessController* controller = this->Impl->Controller;
  vtkshadow::AllReduceBounds(controller, &scene.casters);
  vtkshadow::AllReduceBounds(controller, &scene.receivers);
  vtkshadow::AllReduceSum(controller, &scene.caster_count);
  unsigned long long casterTime = frame.CasterTime;
  vtkshadow::AllReduceMax(controller, &casterTime);
  frame.CasterTime = static_cast<vtkMTimeType>(casterTime);

  std::copy_n(shared.Eye, 3, scene.camera.position);
  std::copy_n(shared.FocalPoint, 3, scene.camera.focal_point);
  std::copy_n(shared.ViewUp, 3, scene.camera.view_up);
  scene.camera.view_angle = shared.ViewAngle;
  std::copy_n(shared.ClippingRange, 2, scene.clip);

  this->GatherLights(frame);
  this->GatherSettings(frame.Settings);
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::GatherLights(Frame& frame)
{
  int l = 0;
  Internals& impl = *this->Impl;
  impl.PCSS = false;
  for (const vtkshadow::ShadowFrameLight& light : frame.Shared.Lights)
  {
    vsh_csm_light plain{};
    std::copy_n(light.Position, 3, plain.position);
    std::copy_n(light.FocalPoint, 3, plain.focal_point);
    plain.positional = light.Positional ? 1 : 0;
    plain.cone_angle = light.ConeAngle;
    plain.casts = light.Casts ? 1 : 0;
    if (l < MaxLights)
    {
      // The size only matters with PCSS on and for a light that casts; 0
      // keeps the light's lookup hard.
      const double term = vsh_pcss_light_term(plain.positional, light.Radius, light.Angle);
      impl.SoftTerm[l] = (this->Soft == SOFT_PCSS && plain.casts) ? static_cast<float>(term) : 0.0f;
      impl.PCSS = impl.PCSS || impl.SoftTerm[l] > 0.0f;
      impl.SampleSize[l] =
        (this->Soft == SOFT_SAMPLED && term > 0.0) ? static_cast<float>(light.Size) : 0.0f;
    }
    ++l;
    frame.Lights.push_back(plain);
  }
  for (; l < MaxLights; ++l)
  {
    impl.SoftTerm[l] = 0.0f;
    impl.SampleSize[l] = 0.0f;
  }
  this->UsedPCSS = impl.PCSS;
  frame.Scene.lights = frame.Lights.data();
  frame.Scene.light_count = static_cast<int>(frame.Lights.size());
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::GatherSettings(vsh_csm_settings& out) const
{
  out.cascade_count = this->CascadeCount;
  out.ratio_per_cascade = this->RatioPerCascade;
  out.split_scheme = static_cast<vsh_split_scheme>(this->SplitScheme);
  out.split_lambda = this->SplitLambda;
  std::copy_n(this->Impl->SplitFractions, VSH_CSM_MAX_CASCADES, out.split_fractions);
  out.stable = this->Stable ? 1 : 0;
  out.map_resolution = this->MapResolution;
  out.max_texel_px = this->MaxTexelPixels;
  out.memory_budget = this->MemoryBudget;
  out.max_shadow_distance = this->MaxShadowDistance;
  out.fade_fraction = this->FadeFraction;
  out.bias_scale = this->BiasScale;
}

//------------------------------------------------------------------------------
// Depth range -> resolution and cascades -> tiles per light (the C core).
void vtkCascadedShadowMapPass::PlanMaps(const Frame& frame)
{
  vsh_csm_plan& plan = this->Impl->Plan;
  vsh_csm_plan_frame(&frame.Scene, &frame.Settings, &plan);
  if (plan.resolution.split_fallback)
  {
    vtkWarningMacro("explicit split fractions are invalid for "
      << plan.resolution.cascade_count << " cascades: using practical splits");
  }
  if (plan.tiles.lights_dropped > 0)
  {
    vtkWarningMacro("only the first " << MaxLights << " lights cast shadows");
  }
}

//------------------------------------------------------------------------------
// What the receivers' shaders read besides the tiles: the view rotation, the
// fade, each point light's position in view coordinates; and the shader
// code's signature (the lights' kinds and the filter are compiled in).
void vtkCascadedShadowMapPass::UpdateShaderState(const Frame& frame)
{
  Internals& impl = *this->Impl;
  const vsh_csm_plan& plan = impl.Plan;
  double viewToRelative[16]; // view coordinates -> camera-relative world
  vsh_mat4_transpose(frame.Shared.ViewRotation, viewToRelative);
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      impl.ViewToWorld[c * 3 + r] = static_cast<float>(viewToRelative[r * 4 + c]);
    }
  }
  impl.MaxDistance = static_cast<float>(plan.depth.max_distance);
  impl.FadeStart = static_cast<float>(plan.depth.fade_start);
  const double* eye = frame.Scene.camera.position;
  for (int l = 0; l < std::min(plan.tiles.light_count, MaxLights); ++l)
  {
    // Camera-relative in double, then float: the light's position (or its
    // direction) in view coordinates.
    const vsh_csm_light& light = frame.Lights[l];
    const double* p = light.position;
    const double* f = light.focal_point;
    const double rel[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
    const double dir[3] = { p[0] - f[0], p[1] - f[1], p[2] - f[2] };
    double vc[3];
    vsh_mat4_transform_direction(frame.Shared.ViewRotation, light.positional ? rel : dir, vc);
    for (int k = 0; k < 3; ++k)
    {
      impl.ToLightVC[l][k] = static_cast<float>(vc[k]);
      impl.LightVC[l][k] = light.positional ? static_cast<float>(vc[k]) : 0.0f;
    }
    impl.ToLightVC[l][3] = light.positional ? 1.0f : 0.0f;
  }
  // World size of a pixel at view depth z (the core's cameras are
  // perspective, with a vertical view angle).
  const double height = std::max(frame.Scene.viewport_height, 1);
  impl.PixelSize[0] = 0.0f;
  impl.PixelSize[1] = static_cast<float>(
    2.0 * std::tan(vtkMath::RadiansFromDegrees(0.5 * frame.Scene.camera.view_angle)) / height);
  std::string signature = this->LookupDefines() + (impl.Screen ? "/screen:" : "/forward:");
  for (int l = 0; l < plan.tiles.light_count; ++l)
  {
    // The tiles are literals in the lookup code (CascadedLookupCode).
    signature += std::to_string(plan.tiles.kind[l]) + "," + std::to_string(plan.tiles.first[l]) +
      "," + std::to_string(plan.tiles.count[l]) +
      (impl.Sampled ? "," + std::to_string(impl.SampleFirst[l]) : std::string()) + ";";
  }
  if (signature != impl.ShaderSignature)
  {
    impl.ShaderSignature = signature;
    this->BumpShaderTime();
    this->UpdateResolveSources();
  }
}

//------------------------------------------------------------------------------
// The atlas: a grid of resolution^2 tiles, clamped to the GL's limit.
// Returns the resolution of a tile.
int vtkCascadedShadowMapPass::AllocateAtlas(vtkOpenGLRenderWindow* window)
{
  Internals& impl = *this->Impl;
  const int tiles = impl.Plan.tiles.tile_count;
  GLint maxSize = 4096;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  vsh_csm_atlas_layout layout;
  vsh_csm_atlas_layout_for(
    tiles + impl.SampleSlots, impl.Plan.resolution.resolution, maxSize, &layout);
  if (layout.clamped)
  {
    vtkWarningMacro("shadow map resolution "
      << impl.Plan.resolution.resolution << " x " << layout.columns << " x " << layout.rows
      << " exceeds the GL limit " << maxSize << ": using " << layout.resolution);
  }
  this->UsedResolution = layout.resolution;
  if (!impl.Held.Atlas)
  {
    impl.Held.Atlas = vtkSmartPointer<vtkTextureObject>::New();
    impl.Held.FBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  impl.Held.Atlas->SetContext(window);
  impl.Held.FBO->SetContext(window);
  if (!impl.Held.Atlas->GetHandle() || impl.Held.AtlasSize[0] != layout.width ||
    impl.Held.AtlasSize[1] != layout.height)
  {
    vtkshadow::AllocateDepthAtlas(impl.Held.Atlas, window, layout.width, layout.height);
    impl.Held.AtlasSize[0] = layout.width;
    impl.Held.AtlasSize[1] = layout.height;
    impl.Held.Rendered.clear(); // nothing held survives a new texture
  }
  this->AllocateTransmit(window);
  // A held map is only reusable in the slot and at the texel size it was
  // rendered with: a new grid or resolution (auto's texel target follows the
  // window size and the casters) can keep the atlas size but not its layout.
  if (impl.Held.TileGrid[0] != layout.columns || impl.Held.TileGrid[1] != layout.rows ||
    impl.Held.RenderedResolution != layout.resolution)
  {
    impl.Held.Rendered.clear();
  }
  impl.Held.TileGrid[0] = layout.columns;
  impl.Held.TileGrid[1] = layout.rows;
  impl.Held.RenderedResolution = layout.resolution;
  impl.Held.Rendered.resize(tiles);
  return layout.resolution;
}

//------------------------------------------------------------------------------
// Which tiles to bake. A cascade whose map from an earlier frame still covers
// every lookup of this frame keeps that map (and its matrix and bias): a
// stable cascade is a square around its slice's bounding sphere, so small
// camera moves rarely leave it.
void vtkCascadedShadowMapPass::SelectReusable(
  const Frame& frame, int resolution, std::vector<int>& bake)
{
  Internals& impl = *this->Impl;
  vsh_csm_reuse_params p{};
  p.camera = &frame.Scene.camera;
  p.aspect = frame.Scene.aspect;
  p.depth_near = impl.Plan.depth.range[0];
  p.blend_band = this->BlendBand;
  p.receivers = &frame.Scene.receivers;
  p.casters = &frame.Scene.casters;
  p.stable = this->Stable ? 1 : 0;
  p.resolution = resolution;
  p.reach_texels = this->LookupReachTexels();
  p.caster_time = frame.CasterTime;
  vsh_csm_selection selection;
  vsh_csm_select_reusable(
    &p, impl.Plan.tiles.tiles, impl.Plan.tiles.tile_count, impl.Held.Rendered.data(), &selection);
  this->NumberOfMapsReused = selection.reused_count;
  bake.assign(selection.bake, selection.bake + selection.bake_count);
}

//------------------------------------------------------------------------------
// How far from a lookup the filter and the bias read, in texels.
double vtkCascadedShadowMapPass::LookupReachTexels() const
{
  return 2.0 + this->BiasScale * 2.0 +
    (this->Filter == PCF          ? 0.5 * this->PCFSize + 1.0
        : this->Filter == POISSON ? this->PoissonRadius + 1.0
                                  : 1.0) +
    (this->Impl->PCSS ? this->PCSSMaxTexels + 1.0 : 0.0) +
    (this->Impl->Sampled ? this->Impl->ShearTexels + 1.0 : 0.0);
}

//------------------------------------------------------------------------------
// Render the casters into the listed tiles of the atlas.
void vtkCascadedShadowMapPass::BakeMaps(
  vtkOpenGLRenderWindow* window, const Frame& frame, const std::vector<int>& bake, int resolution)
{
  if (bake.empty())
  {
    return;
  }
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkShadowMapDepthVS, vtkShadowMapDepthFS, "");
  state->PushFramebufferBindings();
  impl.Held.FBO->Bind();
  impl.Held.FBO->AddDepthAttachment(impl.Held.Atlas);
  impl.Held.FBO->DeactivateDrawBuffers();
  {
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglScissor scissor(state);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable scissorTest(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglDepthFunc(GL_LEQUAL);
    // Slope-scaled offset while baking: steep receivers need more.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(
      1.5f * static_cast<float>(this->BiasScale), 2.0f * static_cast<float>(this->BiasScale));
    for (const auto* casters : { &frame.Casters, &frame.Translucent })
    {
      for (const vtkshadow::ShadowActor& caster : *casters)
      {
        if (caster.Proxy)
        {
          continue; // built by the proxies
        }
        auto& geometry = impl.Casters[caster.Actor];
        if (!geometry)
        {
          geometry.reset(new vtkShadowCasterGeometry);
        }
        geometry->Update(caster.Actor);
      }
    }
    const int columns = impl.Held.TileGrid[0];
    for (int t : bake)
    {
      const int x = (t % columns) * resolution, y = (t / columns) * resolution;
      state->vtkglViewport(x, y, resolution, resolution);
      state->vtkglScissor(x, y, resolution, resolution);
      state->vtkglClearDepth(1.0);
      state->vtkglClear(GL_DEPTH_BUFFER_BIT);
      ++this->NumberOfMapsRendered;
      this->DrawCasters(program, frame.Casters, frame, this->BakeTile(t));
      // Each rank drew its own casters: the nearest depth of all is the map.
      vtkshadow::AllReduceDepthRegion(
        impl.Controller, impl.Held.Atlas, x, y, resolution, resolution, impl.ReduceScratch);
    }
    if (impl.Transmit)
    {
      this->BakeTranslucent(window, frame, bake, resolution);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  impl.Held.FBO->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  this->TotalMapsRendered += this->NumberOfMapsRendered;
  this->Impl->FrameMapsRendered += this->NumberOfMapsRendered;
}

//------------------------------------------------------------------------------
// Each of `casters` into the current tile (an empty map stays cleared); a
// program reading vshCrossing (the transmittance maps') gets each caster's
// 1 - opacity.
void vtkCascadedShadowMapPass::DrawCasters(vtkShaderProgram* program,
  const std::vector<vtkshadow::ShadowActor>& casters, const Frame& frame, const vsh_csm_tile& tile)
{
  if (tile.view.texel_world <= 0.0)
  {
    return;
  }
  const bool crossing = program->IsUniformUsed("vshCrossing");
  for (const vtkshadow::ShadowActor& caster : casters)
  {
    vtkShadowCasterGeometry* geometry =
      caster.Proxy ? caster.Proxy : this->Impl->Casters[caster.Actor].get();
    if (geometry->GetNumberOfTriangles() == 0)
    {
      continue;
    }
    double modelRelative[16];
    geometry->GetModelRelativeMatrix(caster.Matrix, frame.Scene.camera.position, modelRelative);
    double mcdc[16];
    vsh_mat4_multiply(tile.view.world_to_clip, modelRelative, mcdc);
    float mcdcF[16];
    ToFloatTransposed(mcdc, mcdcF);
    program->SetUniformMatrix4x4("mapMCDC", mcdcF);
    if (crossing)
    {
      program->SetUniformf(
        "vshCrossing", static_cast<float>(1.0 - vtkshadow::CasterOpacity(caster.Actor)));
    }
    geometry->Draw(program);
  }
}

//------------------------------------------------------------------------------
// Drop the GL geometry of actors that no longer cast.
void vtkCascadedShadowMapPass::ReleaseRemovedCasters(
  vtkOpenGLRenderWindow* window, const Frame& frame)
{
  Internals& impl = *this->Impl;
  for (auto it = impl.Casters.begin(); it != impl.Casters.end();)
  {
    const auto same = [&](const vtkshadow::ShadowActor& caster)
    { return caster.Actor == it->first; };
    if (std::none_of(frame.Casters.begin(), frame.Casters.end(), same) &&
      std::none_of(frame.Translucent.begin(), frame.Translucent.end(), same))
    {
      it->second->ReleaseGraphicsResources(window);
      it = impl.Casters.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  if (fragmentShader.find("//VTK::Light::Dec") == std::string::npos)
  {
    return true;
  }
  Internals& impl = *this->Impl;
  // Screen resolve: opaque surfaces read the mask. Translucent ones are not
  // in the depth pre-pass and keep the forward lookups.
  const bool translucent =
    prop && prop->HasTranslucentPolygonalGeometry() && !prop->HasOpaqueGeometry();
  if (impl.Screen && impl.Mask && !translucent)
  {
    return impl.Mask->PreReplaceShaderValues(fragmentShader, prop);
  }
  // Compile-time filter, then the lookup functions, then one prologue that
  // calls the right lookup for each light that casts.
  const std::string code = this->LookupDefines() + vtkShadowMapLightFS +
    "void vshShadowPrepare(vec3 posVC, vec3 normalVC)\n{\n"
    "  float depth = -posVC.z;\n  float fade = vshShadowFade(depth);\n" +
    vtkshadow::CascadedLookupCode(impl.Plan.tiles, 0, MaxLights, "vshShadowFactor[%d]", 0.0f, "1.0",
      impl.Sampled ? impl.SampleFirst : nullptr) +
    "}\n";
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", std::string("//VTK::Light::Dec\n") + code, false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  this->ReceiveVolumeShadows(fragmentShader, prop);
  if (this->Impl->Mask && fragmentShader.find("vshScreenPrepare") != std::string::npos)
  {
    return this->Impl->Mask->PostReplaceShaderValues(fragmentShader, this->GetResidualLight());
  }
  if (fragmentShader.find("vshShadowPrepare") == std::string::npos)
  {
    return true;
  }
  const std::string surface = vtkshadow::SurfacePositionVC(fragmentShader);
  if (this->InjectLightFactors(fragmentShader, "vshShadowFactor[%d]",
        "vshShadowPrepare(" + surface + ", normalize(normalVCVSOutput));", MaxLights))
  {
    // The debug view tints the final colour by cascade.
    const std::string output = "gl_FragData[0] = vec4(ambientColor + diffuse + specular, opacity);";
    vtkShaderProgram::Substitute(fragmentShader, output,
      output +
        "\n  if (vshDebugCascades != 0 && vshShadowCascadeShown >= 0) "
        "{ gl_FragData[0].rgb *= vshCascadeTint(vshShadowCascadeShown); }",
      false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  this->SetVolumeShadowParameters(program);
  Internals& impl = *this->Impl;
  if (impl.Mask && program->IsUniformUsed("vshScreenMask0"))
  {
    // During the depth pre-pass the mask's textures are not bound (and
    // nothing the shader computes is written).
    if (!impl.PrePass)
    {
      impl.Mask->SetShaderParameters(program);
    }
    return true;
  }
  if (impl.Held.Atlas && program->IsUniformUsed("vshShadowAtlas"))
  {
    this->SetLookupUniforms(program);
  }
  return true;
}

//------------------------------------------------------------------------------
// The uniforms of vtkShadowMapLightFS, for the mappers' forward lookups and
// for the resolve shader.
void vtkCascadedShadowMapPass::SetLookupUniforms(vtkShaderProgram* program)
{
  Internals& impl = *this->Impl;
  vsh_csm_tile_plan& plan = impl.Plan.tiles;
  const int tiles = std::min<int>(plan.tile_count, MaxTiles);
  program->SetUniformi("vshShadowAtlas", impl.Held.Atlas->GetTextureUnit());
  if (impl.Transmit)
  {
    program->SetUniformi("vshTranslucentAtlas", impl.Held.TranslucentDepth->GetTextureUnit());
    program->SetUniformi("vshTransmitAtlas", impl.Held.Transmit->GetTextureUnit());
  }
  const float texel[2] = { 1.0f / std::max(impl.Held.AtlasSize[0], 1),
    1.0f / std::max(impl.Held.AtlasSize[1], 1) };
  program->SetUniform2f("vshAtlasTexel", texel);
  program->SetUniformi("vshShadowLightCount", std::min(plan.light_count, MaxLights));
  program->SetUniform1iv("vshShadowKind", MaxLights, plan.kind);
  program->SetUniform3fv("vshShadowLightVC", MaxLights, impl.LightVC);
  program->SetUniform4fv("vshShadowToLightVC", MaxLights, impl.ToLightVC);
  program->SetUniform2f("vshPixelSize", impl.PixelSize);
  program->SetUniformMatrix3x3("vshViewToWorld", impl.ViewToWorld);
  program->SetUniformf("vshPoissonRadius", static_cast<float>(this->PoissonRadius));
  program->SetUniformf("vshBlendBand", static_cast<float>(this->BlendBand));
  program->SetUniformf("vshShadowMaxDistance", impl.MaxDistance);
  program->SetUniformf("vshShadowFadeStart", impl.FadeStart);
  program->SetUniformi("vshDebugCascades", this->DebugCascades ? 1 : 0);
  if (tiles == 0)
  {
    return;
  }
  // Per map: view coordinates -> map clip space (camera-relative, double),
  // its atlas rectangle, bias, texel size and far depth.
  std::vector<float> matrices(16 * tiles), rects(4 * tiles), bias(2 * tiles), fars(tiles),
    texels(tiles), depth(2 * tiles, 0.0f), soft(2 * tiles, 0.0f);
  double viewToRelative[16];
  {
    // vshViewToWorld holds the transposed view rotation as floats; rebuild
    // the double version from the same numbers for the product.
    vsh_mat4_identity(viewToRelative);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        viewToRelative[r * 4 + c] = impl.ViewToWorld[c * 3 + r];
      }
    }
  }
  for (int t = 0; t < tiles; ++t)
  {
    const vsh_csm_tile& tile = plan.tiles[t];
    double m[16];
    vsh_mat4_multiply(tile.view.world_to_clip, viewToRelative, m);
    ToFloatTransposed(m, &matrices[16 * t]);
    const int columns = impl.Held.TileGrid[0];
    const double w = static_cast<double>(this->UsedResolution) / impl.Held.AtlasSize[0];
    const double h = static_cast<double>(this->UsedResolution) / impl.Held.AtlasSize[1];
    rects[4 * t + 0] = static_cast<float>((t % columns) * w);
    rects[4 * t + 1] = static_cast<float>((t / columns) * h);
    rects[4 * t + 2] = static_cast<float>(w);
    rects[4 * t + 3] = static_cast<float>(h);
    bias[2 * t + 0] = static_cast<float>(tile.bias[0]);
    bias[2 * t + 1] = static_cast<float>(tile.bias[1]);
    fars[t] = static_cast<float>(tile.far_depth);
    texels[t] = static_cast<float>(tile.view.texel_world);
    if (tile.view.perspective)
    {
      double terms[2];
      vsh_csm_perspective_depth_terms(&tile.view, terms);
      depth[2 * t + 0] = static_cast<float>(terms[0]);
      depth[2 * t + 1] = static_cast<float>(terms[1]);
    }
    // PCSS: the light's size term and what turns a map depth into a
    // distance: the depth range (orthographic) or the near distance
    // (perspective, where the blocker search starts).
    if (tile.light >= 0 && tile.light < MaxLights)
    {
      soft[2 * t + 0] = impl.SoftTerm[tile.light];
    }
    soft[2 * t + 1] =
      static_cast<float>(tile.view.perspective ? tile.view.near_far[0] : tile.view.depth_extent);
  }
  program->SetUniformMatrix4x4v("vshTileMatrix", tiles, matrices.data());
  program->SetUniform4fv("vshTileRect", tiles, rects.data());
  program->SetUniform2fv("vshTileBias", tiles, bias.data());
  program->SetUniform1fv("vshTileFar", tiles, fars.data());
  program->SetUniform1fv("vshTileTexel", tiles, texels.data());
  program->SetUniform2fv("vshTileDepth", tiles, depth.data());
  if (impl.PCSS && impl.RawUnit >= 0)
  {
    program->SetUniformi("vshShadowAtlasRaw", impl.RawUnit);
    program->SetUniform2fv("vshTileSoft", tiles, soft.data());
  }
  this->SetSampledUniforms(program);
}

//------------------------------------------------------------------------------
std::string vtkCascadedShadowMapPass::LookupDefines() const
{
  std::string out = "#define VSH_FILTER " + std::to_string(this->Filter) +
    "\n#define VSH_PCF_HALF " + std::to_string(this->PCFSize / 2) + "\n#define VSH_TAP_TEXEL_PX " +
    std::to_string(this->TapTexelPixels) + "\n";
  if (this->Impl->PCSS)
  {
    out += "#define VSH_PCSS 1\n#define VSH_PCSS_BLOCKER_TAPS " +
      std::to_string(this->PCSSBlockerTaps) + "\n#define VSH_PCSS_FILTER_TAPS " +
      std::to_string(this->PCSSFilterTaps) + "\n#define VSH_PCSS_MAX_TEXELS " +
      std::to_string(this->PCSSMaxTexels) + "\n";
  }
  if (this->Impl->Transmit)
  {
    out += "#define VSH_TRANSMIT 1\n";
  }
  if (this->Impl->Sampled)
  {
    out += "#define VSH_SAMPLED 1\n#define VSH_SAMPLES " + std::to_string(this->SoftSamples) +
      "\n#define VSH_SAMPLE_BATCH " + std::to_string(this->Impl->SampleBatch) + "\n";
  }
  return out;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::BindRawAtlas(vtkOpenGLRenderWindow* window)
{
  Internals& impl = *this->Impl;
  if (!impl.PCSS)
  {
    return;
  }
  if (!impl.RawSampler)
  {
    glGenSamplers(1, &impl.RawSampler);
    glSamplerParameteri(impl.RawSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(impl.RawSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(impl.RawSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(impl.RawSampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(impl.RawSampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  impl.RawUnit = window->GetTextureUnitManager()->Allocate();
  if (impl.RawUnit < 0)
  {
    vtkWarningMacro("no texture unit left for PCSS's blocker search: hard shadows");
    return;
  }
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + impl.RawUnit);
  glBindTexture(GL_TEXTURE_2D, impl.Held.Atlas->GetHandle());
  glBindSampler(impl.RawUnit, impl.RawSampler);
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::UnbindRawAtlas(vtkOpenGLRenderWindow* window)
{
  Internals& impl = *this->Impl;
  if (impl.RawUnit < 0)
  {
    return;
  }
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + impl.RawUnit);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindSampler(impl.RawUnit, 0);
  window->GetTextureUnitManager()->Free(impl.RawUnit);
  impl.RawUnit = -1;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  ReleaseHeld(impl.Held, w);
  for (auto& parked : impl.Parked)
  {
    ReleaseHeld(parked.second, w);
  }
  impl.Parked.clear();
  if (impl.RawSampler)
  {
    glDeleteSamplers(1, &impl.RawSampler);
    impl.RawSampler = 0;
  }
  if (impl.Mask)
  {
    impl.Mask->ReleaseGraphicsResources(w);
    impl.Rects[0].ReleaseGraphicsResources();
    impl.Rects[1].ReleaseGraphicsResources();
  }
  if (impl.Queries[0])
  {
    glDeleteQueries(2, impl.Queries);
    impl.Queries[0] = impl.Queries[1] = 0;
  }
  impl.Overdraw = -1.0;
  impl.VolumeMaps.ReleaseGraphicsResources(w);
  impl.Proxies.ReleaseGraphicsResources(w);
  for (auto& entry : impl.Casters)
  {
    entry.second->ReleaseGraphicsResources(w);
  }
  impl.Casters.clear();
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UsedPCSS: " << this->UsedPCSS << "\n";
  os << indent << "UsedSampled: " << this->UsedSampled << "\n";
  os << indent << "UsedScreenResolve: " << this->UsedScreenResolve << "\n";
  os << indent << "UsedResolution: " << this->UsedResolution << "\n";
  os << indent << "NumberOfMapsRendered: " << this->NumberOfMapsRendered << "\n";
  os << indent << "NumberOfMapsReused: " << this->NumberOfMapsReused << "\n";
  os << indent << "TotalMapsRendered: " << this->TotalMapsRendered << "\n";
}

//------------------------------------------------------------------------------
// The settings, once (vtkShadowSettings.h): SetOption, PrintSelf, the
// listing and docs/techniques.md all read these rows.
namespace
{
using P = vtkCascadedShadowMapPass;
using vtkshadow::Closed;
using vtkshadow::Flag;
using vtkshadow::Integers;
using vtkshadow::Row;

std::vector<vtkshadow::Setting> CascadeRows()
{
  std::vector<vtkshadow::Setting> rows = {
    Row("map_resolution", vtkshadow::MapResolutionRange(), &P::SetMapResolution,
      &P::GetMapResolution, "edge of each shadow map in texels"),
    Row("cascades", Integers(0, 8), &P::SetCascadeCount, &P::GetCascadeCount,
      "cascades per directional light; 0 picks 1..8 from the visible depth ratio"),
    Row("ratio_per_cascade", Closed(1.5, 1e6), &P::SetRatioPerCascade, &P::GetRatioPerCascade,
      "far/near depth ratio one cascade covers when cascades = 0"),
    Row("split", Integers(P::UNIFORM, P::EXPLICIT), &P::SetSplitScheme, &P::GetSplitScheme,
      "split scheme: 0 uniform, 1 logarithmic, 2 practical, 3 explicit fractions"),
    Row("lambda", Closed(0, 1), &P::SetSplitLambda, &P::GetSplitLambda,
      "practical split: weight of the logarithmic scheme"),
  };
  // split_fraction_0 .. _6: the split between cascade i and i + 1 as a
  // fraction of the visible depth range (split = 3).
  for (int i = 0; i < 7; ++i)
  {
    rows.push_back({ "split_fraction_" + std::to_string(i), vtkshadow::Open(0, 1),
      "split = 3: split after cascade " + std::to_string(i) +
        " as a fraction of the depth range (unset: 0, the practical split)",
      [i](vtkShadowPassBase& p, double v) { static_cast<P&>(p).SetSplitFraction(i, v); },
      [i](vtkShadowPassBase& p) { return static_cast<P&>(p).GetSplitFraction(i); } });
  }
  std::vector<vtkshadow::Setting> more = {
    Row("stable", Flag(), &P::SetStable, &P::GetStable,
      "rotation-invariant cascade size and texel snapping (no shimmer)"),
    Row("max_texel_px", Closed(0, 1e6), &P::SetMaxTexelPixels, &P::GetMaxTexelPixels,
      "error target: at most this many pixels per texel (0 = off)"),
    Row("memory_budget", Closed(1 << 16, 1e12), &P::SetMemoryBudget, &P::GetMemoryBudget,
      "bytes the error target may spend on maps"),
    Row("max_distance", Closed(0, 1e300), &P::SetMaxShadowDistance, &P::GetMaxShadowDistance,
      "shadows end at this view depth (0 = the visible receivers' far end)"),
    Row("fade", Closed(0, 1), &P::SetFadeFraction, &P::GetFadeFraction,
      "fraction of the shadowed depth range the shadows fade out over"),
    Row("debug_cascades", Flag(), &P::SetDebugCascades, &P::GetDebugCascades,
      "tint each cascade with its own colour"),
  };
  rows.insert(rows.end(), more.begin(), more.end());
  return rows;
}

std::vector<vtkshadow::Setting> LookupRows()
{
  return {
    Row("bias_scale", Closed(0, 100), &P::SetBiasScale, &P::GetBiasScale,
      "scale of the automatic slope and normal offset bias"),
    Row("filter", Integers(P::HARDWARE_2X2, P::POISSON), &P::SetFilter, &P::GetFilter,
      "edge filter: 0 hardware 2x2, 1 PCF, 2 Poisson disc"),
    Row("pcf_size", Integers(1, 9), &P::SetPCFSize, &P::GetPCFSize, "PCF kernel edge in texels"),
    Row("poisson_radius", Closed(0, 16), &P::SetPoissonRadius, &P::GetPoissonRadius,
      "Poisson disc radius in texels"),
    Row("blend_band", Closed(0, 0.5), &P::SetBlendBand, &P::GetBlendBand,
      "blend between cascades over this fraction of each (0 = hard switch)"),
    Row("resolve", Integers(P::FORWARD, P::CHOOSE), &P::SetResolve, &P::GetResolve,
      "where lookups run: 0 forward, 1 screen (after a depth pre-pass), 2 choose"),
    Row("tap_texel_px", Closed(0, 1e6), &P::SetTapTexelPixels, &P::GetTapTexelPixels,
      "PCF and Poisson taps only where a texel covers at most this many pixels"),
    Row("tile_cull", Flag(), &P::SetTileCull, &P::GetTileCull,
      "screen resolve: decide per 16x16 tile which lookups it needs"),
  };
}

// Lights with a size (docs/soft-shadows.md).
std::vector<vtkshadow::Setting> SoftRows()
{
  return {
    Row("soft", Integers(P::SOFT_OFF, P::SOFT_SAMPLED), &P::SetSoft, &P::GetSoft,
      "lights with a size: 0 hard, 1 PCSS, 2 sampled maps"),
    Row("soft_samples", Integers(1, 64), &P::SetSoftSamples, &P::GetSoftSamples,
      "soft = 2: maps (points on the light) per map of a light with a size"),
    Row("adaptive", Flag(), &P::SetAdaptive, &P::GetAdaptive,
      "soft = 2, soft_samples > 8: all samples only where the first 8 disagree"),
    Row("pcss_blocker_taps", Integers(1, 64), &P::SetPCSSBlockerTaps, &P::GetPCSSBlockerTaps,
      "PCSS blocker search taps"),
    Row("pcss_filter_taps", Integers(1, 64), &P::SetPCSSFilterTaps, &P::GetPCSSFilterTaps,
      "PCSS filter taps"),
    Row("pcss_max_texels", Closed(1, 256), &P::SetPCSSMaxTexels, &P::GetPCSSMaxTexels,
      "PCSS kernel radius limit in texels"),
  };
}
}

const vtkshadow::Settings& vtkCascadedShadowMapPass::SettingsTable()
{
  static const vtkshadow::Settings table = []
  {
    std::vector<vtkshadow::Setting> rows = CascadeRows();
    for (auto part : { LookupRows(), SoftRows() })
    {
      rows.insert(rows.end(), part.begin(), part.end());
    }
    return vtkshadow::Settings(&vtkShadowPassBase::SettingsTable(), std::move(rows));
  }();
  return table;
}

//------------------------------------------------------------------------------
std::string vtkCascadedShadowMapPass::GetStatsJSON(vtkRenderer* renderer) const
{
  std::ostringstream out;
  out.precision(6);
  out << "\"resolution\": " << this->UsedResolution
      << ", \"maps_rendered_total\": " << this->TotalMapsRendered
      << ", \"maps_reused_last_frame\": " << this->NumberOfMapsReused
      << ", \"frame_maps_rendered\": " << this->Impl->FrameMapsRendered
      << ", \"worlds_held\": " << 1 + this->Impl->Parked.size()
      << ", \"other_worlds_bytes\": " << this->GetWorldsMemoryBytes() << ", \"resolve\": \""
      << (this->UsedScreenResolve ? "screen" : "forward")
      << "\", \"overdraw\": " << this->Impl->Overdraw
      << ", \"tiles_culled\": " << this->NumberOfTilesCulled << ", \"soft\": \""
      << (this->UsedPCSS         ? "pcss"
             : this->UsedSampled ? "sampled"
                                 : "hard")
      << "\", \"soft_samples\": " << (this->UsedSampled ? this->SoftSamples : 0)
      << ", \"sample_batch\": " << (this->UsedSampled ? this->Impl->SampleBatch : 0)
      << ", \"sample_maps\": " << this->Impl->SampleSlots
      << ", \"pcss_blocker_taps\": " << (this->UsedPCSS ? this->PCSSBlockerTaps : 0)
      << ", \"pcss_filter_taps\": " << (this->UsedPCSS ? this->PCSSFilterTaps : 0)
      << ", \"pcss_max_texels\": " << this->PCSSMaxTexels << ", " << this->Impl->Proxies.StatsJSON()
      << ", " << this->Impl->VolumeMaps.StatsJSON() << ", " << this->VolumeReceiverStatsJSON()
      << ", " << this->DepthSeedStatsJSON() << ", \"lights\": [";
  const int lights = renderer ? renderer->GetLights()->GetNumberOfItems() : 0;
  for (int l = 0; l < lights; ++l)
  {
    const int cascades = this->GetNumberOfCascades(l);
    out << (l ? ", " : "") << "{\"cascades\": " << cascades << ", \"far\": [";
    for (int c = 0; c < cascades; ++c)
    {
      out << (c ? ", " : "") << this->GetCascadeFar(l, c);
    }
    out << "], \"texel_px\": [";
    for (int c = 0; c < cascades; ++c)
    {
      out << (c ? ", " : "") << this->GetCascadeTexelPixels(l, c);
    }
    out << "]}";
  }
  out << "]";
  return out.str();
}
