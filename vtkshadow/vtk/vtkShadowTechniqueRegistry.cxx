#include "vtkShadowTechniqueRegistry.h"

#include "vtkAutoShadowPass.h"
#include "vtkBuiltinShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkNoShadowPass.h"
#include "vtkObjectFactory.h"
#include "vtkPlanarShadowPass.h"
#include "vtkRayTracedShadowPass.h"
#include "vtkShadowSettings.h"
#include "vtkShadowVolumePass.h"

#include <cstring>
#include <string>

vtkStandardNewMacro(vtkShadowTechniqueRegistry);

namespace
{
struct Technique
{
  const char* Name;
  const char* Description;
  vtkShadowPassBase* (*Create)();
  const vtkshadow::Settings& (*Settings)(); // read without making a pass
};

template <class Pass>
vtkShadowPassBase* Make()
{
  return Pass::New();
}

template <class Pass>
Technique Of(const char* name, const char* description)
{
  return { name, description, &Make<Pass>, &Pass::SettingsTable };
}

// The table. Order is the order tools list and run techniques in.
const Technique Techniques[] = {
  Of<vtkNoShadowPass>("none", "VTK's standard passes, no shadows (the cost and error floor)"),
  Of<vtkBuiltinShadowMapPass>(
    "vtk", "VTK 9.1's own shadow maps (vtkShadowMapPass) at map_resolution, the baseline"),
  Of<vtkPlanarShadowPass>("planar", "exact projected shadows on plane receivers, every light type"),
  Of<vtkCascadedShadowMapPass>(
    "csm", "cascaded shadow maps (directional), perspective (spot) and cube (point) maps"),
  Of<vtkAutoShadowPass>(
    "auto", "per light the cheapest technique that meets an error target (max_error)"),
  Of<vtkShadowVolumePass>(
    "volume", "stencil shadow volumes: exact hard shadows on every surface, every light type"),
  Of<vtkRayTracedShadowPass>("raytrace",
    "exact shadows of any geometry: a light-space map decides what it proves, Embree rays the "
    "rest"),
};
constexpr int TechniqueCount = static_cast<int>(sizeof(Techniques) / sizeof(Techniques[0]));
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueRegistry::GetNumberOfTechniques()
{
  return TechniqueCount;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueRegistry::GetName(int index)
{
  return index >= 0 && index < TechniqueCount ? Techniques[index].Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueRegistry::GetDescription(int index)
{
  return index >= 0 && index < TechniqueCount ? Techniques[index].Description : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueRegistry::FindTechnique(const char* name)
{
  for (int i = 0; name && i < TechniqueCount; ++i)
  {
    if (std::strcmp(name, Techniques[i].Name) == 0)
    {
      return i;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
const vtkshadow::Settings& vtkShadowTechniqueRegistry::GetSettings(int index)
{
  static const vtkshadow::Settings none;
  return index >= 0 && index < TechniqueCount ? Techniques[index].Settings() : none;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueRegistry::GetNames()
{
  static const std::string names = []
  {
    std::string all;
    for (const Technique& t : Techniques)
    {
      all += (all.empty() ? "" : " ") + std::string(t.Name);
    }
    return all;
  }();
  return names.c_str();
}

//------------------------------------------------------------------------------
vtkShadowPassBase* vtkShadowTechniqueRegistry::CreatePass(const char* name)
{
  const int index = FindTechnique(name);
  return index < 0 ? nullptr : Techniques[index].Create();
}

//------------------------------------------------------------------------------
void vtkShadowTechniqueRegistry::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const Technique& t : Techniques)
  {
    os << indent << t.Name << ": " << t.Description << "\n";
  }
}
