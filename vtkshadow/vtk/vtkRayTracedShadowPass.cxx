#include "vtkRayTracedShadowPass.h"
#include "vtkShadowSettings.h"
#include "vtkShadowStageProfile.h"

#include "vtkActor.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterTriangles.h"
#include "vtkShadowEmbreeScene.h"
#include "vtkShadowFrame.h"
#include "vtkShadowImpostors.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowRayClassifier.h"
#include "vtkShadowRayTracer.h"
#include "vtkShadowScreenMask.h"
#include "vtkShadowVolumeCasters.h"

#include "vsh_raytrace.h"
#include "vsh_rt_adaptive.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

namespace
{
// One actor of the frame for the Embree scene, with what a still frame's
// key holds of it appended to `key`.
vtkShadowEmbreeScene::Actor FrameActor(
  const vtkshadow::ShadowActor& a, double opacity, std::vector<double>& key)
{
  vtkShadowEmbreeScene::Actor actor{ a.Actor,
    vtkshadow::CastsAsSurface(a, vtkShadowPassBase::NO_CAST()), {} };
  std::copy_n(a.Matrix, 16, actor.Matrix);
  actor.Opacity = opacity;
  if (opacity < 1.0)
  {
    actor.Tinted = vtkshadow::CasterTransmit(a, actor.Transmit);
  }
  actor.CastsImpostors = !vtkshadow::HasFlag(a, vtkShadowPassBase::NO_CAST());
  key.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(a.Actor)));
  key.push_back(static_cast<double>(vtkshadow::ImpostorTime(a.Actor)));
  key.push_back(actor.Casts ? 1.0 : 0.0);
  key.push_back(actor.CastsImpostors ? 1.0 : 0.0);
  key.push_back(actor.Opacity);
  key.insert(key.end(), actor.Transmit, actor.Transmit + 3);
  key.insert(key.end(), a.Matrix, a.Matrix + 16);
  return actor;
}
}

vtkStandardNewMacro(vtkRayTracedShadowPass);

struct vtkRayTracedShadowPass::Internals
{
  // What a still frame reuses, per world (vtkShadowPassBase::SetWorldKey):
  // the mask with the last traced visibility and what that frame depended
  // on (an equal key means a still frame). A mirror's reflection is another
  // world: with one mask, the two views alternated and every frame traced.
  struct World
  {
    vtkShadowScreenMask Mask;
    // The translucent layer: translucent surfaces' own visibility, traced
    // from their depth where they are the nearest surface.
    vtkShadowScreenMask Translucent;
    std::vector<double> LastKey;
    bool HaveMask = false;
    // The light-space maps that decide pixels without rays (Classify).
    vtkShadowRayClassifier Classifier;

    World() { this->Translucent.SetTranslucentSurfaces(true); }
    // The mask `prop`'s fragments read.
    vtkShadowScreenMask& For(vtkProp* prop)
    {
      return this->Translucent.ReadBy(prop) ? this->Translucent : this->Mask;
    }
    long long GetMemoryBytes() const
    {
      return this->Mask.GetMemoryBytes() + this->Translucent.GetMemoryBytes() +
        this->Classifier.GetMemoryBytes();
    }
    void ReleaseGraphicsResources(vtkWindow* w)
    {
      this->Mask.ReleaseGraphicsResources(w);
      this->Translucent.ReleaseGraphicsResources(w);
    }
  };
  std::map<int, std::unique_ptr<World>> Worlds;
  World* W = nullptr;        // the world being drawn
  int FrameWorldsTraced = 0; // worlds traced since world 0 was last drawn
  vtkShadowEmbreeScene Scene;
  // The renderer's vtkVolumes that cast: the shadow rays Embree leaves free
  // march them (empty, and free of cost, without volumes).
  vtkShadowVolumeCasters Volumes;
  vsh_rt_cost_model Cost;
  // The fraction of a sized light's traced pixels whose first batch
  // disagreed (adaptive counts: they trace all Samples), for the cost
  // estimate: DefaultPenumbra until a frame measures it, then an
  // exponential average like the ray rate's.
  double Penumbra = DefaultPenumbra;
  static constexpr double DefaultPenumbra = 0.25;
  // The fraction of hard (pixel, light) pairs the classifier left to rays,
  // for the cost estimate: DefaultTraced until a frame measures it (the
  // library's scivis and cad scenes measured 0.13-0.65 at 800x600), then
  // an exponential average; 1 where the classifier cannot run.
  double Traced = DefaultTraced;
  static constexpr double DefaultTraced = 0.5;
  std::vector<float> Depth;
  std::vector<std::vector<float>> Visibility;
  // Each light's tint, 3 per pixel, where filtering casters colour it.
  std::vector<std::vector<float>> Tint;
  std::vector<std::vector<float>> TranslucentTint;
  // The translucent layer's depth (1 where the opaque surface is nearest)
  // and visibility, when the renderer draws translucent props.
  std::vector<float> TranslucentDepth;
  std::vector<std::vector<float>> TranslucentVisibility;
  bool TracedTranslucent = false;
  bool ClassifierUsed = false;
  // This frame's impostors for each light's map (vsh_rt_classify_occluders).
  std::vector<vsh_rt_classify_occluders> Occluders;
  ~Internals() { this->FreeOccluders(); }
  void FreeOccluders()
  {
    for (vsh_rt_classify_occluders& o : this->Occluders)
    {
      vsh_rt_classify_occluders_free(&o);
    }
    this->Occluders.clear();
  }
  bool Still = false;
  vtkShadowRayTracer::Counters Counters;
  vtkShadowRayTracer::Counters LastTraced; // the last frame that traced, for its rays per pixel
  int LightsTraced = 0;
  double FrameSeconds = 0;

