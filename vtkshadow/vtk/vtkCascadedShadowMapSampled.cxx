// vtkCascadedShadowMapSampled.cxx - SOFT_SAMPLED of vtkCascadedShadowMapPass:
// the lecture's sampled area light. Each casting light with a size gets N
// hard maps per planned map, one from each of N stratified points on the
// light (vsh_csm_sampled.h: a spot or point light's map moved to the point
// on its disk facing the casters' centre, a directional map sheared to the
// sample's direction), baked into extra tiles of the same atlas after the
// planned ones: sample k of the light's map j is slot SampleFirst + k count
// + j. Extra tiles rather than a texture array keep one depth texture, one
// sampler, the FBO and the reuse bookkeeping of the hard path; the lookup
// code keeps its literal tile indices for the base map's uniforms (matrix,
// bias, depth terms) and computes only the sample's slot rectangle and its
// offset or shear per sample. The planned maps of a sampled light are not
// rendered (only its samples are read).
#include "vtkCascadedShadowMapPass.h"
#include "vtkCascadedShadowMapPassInternals.h"

#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vsh_bounds.h"
#include "vsh_csm_sampled.h"
#include "vsh_mat4.h"
#include "vsh_soft_adaptive.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
constexpr int MaxLights = VSH_CSM_MAX_LIGHTS;

// FNV-1a, continued over `n` bytes.
void Mix(unsigned long long& h, const void* data, size_t n)
{
  const unsigned char* b = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i)
  {
    h = (h ^ b[i]) * 1099511628211ULL;
  }
}
}

//------------------------------------------------------------------------------
// Which lights are sampled, their frames and slots; the resolution capped to
// the memory budget (the plan is redone at the capped resolution, so the
// biases match the texels); the shears and what the slots must hold.
void vtkCascadedShadowMapPass::PlanSamples(const Frame& frame)
{
  Internals& impl = *this->Impl;
  vsh_csm_tile_plan& plan = impl.Plan.tiles;
  const int n = this->SoftSamples;
  impl.Sampled = false;
  impl.SampleSlots = 0;
  impl.ShearTexels = 0.0;
  std::fill_n(impl.SampleFirst, MaxLights, -1);
  std::memset(impl.TileShear, 0, sizeof impl.TileShear);
  double toward[3] = { 0.0, 0.0, 0.0 };
  const bool haveCentre = vsh_bounds_center(&frame.Scene.casters, toward) == 0;
  int perLight = 0; // sample maps per map, summed over sampled lights' maps
  for (int l = 0; l < std::min(plan.light_count, MaxLights); ++l)
  {
    vsh_csm_sample_frame& f = impl.SampleFrame[l];
    std::memset(&f, 0, sizeof f);
    if (impl.SampleSize[l] <= 0.0f || plan.kind[l] == VSH_CSM_NO_SHADOW || plan.count[l] == 0 ||
      !haveCentre ||
      vsh_csm_sample_frame_for(&frame.Lights[l], impl.SampleSize[l], toward, n, &f) != VSH_CSM_OK)
    {
      f.sampled = 0;
      continue;
    }
    perLight += f.sampled ? plan.count[l] : 0;
  }
  if (perLight > 0)
  {
    const int cap = vsh_csm_sampled_resolution(
      impl.Plan.resolution.resolution, plan.tile_count + n * perLight, this->MemoryBudget);
    if (cap < impl.Plan.resolution.resolution)
    {
      vsh_csm_settings settings = frame.Settings;
      settings.map_resolution = cap;
      vsh_csm_plan_frame(&frame.Scene, &settings, &impl.Plan);
    }
  }
  const double res = impl.Plan.resolution.resolution;
  int slot = plan.tile_count;
  for (int l = 0; l < std::min(plan.light_count, MaxLights); ++l)
  {
    vsh_csm_sample_frame& f = impl.SampleFrame[l];
    for (int j = 0; j < plan.count[l] && f.sampled && !f.positional; ++j)
    {
      // A directional sample shears its map: the shear per unit of disk
      // sample, and how far (in texels) it moves a lookup at most.
      const int t = plan.first[l] + j;
      double s[4] = { 0, 0, 0, 0 };
      if (plan.tiles[t].view.texel_world > 0.0 &&
        vsh_csm_sample_shear(&plan.tiles[t].view, &f, s) != VSH_CSM_OK)
      {
        f.sampled = 0; // the map does not look along the light: hard
      }
      std::copy_n(s, 4, impl.TileShear[t]);
      impl.ShearTexels =
        std::max(impl.ShearTexels, (std::hypot(s[0], s[1]) + std::hypot(s[2], s[3])) * 0.5 * res);
    }
    for (int j = 0; j < plan.count[l] && f.sampled && f.positional; ++j)
    {
      vsh_csm_sample_widen(&plan.tiles[plan.first[l] + j], &f);
    }
    if (f.sampled)
    {
      impl.SampleFirst[l] = slot;
      slot += n * plan.count[l];
      impl.Sampled = true;
    }
  }
  impl.SampleSlots = slot - plan.tile_count;
  this->UsedSampled = impl.Sampled;
  this->OrderSamples(n);
  // The terms the shader rebuilds each sample's map from, and what the
  // slots hold: when that changes (or sampling stops: the planned maps of a
  // sampled light were not rendered) nothing held is reused.
  unsigned long long key = 0;
  if (impl.Sampled)
  {
    key = 1469598103934665603ULL;
    Mix(key, &n, sizeof n);
    Mix(key, &impl.SampleBatch, sizeof impl.SampleBatch);
    Mix(key, &res, sizeof res);
    Mix(key, &plan.tile_count, sizeof plan.tile_count);
    Mix(key, impl.SampleFirst, sizeof impl.SampleFirst);
    for (int l = 0; l < std::min(plan.light_count, MaxLights); ++l)
    {
      const vsh_csm_sample_frame& f = impl.SampleFrame[l];
      Mix(key, f.u, sizeof f.u);
      Mix(key, f.v, sizeof f.v);
      double u[3], v[3];
      vsh_mat4_transform_direction(frame.Shared.ViewRotation, f.u, u);
      vsh_mat4_transform_direction(frame.Shared.ViewRotation, f.v, v);
      for (int k = 0; k < 3; ++k)
      {
        impl.SampleU[l][k] = f.positional ? static_cast<float>(u[k]) : 0.0f;
        impl.SampleV[l][k] = f.positional ? static_cast<float>(v[k]) : 0.0f;
      }
    }
    for (int i = 0; i < n; ++i)
    {
      double q[2];
      vsh_csm_sample_disk(impl.SampleOrder[static_cast<size_t>(i)], n, q);
      impl.SampleDisk[i][0] = static_cast<float>(q[0]);
      impl.SampleDisk[i][1] = static_cast<float>(q[1]);
    }
  }
  if (key != impl.Held.SampleKey)
  {
    impl.Held.SampleKey = key;
    impl.Held.Rendered.clear();
  }
}

