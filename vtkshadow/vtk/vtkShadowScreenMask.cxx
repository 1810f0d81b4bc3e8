#include "vtkShadowScreenMask.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLightsPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowClipSpaceQuad.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowPassBase.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtk_glew.h"

#include "vsh_soft_adaptive.h"

#include "vtkShadowScreenBatchFS.h"
#include "vtkShadowScreenLightFS.h"
#include "vtkShadowScreenQuadFS.h"
#include "vtkShadowScreenQuadVS.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace
{
constexpr int LayerCount = 2;

// The translucent layer's depth: translucent geometry drawn with depth
// writes (VTK turns them off for translucent actors; GLDepthMaskOverride
// turns them back on), so the depth holds the nearest surface of all.
// Each actor's property keys are given back as they were.
class TranslucentDepthPass : public vtkTranslucentPass
{
public:
  static TranslucentDepthPass* New();
  vtkTypeMacro(TranslucentDepthPass, vtkTranslucentPass);
  void Render(const vtkRenderState* s) override
  {
    std::vector<std::pair<vtkActor*, int>> restore; // -1: the key was absent
    for (int i = 0; i < s->GetPropArrayCount(); ++i)
    {
      vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
      if (!actor || !actor->HasTranslucentPolygonalGeometry())
      {
        continue;
      }
      vtkInformation* keys = actor->GetPropertyKeys();
      if (!keys)
      {
        vtkNew<vtkInformation> fresh;
        actor->SetPropertyKeys(fresh);
        keys = fresh;
      }
      vtkInformationIntegerKey* key = vtkOpenGLActor::GLDepthMaskOverride();
      restore.emplace_back(actor, keys->Has(key) ? keys->Get(key) : -1);
      keys->Set(vtkOpenGLActor::GLDepthMaskOverride(), 1);
    }
    this->Superclass::Render(s);
    for (const auto& r : restore)
    {
      vtkInformation* keys = r.first->GetPropertyKeys();
      if (r.second < 0)
      {
        keys->Remove(vtkOpenGLActor::GLDepthMaskOverride());
      }
      else
      {
        keys->Set(vtkOpenGLActor::GLDepthMaskOverride(), r.second);
      }
    }
  }

protected:
  TranslucentDepthPass() = default;
  ~TranslucentDepthPass() override = default;
};
vtkStandardNewMacro(TranslucentDepthPass);

int LayerOf(int light)
{
  return light / 4;
}
}

struct vtkShadowScreenMask::Internals
{
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FBO;
  vtkSmartPointer<vtkTextureObject> DepthStencil;
  vtkSmartPointer<vtkTextureObject> Layers[LayerCount];
  // The opaque scene, lights first so the mappers build the same shader
  // variant as in the main pass.
  vtkSmartPointer<vtkSequencePass> DepthScene;
  vtkShadowClipSpaceQuad Quad;
  // CPU copies for UploadLight: RGBA8 per layer, and which layers changed.
  std::vector<unsigned char> Staged[LayerCount];
  bool Dirty[LayerCount] = { false, false };
  // Lights' tints (UploadTint): RGBA8, light I's rows from I x height; 1x1
  // while no light of the frame is tinted (a sampler the hooked shaders
  // name must always have a unit of its own).
  vtkSmartPointer<vtkTextureObject> Tint;
  std::vector<unsigned char> TintStaged;
  bool Tinted = false;
  bool TintDirty = false;

  // The tint texture at `width` x `height` RGBA8 (reallocated on a change).
  bool SizeTint(vtkOpenGLRenderWindow* window, int width, int height)
  {
    this->Tint->SetContext(window);
    if (this->Tint->GetWidth() == static_cast<unsigned int>(width) &&
      this->Tint->GetHeight() == static_cast<unsigned int>(height) && this->Tint->GetHandle())
    {
      return true;
    }
    this->Tint->ReleaseGraphicsResources(window);
    this->Tint->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Tint->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Tint->SetInternalFormat(GL_RGBA8);
    this->Tint->SetFormat(GL_RGBA);
    this->Tint->SetDataType(GL_UNSIGNED_BYTE);
    const std::vector<unsigned char> white(4 * static_cast<size_t>(width) * height, 255);
    return this->Tint->Create2DFromRaw(
      width, height, 4, VTK_UNSIGNED_CHAR, const_cast<unsigned char*>(white.data()));
  }
  bool Drawing = false;
  int SavedViewport[4] = { 0, 0, 0, 0 };
  int SavedScissor[4] = { 0, 0, 0, 0 };
};