  Internals()
  {
    vsh_rt_cost_model_default(&this->Cost);
    this->Select(0);
  }

  // Translucent surfaces receive on their own fragments: the nearest
  // surface's depth, translucent ones included, traced where it is nearer
  // than the opaque depth (elsewhere no translucent fragment passes the
  // depth test, so those pixels are left out as background). The rays
  // start on the translucent surface, offset towards the camera as for a
  // depth point, so the surface does not shadow its own point. False when
  // the layer's depth pass fails (W->Translucent.GetError()).
  bool TraceTranslucentLayer(
    const vtkRenderState* s, int lightCount, vtkShadowRayTracer::Frame& rays, int threads)
  {
    this->TracedTranslucent = false;
    if (!vtkShadowScreenMask::HasTranslucentProps(s))
    {
      return true;
    }
    if (!this->W->Translucent.RenderDepth(s, lightCount))
    {
      return false;
    }
    this->W->Translucent.ReadDepth(this->TranslucentDepth);
    if (this->TranslucentDepth.size() != this->Depth.size() || rays.Lights.empty())
    {
      return true;
    }
    bool any = false;
    for (size_t p = 0; p < this->Depth.size(); ++p)
    {
      if (this->TranslucentDepth[p] >= this->Depth[p])
      {
        this->TranslucentDepth[p] = 1.0f;
      }
      any = any || this->TranslucentDepth[p] < 1.0f;
    }
    if (!any)
    {
      return true;
    }
    vtkShadowRayTracer::Counters counters;
    rays.Depth = this->TranslucentDepth.data();
    vtkShadowRayTracer::Trace(this->Scene, rays, threads, this->TranslucentVisibility, counters,
      this->Scene.HasTintedCasters() ? &this->TranslucentTint : nullptr);
    rays.Depth = this->Depth.data();
    this->Counters.PrimaryRays += counters.PrimaryRays;
    this->Counters.ShadowRays += counters.ShadowRays;
    this->Counters.VolumeSamples += counters.VolumeSamples;
    this->TracedTranslucent = true;
    return true;
  }

  // The maps that decide pixels without rays (vtkShadowRayClassifier), for
  // hard lights, when `classify` is on and no volume casts; with the
  // frame's impostors as their occluders.
  void PrepareClassifier(vtkShadowRayTracer::Frame& rays, bool classify, int resolution)
  {
    this->ClassifierUsed = false;
    this->FreeOccluders();
    if (!classify || !this->Volumes.IsEmpty() || this->Scene.IsEmpty())
    {
      return;
    }
    std::vector<bool> hard;
    for (int samples : rays.Samples)
    {
      hard.push_back(samples <= 1);
    }
    vtkShadowRayClassifier& classifier = this->W->Classifier;
    classifier.Update(this->Scene, rays.Lights, hard, rays.Eye, resolution);
    rays.Classify = classifier.GetMaps();
    classifier.Policy(rays.ClassifyBlocks, rays.ClassifyPixels);
    std::copy_n(classifier.GetAnchor(), 3, rays.ClassifyAnchor);
    rays.InstanceRadius = this->Scene.GetLargestRadius();
    this->ClassifierUsed = !rays.Classify.empty();
    if (this->ClassifierUsed && this->Scene.HasImpostors())
    {
      this->BuildOccluders(rays);
    }
  }

