#include "vtkNoShadowPass.h"

#include "vtkObjectFactory.h"
#include "vtkShadowStageProfile.h"

vtkStandardNewMacro(vtkNoShadowPass);

//------------------------------------------------------------------------------
void vtkNoShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkshadow::MarkStage("setup");
  this->RenderDelegate(s);
}

//------------------------------------------------------------------------------
void vtkNoShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
