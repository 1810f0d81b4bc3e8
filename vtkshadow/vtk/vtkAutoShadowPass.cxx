#include "vtkAutoShadowPass.h"
#include "vtkShadowSettings.h"
#include "vtkShadowStageProfile.h"

#include "vtkCamera.h"

#include "vtkActor.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlanarShadowPass.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRayTracedShadowPass.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowFrame.h"
#include "vtkShadowImpostorProxies.h"
#include "vtkShadowImpostors.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowReceiverPlane.h"
#include "vtkShadowTechniqueSet.h"
#include "vtkShadowVolumePass.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vsh_auto.h"
#include "vsh_auto_general.h"
#include "vsh_auto_plan.h"
#include "vsh_auto_soft.h"
#include "vsh_auto_trial.h"
#include "vsh_mat4.h"
#include "vsh_silhouette.h"
#include "vsh_volume.h"
#include "vsh_volume_cost.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkAutoShadowPass);

struct vtkAutoShadowPass::Internals
{
  using WorldLight = std::pair<int, int>; // (world key, light number)
  struct Caster
  {
    vtkShadowCasterGeometry Geometry;
    vtkMTimeType MeshTime = 0;
    bool Convex = false;
    // Silhouette length (data units) per (world, light), with the light
    // (data coordinates) it was computed for. Per world: a mirror's world
    // places the actor elsewhere, and one cache for both was recomputed
    // twice a frame (auto.decide 17.7 ms against 0.4 on
    // mirror/ball-stick-mirror-floor).
    std::map<WorldLight, std::pair<std::vector<double>, double>> Silhouette;
    // Shadow-volume side quads (all, and an open caster's) per light, with the light
    // (shifted data coordinates) they were counted for.
    std::map<WorldLight, std::pair<std::vector<double>, vtkAutoShadowPass::VolumeSilhouette>>
      VolumeEdges;
    // What it draws as points and lines (spheres, tubes, splats, squares,
    // bands), extracted again when ImpostorTime changes.
    vtkshadow::Impostors Drawn;
    vtkMTimeType DrawnTime = 0;
    // Their outlines (points, lines) per light, with what they were
    // measured for: the light, the actor's matrix, the camera, the viewport
    // and DrawnTime.
    std::map<WorldLight, std::pair<std::vector<double>, std::array<double, 2>>> DrawnOutline;
  };
  std::map<vtkProp*, std::unique_ptr<Caster>> Casters;

  // The frame's objects: plain data for the core's decision, and their actors
  // (with the matrices they are drawn with).
  std::vector<vsh_auto_object> Objects;
  std::vector<vtkshadow::ShadowActor> Actors;
  std::vector<vtkWeakPointer<vtkActor>> Detected; // receivers found, not marked
  std::string GeneralJSON;                        // per map light: the candidates auto weighed
  // Per light: pixels of outline of the casters drawn as spheres, splats
  // and squares (ThinPoints) and as tubes and bands (ThinLines).
  std::vector<double> ThinPoints, ThinLines;
  // Per light: the thin-impostor terms of the csm candidate (wrong_pct).
  std::vector<double> ThinFloorPct, ThinMapPct;
  // Per light: the map's outline floor (vsh_auto_map_outline_error).
  std::vector<double> OutlinePct;
  // Per light, volume's open quads (VolumeSilhouette), for the stats.
  std::vector<double> VolumeOpenQuads;
  std::vector<bool> SoftLights; // per switched-on light: has a radius or angle
  std::string SoftJSON;         // per light with a size: the soft candidates
  int PlanarSamples = 0; // the frame's soft_samples for planar's lights with a size (0: none)
  int RaySamples = 0;    // the frame's samples for raytrace's lights with a size (0: none)
  int VolumeSamples = 0; // the frame's soft_samples for volume's lights with a size (0: none)
  int CsmSamples = 0;    // the frame's soft_samples for csm's sampled lights with a size (0: none)
  // csm's soft setting is one per pass: auto sets it in frames where a light
  // with a size picks csm, and puts the user's back otherwise. AsSet is the
  // user's setting; Applied what auto last set (-1: nothing).
  int CsmSoftAsSet = -1;
  int CsmSoftApplied = -1;
  std::vector<int> LightTiles; // per switched-on light: csm's planned maps, estimated
  // Per switched-on light: the soft candidates weighed (pick -1: hard, or
  // nothing to shadow) and the inputs of the volume candidate.
  std::vector<vsh_auto_soft_choice> SoftChoices;

  // What was chosen: for the frame and per switched-on light.
  vtkshadow::TechniqueSet Choice = vtkshadow::TechniqueSet::None;
  std::vector<vtkshadow::TechniqueSet> LightChoices;

  // The timed choice between the exact techniques (vsh_auto_trial.h): its
  // state across frames, and this frame's lights, models' pick and
  // predictions, the technique drawn and whether the frame is timed.
  // One trial per world (vtkShadowPassBase::SetWorldKey): a mirror's world
  // is another scene with its own costs. Trial is the frame's world's.
  std::map<int, vsh_auto_trial> Trials;
  vsh_auto_trial* Trial = nullptr;
  unsigned int TrialLights = 0;
  int TrialModel = -1;
  double TrialPredicted[VSH_AUTO_TRIAL_COUNT] = { 0.0, 0.0 };
  vsh_auto_trial_step TrialStep = { -1, 0 };
  // Why every casting light goes to raytrace this frame (empty: no reason).
  std::string RaytraceOnlyWhy;
  unsigned long long SceneKey = 0; // the frame's casters and lights (SceneKey())

  vsh_auto_trial& TrialOf(int world)
  {
    auto found = this->Trials.find(world);
    if (found == this->Trials.end())
    {
      found = this->Trials.emplace(world, vsh_auto_trial{}).first;
      vsh_auto_trial_reset(&found->second);
    }
    return found->second;
  }

  // The caster's mesh analysis, redone only when the mesh changes: its
  // convexity and silhouettes survive every affine placement, so the
  // actor's own MTime (which VTK's pass machinery bumps) does not count.
  Caster& For(vtkActor* actor)
  {
    auto& caster = this->Casters[actor];
    if (!caster)
    {
      caster.reset(new Caster);
    }
    const vtkMTimeType t = vtkshadow::MeshTime(actor);
    if (caster->MeshTime != t || t == 0)
    {
      caster->MeshTime = t;
      caster->Convex = caster->Geometry.Update(actor) && caster->Geometry.IsConvex();
      caster->Silhouette.clear();
      caster->VolumeEdges.clear();
    }
    return *caster;
  }
};

namespace
{
// How wide on screen the actor's points, lines and splats are drawn, the
// thinnest of them: the point size or the line width, twice the smallest
// splat radius over one pixel's world size `pixel` at the actor.
double ImpostorPixels(vtkActor* actor, double pixel)
{
  const int kinds = vtkshadow::ImpostorKinds(actor);
  vtkProperty* property = actor->GetProperty();
  double thinnest = std::numeric_limits<double>::infinity();
  if (kinds & (vtkshadow::SPHERES | vtkshadow::FLAT_POINTS))
  {
    thinnest = std::min(thinnest, double(property->GetPointSize()));
  }
  if (kinds & (vtkshadow::TUBES | vtkshadow::FLAT_LINES))
  {
    thinnest = std::min(thinnest, double(property->GetLineWidth()));
  }
  double radii[2];
  if (vtkshadow::SplatRadiusRange(actor, radii) && pixel > 0.0)
  {
    thinnest = std::min(thinnest, 2.0 * radii[0] / pixel);
  }
  return thinnest;
}
}

namespace
{
// FNV-1a over a value's bytes, folded into `key`.
template <typename T>
void Fold(unsigned long long& key, const T& value)
{
  const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&value);
  for (size_t i = 0; i < sizeof(T); ++i)
  {
    key = (key ^ bytes[i]) * 1099511628211ull;
  }
}

// What the exact techniques' cost depends on besides the camera: each
// actor's mesh and placement, and each light (vsh_auto_trial: an edit).
unsigned long long SceneKey(
  const std::vector<vtkshadow::ShadowActor>& actors, const vtkshadow::ShadowFrame& frame)
{
  unsigned long long key = 14695981039346656037ull;
  for (const vtkshadow::ShadowActor& a : actors)
  {
    Fold(key, vtkshadow::MeshTime(a.Actor));
    for (double m : a.Matrix)
    {
      Fold(key, m);
    }
  }
  for (const vtkshadow::ShadowFrameLight& light : frame.Lights)
  {
    Fold(key, light.Casts);
    for (double h : light.Homogeneous)
    {
      Fold(key, h);
    }
  }
  return key;
}
}