  // Each map's occluders from the scene's impostor capsules, moved from
  // the top levels' centre to the maps' anchor. A light whose occluders
  // cannot be built loses its map this frame (every pixel traced).
  void BuildOccluders(vtkShadowRayTracer::Frame& rays)
  {
    std::vector<double> capsules = this->Scene.GetImpostorCapsules();
    const double* centre = this->Scene.GetCentre();
    for (size_t k = 0; k < capsules.size(); ++k)
    {
      const size_t r = k % 4;
      capsules[k] += r < 3 ? centre[r] - rays.ClassifyAnchor[r] : 0.0;
    }
    this->Occluders.assign(rays.Classify.size(), vsh_rt_classify_occluders());
    rays.Occluders.assign(rays.Classify.size(), nullptr);
    for (size_t l = 0; l < rays.Classify.size(); ++l)
    {
      if (!rays.Classify[l])
      {
        continue;
      }
      if (vsh_rt_classify_occluders_build(
            &this->Occluders[l], rays.Classify[l], capsules.data(), capsules.size() / 8) != 0)
      {
        rays.Classify[l] = nullptr;
        continue;
      }
      rays.Occluders[l] = &this->Occluders[l];
    }
  }

  // Fold the last frame's traced fraction of hard lights into Traced.
  void ObserveTraced()
  {
    const vtkShadowRayTracer::Counters& c = this->Counters;
    long long asked = 0, decided = 0, pairs = 0;
    for (size_t l = 0; l < c.LightPixels.size(); ++l)
    {
      pairs += c.LightPixels[l];
    }
    for (size_t l = 0; l < c.Classifiable.size(); ++l)
    {
      asked += c.Classifiable[l];
      decided += c.ClassifiedLit[l] + c.ClassifiedShadowed[l];
    }
    const double traced =
      this->ClassifierUsed && asked > 0 ? 1.0 - double(decided) / double(asked) : 1.0;
    if (asked > 0 || pairs > 0)
    {
      this->Traced = 0.5 * this->Traced + 0.5 * traced;
    }
  }

  // Fold the last frame's penumbra fraction of adaptive lights into Penumbra.
  void ObservePenumbra(const vtkShadowRayTracer::Frame& rays)
  {
    const vtkShadowRayTracer::Counters& c = this->Counters;
    long long pixels = 0, refined = 0;
    for (size_t l = 0; l < rays.First.size() && l < c.LightPixels.size(); ++l)
    {
      if (rays.First[l] < rays.Samples[l]) // adaptive lights only
      {
        pixels += c.LightPixels[l];
        refined += c.LightRefined[l];
      }
    }
    if (pixels > 0)
    {
      this->Penumbra = 0.75 * this->Penumbra + 0.25 * double(refined) / double(pixels);
    }
  }

  void Select(int key)
  {
    std::unique_ptr<World>& world = this->Worlds[key];
    if (!world)
    {
      world.reset(new World);
    }
    this->W = world.get();
  }
};

// The frame: the shared inputs (vtkShadowFrame.h) and what the tracer takes
// from them, with the key a still frame is recognised by.
struct vtkRayTracedShadowPass::Frame
{
  explicit Frame(const vtkshadow::ShadowFrame& shared)
    : Shared(shared)
  {
  }
  const vtkshadow::ShadowFrame& Shared;
  int Size[2] = { 1, 1 };           // the viewport, at least a pixel each way
  int LightCount = 0;               // switched-on lights (mapper numbering), <= MaxLights
  std::vector<vsh_rt_light> Lights; // the lights that cast, camera-relative
  std::vector<int> Channels;        // their mask channels
  std::vector<int> Samples;         // their rays per pixel (1 for a light without a size)
  std::vector<vtkShadowEmbreeScene::Actor> Actors;
  std::vector<double> Key;
};

//------------------------------------------------------------------------------
vtkRayTracedShadowPass::vtkRayTracedShadowPass()
  : Samples(128)
  , Adaptive(1)
  , Classify(1)
  , ClassifyResolution(1024)
  , LightRadius(0.0)
  , LightAngle(0.0)
  , NumberOfThreads(0)
  , NumberOfRaysTraced(0)
  , NumberOfTracedFrames(0)
  , Impl(new Internals)
{
  this->VolumesReceive = true;
}