//------------------------------------------------------------------------------
vtkShadowScreenMask::vtkShadowScreenMask()
  : Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkShadowScreenMask::~vtkShadowScreenMask()
{
  delete this->Impl;
}

//------------------------------------------------------------------------------
long long vtkShadowScreenMask::GetMemoryBytes() const
{
  if (!this->Impl->FBO)
  {
    return 0;
  }
  const long long pixels = static_cast<long long>(this->Size[0]) * this->Size[1];
  // Depth-stencil (4 bytes) plus 4 bytes per layer in use, and a tinted
  // frame's 4 bytes per pixel and light.
  vtkTextureObject* tint = this->Impl->Tint;
  return pixels * 4 * (1 + (this->LightCount > 4 ? 2 : 1)) +
    4LL * tint->GetWidth() * tint->GetHeight();
}

//------------------------------------------------------------------------------
bool vtkShadowScreenMask::Allocate(vtkOpenGLRenderWindow* window)
{
  Internals& impl = *this->Impl;
  if (impl.Window != window && impl.Window)
  {
    this->ReleaseGraphicsResources(impl.Window);
  }
  impl.Window = window;
  if (!impl.FBO)
  {
    impl.FBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    impl.DepthStencil = vtkSmartPointer<vtkTextureObject>::New();
    for (auto& layer : impl.Layers)
    {
      layer = vtkSmartPointer<vtkTextureObject>::New();
    }
    impl.Tint = vtkSmartPointer<vtkTextureObject>::New();
  }
  if (!impl.Tint->GetHandle() && !impl.SizeTint(window, 1, 1))
  {
    this->Error = "cannot allocate the tint texture";
    return false;
  }
  impl.FBO->SetContext(window);
  impl.DepthStencil->SetContext(window);
  const int w = this->Size[0], h = this->Size[1];
  if (impl.DepthStencil->GetWidth() != static_cast<unsigned int>(w) ||
    impl.DepthStencil->GetHeight() != static_cast<unsigned int>(h) ||
    !impl.DepthStencil->GetHandle())
  {
    impl.DepthStencil->ReleaseGraphicsResources(window);
    impl.DepthStencil->SetMinificationFilter(vtkTextureObject::Nearest);
    impl.DepthStencil->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!impl.DepthStencil->AllocateDepthStencil(w, h))
    {
      this->Error = "cannot allocate a " + std::to_string(w) + "x" + std::to_string(h) +
        " depth-stencil texture";
      return false;
    }
  }
  for (auto& layer : impl.Layers)
  {
    layer->SetContext(window);
    if (layer->GetWidth() != static_cast<unsigned int>(w) ||
      layer->GetHeight() != static_cast<unsigned int>(h) || !layer->GetHandle())
    {
      layer->ReleaseGraphicsResources(window);
      layer->SetMinificationFilter(vtkTextureObject::Nearest);
      layer->SetMagnificationFilter(vtkTextureObject::Nearest);
      layer->SetInternalFormat(GL_RGBA8);
      layer->SetFormat(GL_RGBA);
      layer->SetDataType(GL_UNSIGNED_BYTE);
      if (!layer->Allocate2D(w, h, 4, VTK_UNSIGNED_CHAR))
      {
        this->Error = "cannot allocate a " + std::to_string(w) + "x" + std::to_string(h) +
          " visibility texture";
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowScreenMask::RenderDepth(const vtkRenderState* s, int lightCount)
{
  this->Error.clear();
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    this->Error = "the screen-space mask needs an OpenGL render window";
    return false;
  }
  vtkShadowPassBase::GetViewport(s, this->Size, this->Origin);
  this->Size[0] = std::max(this->Size[0], 1);
  this->Size[1] = std::max(this->Size[1], 1);
  this->LightCount = std::max(0, std::min(lightCount, MaxLights));
  if (!this->Allocate(window))
  {
    return false;
  }
  Internals& impl = *this->Impl;
  if (!impl.DepthScene)
  {
    vtkNew<vtkRenderPassCollection> passes;
    vtkNew<vtkLightsPass> lights;
    vtkNew<vtkOpaquePass> opaque;
    passes->AddItem(lights);
    passes->AddItem(opaque);
    if (this->TranslucentSurfaces)
    {
      vtkNew<TranslucentDepthPass> translucent;
      passes->AddItem(translucent);
    }
    impl.DepthScene = vtkSmartPointer<vtkSequencePass>::New();
    impl.DepthScene->SetPasses(passes);
  }
  vtkOpenGLState* state = window->GetState();
  this->BeginDraw(0);
  if (!this->Error.empty())
  {
    this->EndDraw();
    return false;
  }
  {
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglStencilMask(0xff);
    glClearStencil(0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglEnable(GL_DEPTH_TEST);
    // Depth only, no colour attachment: an owner whose shader hooks are
    // registered during this pass (so the mappers build the same shaders as
    // in the main pass and do not rebuild twice a frame) may then sample the
    // visibility textures without a feedback loop. They are bound to units
    // of their own here too: a hooked shader's mask samplers must never
    // share a unit with a mapper's samplerBuffer (cell normals, cell
    // colours), or the draw fails (GL_INVALID_OPERATION) and the caster is
    // missing from the depth every technique counts against.
    impl.FBO->RemoveColorAttachment(0);
    impl.FBO->DeactivateDrawBuffers();
    this->Activate();
    impl.DepthScene->Render(s);
    this->Deactivate();
  }
  // Every light lit until a technique says otherwise: the textures, and the
  // CPU copies UploadLight() writes into (a light not uploaded this frame
  // must not bring back last frame's channel with another light's upload).
  for (int layer = 0; layer < LayerCount; ++layer)
  {
    std::fill(impl.Staged[layer].begin(), impl.Staged[layer].end(), 255);
    impl.Dirty[layer] = false;
    impl.FBO->AddColorAttachment(0, impl.Layers[layer]);
    impl.FBO->ActivateDrawBuffers(1);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLfloat one[4] = { 1, 1, 1, 1 };
    glClearBufferfv(GL_COLOR, 0, one);
  }
  this->EndDraw();
  // No light tinted until a technique uploads a tint this frame.
  impl.Tinted = false;
  impl.TintDirty = false;
  return this->Error.empty();
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::BeginDraw(int light, bool depthAttached)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = impl.Window->GetState();
  state->PushFramebufferBindings();
  impl.FBO->Bind();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
    depthAttached ? impl.DepthStencil->GetHandle() : 0, 0);
  const int layer = std::max(0, std::min(LayerOf(light), LayerCount - 1));
  impl.FBO->AddColorAttachment(0, impl.Layers[layer]);
  impl.FBO->ActivateDrawBuffers(1);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
  {
    this->Error = "the screen-space mask's framebuffer is incomplete";
  }
  state->vtkglGetIntegerv(GL_VIEWPORT, impl.SavedViewport);
  state->vtkglGetIntegerv(GL_SCISSOR_BOX, impl.SavedScissor);
  state->vtkglViewport(0, 0, this->Size[0], this->Size[1]);
  state->vtkglScissor(0, 0, this->Size[0], this->Size[1]);
  impl.Drawing = true;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::EndDraw()
{
  Internals& impl = *this->Impl;
  if (!impl.Drawing)
  {
    return;
  }
  vtkOpenGLState* state = impl.Window->GetState();
  state->vtkglScissor(
    impl.SavedScissor[0], impl.SavedScissor[1], impl.SavedScissor[2], impl.SavedScissor[3]);
  state->vtkglViewport(
    impl.SavedViewport[0], impl.SavedViewport[1], impl.SavedViewport[2], impl.SavedViewport[3]);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  impl.FBO->RemoveColorAttachment(0);
  state->PopFramebufferBindings();
  impl.Drawing = false;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::DrawFullScreen(vtkShaderProgram* program)
{
  this->Impl->Quad.Draw(program);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowScreenMask::GetDepthTexture() const
{
  return this->Impl->FBO ? this->Impl->DepthStencil.GetPointer() : nullptr;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::ResolveStencil(int light)
{
  this->DrawChannel(light, 0.0f, Where::StencilSet, false);
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::FillLight(int light, float value)
{
  this->DrawChannel(light, value, Where::Everywhere, false);
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::AccumulateStencil(int light, int levels, int ref)
{
  // levels / 255 converts back to exactly `levels` steps of the 8-bit
  // channel, so the blend adds integers.
  this->DrawChannel(light, static_cast<float>(levels) / 255.0f, Where::StencilZero, true, ref);
}

//------------------------------------------------------------------------------
int vtkShadowScreenMask::MultiplyStencilCount(int light, float transmit, int maxSteps)
{
  Internals& impl = *this->Impl;
  if (!impl.Drawing || light < 0 || light >= this->LightCount)
  {
    return 0;
  }
  GLuint query = 0;
  glGenQueries(1, &query);
  int steps = 0;
  for (GLuint passed = 1; passed && steps < maxSteps; ++steps)
  {
    // Waits for the step: a count is a handful of steps (2 under a closed
    // convex caster), drawn only for translucent casters.
    glBeginQuery(GL_ANY_SAMPLES_PASSED, query);
    this->DrawChannel(light, transmit, Where::StencilCount, false);
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &passed);
  }
  glDeleteQueries(1, &query);
  return steps;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::MarkBatch(int light, int batchLevels, bool refine, int ref)
{
  Internals& impl = *this->Impl;
  if (!impl.Drawing || light < 0 || light >= this->LightCount)
  {
    return;
  }
  vtkOpenGLState* state = impl.Window->GetState();
  vtkShaderProgram* program = impl.Window->GetShaderCache()->ReadyShaderProgram(
    vtkShadowScreenQuadVS, vtkShadowScreenBatchFS, "");
  if (!program)
  {
    this->Error = "the screen-space mask's batch shader did not compile";
    return;
  }
  vtkTextureObject* layer = impl.Layers[LayerOf(light)];
  // Sampled, so not attached: no feedback loop. Depth and stencil stay.
  impl.FBO->RemoveColorAttachment(0);
  impl.FBO->DeactivateDrawBuffers();
  {
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglEnable(GL_STENCIL_TEST);
    state->vtkglStencilFunc(GL_ALWAYS, ref, 0xff);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    state->vtkglStencilMask(static_cast<GLuint>(ref));
    layer->Activate();
    program->SetUniformi("mask", layer->GetTextureUnit());
    program->SetUniformi("channel", light % 4);
    program->SetUniformi("batchLevels", batchLevels);
    program->SetUniformi("refine", refine ? 1 : 0);
    this->DrawFullScreen(program);
    layer->Deactivate();
    state->vtkglStencilMask(0xff);
  }
  impl.FBO->AddColorAttachment(0, layer);
  impl.FBO->ActivateDrawBuffers(1);
}

//------------------------------------------------------------------------------
int vtkShadowScreenMask::AccumulationLevels(int sample, int samples)
{
  if (samples < 1 || sample < 0 || sample >= samples)
  {
    return 0;
  }
  // floor(255 (i + 1) / N) - floor(255 i / N): each floor(255/N) or one
  // more, summing to 255 over i = 0..N-1.
  return vsh_soft_levels(sample, samples);
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::DrawChannel(
  int light, float value, Where where, bool add, int ref, vtkShaderProgram* program)
{
  Internals& impl = *this->Impl;
  if (!impl.Drawing || light < 0 || light >= this->LightCount)
  {
    return;
  }
  vtkOpenGLState* state = impl.Window->GetState();
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  const int channel = light % 4;
  state->vtkglColorMask(channel == 0, channel == 1, channel == 2, channel == 3);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  if (add || where == Where::StencilCount || program)
  {
    // Added, or multiplied (dst * src) for a count or a caller's program.
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_FUNC_ADD);
    state->vtkglBlendFunc(add ? GL_ONE : GL_ZERO, add ? GL_ONE : GL_SRC_COLOR);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }
  if (where == Where::Everywhere)
  {
    state->vtkglDisable(GL_STENCIL_TEST);
  }
  else if (where == Where::StencilCount)
  {
    state->vtkglEnable(GL_STENCIL_TEST);
    state->vtkglStencilMask(0xff);
    state->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xff);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
  }
  else
  {
    state->vtkglEnable(GL_STENCIL_TEST);
    // Through vtkOpenGLState: VTK caches the stencil state, and a raw call
    // here leaves the cache believing the counting pass's func and ops are
    // still set, so the next frame's counting (set through the cache) would
    // be skipped and count nothing.
    state->vtkglStencilFunc(where == Where::StencilSet ? GL_NOTEQUAL : GL_EQUAL, ref, 0xff);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  }
  if (program)
  {
    this->DrawFullScreen(program);
    return;
  }
  program = impl.Window->GetShaderCache()->ReadyShaderProgram(
    vtkShadowScreenQuadVS, vtkShadowScreenQuadFS, "");
  if (!program)
  {
    this->Error = "the screen-space mask's quad shader did not compile";
    return;
  }
  const float values[4] = { value, value, value, value };
  program->SetUniform4f("value", values);
  this->DrawFullScreen(program);
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::MultiplyLight(int light, vtkShaderProgram* program)
{
  this->DrawChannel(light, 1.0f, Where::Everywhere, false, 0, program);
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::ReadDepth(std::vector<float>& depth)
{
  Internals& impl = *this->Impl;
  depth.assign(static_cast<size_t>(this->Size[0]) * this->Size[1], 1.0f);
  if (!impl.FBO)
  {
    return;
  }
  this->BeginDraw(0);
  glReadBuffer(GL_NONE);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, this->Size[0], this->Size[1], GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  this->EndDraw();
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::UploadLight(int light, const float* visibility)
{
  if (light < 0 || light >= this->LightCount || !visibility)
  {
    return;
  }
  Internals& impl = *this->Impl;
  const int layer = LayerOf(light);
  const size_t pixels = static_cast<size_t>(this->Size[0]) * this->Size[1];
  std::vector<unsigned char>& staged = impl.Staged[layer];
  if (staged.size() != 4 * pixels)
  {
    staged.assign(4 * pixels, 255);
  }
  const int channel = light % 4;
  for (size_t p = 0; p < pixels; ++p)
  {
    const float v = std::min(1.0f, std::max(0.0f, visibility[p]));
    staged[4 * p + channel] = static_cast<unsigned char>(std::lround(v * 255.0f));
  }
  impl.Dirty[layer] = true;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::UploadTint(int light, const float* tint)
{
  if (light < 0 || light >= this->LightCount || !tint)
  {
    return;
  }
  Internals& impl = *this->Impl;
  const size_t pixels = static_cast<size_t>(this->Size[0]) * this->Size[1];
  if (!impl.Tinted)
  {
    impl.TintStaged.assign(4 * pixels * static_cast<size_t>(this->LightCount), 255);
    impl.Tinted = true;
  }
  unsigned char* rows = impl.TintStaged.data() + 4 * pixels * static_cast<size_t>(light);
  for (size_t p = 0; p < pixels; ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      const float t = std::min(1.0f, std::max(0.0f, tint[3 * p + k]));
      rows[4 * p + k] = static_cast<unsigned char>(std::lround(t * 255.0f));
    }
  }
  impl.TintDirty = true;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::FinishUploads()
{
  Internals& impl = *this->Impl;
  if (impl.TintDirty)
  {
    if (impl.SizeTint(impl.Window, this->Size[0], this->Size[1] * this->LightCount))
    {
      impl.Tint->Bind();
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, this->Size[0], this->Size[1] * this->LightCount,
        GL_RGBA, GL_UNSIGNED_BYTE, impl.TintStaged.data());
    }
    impl.TintDirty = false;
  }
  for (int layer = 0; layer < LayerCount; ++layer)
  {
    if (!impl.Dirty[layer] || !impl.Layers[layer])
    {
      continue;
    }
    impl.Layers[layer]->Bind();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, this->Size[0], this->Size[1], GL_RGBA, GL_UNSIGNED_BYTE,
      impl.Staged[layer].data());
    impl.Dirty[layer] = false;
  }
}

//------------------------------------------------------------------------------
bool vtkShadowScreenMask::ReadBy(vtkProp* prop) const
{
  const bool translucent =
    prop && prop->HasTranslucentPolygonalGeometry() && !prop->HasOpaqueGeometry();
  return translucent == this->TranslucentSurfaces;
}

//------------------------------------------------------------------------------
bool vtkShadowScreenMask::HasTranslucentProps(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (prop->GetVisibility() && prop->HasTranslucentPolygonalGeometry())
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkShadowScreenMask::PreReplaceShaderValues(std::string& fragmentShader, vtkProp* prop)
{
  // Translucent surfaces are not in the opaque depth pass: that mask
  // describes whatever opaque surface lies behind them, so they read the
  // translucent layer's mask (or keep VTK's shader where there is none).
  if (!this->ReadBy(prop))
  {
    return true;
  }
  if (fragmentShader.find("//VTK::Light::Dec") != std::string::npos)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec",
      std::string("//VTK::Light::Dec\n") + vtkShadowScreenLightFS, false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowScreenMask::PostReplaceShaderValues(std::string& fragmentShader, double residual,
  const std::string& factor, const std::string& prepare)
{
  if (fragmentShader.find("vshScreenPrepare") == std::string::npos)
  {
    return true;
  }
  if (vtkshadow::InjectLightFactors(fragmentShader, factor, prepare, MaxLights, residual))
  {
    ++this->HookedShaders;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::SetShaderParameters(vtkShaderProgram* program)
{
  Internals& impl = *this->Impl;
  // Outside Activate()/Deactivate() the textures have no unit:
  // glUniform1i(sampler, -1) is GL_INVALID_VALUE. Every draw with the
  // owner's hooks registered (the depth pre-pass, the main pass) happens
  // between them, so the samplers always name a unit of their own.
  if (!program->IsUniformUsed("vshScreenMask0") || !impl.FBO ||
    impl.Layers[0]->GetTextureUnit() < 0 ||
    impl.Layers[this->LightCount > 4 ? 1 : 0]->GetTextureUnit() < 0)
  {
    return;
  }
  program->SetUniformi("vshScreenMask0", impl.Layers[0]->GetTextureUnit());
  program->SetUniformi(
    "vshScreenMask1", impl.Layers[this->LightCount > 4 ? 1 : 0]->GetTextureUnit());
  program->SetUniform2i("vshScreenMaskOrigin", this->Origin);
  program->SetUniformi("vshScreenMaskLights", this->LightCount);
  if (impl.Tint->GetTextureUnit() >= 0)
  {
    program->SetUniformi("vshScreenTint", impl.Tint->GetTextureUnit());
    program->SetUniformi("vshScreenTinted", impl.Tinted ? 1 : 0);
    program->SetUniformi("vshScreenMaskHeight", this->Size[1]);
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::Activate()
{
  Internals& impl = *this->Impl;
  if (!impl.FBO)
  {
    return;
  }
  impl.Layers[0]->Activate();
  if (this->LightCount > 4)
  {
    impl.Layers[1]->Activate();
  }
  if (impl.Tint->GetHandle())
  {
    impl.Tint->Activate();
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::Deactivate()
{
  Internals& impl = *this->Impl;
  if (!impl.FBO)
  {
    return;
  }
  impl.Layers[0]->Deactivate();
  if (this->LightCount > 4)
  {
    impl.Layers[1]->Deactivate();
  }
  if (impl.Tint->GetHandle())
  {
    impl.Tint->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenMask::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  if (impl.FBO)
  {
    impl.FBO->ReleaseGraphicsResources(w);
    impl.DepthStencil->ReleaseGraphicsResources(w);
    for (auto& layer : impl.Layers)
    {
      layer->ReleaseGraphicsResources(w);
    }
    impl.Tint->ReleaseGraphicsResources(w);
  }
  if (impl.DepthScene)
  {
    impl.DepthScene->ReleaseGraphicsResources(w);
  }
  impl.Quad.ReleaseGraphicsResources();
  impl.Window = nullptr;
}
