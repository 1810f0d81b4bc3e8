// vtkCascadedShadowMapTiles.cxx - the screen resolve of
// vtkCascadedShadowMapPass per tile of the screen (TileCull): the depth
// pre-pass read back, each 16x16 tile's depth range, the core's decision per
// tile and light (vsh_csm_screen_tile_needs: lit, one cascade, or the
// per-pixel code), and one draw per kind of tile with a resolve shader
// compiled for it. A software rasterizer runs both sides of every branch,
// so work is only saved where the code is not there at all: tiles that are
// lit for every light are not drawn (the mask already reads 1 there), and a
// one-cascade light has no cascade loop, no dynamically indexed map and no
// blend with the next cascade.
#include "vtkCascadedShadowMapPass.h"
#include "vtkCascadedShadowMapPassInternals.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkShadowMapLightFS.h"
#include "vtkShadowMapResolveFS.h"
#include "vtkShadowScreenQuadVS.h"

#include "vsh_csm_screen.h"
#include "vsh_mat4.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace
{
constexpr int TilePixels = 16;
// More kinds of tile than this in one mask texture: every light that needs
// a lookup in a tile gets the per-pixel code, which leaves at most 2^4 kinds
// and so bounds the shaders a frame compiles.
constexpr size_t MaxGroups = 12;
}

namespace vtkshadow
{
std::string CascadedTileLookupCode(
  const vsh_csm_tile_plan& plan, int first, const int codes[4], const int* sampleFirst)
{
  std::string code;
  for (int i = 0; i < 4; ++i)
  {
    const int l = first + i;
    const std::string target = "vis[" + std::to_string(i) + "]";
    const int kind = l < plan.light_count ? plan.kind[l] : VSH_CSM_NO_SHADOW;
    if (codes[i] == VSH_CSM_SCREEN_LIT || kind == VSH_CSM_NO_SHADOW)
    {
      code += "  " + target + " = 1.0;\n";
    }
    else if (codes[i] == VSH_CSM_SCREEN_ANY || kind != VSH_CSM_CASCADES ||
      (sampleFirst && l < VSH_CSM_MAX_LIGHTS && sampleFirst[l] >= 0))
    {
      // A sampled light always takes the per-pixel code (its samples).
      code += CascadedLookupCode(plan, l, 1, target, -2.0f, "1.0", sampleFirst);
    }
    else
    {
      const int c = codes[i] - VSH_CSM_SCREEN_CASCADE;
      const int last = plan.first[l] + plan.count[l] - 1;
      std::string lookup =
        "vshShadowSample(" + std::to_string(plan.first[l] + c) + ", posVC, normalVC, false)";
      if (plan.first[l] + c == last)
      {
        // Past the last cascade the per-pixel code gives 1.
        lookup = "(depth > vshTileFar[" + std::to_string(last) + "] ? 1.0 : " + lookup + ")";
      }
      code += "  " + target + " = mix(1.0, " + lookup + ", fade);\n";
    }
  }
  return code;
}
}

