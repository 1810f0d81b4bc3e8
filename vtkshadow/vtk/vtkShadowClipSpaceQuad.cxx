#include "vtkShadowClipSpaceQuad.h"

#include <vector>

//------------------------------------------------------------------------------
void vtkShadowClipSpaceQuad::Draw(vtkShaderProgram* program)
{
  if (!program)
  {
    return;
  }
  if (!this->Uploaded)
  {
    this->Rect.Upload(std::vector<float>{ -1, -1, 1, 1 });
    this->Uploaded = true;
  }
  this->Rect.Draw(program, 0, 1);
}

//------------------------------------------------------------------------------
void vtkShadowClipSpaceQuad::ReleaseGraphicsResources()
{
  this->Rect.ReleaseGraphicsResources();
  this->Uploaded = false;
}
