// vtkShadowClipSpaceQuad.h - two triangles covering clip space, for the
// passes' full-viewport draws (planar's mask bit over the whole viewport,
// the screen mask's resolves).
#ifndef vtkShadowClipSpaceQuad_h
#define vtkShadowClipSpaceQuad_h

#include "vtkSmartPointer.h"

class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;

class vtkShadowClipSpaceQuad
{
public:
  vtkShadowClipSpaceQuad();
  ~vtkShadowClipSpaceQuad();

  // Draw the quad (x, y in [-1, 1], z 0) with `program`, whose vertex input
  // is `vertexMC`; the caller binds the program and sets uniforms and state.
  void Draw(vtkShaderProgram* program);
  void ReleaseGraphicsResources();

private:
  vtkShadowClipSpaceQuad(const vtkShadowClipSpaceQuad&) = delete;
  void operator=(const vtkShadowClipSpaceQuad&) = delete;

  vtkSmartPointer<vtkOpenGLBufferObject> Corners;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* Program = nullptr; // the program the VAO's attribute is bound for
};

#endif
