// vtkShadowClipSpaceQuad.h - two triangles covering clip space, for the
// passes' full-viewport draws (planar's mask bit over the whole viewport,
// the screen mask's resolves): one vtkShadowClipSpaceRects rectangle.
#ifndef vtkShadowClipSpaceQuad_h
#define vtkShadowClipSpaceQuad_h

#include "vtkShadowClipSpaceRects.h"

class vtkShaderProgram;

class vtkShadowClipSpaceQuad
{
public:
  vtkShadowClipSpaceQuad() = default;

  // Draw the quad (x, y in [-1, 1], z 0) with `program`, whose vertex input
  // is `vertexMC`; the caller binds the program and sets uniforms and state.
  void Draw(vtkShaderProgram* program);
  void ReleaseGraphicsResources();

private:
  vtkShadowClipSpaceQuad(const vtkShadowClipSpaceQuad&) = delete;
  void operator=(const vtkShadowClipSpaceQuad&) = delete;

  vtkShadowClipSpaceRects Rect;
  bool Uploaded = false; // the rectangle is on the GPU (until released)
};

#endif
