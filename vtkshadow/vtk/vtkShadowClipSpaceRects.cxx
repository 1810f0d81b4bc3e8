#include "vtkShadowClipSpaceRects.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

//------------------------------------------------------------------------------
vtkShadowClipSpaceRects::vtkShadowClipSpaceRects() = default;

//------------------------------------------------------------------------------
vtkShadowClipSpaceRects::~vtkShadowClipSpaceRects() = default;

//------------------------------------------------------------------------------
void vtkShadowClipSpaceRects::Upload(const std::vector<float>& rects)
{
  this->Vertices.clear();
  for (size_t r = 0; r + 3 < rects.size(); r += 4)
  {
    const float x0 = rects[r], y0 = rects[r + 1], x1 = rects[r + 2], y1 = rects[r + 3];
    const float corners[18] = { x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y0, 0, x1, y1, 0, x0, y1, 0 };
    this->Vertices.insert(this->Vertices.end(), corners, corners + 18);
  }
  if (!this->Corners)
  {
    this->Corners = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Corners->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->Program = nullptr;
  }
  if (!this->Vertices.empty())
  {
    this->Corners->Upload(this->Vertices, vtkOpenGLBufferObject::ArrayBuffer);
    // A new buffer store: the attribute must point at it again.
    this->Program = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkShadowClipSpaceRects::Draw(vtkShaderProgram* program, int first, int count)
{
  if (!program || !this->Corners || count <= 0 ||
    6 * static_cast<size_t>(first + count) * 3 > this->Vertices.size())
  {
    return;
  }
  if (this->Program != program)
  {
    this->VAO->ShaderProgramChanged();
    this->VAO->Bind();
    this->VAO->AddAttributeArray(
      program, this->Corners, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    this->Program = program;
  }
  this->VAO->Bind();
  glDrawArrays(GL_TRIANGLES, 6 * first, 6 * count);
  this->VAO->Release();
}

//------------------------------------------------------------------------------
void vtkShadowClipSpaceRects::ReleaseGraphicsResources()
{
  if (this->VAO)
  {
    this->VAO->ReleaseGraphicsResources();
    this->Corners->ReleaseGraphicsResources();
  }
  this->Corners = nullptr;
  this->VAO = nullptr;
  this->Program = nullptr;
}
