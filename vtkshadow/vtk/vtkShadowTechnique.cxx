#include "vtkShadowTechnique.h"

#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkShadowDefaultLights.h"
#include "vtkShadowPassBase.h"
#include "vtkShadowPassComposition.h"
#include "vtkShadowSettings.h"
#include "vtkShadowTechniqueRegistry.h"
#include "vtkSmartPointer.h"

#include <algorithm>

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
  // The settings are checked against the technique's table before any pass
  // is made (the name may have changed since they were set).
  const vtkshadow::Settings* settings = vtkshadow::Settings::ForTechnique(this->Name);
  if (!settings)
  {
    vtkErrorMacro("unknown technique \"" << (this->Name ? this->Name : "(null)")
                                         << "\"; known: " << GetKnownTechniques());
    return nullptr;
  }
  for (const auto& option : this->Options)
  {
    const vtkshadow::Setting* row = settings->Find(option.first.c_str());
    if (!row || !row->Accepts(option.second))
    {
      vtkErrorMacro("technique \"" << this->Name << "\" has no setting " << option.first << "="
                                   << option.second);
      return nullptr;
    }
  }
  vtkShadowPassBase* pass = vtkShadowTechniqueRegistry::CreatePass(this->Name);
  settings->Find("map_resolution")->Set(*pass, this->MapResolution);
  for (const auto& option : this->Options)
  {
    settings->Find(option.first.c_str())->Set(*pass, option.second);
  }
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
  // The technique's settings table says which keys and values it takes.
  const vtkshadow::Settings* settings = vtkshadow::Settings::ForTechnique(this->Name);
  const vtkshadow::Setting* row = settings ? settings->Find(key) : nullptr;
  if (!row || !row->Accepts(v))
  {
    return false;
  }
  const std::string k = key;
  if (k == "map_resolution")
  {
    this->SetMapResolution(static_cast<int>(v)); // every pass CreatePass makes gets it
    return true;
  }
  auto same = [&](const std::pair<std::string, double>& o) { return o.first == k; };
  this->Options.erase(
    std::remove_if(this->Options.begin(), this->Options.end(), same), this->Options.end());
  this->Options.emplace_back(k, v);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkShadowTechnique::GetSettingsListing()
{
  std::string out;
  for (int i = 0; i < vtkShadowTechniqueRegistry::GetNumberOfTechniques(); ++i)
  {
    // Defaults are those of a pass as CreatePass makes it (map_resolution
    // from the technique).
    vtkNew<vtkShadowTechnique> technique;
    technique->SetName(vtkShadowTechniqueRegistry::GetName(i));
    vtkSmartPointer<vtkShadowPassBase> pass;
    pass.TakeReference(technique->CreatePass());
    for (const vtkshadow::Setting& row :
      vtkshadow::Settings::ForTechnique(technique->GetName())->GetRows())
    {
      const double value = row.Get ? row.Get(*pass) : technique->GetMapResolution();
      out += std::string(technique->GetName()) + "\t" + row.Key + "\t" + row.RangeText() + "\t" +
        (row.Range.Integer ? "yes" : "no") + "\t" + vtkshadow::FormatNumber(value) + "\t" +
        row.Doc + "\n";
    }
  }
  return out;
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
