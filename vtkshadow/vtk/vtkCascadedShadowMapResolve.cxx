// vtkCascadedShadowMapResolve.cxx - the screen-space resolve of
// vtkCascadedShadowMapPass: the lookups run once per visible pixel in one
// full-screen draw after a depth pre-pass, instead of once per rasterized
// fragment in every mapper (docs/cascaded-shadow-maps.md, "Resolve").
#include "vtkCascadedShadowMapPass.h"
#include "vtkCascadedShadowMapPassInternals.h"
#include "vtkShadowStageProfile.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkShadowMapLightFS.h"
#include "vtkShadowMapResolveFS.h"
#include "vtkShadowScreenQuadVS.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vtkshadow
{
std::string CascadedLookupCode(const vsh_csm_tile_plan& plan, int first, int count,
  const std::string& target, float margin, const std::string& away, const int* sampleFirst)
{
  std::string code;
  for (int l = first; l < first + count; ++l)
  {
    const std::string n = std::to_string(l);
    std::string t = target;
    const size_t at = t.find("%d");
    if (at != std::string::npos)
    {
      t.replace(at, 2, std::to_string(l - first));
    }
    const int kind = l < plan.light_count ? plan.kind[l] : VSH_CSM_NO_SHADOW;
    // The light's tiles are literals in the code: every uniform array index
    // of a lookup is then a constant, which a software rasterizer reads once
    // per draw instead of gathering per pixel.
    const std::string tile = l < plan.light_count ? std::to_string(plan.first[l]) : "0";
    std::string lookup;
    // SOFT_SAMPLED: the light's sample maps from atlas slot `slot` on.
    const int slot = sampleFirst && l < VSH_CSM_MAX_LIGHTS ? sampleFirst[l] : -1;
    const std::string slots = std::to_string(slot);
    if (slot >= 0 && kind == VSH_CSM_CASCADES)
    {
      lookup = "vshShadowCascadesSampled(" + n + ", " + tile + ", " +
        std::to_string(plan.count[l]) + ", " + slots + ", depth, posVC, normalVC)";
    }
    else if (slot >= 0 && kind == VSH_CSM_SPOT)
    {
      lookup = "vshShadowSampled(" + n + ", " + tile + ", " + slots + ", 1, posVC, normalVC, true)";
    }
    else if (slot >= 0 && kind == VSH_CSM_POINT)
    {
      lookup = "vshShadowPointSampled(" + n + ", " + tile + ", " + slots + ", posVC, normalVC)";
    }
    else if (kind == VSH_CSM_CASCADES)
    {
      lookup = "vshShadowCascades(" + tile + ", " + std::to_string(plan.count[l]) +
        ", depth, posVC, normalVC)";
    }
    else if (kind == VSH_CSM_SPOT)
    {
      lookup = "vshShadowSpot(" + tile + ", posVC, normalVC)";
    }
    else if (kind == VSH_CSM_POINT)
    {
      lookup = "vshShadowPoint(" + n + ", " + tile + ", posVC, normalVC)";
    }
    if (lookup.empty())
    {
      code += "  " + t + " = 1.0;\n";
      continue;
    }
    if (margin < -1.0f)
    {
      code += "  " + t + " = mix(1.0, " + lookup + ", fade);\n"; // never skipped
      continue;
    }
    code += "  if (vshShadowFacing(" + n + ", posVC, normalVC, " + std::to_string(margin) +
      "))\n  {\n    " + t + " = mix(1.0, " + lookup + ", fade);\n  }\n  else\n  {\n    " + t +
      " = " + away + ";\n  }\n";
  }
  return code;
}
}

namespace
{
constexpr int MeasureEvery = 64;

// Fragment-shader invocations (GL 4.6 / ARB_pipeline_statistics_query)
// count what a forward lookup costs: a software rasterizer shades whole
// blocks along triangle edges, so many small triangles cost far more than
// their pixels. Without it, fragments passing the depth test.
GLenum FragmentQueryTarget()
{
  constexpr GLenum invocations = 0x82F4; // GL_FRAGMENT_SHADER_INVOCATIONS
  GLint major = 0, minor = 0, count = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major > 4 || (major == 4 && minor >= 6))
  {
    return invocations;
  }
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    if (name && std::string(name) == "GL_ARB_pipeline_statistics_query")
    {
      return invocations;
    }
  }
  return GL_SAMPLES_PASSED;
}