//------------------------------------------------------------------------------
vtkRayTracedShadowPass::~vtkRayTracedShadowPass() = default;

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  if (!vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()))
  {
    vtkErrorMacro("vtkRayTracedShadowPass needs an OpenGL render window");
    return;
  }
  Internals& impl = *this->Impl;
  vtkshadow::MarkStage("setup");
  const auto start = std::chrono::steady_clock::now();
  impl.Select(this->WorldKey);
  // World 0 starts each frame (a mirror's world is drawn after it).
  impl.FrameWorldsTraced = this->WorldKey == 0 ? 0 : impl.FrameWorldsTraced;
  Frame frame(this->BeginFrame(s));
  this->GatherFrame(frame);
  impl.Still = impl.W->HaveMask && frame.Key == impl.W->LastKey;
  this->NumberOfRaysTraced = 0;
  if (impl.Still)
  {
    // Nothing traced: the mask keeps the last traced frame's visibility.
    const long long pixels = static_cast<long long>(frame.Size[0]) * frame.Size[1];
    impl.Counters = vtkShadowRayTracer::Counters();
    impl.Counters.Pixels = pixels;
    impl.LightsTraced = 0;
  }
  else
  {
    impl.W->HaveMask = this->Trace(s, frame);
    vtkshadow::MarkStage("raytrace.trace");
    impl.W->LastKey = impl.W->HaveMask ? frame.Key : std::vector<double>();
    if (impl.W->HaveMask)
    {
      this->Upload(frame);
      vtkshadow::MarkStage("raytrace.upload");
      ++this->NumberOfTracedFrames;
      ++impl.FrameWorldsTraced;
    }
  }
  impl.FrameSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!impl.W->HaveMask)
  {
    this->RenderDelegate(s); // no shadows rather than garbage
    return;
  }
  impl.W->Mask.Activate();
  impl.W->Translucent.Activate();
  // A still frame reuses the mask without a new pre-pass: its depth is then
  // not this frame's, and the lit draw starts from a cleared depth buffer.
  this->RenderDelegateWithShaderHooks(s, impl.Still ? nullptr : &impl.W->Mask);
  impl.W->Translucent.Deactivate();
  impl.W->Mask.Deactivate();
}

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::GatherFrame(Frame& frame)
{
  const vtkshadow::ShadowFrame& shared = frame.Shared;
  frame.Size[0] = std::max(shared.Size[0], 1);
  frame.Size[1] = std::max(shared.Size[1], 1);
  std::vector<double>& key = frame.Key;
  key = { double(frame.Size[0]), double(frame.Size[1]), double(shared.Origin[0]),
    double(shared.Origin[1]), double(this->Samples), this->LightRadius, this->LightAngle,
    double(this->Adaptive) };
  key.insert(key.end(), shared.Eye, shared.Eye + 3);
  key.insert(key.end(), shared.View, shared.View + 16);
  key.insert(key.end(), shared.Projection, shared.Projection + 16);

  frame.LightCount =
    std::min(static_cast<int>(shared.Lights.size()), vtkShadowScreenMask::MaxLights);
  const double toRadians = std::acos(-1.0) / 180.0;
  for (int i = 0; i < frame.LightCount; ++i)
  {
    const vtkshadow::ShadowFrameLight& light = shared.Lights[i];
    double h[4], focal[3];
    std::copy_n(light.Homogeneous, 4, h);
    for (int k = 0; k < 3; ++k)
    {
      h[k] -= h[3] * shared.Eye[k]; // camera-relative
      focal[k] = light.FocalPoint[k] - shared.Eye[k];
    }
    key.insert(key.end(),
      { h[0], h[1], h[2], h[3], focal[0], focal[1], focal[2], light.ConeAngle,
        light.Casts ? 1.0 : 0.0 });
    if (!light.Casts)
    {
      continue;
    }
    // The light's own size (the scene's radius / angle), else the pass's.
    const double radius = light.Radius > 0 ? light.Radius : this->LightRadius;
    const double angle = light.Angle > 0 ? light.Angle : this->LightAngle;
    key.insert(key.end(), { radius, angle });
    vsh_rt_light rt;
    vsh_rt_light_init(h, focal, light.ConeAngle, radius, angle * toRadians, &rt);
    const bool sized = rt.kind == VSH_RT_DIRECTIONAL ? rt.angle > 0 : rt.radius > 0;
    frame.Lights.push_back(rt);
    frame.Samples.push_back(sized ? this->Samples : 1);
    frame.Channels.push_back(i);
  }
  // The renderer's actors, not the render state's frustum-culled ones: a
  // caster behind the camera still shadows the view.
  // Points drawn as spheres and lines drawn as tubes cast too (Embree
  // solids of their pixel width, vtkShadowEmbreeScene) unless NO_CAST; the
  // property's time keys their sizes and representation.
  for (const vtkshadow::ShadowActor& a : shared.Actors)
  {
    frame.Actors.push_back(FrameActor(a, 1.0, key));
  }
  // Translucent actors cast partial shadows with their opacity, tinted by
  // their filter (docs/translucency.md); they receive on the translucent
  // layer (TraceTranslucentLayer).
  for (const vtkshadow::ShadowActor& a : shared.Translucent)
  {
    if (!vtkshadow::HasFlag(a, NO_CAST()))
    {
      frame.Actors.push_back(FrameActor(a, vtkshadow::CasterOpacity(a.Actor), key));
    }
  }
  // Volumes cast the transmittance of their scalar opacity
  // (vtkShadowVolumeCasters); their data, matrix and transfer function
  // key a still frame too.
  this->Impl->Volumes.Gather(shared.Renderer, key);
}

