#include "vtkNoShadowPass.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkShadowStageProfile.h"

vtkStandardNewMacro(vtkNoShadowPass);

//------------------------------------------------------------------------------
void vtkNoShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkshadow::MarkStage("setup");
  // The lights as every technique places them (the key light follows the
  // camera whatever LightFollowCamera says): the frame updates them.
  this->BeginFrame(s, false);
  this->RenderDelegate(s);
}

//------------------------------------------------------------------------------
void vtkNoShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
