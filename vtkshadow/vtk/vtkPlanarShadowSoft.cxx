// vtkPlanarShadowSoft.cxx - the sampled area lights of vtkPlanarShadowPass
// (docs/soft-shadows.md): the (receiver, light) pairs whose light has a size,
// drawn as SoftSamples hard shadows from points on the light and added into
// an accumulation channel each, with adaptive sample counts (the samples
// beyond a batch only where the batch disagrees).
#include "vtkPlanarShadowPass.h"
#include "vtkPlanarShadowPassInternals.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"
#include "vsh_soft.h"
#include "vsh_soft_adaptive.h"

#include "vtkPlanarShadowAdaptiveFS.h"
#include "vtkPlanarShadowMaskVS.h"
#include "vtkPlanarShadowSoftFS.h"

#include <algorithm>
#include <vector>

using vtkshadow::planar::LiesInPlane;
using vtkshadow::planar::MaxSoftPairs;

//------------------------------------------------------------------------------
std::vector<vsh_planar_pair> vtkPlanarShadowPass::SplitSoftPairs(
  const Frame& frame, std::vector<vsh_planar_pair>& pairs)
{
  // A pair whose light has a size is sampled when SoftSamples > 1; the rest
  // (and soft pairs beyond the accumulation's four channels) stay in the
  // hard bit mask.
  Internals& impl = *this->Impl;
  std::vector<vsh_planar_pair> hard, soft;
  for (const vsh_planar_pair& pair : pairs)
  {
    const bool sized = this->SoftSamples > 1 && frame.Shared.Lights[pair.light].Size > 0.0;
    if (sized && static_cast<int>(soft.size()) < MaxSoftPairs)
    {
      soft.push_back(pair);
      continue;
    }
    if (sized && !impl.SoftWarned)
    {
      vtkWarningMacro("more than " << MaxSoftPairs
                                   << " (receiver, light) pairs with a light size: the others "
                                      "get the hard shadow of the light's centre");
      impl.SoftWarned = true;
    }
    hard.push_back(pair);
  }
  pairs.swap(hard);
  this->SetPairChannels(soft, impl.SoftPair, impl.SoftShader);
  this->NumberOfSoftPairs = static_cast<int>(soft.size());
  return soft;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::SetPairChannels(
  const std::vector<vsh_planar_pair>& pairs, int channelPair[4], bool& lookup)
{
  // Channel k holds pairs[k] (-1: no pair). The lookup is compiled into the
  // receivers' shaders only while some channel is used: a frame without
  // such pairs keeps the shader without it.
  for (int k = 0; k < 4; ++k)
  {
    channelPair[k] = k < static_cast<int>(pairs.size()) ? pairs[k].bit : -1;
  }
  if (lookup != !pairs.empty())
  {
    lookup = !pairs.empty();
    this->BumpShaderTime();
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::AttachPairChannels(vtkTextureObject*& texture, int textureSize[2],
  vtkOpenGLRenderWindow* window, const Frame& frame, float clearValue)
{
  // RGBA16F, a pair per channel: sums of k / N are exact for N a power of
  // two up to 1024 (and within 1e-3 otherwise), and so are products of
  // transmittances like 0.5 x 0.5.
  if (!texture)
  {
    texture = vtkTextureObject::New();
  }
  texture->SetContext(window);
  const int* size = frame.Shared.Size;
  if (textureSize[0] != size[0] || textureSize[1] != size[1] || !texture->GetHandle())
  {
    texture->ReleaseGraphicsResources(window);
    texture->SetInternalFormat(GL_RGBA16F);
    texture->SetFormat(GL_RGBA);
    texture->SetDataType(GL_FLOAT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->Allocate2D(size[0], size[1], 4, VTK_FLOAT);
    textureSize[0] = size[0];
    textureSize[1] = size[1];
  }
  // In place of the mask as the mask framebuffer's colour attachment.
  Internals& impl = *this->Impl;
  impl.FBO->RemoveColorAttachment(0);
  impl.FBO->AddColorAttachment(0, texture);
  impl.FBO->ActivateDrawBuffers(1);
  const GLfloat value[4] = { clearValue, clearValue, clearValue, clearValue };
  glClearBufferfv(GL_COLOR, 0, value);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawSoftPairs(vtkOpenGLRenderWindow* window, vtkOpenGLState* state,
  const Frame& frame, const std::vector<vsh_planar_pair>& softPairs)
{
  // The sampled area light: per soft pair, N hard shadows from stratified
  // points on the light, each counted once per pixel (stencil) and added
  // with weight 1/N to the pair's channel.
  Internals& impl = *this->Impl;
  this->AttachPairChannels(impl.Soft, impl.SoftSize, window, frame, 0.0f);
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkPlanarShadowMaskVS, vtkPlanarShadowSoftFS, "");
  if (!program)
  {
    return;
  }
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  // Adaptive: the batch (the light's centre and 7 rim points) first, then
  // the mark, then the rest only at the marked pixels. Otherwise the spiral
  // in order, as before.
  const bool adaptive = this->Adaptive && this->SoftSamples > VSH_SOFT_ADAPTIVE_BATCH;
  const std::vector<int>& order = this->SoftOrder(adaptive);
  const int batch = adaptive ? VSH_SOFT_ADAPTIVE_BATCH : this->SoftSamples;
  impl.SoftAdaptive = adaptive;
  impl.SoftStats.clear();
  this->NumberOfRefinedPixels = adaptive ? 0 : -1;
  for (size_t k = 0; k < softPairs.size(); ++k)
  {
    ++this->NumberOfShadowPairs;
    float weight[4] = { 0, 0, 0, 0 };
    weight[k] = 1.0f / static_cast<float>(this->SoftSamples);
    for (int j = 0; j < batch; ++j)
    {
      this->DrawSoftSample(program, state, frame, softPairs[k], order[j], weight);
    }
    if (!adaptive)
    {
      continue;
    }
    int box[4];
    const long refined = this->MarkSoftBatch(window, state, frame, static_cast<int>(k), box);
    impl.SoftStats.push_back({ softPairs[k].light, refined,
      static_cast<long>(box[2] - box[0]) * static_cast<long>(box[3] - box[1]) });
    this->NumberOfRefinedPixels += std::max(refined, 0L);
    window->GetShaderCache()->ReadyShaderProgram(program);
    if (refined > 0)
    {
      this->DrawSoftRest(program, state, frame, softPairs[k], box, weight);
    }
  }
  state->vtkglStencilMask(0xff);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_BLEND);
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CLIP_DISTANCE1);
}

//------------------------------------------------------------------------------
const std::vector<int>& vtkPlanarShadowPass::SoftOrder(bool adaptive)
{
  // The spiral's indices in drawing order: 0..N-1, or the batch of
  // vsh_soft_batch_order first (computed once per N: about 1e6 operations).
  Internals& impl = *this->Impl;
  if (impl.SoftOrderSamples != this->SoftSamples || impl.SoftOrderAdaptive != adaptive ||
    impl.SoftOrder.size() != static_cast<size_t>(this->SoftSamples))
  {
    impl.SoftOrder.resize(this->SoftSamples);
    vsh_soft_batch_order(
      this->SoftSamples, adaptive ? VSH_SOFT_ADAPTIVE_BATCH : 1, impl.SoftOrder.data());
    impl.SoftOrderSamples = this->SoftSamples;
    impl.SoftOrderAdaptive = adaptive;
  }
  return impl.SoftOrder;
}

//------------------------------------------------------------------------------
long vtkPlanarShadowPass::MarkSoftBatch(
  vtkOpenGLRenderWindow* window, vtkOpenGLState* state, const Frame& frame, int channel, int box[4])
{
  // After the batch of the pair in `channel`: read the accumulation back,
  // mark its pixels (vsh_soft_mark_pixels: refine where the 3x3
  // neighbourhood disagrees), upload the mark, and draw it: the pixels that
  // keep the batch's answer get exactly 0 or 1 and depth 0; the refined ones
  // keep their sum and depth 1 (cleared), which DrawSoftRest tests against.
  Internals& impl = *this->Impl;
  const int w = frame.Shared.Size[0], h = frame.Shared.Size[1];
  std::fill_n(box, 4, 0);
  impl.SoftReadback.resize(static_cast<size_t>(4) * w * h);
  impl.SoftMarkBytes.resize(static_cast<size_t>(w) * h);
  impl.FBO->ActivateReadBuffer(0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, impl.SoftReadback.data());
  const long refined = vsh_soft_mark_pixels(impl.SoftReadback.data() + channel, 4, w, h,
    VSH_SOFT_ADAPTIVE_BATCH, this->SoftSamples, impl.SoftMarkBytes.data(), box);
  if (!impl.SoftMark)
  {
    impl.SoftMark = vtkTextureObject::New();
  }
  impl.SoftMark->SetContext(window);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  impl.SoftMark->Create2DFromRaw(w, h, 1, VTK_UNSIGNED_CHAR, impl.SoftMarkBytes.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    vtkPlanarShadowMaskVS, vtkPlanarShadowAdaptiveFS, "");
  if (!program)
  {
    return -1;
  }
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  state->vtkglColorMask(channel == 0, channel == 1, channel == 2, channel == 3);
  glDepthRange(0.0, 0.0);
  impl.SoftMark->Activate();
  program->SetUniformi("batchMark", impl.SoftMark->GetTextureUnit());
  this->DrawViewportQuad(program);
  impl.SoftMark->Deactivate();
  glDepthRange(0.0, 1.0);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return refined;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawSoftRest(vtkShaderProgram* program, vtkOpenGLState* state,
  const Frame& frame, const vsh_planar_pair& pair, const int box[4], const float weight[4])
{
  // Samples 8..N-1 within the refined pixels' box (the scissor: clears,
  // casters and quads outside it are never rasterized) and, inside it, at
  // the refined pixels only: every draw at depth 0.5 passes where the mark
  // left 1 and fails where it wrote 0 (a failing depth test keeps the
  // stencil, so the quad adds nothing there).
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(box[0], box[1], box[2] - box[0], box[3] - box[1]);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDepthFunc(GL_LESS);
  glDepthRange(0.5, 0.5);
  const std::vector<int>& order = this->Impl->SoftOrder;
  for (int j = VSH_SOFT_ADAPTIVE_BATCH; j < this->SoftSamples; ++j)
  {
    this->DrawSoftSample(program, state, frame, pair, order[j], weight);
  }
  glDepthRange(0.0, 1.0);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawSoftSample(vtkShaderProgram* program, vtkOpenGLState* state,
  const Frame& frame, const vsh_planar_pair& pair, int sample, const float weight[4])
{
  // One light sample's hard shadow into the stencil: bit 7 where a caster
  // triangle covers the pixel, bits 0-6 the silhouette fans' winding number
  // (mod 128); then the sample's weight wherever the stencil is not zero, so
  // overlapping casters count once.
  state->vtkglStencilMask(0xff);
  glClearStencil(0);
  state->vtkglClear(GL_STENCIL_BUFFER_BIT);
  state->vtkglEnable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglStencilMask(0x80);
  state->vtkglStencilFunc(GL_ALWAYS, 0x80, 0xff);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  vtkActor* receiver = frame.Receivers[pair.receiver];
  const double* receiverPlane = &frame.Planes[4 * pair.receiver];
  const double size = frame.Shared.Lights[pair.light].Size;
  std::vector<Fan> fans;
  vsh_planar_rect fanRect;
  vsh_planar_rect_init(&fanRect);
  for (const vtkshadow::ShadowActor& caster : frame.Casters)
  {
    if ((caster.Actor == receiver && !caster.Proxy) ||
      (!receiver && LiesInPlane(caster, receiverPlane)))
    {
      continue; // as in DrawPair
    }
    vtkShadowCasterGeometry* geometry =
      caster.Proxy ? caster.Proxy : this->CasterGeometry(caster.Actor);
    // The light's disk faces the caster's centre (docs/soft-shadows.md: the
    // direction of its shadow's centre too); a directional light ignores it.
    double centre[3];
    for (int i = 0; i < 3; ++i)
    {
      centre[i] = 0.5 * (caster.Bounds[2 * i] + caster.Bounds[2 * i + 1]);
    }
    vsh_planar_light light;
    light.casts = 1;
    vsh_planar_pair samplePair;
    if (geometry->GetNumberOfTriangles() == 0 ||
      vsh_soft_sample_light(frame.Lights[pair.light].homogeneous, size, centre, sample,
        this->SoftSamples, 0.0, light.homogeneous) != 0 ||
      vsh_planar_plan_pairs(receiverPlane, 1, &light, 1, frame.Shared.Eye, &samplePair, 1) != 1)
    {
      continue; // no triangles, a caster centred on the light, or no shadow from this sample
    }
    double shadowDC[16];
    vsh_mat4_multiply(frame.Shared.CameraRelative, samplePair.shadow, shadowDC);
    this->DrawCaster(
      program, frame, samplePair, light.homogeneous, shadowDC, caster, *geometry, &fans, &fanRect);
  }
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CLIP_DISTANCE1);
  const float keepAll[4] = { 0, 0, 0, 1 };
  program->SetUniform4f("receiverSideMC", keepAll);
  program->SetUniform4f("belowLightMC", keepAll);
  state->vtkglStencilMask(0x7f);
  state->vtkglStencilFunc(GL_ALWAYS, 0, 0xff);
  state->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  state->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  this->DrawFans(program, fans);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglEnable(GL_BLEND);
  state->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xff);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  float w[4];
  std::copy_n(weight, 4, w);
  program->SetUniform4f("sampleWeight", w);
  this->DrawViewportQuad(program);
}