//------------------------------------------------------------------------------
bool vtkRayTracedShadowPass::Trace(const vtkRenderState* s, Frame& frame)
{
  Internals& impl = *this->Impl;
  impl.Counters = vtkShadowRayTracer::Counters();
  impl.LightsTraced = 0;
  if (!impl.W->Mask.RenderDepth(s, frame.LightCount))
  {
    vtkErrorMacro("ray-traced shadows: " << impl.W->Mask.GetError());
    return false;
  }
  vtkshadow::MarkStage("raytrace.prepass");
  vtkShadowEmbreeScene::Camera camera;
  std::copy_n(frame.Shared.Projection, 16, camera.Projection);
  std::copy_n(frame.Shared.View, 16, camera.View);
  camera.Width = frame.Size[0];
  if (!impl.Scene.Update(frame.Actors, frame.Shared.Eye, frame.Shared.ClippingRange[0], camera))
  {
    vtkErrorMacro("ray-traced shadows: " << impl.Scene.GetError());
    return false;
  }
  if (frame.Lights.empty())
  {
    return true; // every channel reads lit
  }
  impl.W->Mask.ReadDepth(impl.Depth);
  vtkShadowRayTracer::Frame rays;
  rays.Depth = impl.Depth.data();
  const int* size = impl.W->Mask.GetSize();
  if (vsh_rt_view_init(frame.Shared.Projection, frame.Shared.View, size[0], size[1], &rays.View) !=
    VSH_RT_OK)
  {
    return true; // a degenerate camera shows nothing to shadow
  }
  std::copy_n(frame.Shared.Eye, 3, rays.Eye);
  if (!impl.Volumes.IsEmpty())
  {
    impl.Volumes.Place(impl.Scene.GetCentre());
    rays.Volumes = &impl.Volumes;
  }
  rays.Lights = frame.Lights;
  rays.Samples = frame.Samples;
  rays.ImpostorReland = 2 * impl.Scene.GetLargestImpostorSlack();
  impl.PrepareClassifier(rays, this->Classify != 0, this->ClassifyResolution);
  for (int samples : frame.Samples)
  {
    const int first = vsh_rt_adaptive_first(samples, this->Adaptive, VSH_RT_ADAPTIVE_BATCH);
    std::vector<int> order(static_cast<size_t>(samples));
    vsh_rt_adaptive_order(samples, first, order.data());
    rays.First.push_back(first);
    rays.Order.push_back(std::move(order));
  }
  int threads = this->NumberOfThreads;
  if (threads <= 0)
  {
    threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  }
  vtkShadowRayTracer::Trace(impl.Scene, rays, threads, impl.Visibility, impl.Counters,
    impl.Scene.HasTintedCasters() ? &impl.Tint : nullptr);
  impl.LightsTraced = static_cast<int>(frame.Lights.size());
  if (!impl.TraceTranslucentLayer(s, frame.LightCount, rays, threads))
  {
    vtkErrorMacro("ray-traced shadows (translucent layer): " << impl.W->Translucent.GetError());
    return false;
  }
  const double traced = double(impl.Counters.PrimaryRays + impl.Counters.ShadowRays);
  this->NumberOfRaysTraced = static_cast<vtkIdType>(traced);
  vsh_rt_cost_model_observe(&impl.Cost, traced, impl.Counters.Seconds, impl.Counters.Threads);
  impl.ObservePenumbra(rays);
  impl.ObserveTraced();
  if (impl.ClassifierUsed)
  {
    const vtkShadowRayTracer::Counters& c = impl.Counters;
    impl.W->Classifier.Observe(c.BlockAsked, c.BlockDecided, c.PixelAsked, c.PixelDecided);
  }
  impl.LastTraced = impl.Counters;
  return true;
}

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::Upload(const Frame& frame)
{
  Internals& impl = *this->Impl;
  const bool tinted = impl.Scene.HasTintedCasters();
  for (int l = 0; l < impl.LightsTraced; ++l)
  {
    impl.W->Mask.UploadLight(frame.Channels[l], impl.Visibility[l].data());
    if (tinted)
    {
      impl.W->Mask.UploadTint(frame.Channels[l], impl.Tint[l].data());
    }
    if (impl.TracedTranslucent)
    {
      impl.W->Translucent.UploadLight(frame.Channels[l], impl.TranslucentVisibility[l].data());
      if (tinted)
      {
        impl.W->Translucent.UploadTint(frame.Channels[l], impl.TranslucentTint[l].data());
      }
    }
  }
  impl.W->Mask.FinishUploads();
  impl.W->Translucent.FinishUploads();
}

