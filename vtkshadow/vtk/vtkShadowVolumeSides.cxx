#include "vtkShadowVolumeSides.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include "vtkShadowVolumeSidesFS.h"
#include "vtkShadowVolumeVS.h"

#include <cmath>

//------------------------------------------------------------------------------
void vtkShadowVolumeSides::Ready(
  vtkOpenGLRenderWindow* window, vtkShaderProgram* biased, bool enabled)
{
  this->Sides = nullptr;
  if (!enabled || !window || !biased || !GLEW_EXT_polygon_offset_clamp || !glPolygonOffsetClampEXT)
  {
    return;
  }
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  vtkShaderProgram* sides =
    cache->ReadyShaderProgram(vtkShadowVolumeVS, vtkShadowVolumeSidesFS, "");
  const bool sameLocation = sides &&
    glGetAttribLocation(static_cast<GLuint>(sides->GetHandle()), "vertexMC") ==
      glGetAttribLocation(static_cast<GLuint>(biased->GetHandle()), "vertexMC");
  cache->ReadyShaderProgram(biased);
  this->Sides = sameLocation ? sides : nullptr;
}

//------------------------------------------------------------------------------
void vtkShadowVolumeSides::Draw(vtkOpenGLRenderWindow* window, const float volumeMCDC[16],
  int first, int count, double depthBias, double slopeBias, bool leavingOnly)
{
  vtkOpenGLState* state = window->GetState();
  window->GetShaderCache()->ReadyShaderProgram(this->Sides);
  this->Sides->SetUniformMatrix4x4("volumeMCDC", const_cast<float*>(volumeMCDC));
  // GL's offset is factor x max(|dz/dx|, |dz/dy|) + units x r, r the depth
  // buffer's resolvable step (2^-24 at 24 bits), the whole clamped: a clamp
  // of depthBias x 2^-24 + 2^-12 caps the slope's part at 2^-12, as the
  // biased shader does.
  const float units = static_cast<float>(depthBias);
  const float factor = static_cast<float>(slopeBias);
  const float clamp = static_cast<float>(depthBias * std::ldexp(1.0, -24) + std::ldexp(1.0, -12));
  glEnable(GL_POLYGON_OFFSET_FILL);
  state->vtkglEnable(GL_CULL_FACE);
  if (!leavingOnly)
  {
    state->vtkglCullFace(GL_BACK);
    glPolygonOffsetClampEXT(factor, units, clamp);
    glDrawArrays(GL_TRIANGLES, first, count);
  }
  state->vtkglCullFace(GL_FRONT);
  glPolygonOffsetClampEXT(-factor, -units, -clamp);
  glDrawArrays(GL_TRIANGLES, first, count);
  state->vtkglCullFace(GL_BACK);
  state->vtkglDisable(GL_CULL_FACE);
  glPolygonOffsetClampEXT(0.0f, 0.0f, 0.0f);
  glDisable(GL_POLYGON_OFFSET_FILL);
}