//------------------------------------------------------------------------------
// Which disk sample each of a light's n sample slots holds: adaptive (n
// above the batch), the batch of centre and rim first (vsh_soft_batch_order,
// as volume's adaptive counts), which the lookup stops after where it
// agrees; otherwise the spiral's own order.
void vtkCascadedShadowMapPass::OrderSamples(int n)
{
  Internals& impl = *this->Impl;
  const int batch =
    this->Adaptive && impl.Sampled && n > VSH_SOFT_ADAPTIVE_BATCH ? VSH_SOFT_ADAPTIVE_BATCH : 0;
  if (impl.OrderSamples == n && impl.SampleBatch == batch &&
    impl.SampleOrder.size() == static_cast<size_t>(n))
  {
    return;
  }
  impl.SampleOrder.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    impl.SampleOrder[static_cast<size_t>(i)] = i;
  }
  if (batch > 0)
  {
    vsh_soft_batch_order(n, batch, impl.SampleOrder.data());
  }
  impl.OrderSamples = n;
  impl.SampleBatch = batch;
}

//------------------------------------------------------------------------------
// The sample maps of this frame's maps (after reuse: a reused cascade's
// samples derive from the held map, as the slots were baked from it), and
// the bake list with each sampled light's map replaced by its samples.
void vtkCascadedShadowMapPass::BuildSampleTiles(std::vector<int>& bake)
{
  Internals& impl = *this->Impl;
  if (!impl.Sampled)
  {
    impl.SampleTiles.clear();
    return;
  }
  const vsh_csm_tile_plan& plan = impl.Plan.tiles;
  const int n = this->SoftSamples;
  impl.SampleTiles.assign(impl.SampleSlots, vsh_csm_tile{});
  for (int l = 0; l < std::min(plan.light_count, MaxLights); ++l)
  {
    for (int j = 0; j < plan.count[l] && impl.SampleFirst[l] >= 0; ++j)
    {
      for (int k = 0; k < n; ++k)
      {
        const int slot = impl.SampleFirst[l] + k * plan.count[l] + j - plan.tile_count;
        vsh_csm_sample_tile(&plan.tiles[plan.first[l] + j], &impl.SampleFrame[l],
          impl.SampleOrder[static_cast<size_t>(k)], &impl.SampleTiles[slot]);
      }
    }
  }
  std::vector<int> out;
  for (int t : bake)
  {
    const int l = plan.tiles[t].light;
    if (l < 0 || l >= MaxLights || impl.SampleFirst[l] < 0)
    {
      out.push_back(t);
      continue;
    }
    for (int k = 0; k < n; ++k)
    {
      out.push_back(impl.SampleFirst[l] + k * plan.count[l] + (t - plan.first[l]));
    }
  }
  bake.swap(out);
}

//------------------------------------------------------------------------------
const vsh_csm_tile& vtkCascadedShadowMapPass::BakeTile(int t) const
{
  const Internals& impl = *this->Impl;
  const int base = impl.Plan.tiles.tile_count;
  return t < base ? impl.Plan.tiles.tiles[t] : impl.SampleTiles[t - base];
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::SetSampledUniforms(vtkShaderProgram* program)
{
  Internals& impl = *this->Impl;
  if (!impl.Sampled || !program->IsUniformUsed("vshSampleDisk"))
  {
    return;
  }
  const int tiles = std::min(impl.Plan.tiles.tile_count, VSH_CSM_MAX_TILES);
  program->SetUniform2fv("vshSampleDisk", this->SoftSamples, impl.SampleDisk);
  program->SetUniform3fv("vshSampleU", MaxLights, impl.SampleU);
  program->SetUniform3fv("vshSampleV", MaxLights, impl.SampleV);
  if (tiles > 0)
  {
    program->SetUniform4fv("vshTileShear", tiles, impl.TileShear);
  }
  program->SetUniformi("vshAtlasColumns", std::max(impl.Held.TileGrid[0], 1));
  const float tile[2] = { static_cast<float>(this->UsedResolution) /
      std::max(impl.Held.AtlasSize[0], 1),
    static_cast<float>(this->UsedResolution) / std::max(impl.Held.AtlasSize[1], 1) };
  program->SetUniform2f("vshAtlasTile", tile);
}
