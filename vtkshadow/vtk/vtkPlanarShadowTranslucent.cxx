// vtkPlanarShadowTranslucent.cxx - the partial shadows of translucent
// casters in vtkPlanarShadowPass (docs/translucency.md): their projected
// triangles multiplied into a transmittance channel per (receiver, light)
// pair, which the receivers' lighting multiplies into the light's mask bit.
//
// Why the product is the crossings': the pair's matrix projects a caster
// point X from the light onto the receiver plane, so a projected triangle
// covers the receiver point P exactly when the line from P to the light
// meets the triangle; the clip planes (receiver side, below the light) keep
// only the part of that line between P and the light. Every triangle is
// drawn (culling off, no fans, no stencil, no depth), each multiplying what
// is there by (1 - a): P keeps (1 - a)^k, k the number of the caster's
// triangles the segment from P to the light crosses. Triangles sharing an
// edge never both cover a pixel (the rasterizer's fill rule), so a crossing
// through an edge counts once. A closed sphere's front and back both cover
// its shadow: (1 - a)^2.
#include "vtkPlanarShadowPass.h"
#include "vtkPlanarShadowPassInternals.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"

#include "vtkPlanarShadowMaskVS.h"
#include "vtkPlanarShadowSoftFS.h"

#include <algorithm>
#include <iterator>
#include <vector>

using vtkshadow::planar::LiesInPlane;
using vtkshadow::planar::MaxTransmitPairs;

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::GatherTranslucentCasters(Frame& frame)
{
  // The renderer's translucent actors that cast (as the opaque casters:
  // not NO_CAST, drawn as surfaces). Opacity 0 lets all the light through:
  // such an actor draws nothing.
  for (const vtkshadow::ShadowActor& actor : frame.Shared.Translucent)
  {
    const double opacity = vtkshadow::CasterOpacity(actor.Actor);
    if (opacity > 0.0 && vtkshadow::CastsAsSurface(actor, NO_CAST()))
    {
      frame.Translucent.push_back(actor);
      frame.TranslucentOpacity.push_back(opacity);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::TransmitReachesView(const Frame& frame, const vsh_planar_pair& pair) const
{
  // Whether some translucent caster's projection onto the pair's plane may
  // cover a pixel (its bounds' projected rectangle, as the mask's dirty box
  // is found; nothing of a caster wholly behind the receiver or beyond the
  // light): only such pairs take one of the four channels.
  double shadowDC[16];
  vsh_mat4_multiply(frame.Shared.CameraRelative, pair.shadow, shadowDC);
  const double* receiverPlane = &frame.Planes[4 * pair.receiver];
  const bool explicitPlane = frame.Receivers[pair.receiver] == nullptr;
  vsh_planar_rect rect;
  vsh_planar_rect_init(&rect);
  for (const vtkshadow::ShadowActor& caster : frame.Translucent)
  {
    if (!(explicitPlane && LiesInPlane(caster, receiverPlane)) &&
      !vsh_planar_bounds_culled(pair.clip, caster.Bounds, frame.Shared.Eye))
    {
      vsh_planar_rect_add_bounds(&rect, shadowDC, caster.Bounds, frame.Shared.Eye);
    }
  }
  int box[4];
  return vsh_planar_rect_pixels(&rect, frame.Shared.Size, box) != 0;
}

//------------------------------------------------------------------------------
std::vector<vsh_planar_pair> vtkPlanarShadowPass::TransmitPairs(const Frame& frame,
  const std::vector<vsh_planar_pair>& pairs, const std::vector<vsh_planar_pair>& softPairs)
{
  // The pairs, hard or soft (a soft pair's transmittance is its light
  // centre's), on which a translucent caster's shadow may be seen, up to
  // the texture's four channels; none without translucent casters, so such
  // a frame draws, clears and samples nothing more.
  Internals& impl = *this->Impl;
  std::vector<vsh_planar_pair> chosen;
  for (const std::vector<vsh_planar_pair>* list : { &pairs, &softPairs })
  {
    std::copy_if(list->begin(), list->end(), std::back_inserter(chosen),
      [&](const vsh_planar_pair& pair) { return this->TransmitReachesView(frame, pair); });
  }
  if (static_cast<int>(chosen.size()) > MaxTransmitPairs)
  {
    if (!impl.TransmitWarned)
    {
      vtkWarningMacro("more than " << MaxTransmitPairs
                                   << " (receiver, light) pairs with translucent casters: the "
                                      "others get no shadow from them");
      impl.TransmitWarned = true;
    }
    chosen.resize(MaxTransmitPairs);
  }
  this->SetPairChannels(chosen, impl.TransmitPair, impl.TransmitShader);
  return chosen;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawTransmitPairs(vtkOpenGLRenderWindow* window, vtkOpenGLState* state,
  const Frame& frame, const std::vector<vsh_planar_pair>& transmitPairs)
{
  // The transmittance texture cleared to 1, then per pair (channel k) every
  // translucent caster's projected triangles, each multiplying channel k by
  // (1 - opacity): blending dst * src with src 1 in the other channels.
  Internals& impl = *this->Impl;
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  this->AttachPairChannels(impl.Transmit, impl.TransmitSize, window, frame, 1.0f);
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkPlanarShadowMaskVS, vtkPlanarShadowSoftFS, "");
  if (!program)
  {
    return;
  }
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  state->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_SRC_ALPHA);
  for (size_t k = 0; k < transmitPairs.size(); ++k)
  {
    const vsh_planar_pair& pair = transmitPairs[k];
    double shadowDC[16];
    vsh_mat4_multiply(frame.Shared.CameraRelative, pair.shadow, shadowDC);
    const double* receiverPlane = &frame.Planes[4 * pair.receiver];
    const bool explicitPlane = frame.Receivers[pair.receiver] == nullptr;
    for (size_t c = 0; c < frame.Translucent.size(); ++c)
    {
      const vtkshadow::ShadowActor& caster = frame.Translucent[c];
      vtkShadowCasterGeometry* geometry = this->CasterGeometry(caster.Actor);
      if ((explicitPlane && LiesInPlane(caster, receiverPlane)) ||
        geometry->GetNumberOfTriangles() == 0)
      {
        continue; // as in DrawPair (a translucent actor is never a receiver actor)
      }
      float factor[4] = { 1, 1, 1, 1 };
      factor[k] = static_cast<float>(1.0 - frame.TranslucentOpacity[c]);
      program->SetUniform4f("sampleWeight", factor);
      this->DrawCaster(program, frame, pair, frame.Lights[pair.light].homogeneous, shadowDC, caster,
        *geometry, nullptr, nullptr);
    }
  }
  state->vtkglDisable(GL_BLEND);
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CLIP_DISTANCE1);
}