namespace
{
// JSON has no infinity: "null" stands for "no caster part".
std::string JSONNumber(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

// What a cascaded map's fragment lookup costs per pixel and light on this
// project's machines (llvmpipe: +11.5 ms for one light at 800x600 over an
// unshadowed frame of 8.1 ms, performance-probe.md), in milliseconds. Maps
// baked once with a still camera cost nothing more per frame.
constexpr double MapLookupMsPerPixel = 11.5 / (800.0 * 600.0);

// A placement matrix's linear scale (cube root of its volume change); row
// major, data -> world.
double MatrixScale(const double m[16])
{
  const double linear[3][3] = { { m[0], m[1], m[2] }, { m[4], m[5], m[6] }, { m[8], m[9], m[10] } };
  return std::cbrt(std::abs(vtkMath::Determinant3x3(linear)));
}

std::string Centre(const char* what, const vsh_auto_object& o)
{
  std::ostringstream out;
  out << what << " (bounds centre " << o.center[0] << ", " << o.center[1] << ", " << o.center[2]
      << ")";
  return out.str();
}
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::vtkAutoShadowPass()
  : PlanarPass(vtkPlanarShadowPass::New())
  , CascadedPass(vtkCascadedShadowMapPass::New())
  , RayTracedPass(vtkRayTracedShadowPass::New())
  , VolumePass(vtkShadowVolumePass::New())
  , Reason("not rendered yet")
  , MaxError(0.5)
  , MaxTexelPixels(0.0)
  , UsedTexelTarget(0.0)
  , UsedStretch(1.0)
  , UsedEdgeLength(0.0)
  , Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::~vtkAutoShadowPass()
{
  this->PlanarPass->Delete();
  this->CascadedPass->Delete();
  this->RayTracedPass->Delete();
  this->VolumePass->Delete();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::Decide(const vtkshadow::ShadowFrame& frame)
{
  vtkRenderer* renderer = frame.Renderer;
  this->GatherObjects(frame);
  const int concave = this->FindConcaveCaster();
  Internals& impl = *this->Impl;
  impl.LightChoices.clear();
  impl.SoftLights.clear();
  impl.SoftChoices.clear();
  impl.SoftJSON.clear();
  impl.PlanarSamples = impl.RaySamples = impl.VolumeSamples = impl.CsmSamples = 0;
  impl.LightTiles.clear();
  this->RecallCsmSoft();
  this->LightReasons.clear();
  for (const vtkshadow::ShadowFrameLight& light : frame.Lights)
  {
    impl.SoftLights.push_back(light.Radius > 0.0 || light.Angle > 0.0);
    const vsh_auto_light_choice c = vsh_auto_choose_light(impl.Objects.data(),
      static_cast<int>(impl.Objects.size()), light.Homogeneous, light.Headlight ? 1 : 0, concave);
    this->LightReasons.push_back(this->LightReasonText(c.reason, c.a, c.b));
    impl.LightChoices.push_back(static_cast<vtkshadow::TechniqueSet>(c.technique));
    impl.LightTiles.push_back(this->EstimateCsmTiles(light, impl.LightTiles.size()));
    impl.SoftChoices.emplace_back();
    impl.SoftChoices.back().pick = -1;
  }
  // Lights with a size: the soft candidates by the penumbra target, once
  // every light's maps are known (csm's sampled maps share one atlas).
  for (size_t l = 0; l < impl.SoftChoices.size(); ++l)
  {
    if (impl.SoftLights[l] && impl.LightChoices[l] != vtkshadow::TechniqueSet::None)
    {
      this->WeighSoft(renderer, l, static_cast<int>(impl.LightChoices[l]));
    }
  }
  this->ChooseSoft();
  // What the maps' texels must resolve: the casters' outlines, and how far
  // grazing light stretches them on plane receivers.
  double stretch = 1.0, edgeLength = 0.0;
  std::vector<double> edgeLengths(impl.LightChoices.size(), 0.0); // per map light
  impl.ThinPoints.assign(impl.LightChoices.size(), 0.0);          // of them, impostors' outlines
  impl.ThinLines.assign(impl.LightChoices.size(), 0.0);
  impl.ThinFloorPct.assign(impl.LightChoices.size(), 0.0);
  impl.ThinMapPct.assign(impl.LightChoices.size(), 0.0);
  impl.OutlinePct.assign(impl.LightChoices.size(), 0.0);
  impl.VolumeOpenQuads.assign(impl.LightChoices.size(), 0.0);
  for (size_t l = 0; l < impl.LightChoices.size(); ++l)
  {
    if (impl.LightChoices[l] != vtkshadow::TechniqueSet::Cascaded)
    {
      continue;
    }
    const int index = static_cast<int>(l);
    edgeLengths[l] = this->MapOutlinePixels(
      frame.Lights[l].Homogeneous, index, renderer, &impl.ThinPoints[l], &impl.ThinLines[l]);
    edgeLength = std::max(edgeLength, edgeLengths[l]);
    stretch = std::max(stretch,
      vsh_auto_plane_stretch(
        impl.Objects.data(), static_cast<int>(impl.Objects.size()), frame.Lights[l].Homogeneous));
  }
  this->ChooseTexelTarget(renderer, edgeLength, stretch);
  impl.RaytraceOnlyWhy = this->RaytraceOnlyReason(frame);
  impl.SceneKey = SceneKey(impl.Actors, frame);
  this->ChooseGeneral(renderer, edgeLengths);
  this->ChooseRaytraceOnly(frame);
  this->ApplySoftSamples();
  this->ApplyLightMasks();
  this->DescribeChoice();
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::RaytraceOnlyReason(const vtkshadow::ShadowFrame& frame) const
{
  if (vtkshadow::HasTintingCaster(frame.Translucent, NO_CAST()))
  {
    return "a translucent caster's filter tints the shadow, which only raytrace draws in colour";
  }
  if (frame.ShowsVolumes)
  {
    return "a volume (vtkVolume) casts, which only raytrace draws";
  }
  return "";
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ChooseRaytraceOnly(const vtkshadow::ShadowFrame& frame)
{
  // What only raytrace draws: a translucent caster whose filter tints its
  // shadow (csm, planar and volume hold one value per light and draw it
  // grey, so their colour error is the tint itself, over any target) and a
  // vtkVolume's shadow (the others cast none). Every casting light goes to
  // raytrace, also one whose casters were all volumes ("nothing casts" is
  // never the answer for a visible volume); one pass for them all keeps
  // the volume/raytrace mask clash away.
  Internals& impl = *this->Impl;
  const std::string& why = impl.RaytraceOnlyWhy;
  for (size_t l = 0; !why.empty() && l < impl.LightChoices.size(); ++l)
  {
    vtkshadow::TechniqueSet& choice = impl.LightChoices[l];
    if (l < frame.Lights.size() && frame.Lights[l].Casts &&
      choice != vtkshadow::TechniqueSet::RayTraced)
    {
      const bool none = choice == vtkshadow::TechniqueSet::None;
      choice = vtkshadow::TechniqueSet::RayTraced;
      this->LightReasons[l] =
        none ? "raytrace: " + why : this->LightReasons[l] + "; raytrace: " + why;
      if (impl.SoftLights[l])
      {
        impl.RaySamples = std::max(impl.RaySamples, this->RayTracedPass->GetSamples());
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::GatherObjects(const vtkshadow::ShadowFrame& frame)
{
  vtkRenderer* renderer = frame.Renderer;
  double frustum[24];
  renderer->GetActiveCamera()->GetFrustumPlanes(renderer->GetTiledAspectRatio(), frustum);
  vtkshadow::ReceiverPlaneCache& planes = this->PlanarPass->GetReceiverPlaneCache();
  Internals& impl = *this->Impl;
  impl.Objects.clear();
  // The receivers the planar pass will use: marked, or else detected.
  const vtkshadow::ReceiverChoice receivers = this->PlanarPass->ChooseReceivers(frame.Drawn);
  // Translucent actors cast partial shadows under every technique
  // (docs/translucency.md), so they are casters here like opaque ones: the
  // models weigh their outlines and thin parts, and a scene whose only
  // caster is translucent still has something that casts. They are never
  // planar receivers.
  impl.Actors = frame.Drawn;
  for (const vtkshadow::ShadowActor& translucent : frame.Translucent)
  {
    impl.Actors.push_back(translucent);
  }
  impl.Detected.clear();
  for (const vtkshadow::ShadowActor& receiver : receivers.Receivers)
  {
    if (receivers.Detected)
    {
      impl.Detected.emplace_back(receiver.Actor);
    }
  }
  for (const vtkshadow::ShadowActor& shadowActor : impl.Actors)
  {
    const bool receiver = std::any_of(receivers.Receivers.begin(), receivers.Receivers.end(),
      [&](const vtkshadow::ShadowActor& r)
      { return r.Actor == shadowActor.Actor && r.Instance == shadowActor.Instance; });
    // Points drawn as spheres and lines drawn as tubes cast (their proxies
    // under csm, planar and volume; spheres and curves under raytrace), out
    // to the radius they are drawn with.
    double bounds[6];
    const bool impostors = vtkshadow::ImpostorBounds(frame, shadowActor, bounds) &&
      !vtkshadow::HasFlag(shadowActor, vtkShadowPassBase::NO_CAST());
    const bool casts =
      impostors || vtkshadow::CastsAsSurface(shadowActor, vtkShadowPassBase::NO_CAST());
    vsh_auto_object object;
    vsh_auto_object_init(
      &object, impostors ? bounds : shadowActor.Bounds, receiver ? 1 : 0, casts ? 1 : 0, frustum);
    if (object.receiver)
    {
      const vtkshadow::ReceiverPlaneCache::Entry& plane = planes.Get(shadowActor);
      object.flat = plane.Flat ? 1 : 0;
      std::copy_n(plane.Plane, 4, object.plane);
    }
    impl.Objects.push_back(object);
  }
}

//------------------------------------------------------------------------------
int vtkAutoShadowPass::FindConcaveCaster()
{
  // Self-shadowing: planar puts nothing on casters themselves, which is only
  // right for convex ones (their own shadow is the lighting's terminator).
  Internals& impl = *this->Impl;
  for (size_t i = 0; i < impl.Objects.size(); ++i)
  {
    const vsh_auto_object& o = impl.Objects[i];
    // Spheres and tubes count as not convex: several of them can shadow
    // each other, which planar leaves out.
    vtkActor* actor = impl.Actors[i].Actor;
    if (!o.receiver && o.casts && o.in_view &&
      (!impl.For(actor).Convex || vtkshadow::DrawsImpostors(actor)))
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::LightReasonText(int reason, int a, int b) const
{
  const std::vector<vsh_auto_object>& objects = this->Impl->Objects;
  switch (reason)
  {
    case VSH_AUTO_REASON_HEADLIGHT:
      return "the headlight: its shadows hide behind the casters";
    case VSH_AUTO_REASON_NO_CASTER:
      return "nothing casts shadows";
    case VSH_AUTO_REASON_CONCAVE:
      return Centre("an object that is not convex", objects[a]) + " may shadow itself";
    case VSH_AUTO_REASON_SHADOWS_OTHER:
      return Centre("an object", objects[a]) + " may shadow " +
        Centre(
          objects[b].receiver ? "a receiver that is not a plane" : "a non-receiver", objects[b]);
    case VSH_AUTO_REASON_PLANES_ONLY:
      return "every shadow falls on plane receivers: planar is exact and cheapest";
    default:
      return "no caster can shadow a visible object";
  }
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ApplyLightMasks()
{
  // One frame for all lights: each pass skips the lights the other one has.
  Internals& impl = *this->Impl;
  std::vector<int> techniques;
  for (vtkshadow::TechniqueSet choice : impl.LightChoices)
  {
    techniques.push_back(static_cast<int>(choice));
  }
  const int count = static_cast<int>(techniques.size());
  const unsigned int planarLights = vsh_auto_light_mask(techniques.data(), count, VSH_AUTO_PLANAR);
  const unsigned int csmLights = vsh_auto_light_mask(techniques.data(), count, VSH_AUTO_CSM);
  const unsigned int volumeLights = vsh_auto_light_mask(techniques.data(), count, VSH_AUTO_VOLUME);
  const unsigned int rayLights = vsh_auto_light_mask(techniques.data(), count, VSH_AUTO_RAYTRACE);
  this->PlanarPass->SetSkippedLights(~planarLights);
  this->CascadedPass->SetSkippedLights(~csmLights);
  this->VolumePass->SetSkippedLights(~volumeLights);
  this->RayTracedPass->SetSkippedLights(~rayLights);
  impl.Choice = vtkshadow::FromLightMasks(planarLights, csmLights, volumeLights, rayLights);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ChooseTexelTarget(vtkRenderer* renderer, double edgeLength, double stretch)
{
  const int* size = renderer->GetSize();
  const double pixels = static_cast<double>(size[0]) * size[1];
  this->UsedTexelTarget =
    vsh_auto_frame_texel_target(this->MaxTexelPixels, this->MaxError, pixels, edgeLength, stretch);
  // Impostor casters (spheres, tubes, splats) lose more than the texel
  // model's edges: finer texels where a map can meet the target on them.
  if (!(this->MaxTexelPixels > 0.0))
  {
    const Internals& impl = *this->Impl;
    this->UsedTexelTarget =
      vsh_auto_thin_frame_texel(this->UsedTexelTarget, this->MaxError, impl.ThinPoints.data(),
        impl.ThinLines.data(), static_cast<int>(impl.ThinPoints.size()), pixels);
  }
  // csm's sampled light was weighed at csm's own map_resolution within its
  // memory budget (vsh_auto_soft_csm_texel_ratio): a texel target would
  // shrink its maps further than the model saw (at 256x192 to 512 texels,
  // and glyphs-soft's light 1 from 0.055 to 0.091 against Cycles).
  if (this->Impl->CsmSamples > 0)
  {
    this->UsedTexelTarget = 0.0;
  }
  this->UsedStretch = stretch;
  this->UsedEdgeLength = edgeLength;
  this->CascadedPass->SetMaxTexelPixels(this->UsedTexelTarget);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::DescribeChoice()
{
  if (this->LightReasons.empty())
  {
    this->Reason = "no light is switched on";
    return;
  }
  std::ostringstream why;
  for (size_t l = 0; l < this->LightReasons.size(); ++l)
  {
    why << (l ? "; " : "") << "light " << l << ": " << this->GetLightChoice(static_cast<int>(l))
        << " (" << this->LightReasons[l] << ")";
  }
  this->Reason = why.str();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  using vtkshadow::TechniqueSet;
  const TechniqueSet previous = this->Impl->Choice;
  vtkshadow::MarkStage("setup");
  // Decide with the lights where this frame draws them; the chosen passes
  // draw from the same frame.
  const vtkshadow::ShadowFrame& frame = this->BeginFrame(s);
  this->Decide(frame);
  vtkshadow::MarkStage("auto.decide");
  const bool planar = vtkshadow::Has(this->Impl->Choice, TechniqueSet::Planar);
  const bool csm = vtkshadow::Has(this->Impl->Choice, TechniqueSet::Cascaded);
  const bool volume = vtkshadow::Has(this->Impl->Choice, TechniqueSet::Volume);
  const bool rays = vtkshadow::Has(this->Impl->Choice, TechniqueSet::RayTraced);
  // A pass no longer used keeps no GL memory.
  vtkWindow* window = s->GetRenderer()->GetRenderWindow();
  if (!planar && vtkshadow::Has(previous, TechniqueSet::Planar))
  {
    this->PlanarPass->ReleaseGraphicsResources(window);
  }
  if (!csm && vtkshadow::Has(previous, TechniqueSet::Cascaded))
  {
    this->CascadedPass->ReleaseGraphicsResources(window);
  }
  if (!volume && vtkshadow::Has(previous, TechniqueSet::Volume))
  {
    this->VolumePass->ReleaseGraphicsResources(window);
  }
  if (!rays && vtkshadow::Has(previous, TechniqueSet::RayTraced))
  {
    this->RayTracedPass->ReleaseGraphicsResources(window);
  }
  // The chosen passes in a chain in front of the one scene pipeline (this
  // pass's delegate), so switching keeps VTK's passes: each does its shadow
  // work for its lights, then renders through the next.
  vtkRenderPass* next = this->EnsureDelegatePass();
  vtkShadowPassBase* const candidates[] = { this->PlanarPass, this->CascadedPass, this->VolumePass,
    this->RayTracedPass };
  const bool used[] = { planar, csm, volume, rays };
  for (int i = 0; i < 4; ++i)
  {
    if (used[i])
    {
      candidates[i]->SetDelegatePass(next);
      candidates[i]->SetGivenFrame(&frame);
      next = candidates[i];
    }
  }
  this->RenderTimed(next, s);
  for (vtkShadowPassBase* candidate : candidates)
  {
    candidate->SetGivenFrame(nullptr);
  }
  this->NumberOfRenderedProps = next->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::RenderTimed(vtkRenderPass* chain, const vtkRenderState* s)
{
  // A timed frame of the exact trial: the GL work before it finished first
  // and its own waited for, so the clock sees this frame's shadow work and
  // scene only. Other frames are not synchronised.
  Internals& impl = *this->Impl;
  if (!impl.TrialStep.time_frame)
  {
    chain->Render(s);
    return;
  }
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  chain->Render(s);
  glFinish();
  const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  // A still frame of the ray tracer traces nothing (it keeps the last
  // mask): no measure of what tracing costs. A frame that drew other than
  // the trial's technique is no measure of it either.
  using vtkshadow::TechniqueSet;
  const bool rays = impl.TrialStep.technique == VSH_AUTO_TRIAL_RAYTRACE;
  const TechniqueSet drawn = rays ? TechniqueSet::RayTraced : TechniqueSet::Volume;
  const TechniqueSet other = rays ? TechniqueSet::Volume : TechniqueSet::RayTraced;
  if ((rays && this->RayTracedPass->GetNumberOfRaysTraced() == 0) ||
    !vtkshadow::Has(impl.Choice, drawn) || vtkshadow::Has(impl.Choice, other))
  {
    return;
  }
  vsh_auto_trial_record(impl.Trial, impl.TrialStep.technique, took.count());
}

//------------------------------------------------------------------------------
double vtkAutoShadowPass::MapOutlinePixels(
  const double light[4], int index, vtkRenderer* renderer, double* points, double* lines)
{
  // The outline of every shadow this light's map must draw: the silhouettes
  // of the (non-receiver) casters in view, in pixels; of them, those of the
  // points and lines VTK draws as shapes a few pixels wide.
  Internals& impl = *this->Impl;
  double outline = 0.0;
  *points = *lines = 0.0;
  for (size_t i = 0; i < impl.Objects.size(); ++i)
  {
    const vsh_auto_object& o = impl.Objects[i];
    if (!o.casts || o.receiver || !o.in_view)
    {
      continue;
    }
    if (vtkshadow::DrawsImpostors(impl.Actors[i].Actor))
    {
      double drawn[2];
      this->CachedImpostorOutline(i, light, index, renderer, drawn);
      *points += drawn[0];
      *lines += drawn[1];
      outline += drawn[0] + drawn[1];
      continue;
    }
    outline += this->OutlinePixels(i, light, index, renderer);
  }
  return outline;
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::CachedImpostorOutline(
  size_t object, const double light[4], int index, vtkRenderer* renderer, double outline[2])
{
  // One pass over the points and segments when the light, the actor's
  // placement, its shapes, the camera or the viewport changed; else the
  // last frame's figures.
  const vtkshadow::ShadowActor& actor = this->Impl->Actors[object];
  Internals::Caster& caster = this->Impl->For(actor.Actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  std::vector<double> key(light, light + 4);
  key.insert(key.end(), actor.Matrix, actor.Matrix + 16);
  const double* eye = camera->GetPosition();
  const double* focal = camera->GetFocalPoint();
  key.insert(key.end(), eye, eye + 3);
  key.insert(key.end(), focal, focal + 3);
  key.push_back(camera->GetViewAngle());
  key.push_back(camera->GetParallelProjection() ? camera->GetParallelScale() : -1.0);
  key.push_back(camera->GetClippingRange()[0]);
  key.push_back(renderer->GetSize()[1]);
  key.push_back(static_cast<double>(vtkshadow::ImpostorTime(actor.Actor)));
  auto& cached = caster.DrawnOutline[{ this->WorldKey, index }];
  if (cached.first != key || key.back() == 0.0)
  {
    this->ImpostorOutlinePixels(object, light, renderer, outline);
    cached.first = key;
    cached.second = { outline[0], outline[1] };
  }
  outline[0] = cached.second[0];
  outline[1] = cached.second[1];
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ImpostorOutlinePixels(
  size_t object, const double light[4], vtkRenderer* renderer, double outline[2])
{
  // The outlines of the shapes VTK draws, not of the mesh's bounding sphere
  // (a polyline or a point cloud has no silhouette of its own): a sphere or
  // a splat its circle, a square its four sides, a tube or a band both long
  // sides of each segment without their component along the light.
  const vtkshadow::ShadowActor& actor = this->Impl->Actors[object];
  Internals::Caster& caster = this->Impl->For(actor.Actor);
  const vtkMTimeType time = vtkshadow::ImpostorTime(actor.Actor);
  if (caster.DrawnTime != time || time == 0)
  {
    caster.DrawnTime = time;
    caster.Drawn = vtkshadow::Impostors();
    vtkshadow::ExtractImpostors(actor.Actor, caster.Drawn);
  }
  const vtkshadow::Impostors& drawn = caster.Drawn;
  outline[0] = vtkMath::Pi() * drawn.PointSize * static_cast<double>(drawn.Points.size() / 3) +
    4.0 * drawn.PointSize * static_cast<double>(drawn.FlatPoints.size() / 3);
  for (size_t s = 0; s < drawn.SplatRadii.size(); ++s)
  {
    double center[3];
    vsh_mat4_transform_point(actor.Matrix, &drawn.Splats[3 * s], center);
    const double pixel = this->PixelWorldSize(renderer, center);
    outline[0] += pixel > 0.0 ? 2.0 * vtkMath::Pi() * drawn.SplatRadii[s] / pixel : 0.0;
  }
  outline[1] =
    this->SegmentOutlinePixels(drawn.LineVertices, drawn.Segments, actor, light, renderer) +
    this->SegmentOutlinePixels(drawn.FlatLineVertices, drawn.FlatSegments, actor, light, renderer);
}

//------------------------------------------------------------------------------
double vtkAutoShadowPass::SegmentOutlinePixels(const std::vector<double>& vertices,
  const std::vector<unsigned int>& segments, const vtkshadow::ShadowActor& actor,
  const double light[4], vtkRenderer* renderer)
{
  double outline = 0.0;
  for (unsigned int first : segments)
  {
    double a[3], b[3], towards[3], edge[3], mid[3];
    vsh_mat4_transform_point(actor.Matrix, &vertices[3 * first], a);
    vsh_mat4_transform_point(actor.Matrix, &vertices[3 * first + 3], b);
    for (int k = 0; k < 3; ++k)
    {
      mid[k] = 0.5 * (a[k] + b[k]);
      edge[k] = b[k] - a[k];
      towards[k] = light[k] - light[3] * mid[k];
    }
    const double pixel = this->PixelWorldSize(renderer, mid);
    if (vtkMath::Normalize(towards) == 0.0 || !(pixel > 0.0))
    {
      continue;
    }
    const double along = vtkMath::Dot(edge, towards);
    for (int k = 0; k < 3; ++k)
    {
      edge[k] -= along * towards[k];
    }
    outline += 2.0 * vtkMath::Norm(edge) / pixel;
  }
  return outline;
}

//------------------------------------------------------------------------------
double vtkAutoShadowPass::OutlinePixels(
  size_t object, const double light[4], int index, vtkRenderer* renderer)
{
  const vtkshadow::ShadowActor& actor = this->Impl->Actors[object];
  const vsh_auto_object& o = this->Impl->Objects[object];
  const double pixel = this->PixelWorldSize(renderer, o.center);
  if (!(pixel > 0.0))
  {
    return 0.0;
  }
  // The silhouette seen from the light, in the mesh's own coordinates
  // (cached per light while the light and mesh stay put), then to world
  // units by the actor's scale. A mesh that is not closed has no defined
  // silhouette: its bounding sphere's great circle stands in.
  double world = 2.0 * vtkMath::Pi() * o.radius;
  Internals::Caster& caster = this->Impl->For(actor.Actor);
  double inverse[16], inData[4];
  if (!vsh_mat4_inverse(actor.Matrix, inverse))
  {
    return world / pixel;
  }
  vsh_mat4_transform_point4(inverse, light, inData);
  auto& cached = caster.Silhouette[{ this->WorldKey, index }];
  const std::vector<double> key(inData, inData + 4);
  if (cached.first != key)
  {
    cached.first = key;
    cached.second = caster.Geometry.GetSilhouetteLength(inData);
  }
  if (cached.second >= 0.0)
  {
    world = cached.second * MatrixScale(actor.Matrix);
  }
  return world / pixel;
}

//------------------------------------------------------------------------------
double vtkAutoShadowPass::PixelWorldSize(vtkRenderer* renderer, const double center[3]) const
{
  // One pixel's world size at the point's distance from the camera.
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3], focal[3], clip[2];
  camera->GetPosition(eye);
  camera->GetFocalPoint(focal);
  camera->GetClippingRange(clip);
  double forward[3] = { focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2] };
  vtkMath::Normalize(forward);
  const double toCenter[3] = { center[0] - eye[0], center[1] - eye[1], center[2] - eye[2] };
  const double depth = std::max(vtkMath::Dot(toCenter, forward), clip[0]);
  const int height = std::max(renderer->GetSize()[1], 1);
  if (camera->GetParallelProjection())
  {
    return 2.0 * camera->GetParallelScale() / height;
  }
  return 2.0 * depth * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) / height;
}

//------------------------------------------------------------------------------

//------------------------------------------------------------------------------
double vtkAutoShadowPass::ThinnestCasterPixels(vtkRenderer* renderer)
{
  // The narrowest caster part in view, on screen: its width (data units,
  // from the mesh, once per mesh) times the actor's scale, over one pixel's
  // size at the caster's distance (its bounds centre: parts nearer the far
  // end are thinner still, which the near-end texel target also ignores).
  Internals& impl = *this->Impl;
  double thinnest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < impl.Objects.size(); ++i)
  {
    const vsh_auto_object& o = impl.Objects[i];
    if (!o.casts || o.receiver || !o.in_view)
    {
      continue;
    }
    const vtkshadow::ShadowActor& actor = impl.Actors[i];
    // Spheres, tubes, squares and bands are as wide on screen as VTK draws
    // them: the point size or line width in pixels, whatever their
    // distance; splats twice their smallest radius.
    if (vtkshadow::DrawsImpostors(actor.Actor))
    {
      thinnest =
        std::min(thinnest, ImpostorPixels(actor.Actor, this->PixelWorldSize(renderer, o.center)));
      continue;
    }
    const double width = impl.For(actor.Actor).Geometry.GetThinnestWidth();
    const double pixel = this->PixelWorldSize(renderer, o.center);
    if (!std::isfinite(width) || !(pixel > 0.0))
    {
      continue;
    }
    thinnest = std::min(thinnest, width * MatrixScale(actor.Matrix) / pixel);
  }
  return thinnest;
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::WeighSoft(vtkRenderer* renderer, size_t l, int technique)
{
  Internals& impl = *this->Impl;
  const int* size = renderer->GetSize();
  vsh_auto_soft_input in = {};
  in.target = this->PenumbraTarget;
  in.pixels = std::max(1.0, static_cast<double>(size[0]) * size[1]);
  in.planar_available = technique == VSH_AUTO_PLANAR ? 1 : 0;
  in.csm_available = 1;
  in.pcss = impl.CsmSoftAsSet != vtkCascadedShadowMapPass::SOFT_OFF ? 1 : 0;
  in.raytrace_available = 1;
  in.map_ms = MapLookupMsPerPixel * in.pixels;
  this->RayTracedPass->GetCostInputs(in.pixels, 1.0, 1, true, &in.rt_model, &in.rt_frame);
  in.rt_adaptive = this->RayTracedPass->GetAdaptive();
  // Volumes are exact per sample on any receiver, but draw only casters
  // with triangles and opaque ones (the hard rule, vsh_volume_predicted_error).
  const int unsupported = this->VolumeInputs(
    renderer, this->GetFrame().Lights[l].Homogeneous, static_cast<int>(l), in.volume);
  in.volume_available = unsupported == 0 ? 1 : 0;
  // csm's sampled maps: every light's planned maps, and N more per map of
  // each light with a size, in one atlas within the memory budget.
  in.csm_resolution = this->CascadedPass->GetMapResolution();
  in.csm_budget = this->CascadedPass->GetMemoryBudget();
  for (size_t k = 0; k < impl.LightTiles.size(); ++k)
  {
    in.csm_tiles += impl.LightTiles[k];
    in.csm_sampled_tiles += impl.SoftLights[k] ? impl.LightTiles[k] : 0;
  }
  in.csm_adaptive = this->CascadedPass->GetAdaptive() ? 1 : 0;
  vsh_auto_soft_choose(&in, &impl.SoftChoices[l]);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ChooseSoft()
{
  // The rules across lights (one soft mode per csm, one screen mask per
  // frame) are the core's (vsh_auto_plan.h); here they are applied.
  Internals& impl = *this->Impl;
  std::vector<int> weighed(impl.SoftChoices.size());
  for (size_t l = 0; l < weighed.size(); ++l)
  {
    weighed[l] = impl.SoftLights[l] && impl.LightChoices[l] != vtkshadow::TechniqueSet::None;
  }
  const int count = static_cast<int>(weighed.size());
  vsh_auto_plan_soft(impl.SoftChoices.data(), weighed.data(), count, this->PenumbraTarget);
  int samples[VSH_AUTO_SOFT_COUNT];
  vsh_auto_plan_soft_samples(impl.SoftChoices.data(), weighed.data(), count, samples);
  impl.PlanarSamples = samples[VSH_AUTO_SOFT_PLANAR];
  impl.RaySamples = samples[VSH_AUTO_SOFT_RAYTRACE];
  impl.VolumeSamples = samples[VSH_AUTO_SOFT_VOLUME];
  impl.CsmSamples = samples[VSH_AUTO_SOFT_CSM_SAMPLED];
  for (size_t l = 0; l < weighed.size(); ++l)
  {
    if (weighed[l])
    {
      impl.LightChoices[l] = static_cast<vtkshadow::TechniqueSet>(
        this->ApplySoftPick(l, static_cast<int>(impl.LightChoices[l])));
    }
  }
}

//------------------------------------------------------------------------------
int vtkAutoShadowPass::ApplySoftPick(size_t l, int technique)
{
  Internals& impl = *this->Impl;
  const vsh_auto_soft_choice& choice = impl.SoftChoices[l];
  const int pick = choice.pick;
  static const char* const names[VSH_AUTO_SOFT_COUNT] = { "planar", "pcss", "raytrace", "volume",
    "csm_sampled" };
  std::ostringstream json, why;
  json.precision(4);
  why.precision(3);
  json << (impl.SoftJSON.empty() ? "" : ", ") << "{\"light\": " << l << ", \"candidates\": {";
  why << "a light with a size, penumbra target " << this->PenumbraTarget << ": ";
  bool first = true;
  for (int i = 0; i < VSH_AUTO_SOFT_COUNT; ++i)
  {
    const vsh_auto_soft_candidate& c = choice.candidates[i];
    json << (i ? ", " : "") << "\"" << names[i]
         << "\": {\"available\": " << (c.available ? "true" : "false")
         << ", \"samples\": " << c.samples << ", \"pen_mae\": " << JSONNumber(c.pen_mae)
         << ", \"ms\": " << JSONNumber(c.ms) << "}";
    if (c.available)
    {
      why << (first ? "" : ", ") << names[i] << (i == VSH_AUTO_SOFT_PCSS ? "" : " N ")
          << (i == VSH_AUTO_SOFT_PCSS ? std::string() : std::to_string(c.samples))
          << " predicted pen_mae " << c.pen_mae << ", " << c.ms << " ms";
      first = false;
    }
  }
  json << "}, \"pick\": \"" << (pick >= 0 ? names[pick] : "none")
       << "\", \"met\": " << (choice.met ? "true" : "false") << "}";
  impl.SoftJSON += json.str();
  if (pick < 0)
  {
    return technique;
  }
  why << (choice.met ? "; the cheapest that meets it: " : "; none meets it, the lowest error: ")
      << names[pick];
  // The hard rules' reason stays when the soft pick keeps their technique.
  static const int techniques[VSH_AUTO_SOFT_COUNT] = { VSH_AUTO_PLANAR, VSH_AUTO_CSM,
    VSH_AUTO_RAYTRACE, VSH_AUTO_VOLUME, VSH_AUTO_CSM };
  std::string& reason = this->LightReasons[l];
  reason = techniques[pick] == technique ? reason + "; " + why.str() : why.str();
  return techniques[pick];
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ApplySoftSamples()
{
  // One setting per pass: lights with a size that chose the same pass share
  // the largest N any of them needs. Frames without such lights leave the
  // passes' settings alone (hard lights never read them).
  const Internals& impl = *this->Impl;
  if (impl.PlanarSamples > 0)
  {
    this->PlanarPass->SetSoftSamples(impl.PlanarSamples);
  }
  if (impl.RaySamples > 0)
  {
    this->RayTracedPass->SetSamples(impl.RaySamples);
  }
  if (impl.VolumeSamples > 0)
  {
    this->VolumePass->SetSoftSamples(impl.VolumeSamples);
  }
  this->ApplyCsmSoft();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::RecallCsmSoft()
{
  // The pass shows what auto set last frame unless the user has set it
  // since: then the user's setting is the new one to keep.
  Internals& impl = *this->Impl;
  const int current = this->CascadedPass->GetSoft();
  if (impl.CsmSoftApplied < 0 || current != impl.CsmSoftApplied || impl.CsmSoftAsSet < 0)
  {
    impl.CsmSoftAsSet = current;
  }
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ApplyCsmSoft()
{
  // csm's mode for the frame: sampled when a light with a size picked it
  // (PCSS picks chose again, ChooseSoft), PCSS when one picked PCSS, else
  // the user's setting. The user's `soft=0` keeps csm hard: then neither
  // candidate was offered.
  Internals& impl = *this->Impl;
  int mode = impl.CsmSoftAsSet;
  if (impl.CsmSamples > 0)
  {
    mode = vtkCascadedShadowMapPass::SOFT_SAMPLED;
    this->CascadedPass->SetSoftSamples(impl.CsmSamples);
  }
  else if (std::any_of(impl.SoftChoices.begin(), impl.SoftChoices.end(),
             [](const vsh_auto_soft_choice& c) { return c.pick == VSH_AUTO_SOFT_PCSS; }))
  {
    mode = vtkCascadedShadowMapPass::SOFT_PCSS;
  }
  this->CascadedPass->SetSoft(mode);
  impl.CsmSoftApplied = mode == impl.CsmSoftAsSet ? -1 : mode;
}

//------------------------------------------------------------------------------
int vtkAutoShadowPass::EstimateCsmTiles(const vtkshadow::ShadowFrameLight& light, size_t l) const
{
  // What csm's plan gives a light before it has planned: a cube of 6 for a
  // point light, 1 for a spot (cone under 90 degrees, vsh_csm_map_half_angle),
  // the cascades of a directional light (the last frame's count when csm drew
  // it, else its setting, at least 1).
  if (!light.Positional)
  {
    const int last = this->CascadedPass->GetNumberOfCascades(static_cast<int>(l));
    return std::max(1, last > 0 ? last : this->CascadedPass->GetCascadeCount());
  }
  return light.ConeAngle < 90.0 ? 1 : 6;
}

//------------------------------------------------------------------------------
double vtkAutoShadowPass::TaperErrorPct(vtkRenderer* renderer, double pixels)
{
  // Each caster's cross-section profile (data units, once per mesh) to
  // pixels at its bounds centre, as for the thinnest part; the receivers'
  // stretch lengthens what a lost slice would have shadowed.
  Internals& impl = *this->Impl;
  double total = 0.0;
  for (size_t i = 0; i < impl.Objects.size(); ++i)
  {
    const vsh_auto_object& o = impl.Objects[i];
    if (!o.casts || o.receiver || !o.in_view)
    {
      continue;
    }
    const vtkshadow::ShadowActor& actor = impl.Actors[i];
    vtkShadowCasterGeometry& geometry = impl.For(actor.Actor).Geometry;
    const std::vector<double>& widths = geometry.GetTaperWidths();
    const std::vector<double>& lengths = geometry.GetTaperLengths();
    const double pixel = this->PixelWorldSize(renderer, o.center);
    if (widths.empty() || !(pixel > 0.0))
    {
      continue;
    }
    const double lost = vsh_auto_taper_error(widths.data(), lengths.data(), widths.size(),
      MatrixScale(actor.Matrix) / pixel, this->UsedTexelTarget, 2.0, this->UsedStretch, pixels);
    total += std::isfinite(lost) ? lost : 0.0;
  }
  return total;
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ChooseGeneral(vtkRenderer* renderer, const std::vector<double>& edgeLengths)
{
  // Each map light: csm predicts the target met by its texel model unless a
  // caster part is too thin for the texels (then the part's lost shadow);
  // volume and raytrace are exact (volume only for casters it draws).
  // Costs in milliseconds per frame from each model.
  Internals& impl = *this->Impl;
  impl.GeneralJSON.clear();
  const int* size = renderer->GetSize();
  const double pixels = std::max(1.0, static_cast<double>(size[0]) * size[1]);
  this->UsedThinnestPixels = std::numeric_limits<double>::infinity();
  this->UsedTaperErrorPct = 0.0;
  bool measured = false;
  // Per map light the inputs of each candidate; the picks, with the rules
  // across lights (vsh_auto_plan_general), are the core's.
  std::vector<size_t> lightOf;
  std::vector<vsh_auto_general_light> weighed;
  std::vector<vsh_volume_ms_input> volumes;
  std::vector<int> unsupported;
  for (size_t l = 0; l < impl.LightChoices.size(); ++l)
  {
    if (impl.LightChoices[l] != vtkshadow::TechniqueSet::Cascaded || impl.SoftLights[l])
    {
      continue;
    }
    if (!measured)
    {
      this->UsedThinnestPixels = this->ThinnestCasterPixels(renderer);
      this->UsedTaperErrorPct = this->TaperErrorPct(renderer, pixels);
      measured = true;
    }
    vsh_auto_general_light w = {};
    vsh_volume_ms_input volume = {};
    // Two estimates of what thin parts lose, whole parts narrower than two
    // texels and tapered ends narrower than that: the larger counts.
    const double thin = std::max(vsh_auto_thin_caster_error(this->UsedThinnestPixels,
                                   this->UsedTexelTarget, edgeLengths[l], pixels),
      this->UsedTaperErrorPct);
    // Impostor casters: what every technique misses there (VTK's impostor
    // depth), and what a map adds with its texel size.
    const double floor = vsh_auto_thin_floor_error(impl.ThinPoints[l], impl.ThinLines[l], pixels);
    const double map = vsh_auto_thin_map_error(
      impl.ThinPoints[l] + impl.ThinLines[l], this->UsedTexelTarget, pixels);
    impl.ThinFloorPct[l] = floor;
    impl.ThinMapPct[l] = map;
    // The map's floor along the outline (bias, filtering, terminators).
    const double outline =
      vsh_auto_map_outline_error(edgeLengths[l], std::max(1.0, this->UsedStretch), pixels);
    impl.OutlinePct[l] = outline;
    w.candidates[VSH_AUTO_GENERAL_CSM] = { 1,
      (thin > 0.0 ? thin : 0.0) + map + floor + (std::isfinite(outline) ? outline : 0.0),
      MapLookupMsPerPixel * pixels };
    double openQuads[2] = { 0.0, 0.0 };
    const int notDrawn = this->VolumeInputs(
      renderer, this->GetFrame().Lights[l].Homogeneous, static_cast<int>(l), volume, openQuads);
    impl.VolumeOpenQuads[l] = openQuads[0] + openQuads[1];
    const double stencil =
      vsh_auto_volume_floor_error(edgeLengths[l], openQuads[0], openQuads[1], pixels);
    w.candidates[VSH_AUTO_GENERAL_VOLUME] = { 1,
      vsh_volume_predicted_error(notDrawn, impl.SoftLights[l] ? 1 : 0) + floor +
        (std::isfinite(stencil) ? stencil : 0.0),
      vsh_volume_cost_ms(&volume) };
    w.candidates[VSH_AUTO_GENERAL_RAYTRACE] = { 1, floor,
      this->RayTracedPass->EstimateFrameMilliseconds(pixels, 1.0, 1, impl.SoftLights[l]) };
    lightOf.push_back(l);
    weighed.push_back(w);
    volumes.push_back(volume);
    unsupported.push_back(notDrawn);
  }
  // Lights with a size were weighed by the penumbra target (ChooseSoft);
  // what they took constrains these.
  // The trial weighs the candidates as offered: the plan's rule against
  // mixing volumes and rays in a frame makes a light's volume unavailable
  // when the models' picks would mix, which the trial never does.
  std::vector<vsh_auto_general_light> offered = weighed;
  vsh_auto_plan_general(weighed.data(), static_cast<int>(weighed.size()), this->MaxError,
    impl.VolumeSamples > 0, impl.RaySamples > 0);
  for (size_t i = 0; i < weighed.size(); ++i)
  {
    offered[i].pick = weighed[i].pick;
  }
  const std::vector<int> index(lightOf.begin(), lightOf.end());
  this->TimeExactLights(offered.data(), index.data(), static_cast<int>(offered.size()));
  for (size_t i = 0; i < weighed.size(); ++i)
  {
    this->ApplyGeneralPick(
      lightOf[i], weighed[i].candidates, volumes[i], unsupported[i], offered[i].pick);
    if (impl.TrialLights >> lightOf[i] & 1u)
    {
      this->LightReasons[lightOf[i]] += this->TrialNote();
    }
  }
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::TimeExactLights(vsh_auto_general_light* lights, const int* index, int count)
{
  // Lights with a size constrain which exact technique may draw (one screen
  // mask a frame, vsh_auto_plan_general): with any of them sampled by
  // volumes or rays, the models' picks stand; so do they when a caster only
  // rays draw sends every light to raytrace (ChooseRaytraceOnly).
  Internals& impl = *this->Impl;
  impl.TrialModel = -1;
  impl.TrialLights = this->TimeExact && impl.VolumeSamples == 0 && impl.RaySamples == 0 &&
      impl.RaytraceOnlyWhy.empty()
    ? vsh_auto_trial_lights(
        lights, index, count, this->MaxError, &impl.TrialModel, impl.TrialPredicted)
    : 0u;
  impl.Trial = &impl.TrialOf(this->WorldKey);
  impl.TrialStep = vsh_auto_trial_next(impl.Trial, impl.TrialLights, impl.SceneKey,
    impl.TrialLights ? impl.TrialModel : VSH_AUTO_TRIAL_VOLUME, impl.TrialPredicted);
  // With no lights in the trial the step is the models' pick, untimed, and
  // applying it changes nothing.
  vsh_auto_trial_apply(lights, index, count, impl.TrialLights, impl.TrialStep.technique);
}

//------------------------------------------------------------------------------
namespace
{
const char* const TrialNames[VSH_AUTO_TRIAL_COUNT] = { "volume", "raytrace" };
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::TrialNote() const
{
  const Internals& impl = *this->Impl;
  std::ostringstream note;
  note.precision(3);
  note << "; volumes and rays both exact here, timed on this machine:";
  for (int t = 0; t < VSH_AUTO_TRIAL_COUNT; ++t)
  {
    note << (t ? "," : "") << " " << TrialNames[t] << " ";
    if (vsh_auto_trial_timed(impl.Trial, t))
    {
      note << impl.Trial->ms[t] << " ms a frame";
    }
    else
    {
      note << "not timed yet";
    }
  }
  note << " (the models picked " << TrialNames[impl.TrialModel] << ")";
  return note.str();
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::TrialJSON() const
{
  const Internals& impl = *this->Impl;
  std::ostringstream json;
  json.precision(6);
  json << "{\"lights\": " << impl.TrialLights
       << ", \"enabled\": " << (this->TimeExact ? "true" : "false");
  if (impl.TrialLights && impl.Trial)
  {
    json << ", \"model\": \"" << TrialNames[impl.TrialModel] << "\", \"drawn\": \""
         << TrialNames[impl.TrialStep.technique] << "\", \"incumbent\": \""
         << TrialNames[impl.Trial->incumbent >= 0 ? impl.Trial->incumbent : impl.TrialModel]
         << "\"";
    for (int t = 0; t < VSH_AUTO_TRIAL_COUNT; ++t)
    {
      json << ", \"" << TrialNames[t] << "_predicted_ms\": " << JSONNumber(impl.TrialPredicted[t])
           << ", \"" << TrialNames[t] << "_timed_ms\": "
           << JSONNumber(vsh_auto_trial_timed(impl.Trial, t) ? impl.Trial->ms[t] : std::nan(""));
    }
    json << ", \"timed_frame\": " << (impl.TrialStep.time_frame ? "true" : "false");
  }
  json << "}";
  return json.str();
}

//------------------------------------------------------------------------------
namespace
{
// The general candidates' names, by VSH_AUTO_GENERAL_* index.
const char* const GeneralNames[VSH_AUTO_GENERAL_COUNT] = { "csm", "volume", "raytrace" };
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::GeneralPickJSON(size_t l, const vsh_auto_candidate* candidates,
  const vsh_volume_ms_input& volume, int unsupported, int pick) const
{
  const Internals& impl = *this->Impl;
  std::ostringstream json;
  json.precision(4);
  json << "{\"light\": " << l << ", \"csm_error_pct\": "
       << JSONNumber(candidates[VSH_AUTO_GENERAL_CSM].predicted_error_pct)
       << ", \"csm_ms\": " << JSONNumber(candidates[VSH_AUTO_GENERAL_CSM].cost)
       << ", \"thin_point_outline_px\": " << JSONNumber(impl.ThinPoints[l])
       << ", \"thin_line_outline_px\": " << JSONNumber(impl.ThinLines[l])
       << ", \"csm_outline_error_pct\": " << JSONNumber(impl.OutlinePct[l])
       << ", \"volume_error_pct\": "
       << JSONNumber(candidates[VSH_AUTO_GENERAL_VOLUME].predicted_error_pct)
       << ", \"volume_ms\": " << JSONNumber(candidates[VSH_AUTO_GENERAL_VOLUME].cost)
       << ", \"volume_scene_triangles\": " << volume.scene_triangles
       << ", \"volume_silhouette_edges\": " << volume.silhouette_edges
       << ", \"volume_fill_px\": " << volume.fill_px
       << ", \"volume_cap_triangles\": " << volume.cap_triangles
       << ", \"volume_open_quads\": " << impl.VolumeOpenQuads[l]
       << ", \"volume_unsupported_casters\": " << unsupported << ", \"volume_available\": "
       << (candidates[VSH_AUTO_GENERAL_VOLUME].available ? "true" : "false")
       << ", \"raytrace_error_pct\": "
       << JSONNumber(candidates[VSH_AUTO_GENERAL_RAYTRACE].predicted_error_pct)
       << ", \"raytrace_ms\": " << JSONNumber(candidates[VSH_AUTO_GENERAL_RAYTRACE].cost)
       << ", \"pick\": \"" << (pick >= 0 ? GeneralNames[pick] : "csm") << "\"";
  // Whether the pick is predicted to meet the target (met): where no
  // candidate is, auto says so rather than promise it.
  const double predicted = pick >= 0 ? candidates[pick].predicted_error_pct : -1.0;
  json << ", \"predicted_error_pct\": " << JSONNumber(predicted)
       << ", \"met\": " << (pick >= 0 && predicted <= this->MaxError ? "true" : "false") << "}";
  return json.str();
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::UnmetNote(
  size_t l, const char* name, const vsh_auto_candidate& pick) const
{
  if (pick.predicted_error_pct <= this->MaxError)
  {
    return "";
  }
  std::ostringstream unmet;
  unmet.precision(3);
  unmet << "; none is predicted to meet max_error " << this->MaxError << "%: the lowest is " << name
        << "'s " << pick.predicted_error_pct << "%";
  const double floor = this->Impl->ThinFloorPct[l];
  if (floor > this->MaxError)
  {
    unmet << ", " << floor
          << "% of it the floor of points and lines drawn as spheres or tubes (VTK's"
             " screen-space impostors are not the solids they cast as)";
  }
  return unmet.str();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ApplyGeneralPick(size_t l, const vsh_auto_candidate* candidates,
  const vsh_volume_ms_input& volume, int unsupported, int pick)
{
  Internals& impl = *this->Impl;
  impl.GeneralJSON += (impl.GeneralJSON.empty() ? "" : ", ") +
    this->GeneralPickJSON(l, candidates, volume, unsupported, pick);
  const std::string unmet =
    pick >= 0 ? this->UnmetNote(l, GeneralNames[pick], candidates[pick]) : "";
  if (pick != VSH_AUTO_GENERAL_RAYTRACE && pick != VSH_AUTO_GENERAL_VOLUME)
  {
    this->LightReasons[l] += unmet;
    return;
  }
  const vsh_auto_candidate& map = candidates[VSH_AUTO_GENERAL_CSM];
  std::ostringstream why;
  why.precision(3);
  const double impostors = impl.ThinFloorPct[l] + impl.ThinMapPct[l];
  if (map.predicted_error_pct > this->MaxError && 2.0 * impostors >= map.predicted_error_pct)
  {
    why << "points and lines drawn as spheres, tubes or splats ("
        << std::lround(impl.ThinPoints[l] + impl.ThinLines[l]) << " px of outline) lose "
        << impl.ThinFloorPct[l] << "% with any technique and " << impl.ThinMapPct[l]
        << "% more in maps of " << this->UsedTexelTarget << " px texels (maps predicted "
        << map.predicted_error_pct << "% wrong), ";
  }
  else if (map.predicted_error_pct > this->MaxError &&
    2.0 * impl.OutlinePct[l] >= map.predicted_error_pct)
  {
    why << "maps put about " << VSH_AUTO_MAP_OUTLINE_FLOOR
        << " wrong pixels beside each pixel of the casters' outline (predicted "
        << map.predicted_error_pct << "% wrong), ";
  }
  else if (map.predicted_error_pct > this->MaxError)
  {
    if (this->UsedTaperErrorPct >= map.predicted_error_pct)
    {
      why << "tapered caster parts (tips) narrower than two map texels of " << this->UsedTexelTarget
          << " px";
    }
    else
    {
      why << "a caster part " << this->UsedThinnestPixels
          << " px wide is narrower than two map texels of " << this->UsedTexelTarget << " px";
    }
    why << ": maps may lose their shadow (predicted " << map.predicted_error_pct << "% wrong), ";
  }
  else
  {
    why << "maps predicted " << map.cost << " ms, ";
  }
  if (pick == VSH_AUTO_GENERAL_VOLUME)
  {
    impl.LightChoices[l] = vtkshadow::TechniqueSet::Volume;
    why << "shadow volumes are exact and cheapest (predicted " << candidates[pick].cost
        << " ms: " << volume.silhouette_edges << " silhouette edges, " << volume.fill_px
        << " px of fill)";
  }
  else
  {
    impl.LightChoices[l] = vtkshadow::TechniqueSet::RayTraced;
    why << "ray tracing is exact" << (impl.ThinFloorPct[l] > 0 ? " on meshes" : "")
        << " (predicted " << candidates[pick].cost << " ms)";
  }
  this->LightReasons[l] += "; " + why.str() + unmet;
}

//------------------------------------------------------------------------------
int vtkAutoShadowPass::VolumeInputs(vtkRenderer* renderer, const double light[4], int index,
  vsh_volume_ms_input& input, double* openQuads)
{
  // What the volume pass would draw for this light: every caster's volume
  // scissored to its projected bounds (vsh_volume_screen_rect, the pass's
  // own rule, camera-relative in double), and its silhouette's side quads.
  Internals& impl = *this->Impl;
  const int* size = renderer->GetSize();
  const int width = std::max(size[0], 1), height = std::max(size[1], 1);
  input.pixels = static_cast<double>(width) * height;
  input.scene_triangles = 0.0;
  input.silhouette_edges = 0.0;
  input.fill_px = 0.0;
  input.cap_triangles = 0.0;
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3], view[16], projection[16], clip[16];
  camera->GetPosition(eye);
  vtkMatrix4x4::DeepCopy(view, camera->GetViewTransformMatrix());
  view[3] = view[7] = view[11] = 0.0; // inputs are relative to the eye
  vtkMatrix4x4::DeepCopy(
    projection, camera->GetProjectionTransformMatrix(static_cast<double>(width) / height, -1, 1));
  vsh_mat4_multiply(projection, view, clip);
  double relative[4] = { light[0], light[1], light[2], light[3] };
  for (int k = 0; k < 3; ++k)
  {
    relative[k] -= light[3] * eye[k];
  }
  int unsupported = this->TranslucentCasters(renderer);
  double open[2] = { 0.0, 0.0 };
  double nearCorners[12];
  vsh_volume_near_corners(clip, nearCorners);
  const double origin[3] = { 0.0, 0.0, 0.0 };
  for (size_t i = 0; i < impl.Objects.size(); ++i)
  {
    // The depth pre-pass draws every opaque actor, casting or not.
    input.scene_triangles +=
      static_cast<double>(impl.For(impl.Actors[i].Actor).Geometry.GetNumberOfTriangles());
    if (!impl.Objects[i].casts)
    {
      continue;
    }
    const VolumeSilhouette silhouette = this->VolumeEdges(i, light, index);
    const double edges = silhouette.Quads;
    if (edges < 0.0 || !vtkShadowVolumePass::CastsExactly(impl.Actors[i].Actor))
    {
      ++unsupported; // no triangles to extrude, or not drawn as volumes need
      continue;
    }
    double bounds[6];
    std::copy_n(impl.Objects[i].bounds, 6, bounds);
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] -= eye[k];
      bounds[2 * k + 1] -= eye[k];
    }
    int rect[4];
    if (edges > 0.0 && vsh_volume_screen_rect(clip, bounds, relative, width, height, rect))
    {
      input.silhouette_edges += edges;
      input.fill_px += static_cast<double>(rect[2]) * rect[3];
      // The volume pass's rule: z-fail (caps) wherever z-pass is not safe
      // for this camera, and for a caster that is not closed whose unlit
      // side is in view when the pass counts those z-fail (open_zfail
      // without unlit_caps). With unlit_caps such a caster is z-pass with
      // its caps culled to the faces seen from their unlit side: little
      // fill, not charged.
      double size = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        size = std::max(size, bounds[2 * k + 1] - bounds[2 * k]);
      }
      const bool unlitCaps = this->VolumePass->GetUnlitCaps();
      const bool zfail = (silhouette.SeenUnlit && this->VolumePass->GetOpenZFail() && !unlitCaps) ||
        vsh_volume_zpass_safe(origin, nearCorners, bounds, relative, 1e-3 * size) != 1;
      input.cap_triangles += zfail ? silhouette.CapTriangles : 0.0;
      // The floor charges open casters by how they are counted: z-pass's
      // false shadows only where their unlit side is in view and no caps
      // are drawn there.
      open[zfail || unlitCaps || !silhouette.SeenUnlit ? 1 : 0] += silhouette.OpenQuads;
    }
  }
  if (openQuads)
  {
    openQuads[0] = open[0];
    openQuads[1] = open[1];
  }
  return unsupported;
}

//------------------------------------------------------------------------------
int vtkAutoShadowPass::TranslucentCasters(vtkRenderer* renderer) const
{
  // The volume pass casts a translucent actor by the volumes of every one
  // of its faces (its crossings), a cost volume's model (silhouette edges
  // and fill) does not weigh: 16x the unshadowed frame on the translucent
  // isosurface (docs/translucency.md, "Cost"). Until it does, each
  // translucent caster counts as unsupported, so auto does not pick volume.
  int count = 0;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    vtkshadow::ForEachPathActor(prop,
      [&](vtkActor* actor, const double*)
      {
        const vtkshadow::ShadowActor part{ actor, prop, {}, {}, 0 };
        count += actor->HasTranslucentPolygonalGeometry() &&
            !vtkshadow::HasFlag(part, vtkShadowPassBase::NO_CAST())
          ? 1
          : 0;
      });
  }
  return count;
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::VolumeSilhouette vtkAutoShadowPass::VolumeEdges(
  size_t object, const double light[4], int index)
{
  const vtkshadow::ShadowActor& actor = this->Impl->Actors[object];
  Internals::Caster& caster = this->Impl->For(actor.Actor);
  vtkShadowCasterGeometry& geometry = caster.Geometry;
  const vsh_mesh_topology* topology =
    geometry.GetNumberOfTriangles() > 0 ? geometry.GetTopology() : nullptr;
  double stored[4];
  if (!topology || !geometry.WorldToStored(actor.Matrix, light, stored))
  {
    return VolumeSilhouette{};
  }
  auto& cached = caster.VolumeEdges[{ this->WorldKey, index }];
  const std::vector<double> key(stored, stored + 4);
  if (cached.first != key)
  {
    // The volume pass's own silhouette rule (vsh_volume_build): lit faces
    // for closed meshes, both sides with multiplicities for the others.
    vsh_silhouette silhouette;
    const bool ok = vsh_silhouette_build(topology, stored,
                      topology->closed ? VSH_SILHOUETTE_LIT_FACES : VSH_SILHOUETTE_BOTH_SIDES,
                      &silhouette) == VSH_MESH_OK;
    cached.first = key;
    cached.second = VolumeSilhouette{};
    if (ok)
    {
      cached.second.Quads = static_cast<double>(silhouette.total_multiplicity);
      // A caster that is not closed: its quads are where the volumes meet
      // its own surface without the facing test (folds, border edges).
      cached.second.OpenQuads = topology->closed ? 0.0 : cached.second.Quads;
      // Its caps when counted z-fail (vsh_volume_build): the faces turned
      // from the light (closed) or every face (open), near and far for a
      // positional light.
      double faces = static_cast<double>(topology->triangle_count);
      std::vector<unsigned char> facing(topology->triangle_count);
      if (topology->closed && vsh_silhouette_facing(topology, stored, facing.data()) == VSH_MESH_OK)
      {
        faces -= static_cast<double>(std::count(facing.begin(), facing.end(), 1));
      }
      cached.second.CapTriangles = faces * (stored[3] != 0.0 ? 2.0 : 1.0);
    }
    vsh_silhouette_free(&silhouette);
  }
  VolumeSilhouette out = cached.second;
  if (!topology->closed)
  {
    // The camera as the volume pass places it (vtkShadowVolumePass::SeenUnlit).
    double eye[4], eyeStored[4];
    vtkshadow::EyeHomogeneous(this->GetFrame(), eye);
    geometry.WorldToStored(actor.Matrix, eye, eyeStored);
    out.SeenUnlit = vsh_silhouette_seen_unlit(topology, stored, eyeStored) != 0;
  }
  return out;
}

//------------------------------------------------------------------------------
const char* vtkAutoShadowPass::GetChoice() const
{
  return vtkshadow::TechniqueSetName(this->Impl->Choice);
}

//------------------------------------------------------------------------------
const char* vtkAutoShadowPass::GetLightChoice(int light) const
{
  return light >= 0 && light < this->GetNumberOfLightChoices()
    ? vtkshadow::TechniqueSetName(this->Impl->LightChoices[light])
    : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkAutoShadowPass::GetLightReason(int light) const
{
  return light >= 0 && light < this->GetNumberOfLightChoices() ? this->LightReasons[light].c_str()
                                                               : nullptr;
}

//------------------------------------------------------------------------------
int vtkAutoShadowPass::GetNumberOfDetectedReceivers() const
{
  return static_cast<int>(this->Impl->Detected.size());
}

//------------------------------------------------------------------------------
vtkActor* vtkAutoShadowPass::GetDetectedReceiver(int index) const
{
  const auto& detected = this->Impl->Detected;
  return index >= 0 && index < static_cast<int>(detected.size()) ? detected[index].GetPointer()
                                                                 : nullptr;
}

//------------------------------------------------------------------------------
long long vtkAutoShadowPass::GetMemoryBytes() const
{
  long long bytes = 0;
  if (vtkshadow::Has(this->Impl->Choice, vtkshadow::TechniqueSet::Planar))
  {
    bytes += this->PlanarPass->GetMemoryBytes();
  }
  if (vtkshadow::Has(this->Impl->Choice, vtkshadow::TechniqueSet::Cascaded))
  {
    bytes += this->CascadedPass->GetMemoryBytes();
  }
  if (vtkshadow::Has(this->Impl->Choice, vtkshadow::TechniqueSet::Volume))
  {
    bytes += this->VolumePass->GetMemoryBytes();
  }
  if (vtkshadow::Has(this->Impl->Choice, vtkshadow::TechniqueSet::RayTraced))
  {
    bytes += this->RayTracedPass->GetMemoryBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::SetWorldKey(int key)
{
  this->Superclass::SetWorldKey(key);
  this->PlanarPass->SetWorldKey(key);
  this->CascadedPass->SetWorldKey(key);
  this->RayTracedPass->SetWorldKey(key);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ReleaseWorlds(vtkWindow* w, int first)
{
  this->PlanarPass->ReleaseWorlds(w, first);
  this->CascadedPass->ReleaseWorlds(w, first);
  this->RayTracedPass->ReleaseWorlds(w, first);
}

//------------------------------------------------------------------------------
long long vtkAutoShadowPass::GetWorldsMemoryBytes() const
{
  return this->PlanarPass->GetWorldsMemoryBytes() + this->CascadedPass->GetWorldsMemoryBytes() +
    this->RayTracedPass->GetWorldsMemoryBytes();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->PlanarPass->ReleaseGraphicsResources(w);
  this->CascadedPass->ReleaseGraphicsResources(w);
  this->RayTracedPass->ReleaseGraphicsResources(w);
  this->VolumePass->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UsedTexelTarget: " << this->UsedTexelTarget << "\n";
  os << indent << "UsedStretch: " << this->UsedStretch << "\n";
  os << indent << "UsedEdgeLength: " << this->UsedEdgeLength << "\n";
  os << indent << "Choice: " << this->GetChoice() << "\n";
  os << indent << "Reason: " << this->Reason << "\n";
}

//------------------------------------------------------------------------------
// The settings (vtkShadowSettings.h): auto's own, the base's residual_light
// and early_depth (their setters hand them to every candidate), then every
// other key of its candidates.
namespace
{
using P = vtkAutoShadowPass;

// The candidates, in the order a handed-on setting is offered to them.
struct Candidate
{
  const char* Name;
  const vtkshadow::Settings& (*Table)();
  vtkShadowPassBase* (*Pass)(P&);
};
const Candidate Candidates[] = {
  { "csm", &vtkCascadedShadowMapPass::SettingsTable,
    [](P& a) -> vtkShadowPassBase* { return a.GetCascadedPass(); } },
  { "planar", &vtkPlanarShadowPass::SettingsTable,
    [](P& a) -> vtkShadowPassBase* { return a.GetPlanarPass(); } },
  { "raytrace", &vtkRayTracedShadowPass::SettingsTable,
    [](P& a) -> vtkShadowPassBase* { return a.GetRayTracedPass(); } },
  { "volume", &vtkShadowVolumePass::SettingsTable,
    [](P& a) -> vtkShadowPassBase* { return a.GetVolumePass(); } },
};

// A candidate's key, handed on as before the tables: to the first candidate
// that takes the value (soft_samples 100 reaches planar, 10 only csm).
vtkshadow::Setting HandedOn(const vtkshadow::Setting& row, const char* candidate)
{
  const std::string key = row.Key;
  auto set = [key](vtkShadowPassBase& p, double v)
  {
    for (const Candidate& c : Candidates)
    {
      if (c.Pass(static_cast<P&>(p))->SetOption(key.c_str(), v))
      {
        return;
      }
    }
  };
  auto get = [key](vtkShadowPassBase& p)
  {
    for (const Candidate& c : Candidates)
    {
      vtkShadowPassBase* pass = c.Pass(static_cast<P&>(p));
      const vtkshadow::Setting* found = pass->GetSettings().Find(key.c_str());
      if (found && found->Get)
      {
        return found->Get(*pass);
      }
    }
    return 0.0;
  };
  return { key, row.Range, std::string("to ") + candidate + ": " + row.Doc, set, get };
}

// A second candidate with the key: the listed range covers both (the
// candidates' ranges of a shared key overlap: 1..64, 1..1024, 1..255), the
// doc names them in the order they are offered the value.
void Widen(vtkshadow::Setting& had, const vtkshadow::Setting& row, const char* candidate)
{
  vtkshadow::SettingRange& r = had.Range;
  if (row.Range.Min < r.Min || (row.Range.Min == r.Min && !row.Range.MinOpen))
  {
    r.Min = row.Range.Min;
    r.MinOpen = row.Range.MinOpen;
  }
  if (row.Range.Max > r.Max || (row.Range.Max == r.Max && !row.Range.MaxOpen))
  {
    r.Max = row.Range.Max;
    r.MaxOpen = row.Range.MaxOpen;
  }
  r.Integer = r.Integer && row.Range.Integer;
  if (had.Doc.rfind("to the first of ", 0) != 0)
  {
    had.Doc.insert(3, "the first of ");
  }
  had.Doc.insert(had.Doc.find(':'), std::string(", ") + candidate);
}

std::vector<vtkshadow::Setting> AutoRows()
{
  using vtkshadow::Row;
  std::vector<vtkshadow::Setting> rows = {
    Row("max_error", vtkshadow::Closed(0, 100), &P::SetMaxError, &P::GetMaxError,
      "error target: % of visible pixels whose light visibility may be wrong"),
    Row("max_texel_px", vtkshadow::Closed(0, 1e6), &P::SetMaxTexelPixels, &P::GetMaxTexelPixels,
      "map candidates: at most this many pixels per texel (0 = off)"),
    Row("penumbra_target", vtkshadow::OpenAbove(0, 1), &P::SetPenumbraTarget, &P::GetPenumbraTarget,
      "pen_mae target for lights with a size (docs/auto.md)"),
    Row("time_exact", vtkshadow::Integers(0, 1), &P::SetTimeExact, &P::GetTimeExact,
      "1: volumes or rays, where both are exact, by frames timed here; 0: by the cost models"),
    *vtkShadowPassBase::SettingsTable().Find("residual_light"),
    *vtkShadowPassBase::SettingsTable().Find("early_depth"),
  };
  const size_t own = rows.size();
  for (const Candidate& c : Candidates)
  {
    for (const vtkshadow::Setting& row : c.Table().GetRows())
    {
      auto same = [&](const vtkshadow::Setting& s) { return s.Key == row.Key; };
      auto had = std::find_if(rows.begin(), rows.end(), same);
      if (had == rows.end())
      {
        rows.push_back(HandedOn(row, c.Name));
      }
      else if (had - rows.begin() >= static_cast<std::ptrdiff_t>(own))
      {
        Widen(*had, row, c.Name);
      }
    }
  }
  return rows;
}
}

const vtkshadow::Settings& vtkAutoShadowPass::SettingsTable()
{
  static const vtkshadow::Settings table(nullptr, AutoRows());
  return table;
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::SetResidualLight(double residual)
{
  this->Superclass::SetResidualLight(residual);
  for (const Candidate& c : Candidates)
  {
    c.Pass(*this)->SetResidualLight(this->ResidualLight);
  }
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::SetEarlyDepth(int mode)
{
  this->Superclass::SetEarlyDepth(mode);
  for (const Candidate& c : Candidates)
  {
    c.Pass(*this)->SetEarlyDepth(this->EarlyDepth);
  }
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::GetStatsJSON(vtkRenderer* renderer) const
{
  std::string reason = this->Reason;
  for (size_t at = reason.find('"'); at != std::string::npos; at = reason.find('"', at + 2))
  {
    reason.insert(at, "\\");
  }
  std::ostringstream out;
  out.precision(6);
  out << "\"choice\": \"" << this->GetChoice() << "\", \"reason\": \"" << reason << "\""
      << ", \"texel_target_px\": " << this->UsedTexelTarget
      << ", \"texel_stretch\": " << this->UsedStretch
      << ", \"edge_length_px\": " << this->UsedEdgeLength << ", \"light_choices\": [";
  for (int l = 0; l < this->GetNumberOfLightChoices(); ++l)
  {
    out << (l ? ", " : "") << "\"" << this->GetLightChoice(l) << "\"";
  }
  out << "]";
  // Details of the map pass when there is one, else of the planar pass.
  using vtkshadow::TechniqueSet;
  const vtkShadowPassBase* details = vtkshadow::Has(this->Impl->Choice, TechniqueSet::Cascaded)
    ? static_cast<vtkShadowPassBase*>(this->CascadedPass)
    : this->Impl->Choice == TechniqueSet::Planar ? static_cast<vtkShadowPassBase*>(this->PlanarPass)
                                                 : nullptr;
  if (details != this->PlanarPass)
  {
    // (the planar pass's own details say it otherwise)
    out << ", \"detected_receivers\": " << this->DetectedReceiversJSON(renderer);
  }
  if (details)
  {
    out << ", " << details->GetStatsJSON(renderer);
  }
  out << ", \"thinnest_caster_px\": " << JSONNumber(this->UsedThinnestPixels)
      << ", \"taper_error_pct\": " << JSONNumber(this->UsedTaperErrorPct) << ", \"general\": ["
      << this->Impl->GeneralJSON << "]"
      << ", \"exact_trial\": " << this->TrialJSON();
  out << ", \"penumbra_target\": " << this->PenumbraTarget << ", \"soft\": ["
      << this->Impl->SoftJSON << "]";
  if (vtkshadow::Has(this->Impl->Choice, TechniqueSet::RayTraced))
  {
    out << ", \"raytrace\": {" << this->RayTracedPass->GetStatsJSON(renderer) << "}";
  }
  if (vtkshadow::Has(this->Impl->Choice, TechniqueSet::Volume))
  {
    out << ", \"volume\": {" << this->VolumePass->GetStatsJSON(renderer) << "}";
  }
  return out.str();
}