//------------------------------------------------------------------------------
// Read the pre-pass depth, reduce it per tile and ask the core what each
// tile needs; group the tiles of each mask texture by their lights' needs.
void vtkCascadedShadowMapPass::PlanScreenTiles(const Frame& frame, const double ndcToView[16])
{
  Internals& impl = *this->Impl;
  vtkShadowScreenMask& mask = *impl.Mask;
  const int w = mask.GetSize()[0], h = mask.GetSize()[1];
  const int cols = (w + TilePixels - 1) / TilePixels, rows = (h + TilePixels - 1) / TilePixels;
  mask.ReadDepth(impl.DepthRead);
  impl.TileMin.resize(static_cast<size_t>(cols) * rows);
  impl.TileMax.resize(impl.TileMin.size());
  impl.TilesPlanned =
    vsh_csm_screen_depth_ranges(impl.DepthRead.data(), w, h, TilePixels, impl.TileMin.data(),
      impl.TileMax.data(), &impl.CoveredPixels) == VSH_CSM_OK;
  double viewToRelative[16];
  vsh_mat4_transpose(frame.Shared.ViewRotation, viewToRelative);
  vsh_csm_screen_params p{};
  p.plan = &impl.Plan.tiles;
  p.lights = frame.Lights.data();
  p.origin = frame.Scene.camera.position;
  p.ndc_to_view = ndcToView;
  p.view_to_relative = viewToRelative;
  p.casters = &frame.Scene.casters;
  p.viewport[0] = w;
  p.viewport[1] = h;
  p.blend_band = this->BlendBand;
  p.max_distance = impl.Plan.depth.max_distance;
  p.reach_texels = this->LookupReachTexels();
  p.resolution = std::max(this->UsedResolution, 1);
  // PCSS's blocker search reaches up to its maximum kernel and compares
  // with a receiver-plane slope: only the depth decisions then.
  p.cull_casters = impl.PCSS || impl.Sampled ? 0 : 1;
  const int lights = std::min(impl.Plan.tiles.light_count, VSH_CSM_MAX_LIGHTS);
  std::vector<std::map<std::string, std::vector<int>>> groups(2);
  std::vector<int> codes(static_cast<size_t>(cols) * rows * VSH_CSM_MAX_LIGHTS, 0);
  this->NumberOfTilesCulled = 0;
  for (int t = 0; t < cols * rows && impl.TilesPlanned; ++t)
  {
    const vsh_csm_screen_tile tile = { (t % cols) * TilePixels, (t / cols) * TilePixels,
      std::min((t % cols + 1) * TilePixels, w), std::min((t / cols + 1) * TilePixels, h),
      impl.TileMin[t], impl.TileMax[t] };
    int* out = &codes[static_cast<size_t>(t) * VSH_CSM_MAX_LIGHTS];
    impl.TilesPlanned = vsh_csm_screen_tile_needs(&p, &tile, out) == VSH_CSM_OK;
    for (int l = 0; l < lights && tile.depth_min <= tile.depth_max; ++l)
    {
      this->NumberOfTilesCulled +=
        impl.Plan.tiles.kind[l] != VSH_CSM_NO_SHADOW && out[l] != VSH_CSM_SCREEN_ANY ? 1 : 0;
    }
  }
  for (int layer = 0; layer < 2 && impl.TilesPlanned; ++layer)
  {
    for (int widen = 0; widen < 2; ++widen)
    {
      auto& g = groups[layer];
      g.clear();
      for (int t = 0; t < cols * rows; ++t)
      {
        int* out = &codes[static_cast<size_t>(t) * VSH_CSM_MAX_LIGHTS + 4 * layer];
        std::string key(4, '\0');
        bool any = false;
        for (int i = 0; i < 4; ++i)
        {
          if (widen && out[i] != VSH_CSM_SCREEN_LIT)
          {
            out[i] = VSH_CSM_SCREEN_ANY;
          }
          key[i] = static_cast<char>('0' + out[i]);
          any = any || out[i] != VSH_CSM_SCREEN_LIT;
        }
        if (any)
        {
          g[key].push_back(t);
        }
      }
      if (g.size() <= MaxGroups)
      {
        break;
      }
    }
  }
  // The rectangles (clip space) of each texture's groups, in order, and
  // the resolve source of each group.
  const std::string head = "//VTK::System::Dec\n" + this->LookupDefines() + vtkShadowMapLightFS;
  for (int layer = 0; layer < 2; ++layer)
  {
    impl.Groups[layer].clear();
    std::vector<float> rects;
    for (const auto& entry : groups[layer])
    {
      Internals::TileGroup group;
      group.First = static_cast<int>(rects.size() / 4);
      group.Count = static_cast<int>(entry.second.size());
      const int t0 = entry.second.front();
      const int* out = &codes[static_cast<size_t>(t0) * VSH_CSM_MAX_LIGHTS + 4 * layer];
      group.Source = head +
        "vec4 vshResolveLights(vec3 posVC, vec3 normalVC, float depth)\n{\n"
        "  float fade = vshShadowFade(depth);\n  vec4 vis = vec4(1.0);\n" +
        vtkshadow::CascadedTileLookupCode(
          impl.Plan.tiles, 4 * layer, out, impl.Sampled ? impl.SampleFirst : nullptr) +
        "  return vis;\n}\n" + vtkShadowMapResolveFS;
      for (int t : entry.second)
      {
        const float x0 = static_cast<float>((t % cols) * TilePixels) / w * 2.0f - 1.0f;
        const float y0 = static_cast<float>((t / cols) * TilePixels) / h * 2.0f - 1.0f;
        const float x1 =
          static_cast<float>(std::min((t % cols + 1) * TilePixels, w)) / w * 2.0f - 1.0f;
        const float y1 =
          static_cast<float>(std::min((t / cols + 1) * TilePixels, h)) / h * 2.0f - 1.0f;
        rects.insert(rects.end(), { x0, y0, x1, y1 });
      }
      impl.Groups[layer].push_back(group);
    }
    impl.Rects[layer].Upload(rects);
  }
}

//------------------------------------------------------------------------------
// Inside the mask's BeginDraw for `layer`: each kind of tile with its shader.
bool vtkCascadedShadowMapPass::DrawResolveTiles(
  vtkOpenGLRenderWindow* window, int layer, const float ndcToView[16])
{
  Internals& impl = *this->Impl;
  for (const Internals::TileGroup& group : impl.Groups[layer])
  {
    vtkShaderProgram* program =
      window->GetShaderCache()->ReadyShaderProgram(vtkShadowScreenQuadVS, group.Source.c_str(), "");
    if (!program)
    {
      return false;
    }
    this->SetResolveUniforms(program, ndcToView);
    impl.Rects[layer].Draw(program, group.First, group.Count);
  }
  return true;
}
