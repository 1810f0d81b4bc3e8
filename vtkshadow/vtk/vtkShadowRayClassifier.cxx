#include "vtkShadowRayClassifier.h"

#include "vtkShadowEmbreeScene.h"

#include <algorithm>
#include <chrono>

//------------------------------------------------------------------------------
vtkShadowRayClassifier::~vtkShadowRayClassifier()
{
  this->Clear();
}

//------------------------------------------------------------------------------
void vtkShadowRayClassifier::Clear()
{
  for (size_t l = 0; l < this->Maps.size(); ++l)
  {
    if (this->Built[l])
    {
      vsh_rt_classify_free(&this->Maps[l]);
    }
  }
  this->Maps.clear();
  this->Built.clear();
  this->Pointers.clear();
  this->Key.clear();
}

//------------------------------------------------------------------------------
void vtkShadowRayClassifier::Update(const vtkShadowEmbreeScene& scene,
  const std::vector<vsh_rt_light>& lights, const std::vector<bool>& hard, const double eye[3],
  int resolution)
{
  // What the maps depend on: the casters (the scene's rebuild counters) and
  // each light in world space; not the camera. With impostors the top
  // levels are rebuilt whenever the camera changes their radii, so the
  // maps (triangles only) follow the world's placements instead; the
  // impostors are the tracer's per-frame occluders.
  const bool impostors = scene.HasImpostors();
  std::vector<double> key = { double(resolution), double(impostors),
    double(impostors ? scene.GetWorldCommits() : scene.GetTopLevelCommits()),
    double(scene.GetMeshBuilds()) };
  for (size_t l = 0; l < lights.size(); ++l)
  {
    // A position in world space, rounded to float: the tracer's lights are
    // relative to the eye, and (p - eye) + eye differs from p in its last
    // bits as the camera moves (far below the map's margins). A
    // directional light has no position.
    const vsh_rt_light& light = lights[l];
    const bool positional = light.kind != VSH_RT_DIRECTIONAL;
    key.insert(key.end(), { double(hard[l]), double(light.kind), light.cos_cone });
    for (int r = 0; r < 3; ++r)
    {
      key.push_back(double(static_cast<float>(light.direction[r])));
      key.push_back(positional ? double(static_cast<float>(light.position[r] + eye[r])) : 0.0);
    }
  }
  ++this->Updates;
  this->Rebuilt = false;
  if (key == this->Key)
  {
    return;
  }
  // The maps are stale. A map pays for its build only over frames that
  // keep it: wait until the new key has held Wait updates (0 at first),
  // twice as long (at least MinWait, up to MaxWait) each time maps are
  // dropped soon after being built, half as long when they last (a scene
  // edited every few frames traces every pixel instead of building maps it
  // throws away).
  if (!this->Key.empty())
  {
    const long long lived = this->Updates - this->BuiltAt;
    this->Wait = lived < 4 * std::max(this->Wait, MinWait)
      ? std::min(std::max(2 * this->Wait, MinWait), MaxWait)
      : this->Wait / 2;
    this->Clear();
  }
  if (key != this->Pending)
  {
    this->Pending = key;
    this->PendingSince = this->Updates;
  }
  if (this->Updates - this->PendingSince < this->Wait)
  {
    return; // no maps yet: every pixel is traced
  }
  this->Rebuilt = true;
  this->BuiltAt = this->Updates;
  this->Key = key;
  this->BlockRate.clear();
  this->PixelRate.clear();
  const auto start = std::chrono::steady_clock::now();
  std::copy_n(scene.GetCentre(), 3, this->Anchor);
  std::vector<double> triangles;
  std::vector<unsigned char> flags;
  std::vector<int> placements;
  scene.CollectTriangles(triangles, flags, placements);
  this->Maps.resize(lights.size());
  this->Built.assign(lights.size(), false);
  this->Pointers.assign(lights.size(), nullptr);
  for (size_t l = 0; l < lights.size(); ++l)
  {
    if (!hard[l])
    {
      continue;
    }
    // The light in the anchor's frame (the tracer's lights are relative
    // to the eye).
    vsh_rt_light light = lights[l];
    for (int r = 0; r < 3; ++r)
    {
      light.position[r] += eye[r] - this->Anchor[r];
    }
    this->Built[l] = true;
    if (vsh_rt_classify_build(&this->Maps[l], &light, triangles.data(), flags.data(),
          placements.data(), flags.size(), resolution) == 0)
    {
      this->Pointers[l] = &this->Maps[l];
    }
    ++this->Builds;
  }
  this->BuildSeconds +=
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//------------------------------------------------------------------------------
void vtkShadowRayClassifier::Policy(std::vector<bool>& blocks, std::vector<bool>& pixels)
{
  const bool probe = ++this->Frames % ProbeEvery == 0;
  this->BlockRate.resize(this->Maps.size(), 1.0);
  this->PixelRate.resize(this->Maps.size(), 1.0);
  blocks.clear();
  pixels.clear();
  for (size_t l = 0; l < this->Maps.size(); ++l)
  {
    blocks.push_back(probe || this->BlockRate[l] >= BlockWorth);
    pixels.push_back(probe || this->PixelRate[l] >= PixelWorth);
  }
}

namespace
{
// Fold a frame's rate (decided / asked) into an exponential average.
void Fold(std::vector<double>& rate, const std::vector<long long>& asked,
  const std::vector<long long>& decided)
{
  for (size_t l = 0; l < asked.size() && l < rate.size() && l < decided.size(); ++l)
  {
    if (asked[l] > 0)
    {
      rate[l] = 0.5 * rate[l] + 0.5 * double(decided[l]) / double(asked[l]);
    }
  }
}
}

//------------------------------------------------------------------------------
void vtkShadowRayClassifier::Observe(const std::vector<long long>& blockAsked,
  const std::vector<long long>& blockDecided, const std::vector<long long>& pixelAsked,
  const std::vector<long long>& pixelDecided)
{
  Fold(this->BlockRate, blockAsked, blockDecided);
  Fold(this->PixelRate, pixelAsked, pixelDecided);
}

//------------------------------------------------------------------------------
long long vtkShadowRayClassifier::GetMemoryBytes() const
{
  long long bytes = 0;
  for (size_t l = 0; l < this->Maps.size(); ++l)
  {
    bytes += this->Built[l] ? static_cast<long long>(vsh_rt_classify_bytes(&this->Maps[l])) : 0;
  }
  return bytes;
}
