// vtkCascadedShadowMapTranslucent.cxx - translucent casters of
// vtkCascadedShadowMapPass (docs/translucency.md): a surface of opacity a
// lets (1 - a) of the light through at each crossing, and crossings
// multiply. Beside the depth atlas, in its layout, two more atlases hold per
// texel of every map:
//  - the transmittance: the product of (1 - opacity) over the translucent
//    surfaces in front of the opaque map, drawn with multiplicative
//    blending into a texture cleared to 1, depth-tested against the opaque
//    map without writing it, culling off (both crossings of a closed mesh
//    count);
//  - the nearest translucent depth, drawn as a depth map (same polygon
//    offset as the opaque one), so that a receiver nearer the light than
//    every translucent surface keeps its light: the lookup compares it like
//    the opaque map, with the same reference depth and bias.
// A lookup is then the opaque visibility times the transmittance where the
// receiver is behind the nearest translucent surface (vshTransmittance in
// vtkShadowMapLightFS.glsl). Both atlases exist only while the scene has a
// translucent caster: without one nothing here allocates, bakes or binds.
#include "vtkCascadedShadowMapPass.h"
#include "vtkCascadedShadowMapPassInternals.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkShadowMapDepthFS.h"
#include "vtkShadowMapDepthVS.h"
#include "vtkShadowMapTransmitFS.h"

//------------------------------------------------------------------------------
// The translucent atlases at the depth atlas's size while the frame has
// translucent casters; released when it has none or the atlas's size
// changed.
void vtkCascadedShadowMapPass::AllocateTransmit(vtkOpenGLRenderWindow* window)
{
  vtkshadow::CascadedHeldMaps& held = this->Impl->Held;
  const bool fits = held.TransmitAllocated &&
    static_cast<int>(held.Transmit->GetWidth()) == held.AtlasSize[0] &&
    static_cast<int>(held.Transmit->GetHeight()) == held.AtlasSize[1];
  if (held.TransmitAllocated && (!this->Impl->Transmit || !fits))
  {
    held.TranslucentDepth->ReleaseGraphicsResources(window);
    held.Transmit->ReleaseGraphicsResources(window);
    held.TransmitAllocated = false;
  }
  if (!this->Impl->Transmit || fits)
  {
    return;
  }
  if (!held.Transmit)
  {
    held.TranslucentDepth = vtkSmartPointer<vtkTextureObject>::New();
    held.Transmit = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkshadow::AllocateDepthAtlas(
    held.TranslucentDepth, window, held.AtlasSize[0], held.AtlasSize[1]);
  vtkTextureObject* transmit = held.Transmit;
  transmit->SetContext(window);
  transmit->ReleaseGraphicsResources(window);
  transmit->SetWrapS(vtkTextureObject::ClampToEdge);
  transmit->SetWrapT(vtkTextureObject::ClampToEdge);
  transmit->SetMinificationFilter(vtkTextureObject::Linear);
  transmit->SetMagnificationFilter(vtkTextureObject::Linear);
  // Half floats: a product of many crossings keeps its precision, where
  // 8-bit fixed point would round at every blend.
  transmit->SetInternalFormat(GL_R16F);
  transmit->Allocate2D(held.AtlasSize[0], held.AtlasSize[1], 1, VTK_FLOAT);
  transmit->Modified();
  held.TransmitAllocated = true;
  // Maps held from before have no transmittance: bake them all again (the
  // casters' key changed with the translucent casters anyway).
  held.Rendered.clear();
}

//------------------------------------------------------------------------------
// The translucent casters into the baked tiles of both translucent atlases,
// inside BakeMaps (its FBO bound with the opaque atlas as depth, its viewport,
// scissor, depth test, polygon offset and culling state).
void vtkCascadedShadowMapPass::BakeTranslucent(
  vtkOpenGLRenderWindow* window, const Frame& frame, const std::vector<int>& bake, int resolution)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLFramebufferObject* fbo = impl.Held.FBO;
  const int columns = impl.Held.TileGrid[0];
  const auto select = [&](int t)
  {
    const int x = (t % columns) * resolution, y = (t / columns) * resolution;
    state->vtkglViewport(x, y, resolution, resolution);
    state->vtkglScissor(x, y, resolution, resolution);
  };
  vtkOpenGLState::ScopedglClearColor clearColor(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkShadowMapDepthVS, vtkShadowMapTransmitFS, "");
  // Transmittance: tested against the opaque map, which it leaves as is;
  // each fragment multiplies the texel by its 1 - opacity.
  fbo->AddColorAttachment(0, impl.Held.Transmit);
  fbo->ActivateDrawBuffers(1);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  state->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_SRC_ALPHA);
  state->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  for (int t : bake)
  {
    select(t);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->DrawCasters(program, frame.Translucent, frame, this->BakeTile(t));
  }
  state->vtkglDisable(GL_BLEND);
  fbo->RemoveColorAttachment(0);
  fbo->DeactivateDrawBuffers();
  // The nearest translucent depth: a depth map of the translucent casters
  // alone (the opaque map decides where they are hidden).
  program =
    window->GetShaderCache()->ReadyShaderProgram(vtkShadowMapDepthVS, vtkShadowMapDepthFS, "");
  fbo->AddDepthAttachment(impl.Held.TranslucentDepth);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_LEQUAL);
  for (int t : bake)
  {
    select(t);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    this->DrawCasters(program, frame.Translucent, frame, this->BakeTile(t));
  }
  fbo->AddDepthAttachment(impl.Held.Atlas);
}
