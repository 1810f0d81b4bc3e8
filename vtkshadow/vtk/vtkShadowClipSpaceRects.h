// vtkShadowClipSpaceRects.h - a list of axis-aligned rectangles given in
// clip space, two triangles each, drawn in ranges: the screen tiles a
// resolve draws with one shader per kind of tile.
#ifndef vtkShadowClipSpaceRects_h
#define vtkShadowClipSpaceRects_h

#include "vtkSmartPointer.h"

#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;

class vtkShadowClipSpaceRects
{
public:
  vtkShadowClipSpaceRects();
  ~vtkShadowClipSpaceRects();

  // Replace the list: `rects` holds x0, y0, x1, y1 (clip space) per rectangle.
  void Upload(const std::vector<float>& rects);
  // Draw rectangles first..first+count-1 with `program`, whose vertex
  // input is `vertexMC` (z 0); the caller binds the program and sets state.
  void Draw(vtkShaderProgram* program, int first, int count);
  void ReleaseGraphicsResources();

private:
  vtkShadowClipSpaceRects(const vtkShadowClipSpaceRects&) = delete;
  void operator=(const vtkShadowClipSpaceRects&) = delete;

  vtkSmartPointer<vtkOpenGLBufferObject> Corners;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* Program = nullptr; // the program the VAO's attribute is bound for
  std::vector<float> Vertices;
};

#endif
