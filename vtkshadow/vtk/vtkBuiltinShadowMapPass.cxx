#include "vtkBuiltinShadowMapPass.h"

#include "vtkCameraPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"

#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkBuiltinShadowMapPass);

//------------------------------------------------------------------------------
vtkBuiltinShadowMapPass::vtkBuiltinShadowMapPass()
  : Shadows(vtkShadowMapPass::New())
  , MapResolution(2048)
  , ShadowingLights(0)
{
  this->Shadows->GetShadowMapBakerPass()->SetResolution(this->MapResolution);
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(this->Shadows->GetShadowMapBakerPass());
  passes->AddItem(this->Shadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  vtkNew<vtkCameraPass> camera;
  camera->SetDelegatePass(sequence);
  this->SetDelegatePass(camera);
}

//------------------------------------------------------------------------------
vtkBuiltinShadowMapPass::~vtkBuiltinShadowMapPass()
{
  this->Shadows->Delete();
}

//------------------------------------------------------------------------------
void vtkBuiltinShadowMapPass::SetMapResolution(int resolution)
{
  this->MapResolution = resolution;
  this->Shadows->GetShadowMapBakerPass()->SetResolution(static_cast<unsigned int>(resolution));
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkBuiltinShadowMapPass::SetOption(const char* key, double value)
{
  if (key && std::strcmp(key, "map_resolution") == 0)
  {
    if (!(value >= 16 && value <= 16384 && value == std::floor(value)))
    {
      return false;
    }
    this->SetMapResolution(static_cast<int>(value));
    return true;
  }
  return this->Superclass::SetOption(key, value);
}

//------------------------------------------------------------------------------
void vtkBuiltinShadowMapPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  // The lights VTK's baker gives a map: switched on, not the headlight, and
  // directional or a spot (VTK's pass skips point lights).
  this->ShadowingLights = 0;
  vtkLightCollection* collection = s->GetRenderer()->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* l = collection->GetNextLight(it))
  {
    const bool casts =
      !l->LightTypeIsHeadlight() && (!l->GetPositional() || l->GetConeAngle() < 90.0);
    this->ShadowingLights += (l->GetSwitch() && casts) ? 1 : 0;
  }
  this->RenderDelegate(s);
}

//------------------------------------------------------------------------------
long long vtkBuiltinShadowMapPass::GetMemoryBytes() const
{
  const long long texels = static_cast<long long>(this->MapResolution) * this->MapResolution;
  return this->ShadowingLights > 0 ? (this->ShadowingLights + 1) * texels * 4 : 0;
}

//------------------------------------------------------------------------------
void vtkBuiltinShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MapResolution: " << this->MapResolution << "\n";
}
