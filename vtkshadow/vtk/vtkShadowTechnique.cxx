#include "vtkShadowTechnique.h"

#include "vtkCameraPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPlanarShadowPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"

#include <cstring>

vtkStandardNewMacro(vtkShadowTechnique);

namespace
{
const char* const KnownTechniques[] = { "none", "vtk", "planar", "csm" };
}

//------------------------------------------------------------------------------
vtkShadowTechnique::vtkShadowTechnique()
  : Name(nullptr)
  , MapResolution(2048)
  , CascadedSettings(vtkCascadedShadowMapPass::New())
{
  this->SetName("none");
}

//------------------------------------------------------------------------------
vtkShadowTechnique::~vtkShadowTechnique()
{
  this->SetName(nullptr);
  this->CascadedSettings->Delete();
}

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass* vtkShadowTechnique::GetCascadedSettings()
{
  return this->CascadedSettings;
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::IsKnownTechnique(const char* name)
{
  if (!name)
  {
    return false;
  }
  for (const char* known : KnownTechniques)
  {
    if (std::strcmp(name, known) == 0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::IsValid() const
{
  return IsKnownTechnique(this->Name);
}

//------------------------------------------------------------------------------
const char* vtkShadowTechnique::GetKnownTechniques()
{
  return "none vtk planar csm";
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkShadowTechnique::CreatePass()
{
  if (!this->IsValid())
  {
    vtkErrorMacro("unknown technique \"" << (this->Name ? this->Name : "(null)")
                                         << "\"; known: " << GetKnownTechniques());
    return nullptr;
  }
  if (std::strcmp(this->Name, "none") == 0)
  {
    return vtkRenderStepsPass::New();
  }
  if (std::strcmp(this->Name, "planar") == 0)
  {
    // Receivers are the actors marked vtkPlanarShadowPass::RECEIVER().
    return vtkPlanarShadowPass::New();
  }
  if (std::strcmp(this->Name, "csm") == 0)
  {
    vtkCascadedShadowMapPass* csm = vtkCascadedShadowMapPass::New();
    csm->CopySettings(this->CascadedSettings);
    csm->SetMapResolution(this->MapResolution);
    return csm;
  }
  // "vtk": VTK's own shadow maps, assembled as in VTK's TestShadowMapPass.
  vtkNew<vtkShadowMapPass> shadows;
  shadows->GetShadowMapBakerPass()->SetResolution(this->MapResolution);
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(shadows->GetShadowMapBakerPass());
  passes->AddItem(shadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  vtkCameraPass* camera = vtkCameraPass::New();
  camera->SetDelegatePass(sequence);
  return camera;
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::Install(vtkRenderer* renderer)
{
  auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
  if (!gl)
  {
    vtkErrorMacro("Install: a vtkOpenGLRenderer is required");
    return false;
  }
  vtkRenderPass* pass = this->CreatePass();
  if (!pass)
  {
    return false;
  }
  // Free the GL objects of the pass we replace while its context exists;
  // VTK's passes complain (and leak) when they are deleted with them.
  if (gl->GetPass() && gl->GetRenderWindow())
  {
    gl->GetPass()->ReleaseGraphicsResources(gl->GetRenderWindow());
  }
  gl->SetPass(pass);
  pass->Delete();
  return true;
}

//------------------------------------------------------------------------------
long long vtkShadowTechnique::GetShadowMapMemory(vtkRenderer* renderer) const
{
  if (!renderer || !this->Name)
  {
    return 0;
  }
  if (std::strcmp(this->Name, "planar") == 0)
  {
    // The mask and caster copies of the installed pass, as of its last frame.
    auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
    auto* planar = gl ? vtkPlanarShadowPass::SafeDownCast(gl->GetPass()) : nullptr;
    return planar ? planar->GetMemoryBytes() : 0;
  }
  if (std::strcmp(this->Name, "csm") == 0)
  {
    auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
    auto* csm = gl ? vtkCascadedShadowMapPass::SafeDownCast(gl->GetPass()) : nullptr;
    return csm ? csm->GetMemoryBytes() : 0;
  }
  if (std::strcmp(this->Name, "vtk") != 0)
  {
    return 0;
  }
  // The baker keeps one single-channel float map per shadowing light and
  // shares one depth attachment of the same size (4 bytes a texel each).
  long long lights = 0;
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* l = collection->GetNextLight(it))
  {
    const bool casts =
      !l->LightTypeIsHeadlight() && (!l->GetPositional() || l->GetConeAngle() < 90.0);
    lights += (l->GetSwitch() && casts) ? 1 : 0;
  }
  const long long texels = static_cast<long long>(this->MapResolution) * this->MapResolution;
  return lights > 0 ? (lights + 1) * texels * 4 : 0;
}

//------------------------------------------------------------------------------
void vtkShadowTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << (this->Name ? this->Name : "(null)") << "\n";
  os << indent << "MapResolution: " << this->MapResolution << "\n";
}
