#include "vtkShadowClipSpaceQuad.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <vector>

//------------------------------------------------------------------------------
vtkShadowClipSpaceQuad::vtkShadowClipSpaceQuad() = default;

//------------------------------------------------------------------------------
vtkShadowClipSpaceQuad::~vtkShadowClipSpaceQuad() = default;

//------------------------------------------------------------------------------
void vtkShadowClipSpaceQuad::Draw(vtkShaderProgram* program)
{
  if (!program)
  {
    return;
  }
  if (!this->Corners)
  {
    const std::vector<float> corners = { -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1,
      0 };
    this->Corners = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Corners->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->Corners->Upload(corners, vtkOpenGLBufferObject::ArrayBuffer);
    this->VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->Program = nullptr;
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
  glDrawArrays(GL_TRIANGLES, 0, 6);
  this->VAO->Release();
}

//------------------------------------------------------------------------------
void vtkShadowClipSpaceQuad::ReleaseGraphicsResources()
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
