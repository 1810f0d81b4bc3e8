#include "vtkShadowDepthSeed.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkShadowDepthSeedFS.h"
#include "vtkShadowScreenQuadVS.h"

#include "vsh_depth_seed.h"

//------------------------------------------------------------------------------
void vtkShadowDepthSeed::BeginOpaque(vtkOpenGLRenderWindow* window, vtkTextureObject* depth)
{
  this->Seeded = false;
  this->Counting = false;
  this->CollectMeasurement();
  int viewport[4];
  if (!window || !this->Usable(depth, viewport))
  {
    return;
  }
  if (this->Always)
  {
    this->Seeded = this->Draw(window, depth, viewport);
    return;
  }
  if (this->Next == Phase::Decided && this->FramesDecided >= VSH_DEPTH_SEED_MEASURE_EVERY)
  {
    this->Next = Phase::MeasureUnseeded;
  }
  const Phase phase = this->Next;
  const bool measuring = phase != Phase::Decided;
  const bool seed = measuring ? phase == Phase::MeasureSeeded : this->Pays;
  if (!measuring)
  {
    ++this->FramesDecided;
  }
  this->Seeded = seed && this->Draw(window, depth, viewport);
  if (!measuring || this->Seeded != seed)
  {
    return; // a measuring frame counts only as what its phase asks for
  }
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  if (this->Query)
  {
    this->Counting = true;
    this->Pixels = static_cast<double>(viewport[2]) * viewport[3];
    this->PendingPhase = phase;
    glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  }
}

//------------------------------------------------------------------------------
void vtkShadowDepthSeed::EndOpaque()
{
  if (!this->Counting)
  {
    return;
  }
  glEndQuery(GL_SAMPLES_PASSED);
  this->Counting = false;
  this->Pending = true;
  this->Next = this->PendingPhase == Phase::MeasureUnseeded ? Phase::MeasureSeeded : Phase::Decided;
}

//------------------------------------------------------------------------------
// The count of the last measuring frame, read a frame later (the GPU is
// done with it by then): the unseeded one is kept, the seeded one decides.
void vtkShadowDepthSeed::CollectMeasurement()
{
  if (!this->Pending)
  {
    return;
  }
  this->Pending = false;
  GLuint fragments = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &fragments);
  if (this->PendingPhase == Phase::MeasureUnseeded)
  {
    this->UnseededFragments = fragments;
    return;
  }
  const double seeded = fragments;
  this->Pays = vsh_depth_seed_pays(this->UnseededFragments, seeded, this->Pixels) != 0;
  this->HiddenPerPixel = (this->UnseededFragments - seeded) / this->Pixels;
  this->FramesDecided = 0;
}

//------------------------------------------------------------------------------
bool vtkShadowDepthSeed::Usable(vtkTextureObject* depth, int viewport[4]) const
{
  if (!depth || !depth->GetHandle())
  {
    return false;
  }
  // A caller drawing the scene through a stencil test limits the lit draw
  // to some pixels; the seed would write depth at all of them.
  if (glIsEnabled(GL_STENCIL_TEST))
  {
    return false;
  }
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  glGetIntegerv(GL_VIEWPORT, viewport);
  return samples <= 1 && viewport[2] == static_cast<int>(depth->GetWidth()) &&
    viewport[3] == static_cast<int>(depth->GetHeight());
}

//------------------------------------------------------------------------------
bool vtkShadowDepthSeed::Draw(
  vtkOpenGLRenderWindow* window, vtkTextureObject* depth, const int viewport[4])
{
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkShadowScreenQuadVS, vtkShadowDepthSeedFS, "");
  if (!program)
  {
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  depth->Activate();
  program->SetUniformi("seedDepth", depth->GetTextureUnit());
  const int origin[2] = { viewport[0], viewport[1] };
  program->SetUniform2i("seedOrigin", origin);
  this->Quad.Draw(program);
  depth->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowDepthSeed::ReleaseGraphicsResources()
{
  this->Quad.ReleaseGraphicsResources();
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  // A new context measures again.
  this->Counting = false;
  this->Pending = false;
  this->Next = Phase::MeasureUnseeded;
  this->Pays = false;
  this->FramesDecided = 0;
  this->HiddenPerPixel = -1.0;
}