// Window depth is 24-bit: one step of it at view depth z spans
// eps (f - n) z^2 / (f n). The resolve needs that well under the shadow
// texel there, or the reconstructed positions (and normals) are coarser
// than the bias and the lookups turn to acne.
double DepthStep(double z, const double clip[2])
{
  const double n = std::max(clip[0], 1e-300), f = std::max(clip[1], n * (1 + 1e-12));
  return std::ldexp(1.0, -24) * (f - n) * z * z / (f * n);
}
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::ChooseScreenResolve(const Frame& frame) const
{
  const Internals& impl = *this->Impl;
  if (impl.ScreenFailed)
  {
    return false;
  }
  if (this->Resolve == SCREEN)
  {
    return true;
  }
  // The debug tint is per cascade, which the mask does not carry.
  if (this->DebugCascades)
  {
    return false;
  }
  // A volume casting under some light: its opacity shadow map multiplies
  // into the mask, which only the screen resolve has, so the frame takes it
  // under FORWARD too whenever the depth holds the positions (the cost:
  // reconstructed normals on thin geometry, see Resolve).
  if (impl.VolumeMaps.CoversAny() && this->DepthPreciseEnough(frame))
  {
    return true;
  }
  if (this->Resolve == FORWARD)
  {
    return false;
  }
  const vsh_csm_tile_plan& tiles = impl.Plan.tiles;
  int casting = 0;
  for (int l = 0; l < std::min(tiles.light_count, VSH_CSM_MAX_LIGHTS); ++l)
  {
    casting += tiles.kind[l] != VSH_CSM_NO_SHADOW ? 1 : 0;
  }
  if (casting == 0)
  {
    return false;
  }
  if (!this->DepthPreciseEnough(frame))
  {
    return false;
  }
  // Measured on llvmpipe (docs/cascaded-shadow-maps.md): a lookup costs
  // about c per fragment-shader invocation, the resolve's reconstruction
  // about 0.45 c per covered pixel and the depth pre-pass about 0.2 c per
  // invocation. With o invocations per covered pixel, forward pays L c o
  // per pixel for L casting lights, the resolve (0.2 o + 0.45 + L) c.
  // Unknown or stale overdraw: one screen frame measures it.
  if (impl.Overdraw < 0.0 || impl.FramesSinceMeasure >= MeasureEvery)
  {
    return true;
  }
  const double o = impl.Overdraw;
  return casting * o > 0.2 * o + 0.45 + casting;
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::DepthPreciseEnough(const Frame& frame) const
{
  const vsh_csm_tile_plan& tiles = this->Impl->Plan.tiles;
  // Depth precision at the far end of each map's reach against its texel.
  const double farDepth = this->Impl->Plan.depth.range[1];
  for (int t = 0; t < std::min(tiles.tile_count, VSH_CSM_MAX_TILES); ++t)
  {
    const vsh_csm_tile& tile = tiles.tiles[t];
    if (tile.view.texel_world <= 0.0)
    {
      continue;
    }
    const double z = tile.view.perspective ? farDepth : std::min(tile.far_depth, farDepth);
    const double texel = tile.view.texel_world * (tile.view.perspective ? farDepth : 1.0);
    if (DepthStep(z, frame.Scene.clip) > 0.25 * texel)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The resolve shader for each mask texture (lights 0-3 and 4-7), specialized
// like the forward code: filter and light kinds compiled in.
void vtkCascadedShadowMapPass::UpdateResolveSources()
{
  Internals& impl = *this->Impl;
  const std::string head = "//VTK::System::Dec\n" + this->LookupDefines() + vtkShadowMapLightFS;
  for (int layer = 0; layer < 2; ++layer)
  {
    impl.ResolveSource[layer] = head +
      "vec4 vshResolveLights(vec3 posVC, vec3 normalVC, float depth)\n{\n"
      "  float fade = vshShadowFade(depth);\n  vec4 vis = vec4(1.0);\n" +
      vtkshadow::CascadedLookupCode(impl.Plan.tiles, 4 * layer, 4, "vis[%d]", -2.0f, "1.0",
        impl.Sampled ? impl.SampleFirst : nullptr) +
      "  return vis;\n}\n" + vtkShadowMapResolveFS;
  }
}

//------------------------------------------------------------------------------
// Depth pre-pass, resolve, then the scene reading the mask. The pass's
// hooks stay registered through the pre-pass so the mappers build one
// shader per frame, not two.
void vtkCascadedShadowMapPass::RenderScreenResolved(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, const Frame& frame)
{
  Internals& impl = *this->Impl;
  if (!impl.Mask)
  {
    impl.Mask.reset(new vtkShadowScreenMask);
  }
  vtkShadowScreenMask& mask = *impl.Mask;
  // Under CHOOSE, count the fragments of the pre-pass and the covered
  // pixels of the resolve now and then.
  impl.Measuring =
    this->Resolve == CHOOSE && (impl.Overdraw < 0.0 || impl.FramesSinceMeasure >= MeasureEvery);
  if (impl.Measuring && !impl.Queries[0])
  {
    glGenQueries(2, impl.Queries);
    impl.FragmentQuery = FragmentQueryTarget();
  }
  this->PreRender(s);
  impl.PrePass = true;
  if (impl.Measuring)
  {
    glBeginQuery(impl.FragmentQuery, impl.Queries[0]);
  }
  bool ok = mask.RenderDepth(s, std::min(impl.Plan.tiles.light_count, VSH_CSM_MAX_LIGHTS));
  if (impl.Measuring)
  {
    glEndQuery(impl.FragmentQuery);
  }
  impl.PrePass = false;
  vtkshadow::MarkStage("csm.prepass");
  ok = ok && this->ResolveScreen(s, window, frame);
  vtkshadow::MarkStage("csm.resolve");
  if (ok && impl.VolumeMaps.CoversAny())
  {
    ok = impl.VolumeMaps.Apply(window, mask, frame.Shared);
    vtkshadow::MarkStage("csm.volumes");
  }
  if (ok && impl.Measuring)
  {
    GLuint fragments = 0, pixels = 0;
    glGetQueryObjectuiv(impl.Queries[0], GL_QUERY_RESULT, &fragments);
    if (impl.TilesPlanned)
    {
      // The tiled resolve draws only some tiles: the pixels covered come
      // from the depth it read back.
      pixels = static_cast<GLuint>(impl.CoveredPixels);
    }
    else
    {
      glGetQueryObjectuiv(impl.Queries[1], GL_QUERY_RESULT, &pixels);
    }
    impl.Overdraw = pixels > 0 ? static_cast<double>(fragments) / pixels : 1.0;
    impl.FramesSinceMeasure = 0;
  }
  if (!ok)
  {
    // Forward lookups from the next frame on; this one is unshadowed.
    vtkWarningMacro(
      "screen-space resolve unavailable (" << mask.GetError() << "): using forward lookups");
    impl.ScreenFailed = true;
  }
  this->BeginVolumeReceiver(s);
  mask.Activate();
  this->RenderDelegate(s, ok ? &mask : nullptr);
  mask.Deactivate();
  this->PostRender(s);
  this->EndVolumeReceiver();
}

//------------------------------------------------------------------------------
// One full-screen draw per mask texture: every visible pixel's position
// (camera-relative view coordinates) from the depth, its normal from the
// neighbours, and each light's filtered lookup.
bool vtkCascadedShadowMapPass::ResolveScreen(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, const Frame& frame)
{
  Internals& impl = *this->Impl;
  vtkShadowScreenMask& mask = *impl.Mask;
  vtkTextureObject* depth = mask.GetDepthTexture();
  if (!depth)
  {
    return false;
  }
  vtkRenderer* renderer = s->GetRenderer();
  double ndcToView[16];
  vtkMatrix4x4::DeepCopy(ndcToView,
    renderer->GetActiveCamera()->GetProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), -1, 1));
  vtkMatrix4x4::Invert(ndcToView, ndcToView);
  float ndcToViewF[16];
  vtkshadow::ToFloatTransposed(ndcToView, ndcToViewF);
  impl.TilesPlanned = false;
  if (this->TileCull)
  {
    this->PlanScreenTiles(frame, ndcToView);
  }

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  depth->Activate();
  bool ok = true;
  const int layers = mask.GetLightCount() > 4 ? 2 : 1;
  for (int layer = 0; layer < layers && ok; ++layer)
  {
    if (impl.TilesPlanned)
    {
      mask.BeginDraw(4 * layer, false);
      ok = this->DrawResolveTiles(window, layer, ndcToViewF);
      mask.EndDraw();
      ok = ok && mask.GetError().empty();
      continue;
    }
    vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
      vtkShadowScreenQuadVS, impl.ResolveSource[layer].c_str(), "");
    if (!program)
    {
      ok = false;
      break;
    }
    this->SetResolveUniforms(program, ndcToViewF);
    mask.BeginDraw(4 * layer, false);
    if (impl.Measuring && layer == 0)
    {
      glBeginQuery(GL_SAMPLES_PASSED, impl.Queries[1]);
    }
    mask.DrawFullScreen(program);
    if (impl.Measuring && layer == 0)
    {
      glEndQuery(GL_SAMPLES_PASSED);
    }
    mask.EndDraw();
    ok = mask.GetError().empty();
  }
  depth->Deactivate();
  return ok;
}

//------------------------------------------------------------------------------
// The resolve shader's uniforms: the lookups', the pre-pass depth and the
// reconstruction's.
void vtkCascadedShadowMapPass::SetResolveUniforms(
  vtkShaderProgram* program, const float ndcToView[16])
{
  vtkShadowScreenMask& mask = *this->Impl->Mask;
  const float size[2] = { static_cast<float>(mask.GetSize()[0]),
    static_cast<float>(mask.GetSize()[1]) };
  this->SetLookupUniforms(program);
  program->SetUniformi("vshDepth", mask.GetDepthTexture()->GetTextureUnit());
  program->SetUniformMatrix4x4("vshNDCToView", const_cast<float*>(ndcToView));
  program->SetUniform2f("vshMaskSize", size);
}