//------------------------------------------------------------------------------
int vtkRayTracedShadowPass::GetNumberOfMeshBuilds() const
{
  return this->Impl->Scene.GetMeshBuilds();
}

//------------------------------------------------------------------------------
int vtkRayTracedShadowPass::GetNumberOfTopLevelCommits() const
{
  return this->Impl->Scene.GetTopLevelCommits();
}

//------------------------------------------------------------------------------
vtkIdType vtkRayTracedShadowPass::GetNumberOfCasterTriangles() const
{
  return static_cast<vtkIdType>(this->Impl->Scene.GetNumberOfTriangles());
}

//------------------------------------------------------------------------------
double vtkRayTracedShadowPass::EstimateFrameMilliseconds(
  double pixels, double coverage, int lights, bool sized) const
{
  vsh_rt_cost_model model;
  vsh_rt_cost_input input;
  this->GetCostInputs(pixels, coverage, lights, sized, &model, &input);
  return vsh_rt_cost_ms(&model, &input);
}

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::GetCostInputs(double pixels, double coverage, int lights, bool sized,
  vsh_rt_cost_model* model, vsh_rt_cost_input* input) const
{
  *model = this->Impl->Cost;
  input->pixels = pixels;
  input->coverage = coverage;
  input->lights = lights;
  // A hard light traces one ray per pixel, whatever Samples says: counting
  // Samples (64) for it made auto predict 7.8 s for arrow-glyphs' 133 ms.
  input->samples = sized ? this->Samples : 1;
  // Adaptive counts: every pixel pays the first batch, only the measured
  // penumbra fraction the rest.
  input->first = vsh_rt_adaptive_first(input->samples, this->Adaptive, VSH_RT_ADAPTIVE_BATCH);
  input->penumbra = this->Impl->Penumbra;
  // The classifier decides lights traced with one ray only (hard ones, or
  // a sized one at one sample).
  input->traced = input->samples > 1 || !this->Classify ? 1.0 : this->Impl->Traced;
  input->threads = this->NumberOfThreads > 0
    ? this->NumberOfThreads
    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

//------------------------------------------------------------------------------
long long vtkRayTracedShadowPass::GetMemoryBytes() const
{
  long long bytes = 0;
  for (const auto& world : this->Impl->Worlds)
  {
    bytes += world.second->GetMemoryBytes();
  }
  return bytes + this->GetVolumeReceiverMemoryBytes();
}

//------------------------------------------------------------------------------
long long vtkRayTracedShadowPass::GetWorldsMemoryBytes() const
{
  long long bytes = 0;
  for (const auto& world : this->Impl->Worlds)
  {
    bytes += world.first != 0 ? world.second->GetMemoryBytes() : 0;
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::ReleaseWorlds(vtkWindow* w, int first)
{
  Internals& impl = *this->Impl;
  first = std::max(first, 1);
  for (auto it = impl.Worlds.begin(); it != impl.Worlds.end();)
  {
    if (it->first >= first)
    {
      it->second->ReleaseGraphicsResources(w);
      it = impl.Worlds.erase(it);
    }
    else
    {
      ++it;
    }
  }
  if (impl.Worlds.find(this->WorldKey) == impl.Worlds.end())
  {
    impl.Select(0);
  }
}

//------------------------------------------------------------------------------
// The settings, once (vtkShadowSettings.h). light_angle follows the
// scene's range, [0, 180) (it was [0, 90] here before the tables).
const vtkshadow::Settings& vtkRayTracedShadowPass::SettingsTable()
{
  using P = vtkRayTracedShadowPass;
  using vtkshadow::Row;
  static const vtkshadow::Settings table(&vtkShadowPassBase::SettingsTable(),
    {
      Row("samples", vtkshadow::Integers(1, 1024), &P::SetSamples, &P::GetSamples,
        "rays per pixel for a light with a size (hard lights trace 1)"),
      Row("adaptive", vtkshadow::Flag(), &P::SetAdaptive, &P::GetAdaptive,
        "more rays only near a penumbra"),
      Row("classify", vtkshadow::Flag(), &P::SetClassify, &P::GetClassify,
        "decide the pixels a light-space map proves lit or shadowed without rays"),
      Row("classify_resolution", vtkshadow::Integers(64, 4096), &P::SetClassifyResolution,
        &P::GetClassifyResolution, "texels a side of the classifier's maps"),
      Row("threads", vtkshadow::Integers(0, 256), &P::SetNumberOfThreads, &P::GetNumberOfThreads,
        "tracing threads (0 = one per core)"),
      Row("light_radius", vtkshadow::OpenBelow(0, std::numeric_limits<double>::infinity()),
        &P::SetLightRadius, &P::GetLightRadius,
        "radius of point and spot lights that have none of their own"),
      Row("light_angle", vtkshadow::OpenBelow(0, 180), &P::SetLightAngle, &P::GetLightAngle,
        "angular diameter (degrees) of directional lights without one (traced as at most 90)"),
    });
  return table;
}

//------------------------------------------------------------------------------
namespace
{
// Shadow rays per traced pixel for each light of the last traced frame (a
// still frame traces none), their mean
// over the lights, and the fraction of traced pixels that traced the rest
// of an adaptive light's samples.
std::string RaysPerPixelJSON(const vtkShadowRayTracer::Counters& c)
{
  std::ostringstream out, per, refined;
  double sum = 0;
  int lights = 0;
  for (size_t l = 0; l < c.LightPixels.size(); ++l)
  {
    const double pixels = double(c.LightPixels[l]);
    const double mean = pixels > 0 ? double(c.LightRays[l]) / pixels : 0.0;
    per << (l ? ", " : "") << mean;
    refined << (l ? ", " : "") << (pixels > 0 ? double(c.LightRefined[l]) / pixels : 0.0);
    sum += mean;
    lights += pixels > 0 ? 1 : 0;
  }
  out << ", \"rays_per_pixel_light\": [" << per.str()
      << "], \"mean_rays_per_pixel_light\": " << (lights ? sum / lights : 0.0)
      << ", \"refined_fraction_light\": [" << refined.str() << "]";
  return out.str();
}

// The volumes that cast, why the others do not (a list of strings), and
// the opacity samples the last frame's shadow rays took in them.
std::string VolumesJSON(
  const vtkShadowVolumeCasters& volumes, const vtkShadowRayTracer::Counters& c)
{
  std::ostringstream out;
  out << ", \"volumes\": " << volumes.GetNumberOfVolumes() << ", \"volumes_skipped\": [";
  const std::vector<std::string>& skipped = volumes.GetSkipped();
  for (size_t k = 0; k < skipped.size(); ++k)
  {
    out << (k ? ", " : "") << '"';
    for (char ch : skipped[k])
    {
      out << (ch == '"' || ch == '\\' ? "\\" : "") << ch;
    }
    out << '"';
  }
  out << "], \"volume_samples\": " << c.VolumeSamples;
  return out.str();
}

// Numbers separated by commas.
std::string Join(const std::vector<double>& values)
{
  std::ostringstream out;
  for (size_t k = 0; k < values.size(); ++k)
  {
    out << (k ? ", " : "") << values[k];
  }
  return out.str();
}

// The classifier's part of the last frame: whether it ran, per light the
// fraction of (pixel, light) pairs it decided and of surface pixels traced,
// pixels that traced no ray, and its maps (built, ms, bytes).
std::string ClassifyJSON(
  bool used, const vtkShadowRayClassifier& classifier, const vtkShadowRayTracer::Counters& c)
{
  std::ostringstream out, decided, traced, lit, shadowed;
  long long asked = 0, settled = 0;
  for (size_t l = 0; l < c.Classifiable.size(); ++l)
  {
    lit << (l ? ", " : "") << c.ClassifiedLit[l];
    shadowed << (l ? ", " : "") << c.ClassifiedShadowed[l];
    const double n = double(c.Classifiable[l]);
    const long long d = c.ClassifiedLit[l] + c.ClassifiedShadowed[l];
    decided << (l ? ", " : "") << (n > 0 ? double(d) / n : 0.0);
    traced << (l ? ", " : "") << (n > 0 ? 1.0 - double(d) / n : 1.0);
    asked += c.Classifiable[l];
    settled += d;
  }
  const long long surface = c.Pixels - c.Background;
  out << ", \"classify\": " << (used ? "true" : "false") << ", \"classified_fraction_light\": ["
      << decided.str() << "], \"traced_fraction_light\": [" << traced.str()
      << "], \"traced_fraction\": " << (asked > 0 ? 1.0 - double(settled) / double(asked) : 1.0)
      << ", \"classified_lit_light\": [" << lit.str() << "], \"classified_shadowed_light\": ["
      << shadowed.str() << "]"
      << ", \"pixels_without_rays\": " << c.PixelsWithoutRays
      << ", \"block_decided_pixels\": " << c.BlockPixels << ", \"surface_pixels\": " << surface
      << ", \"classify_maps_built\": " << classifier.GetBuilds()
      << ", \"classify_maps_built_last_frame\": " << (classifier.BuiltLastUpdate() ? 1 : 0)
      << ", \"classify_build_ms\": " << 1e3 * classifier.GetBuildSeconds()
      << ", \"classify_bytes\": " << classifier.GetMemoryBytes()
      << ", \"classify_wait_frames\": " << classifier.GetWait() << ", \"classify_block_yield\": ["
      << Join(classifier.GetBlockYield()) << "], \"classify_pixel_yield\": ["
      << Join(classifier.GetPixelYield()) << "]";
  return out.str();
}
}

//------------------------------------------------------------------------------
std::string vtkRayTracedShadowPass::GetStatsJSON(vtkRenderer*) const
{
  const Internals& impl = *this->Impl;
  const vtkShadowRayTracer::Counters& c = impl.Counters;
  const double rays = double(c.PrimaryRays + c.ShadowRays);
  std::ostringstream out;
  out << "\"still_frame\": " << (impl.Still ? "true" : "false")
      << ", \"traced\": " << (impl.Still || !impl.W->HaveMask ? "false" : "true")
      << ", \"rays_traced\": " << static_cast<long long>(rays)
      << ", \"primary_rays\": " << c.PrimaryRays << ", \"shadow_rays\": " << c.ShadowRays
      << ", \"lights_traced\": " << impl.LightsTraced << ", \"samples\": " << this->Samples
      << ", \"adaptive\": " << this->Adaptive << RaysPerPixelJSON(impl.LastTraced)
      << ", \"penumbra_fraction_model\": " << impl.Penumbra
      << ", \"traced_fraction_model\": " << impl.Traced << ", \"pixels\": " << c.Pixels
      << ", \"skipped_still_frame_px\": " << (impl.Still ? c.Pixels : 0)
      << ", \"skipped_background_px\": " << c.Background
      << ", \"traced_facing_away\": " << c.FacingAway
      << ", \"skipped_outside_cone\": " << c.OutsideCone
      << ", \"refine_misses_px\": " << c.RefineMisses << ", \"landed_px\": " << c.Landed
      << ", \"landed_beyond_half_tolerance_px\": " << c.LandedBeyondHalfTolerance
      << ", \"trace_ms\": " << 1e3 * c.Seconds
      << ", \"rays_per_second\": " << (c.Seconds > 0 ? rays / c.Seconds : 0.0)
      << ", \"rays_per_second_per_thread_model\": " << impl.Cost.rays_per_second_per_thread
      << ", \"threads\": " << c.Threads << ", \"shadow_stage_ms\": " << 1e3 * impl.FrameSeconds
      << ", \"traced_frames\": " << this->NumberOfTracedFrames
      << ", \"worlds_held\": " << impl.Worlds.size()
      << ", \"frame_worlds_traced\": " << impl.FrameWorldsTraced
      << ", \"other_worlds_bytes\": " << this->GetWorldsMemoryBytes()
      << ", \"meshes\": " << impl.Scene.GetNumberOfMeshes()
      << ", \"triangles\": " << impl.Scene.GetNumberOfTriangles()
      << ", \"impostors\": " << impl.Scene.GetNumberOfImpostors() << VolumesJSON(impl.Volumes, c)
      << ", " << this->VolumeReceiverStatsJSON() << ", " << this->DepthSeedStatsJSON()
      << ClassifyJSON(impl.ClassifierUsed, impl.W->Classifier, c)
      << ", \"mesh_builds\": " << impl.Scene.GetMeshBuilds()
      << ", \"mesh_build_ms\": " << 1e3 * impl.Scene.GetMeshBuildSeconds()
      << ", \"top_level_commits\": " << impl.Scene.GetTopLevelCommits()
      << ", \"top_level_ms\": " << 1e3 * impl.Scene.GetTopLevelSeconds();
  return out.str();
}

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  // The masks' textures are gone: the next frame traces again.
  for (auto& world : this->Impl->Worlds)
  {
    world.second->ReleaseGraphicsResources(w);
    world.second->HaveMask = false;
    world.second->LastKey.clear();
  }
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
bool vtkRayTracedShadowPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  return this->Impl->W->For(prop).PreReplaceShaderValues(fragmentShader, prop);
}

//------------------------------------------------------------------------------
bool vtkRayTracedShadowPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  this->ReceiveVolumeShadows(fragmentShader, prop);
  return this->Impl->W->For(prop).PostReplaceShaderValues(fragmentShader, this->GetResidualLight());
}

//------------------------------------------------------------------------------
bool vtkRayTracedShadowPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  this->SetVolumeShadowParameters(program);
  this->Impl->W->For(prop).SetShaderParameters(program);
  return true;
}

//------------------------------------------------------------------------------
void vtkRayTracedShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfRaysTraced: " << this->NumberOfRaysTraced << "\n";
  os << indent << "NumberOfTracedFrames: " << this->NumberOfTracedFrames << "\n";
}
