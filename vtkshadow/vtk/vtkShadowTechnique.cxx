#include "vtkShadowTechnique.h"

#include "vtkLight.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkShadowDefaultLights.h"
#include "vtkShadowPassBase.h"
#include "vtkShadowPassComposition.h"
#include "vtkShadowTechniqueRegistry.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkShadowTechnique);

//------------------------------------------------------------------------------
vtkShadowTechnique::vtkShadowTechnique()
  : Name(nullptr)
  , MapResolution(2048)
  , AutoKeyLight(true)
{
  this->SetName("none");
}

//------------------------------------------------------------------------------
vtkShadowTechnique::~vtkShadowTechnique()
{
  this->SetName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::IsKnownTechnique(const char* name)
{
  return vtkShadowTechniqueRegistry::FindTechnique(name) >= 0;
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::IsValid() const
{
  return IsKnownTechnique(this->Name);
}

//------------------------------------------------------------------------------
const char* vtkShadowTechnique::GetKnownTechniques()
{
  return vtkShadowTechniqueRegistry::GetNames();
}

//------------------------------------------------------------------------------
vtkShadowPassBase* vtkShadowTechnique::CreatePass()
{
  vtkSmartPointer<vtkShadowPassBase> pass;
  pass.TakeReference(vtkShadowTechniqueRegistry::CreatePass(this->Name));
  if (!pass)
  {
    vtkErrorMacro("unknown technique \"" << (this->Name ? this->Name : "(null)")
                                         << "\"; known: " << GetKnownTechniques());
    return nullptr;
  }
  // Techniques without maps have no map_resolution: nothing to apply then.
  pass->SetOption("map_resolution", this->MapResolution);
  for (const auto& option : this->Options)
  {
    if (!pass->SetOption(option.first.c_str(), option.second))
    {
      vtkErrorMacro("technique \"" << this->Name << "\" has no setting " << option.first << "="
                                   << option.second);
      return nullptr;
    }
  }
  pass->Register(nullptr);
  return pass;
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
  vtkSmartPointer<vtkShadowPassBase> pass;
  pass.TakeReference(this->CreatePass());
  return pass && this->SetPass(gl, pass);
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::SetPass(vtkRenderer* renderer, vtkShadowPassBase* pass)
{
  auto* gl = static_cast<vtkOpenGLRenderer*>(renderer);
  vtkshadow::PassComposition composed = vtkshadow::ComposeShadowPass(gl->GetPass(), pass);
  this->PassMessage = composed.Message;
  if (!composed.Ok)
  {
    vtkErrorMacro(<< this->PassMessage);
    return false;
  }
  if (composed.Replaced && composed.Replaced->IsA("vtkShadowPassBase") == 0)
  {
    vtkWarningMacro(<< "enable shadows: " << this->PassMessage);
  }
  // Free the GL objects of the pass we take out while its context exists;
  // VTK's passes complain (and leak) when they are deleted with them.
  if (composed.Replaced && gl->GetRenderWindow())
  {
    composed.Replaced->ReleaseGraphicsResources(gl->GetRenderWindow());
  }
  gl->SetPass(composed.Top);
  this->Renderer = renderer;
  return true;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechnique::GetPassMessage() const
{
  return this->PassMessage.c_str();
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::Enable(vtkRenderer* renderer)
{
  if (!vtkOpenGLRenderer::SafeDownCast(renderer))
  {
    vtkErrorMacro("Enable: a vtkOpenGLRenderer is required");
    return false;
  }
  // The pass first: a bad name or setting leaves the renderer as it was.
  vtkSmartPointer<vtkShadowPassBase> pass;
  pass.TakeReference(this->CreatePass());
  if (!pass || !this->SetPass(renderer, pass))
  {
    return false;
  }
  // The lights are decided at each frame (vtkshadow::UpdateLights), from
  // the lights the application has then.
  vtkshadow::SetAutoKeyLight(renderer, this->AutoKeyLight);
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkShadowTechnique> vtkShadowTechnique::EnableShadows(
  vtkRenderer* renderer, const char* technique)
{
  auto made = vtkSmartPointer<vtkShadowTechnique>::New();
  made->SetName(technique ? technique : "auto");
  return made->Enable(renderer) ? made : nullptr;
}

//------------------------------------------------------------------------------
vtkLight* vtkShadowTechnique::GetAddedKeyLight() const
{
  return vtkshadow::FindKeyLight(this->Renderer);
}

//------------------------------------------------------------------------------
const char* vtkShadowTechnique::GetLightMessage() const
{
  this->LightMessage = vtkshadow::DescribeDefaultLights(this->Renderer);
  return this->LightMessage.c_str();
}

//------------------------------------------------------------------------------
vtkRenderer* vtkShadowTechnique::GetRenderer() const
{
  return this->Renderer;
}

//------------------------------------------------------------------------------
int vtkShadowTechnique::GetNumberOfDetectedReceivers() const
{
  auto* pass = vtkshadow::FindShadowPass(this->Renderer);
  return pass ? pass->GetNumberOfDetectedReceivers() : 0;
}

//------------------------------------------------------------------------------
vtkActor* vtkShadowTechnique::GetDetectedReceiver(int index) const
{
  auto* pass = vtkshadow::FindShadowPass(this->Renderer);
  return pass ? pass->GetDetectedReceiver(index) : nullptr;
}

//------------------------------------------------------------------------------
namespace
{
vtkShadowPassBase* InstalledPass(vtkRenderer* renderer)
{
  return vtkshadow::FindShadowPass(renderer);
}
}

//------------------------------------------------------------------------------
long long vtkShadowTechnique::GetShadowMapMemory(vtkRenderer* renderer) const
{
  vtkShadowPassBase* pass = InstalledPass(renderer);
  return pass ? pass->GetMemoryBytes() : 0;
}

//------------------------------------------------------------------------------
bool vtkShadowTechnique::SetOption(const char* key, double v)
{
  if (!key || !std::isfinite(v))
  {
    return false;
  }
  const std::string k = key;
  if (k == "map_resolution")
  {
    if (!(v >= 16 && v <= 16384 && v == std::floor(v)))
    {
      return false;
    }
    this->SetMapResolution(static_cast<int>(v));
    return true;
  }
  // The technique's own pass says which keys and values it takes.
  vtkSmartPointer<vtkShadowPassBase> probe;
  probe.TakeReference(vtkShadowTechniqueRegistry::CreatePass(this->Name));
  if (!probe || !probe->SetOption(key, v))
  {
    return false;
  }
  auto same = [&](const std::pair<std::string, double>& o) { return o.first == k; };
  this->Options.erase(
    std::remove_if(this->Options.begin(), this->Options.end(), same), this->Options.end());
  this->Options.emplace_back(k, v);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkShadowTechnique::GetStatsJSON(vtkRenderer* renderer) const
{
  vtkShadowPassBase* pass = InstalledPass(renderer);
  return "{" + (pass ? pass->GetStatsJSON(renderer) : std::string()) + "}";
}

//------------------------------------------------------------------------------
void vtkShadowTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << (this->Name ? this->Name : "(null)") << "\n";
  os << indent << "MapResolution: " << this->MapResolution << "\n";
  os << indent << "AutoKeyLight: " << this->AutoKeyLight << "\n";
  for (const auto& option : this->Options)
  {
    os << indent << "Option " << option.first << ": " << option.second << "\n";
  }
}
