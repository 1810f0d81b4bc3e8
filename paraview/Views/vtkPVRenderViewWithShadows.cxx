#include "vtkPVRenderViewWithShadows.h"

#include "vtkActor.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShadowPassBase.h"
#include "vtkShadowSettings.h"
#include "vtkShadowTechniqueRegistry.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <sstream>

vtkStandardNewMacro(vtkPVRenderViewWithShadows);

//------------------------------------------------------------------------------
vtkPVRenderViewWithShadows::vtkPVRenderViewWithShadows()
  : Technique("csm")
  , MaxError(0.5)
  , Cascades(0)
  , MapResolution(2048)
  , Filter(0)
  , Pass(nullptr)
  , Names(vtkStringArray::New())
{
  for (int i = 0; i < vtkShadowTechniqueRegistry::GetNumberOfTechniques(); ++i)
  {
    this->Names->InsertNextValue(vtkShadowTechniqueRegistry::GetName(i));
  }
  this->RebuildPass();
}

//------------------------------------------------------------------------------
vtkPVRenderViewWithShadows::~vtkPVRenderViewWithShadows()
{
  if (this->Pass)
  {
    this->SynchronizedRenderers->SetRenderPass(nullptr);
    this->Pass->Delete();
  }
  this->Names->Delete();
}

//------------------------------------------------------------------------------
vtkStringArray* vtkPVRenderViewWithShadows::GetShadowTechniqueNames()
{
  return this->Names;
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::SetShadowTechnique(const char* name)
{
  if (!name || vtkShadowTechniqueRegistry::FindTechnique(name) < 0)
  {
    vtkErrorMacro("ShadowTechnique: unknown technique \""
      << (name ? name : "(null)") << "\"; known: " << vtkShadowTechniqueRegistry::GetNames());
    return;
  }
  if (this->Technique != name)
  {
    this->Technique = name;
    this->RebuildPass();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
namespace
{
// "" when `value` is in the range of `technique`'s setting `key`, else why
// not: the ranges are the settings tables' (vtkShadowSettings.h), written
// nowhere else; the XML's domains are checked against them
// (tests/paraview/test_pv_settings.py).
std::string OutOfRange(const char* technique, const char* key, double value)
{
  const vtkshadow::Setting* row = vtkshadow::Settings::ForTechnique(technique)->Find(key);
  return row->Accepts(value) ? std::string()
                             : vtkshadow::FormatNumber(value) + " is outside " + row->RangeText();
}
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::SetShadowMaxError(double percent)
{
  const std::string bad = OutOfRange("auto", "max_error", percent);
  if (!bad.empty())
  {
    vtkErrorMacro("ShadowMaxError: " << bad);
    return;
  }
  this->MaxError = percent;
  this->RebuildPass();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::SetShadowCascades(int cascades)
{
  const std::string bad = OutOfRange("csm", "cascades", cascades);
  if (!bad.empty())
  {
    vtkErrorMacro("ShadowCascades: " << bad);
    return;
  }
  this->Cascades = cascades;
  this->RebuildPass();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::SetShadowMapResolution(int texels)
{
  const std::string bad = OutOfRange("csm", "map_resolution", texels);
  if (!bad.empty())
  {
    vtkErrorMacro("ShadowMapResolution: " << bad);
    return;
  }
  this->MapResolution = texels;
  this->RebuildPass();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::SetShadowFilter(int filter)
{
  const std::string bad = OutOfRange("csm", "filter", filter);
  if (!bad.empty())
  {
    vtkErrorMacro("ShadowFilter: " << bad);
    return;
  }
  this->Filter = filter;
  this->RebuildPass();
  this->Modified();
}

//------------------------------------------------------------------------------
// A new pass with every setting the technique has: a technique without a
// key (planar has no cascades) refuses it, which is not an error here.
void vtkPVRenderViewWithShadows::RebuildPass()
{
  vtkShadowPassBase* old = this->Pass;
  this->Pass = nullptr;
  this->Fallback.clear();
  // Ranks that composite one image: only csm (maps planned from reduced
  // bounds, min-reduced) and none are right across ranks. planar's screen
  // mask, vtk's per-rank fitted maps and auto (whose planar choice and
  // resolution depend on local data) are not: they fall back to csm.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool parallel = controller && controller->GetNumberOfProcesses() > 1;
  std::string technique = this->Technique;
  if (parallel && technique != "none" && technique != "csm")
  {
    this->Fallback = technique + " is not right across " +
      std::to_string(controller->GetNumberOfProcesses()) + " ranks: using csm";
    technique = "csm";
    if (controller->GetLocalProcessId() == 0)
    {
      vtkWarningMacro("ShadowTechnique: " << this->Fallback);
    }
  }
  if (technique != "none")
  {
    this->Pass = vtkShadowTechniqueRegistry::CreatePass(technique.c_str());
  }
  if (auto* csm = vtkCascadedShadowMapPass::SafeDownCast(this->Pass))
  {
    csm->SetController(parallel ? controller : nullptr);
  }
  if (this->Pass)
  {
    this->Pass->SetOption("max_error", this->MaxError);
    this->Pass->SetOption("cascades", this->Cascades);
    this->Pass->SetOption("map_resolution", this->MapResolution);
    this->Pass->SetOption("filter", this->Filter);
    // The scene itself is drawn the way ParaView draws it: lights, opaque,
    // translucent (depth peeling), volumes, hidden-line removal. "vtk" keeps
    // its own pipeline (VTK's baker and shadow pass need their sequence).
    if (!this->Pass->GetDelegatePass())
    {
      vtkPVDefaultPass* scene = vtkPVDefaultPass::New();
      this->Pass->SetDelegatePass(scene);
      scene->Delete();
    }
  }
  // The old pass's GL objects go while the window's context still exists.
  vtkRenderWindow* window = this->GetRenderWindow();
  if (old && window)
  {
    old->ReleaseGraphicsResources(window);
  }
  this->SynchronizedRenderers->SetRenderPass(this->Pass);
  if (old)
  {
    old->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::MarkPlanarReceivers()
{
  vtkPropCollection* props = this->GetRenderer()->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetMapper())
    {
      continue;
    }
    double b[6];
    actor->GetBounds(b);
    if (!vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    const double extent[3] = { b[1] - b[0], b[3] - b[2], b[5] - b[4] };
    const double largest = std::max({ extent[0], extent[1], extent[2] });
    const double smallest = std::min({ extent[0], extent[1], extent[2] });
    const int flat = largest > 0.0 && smallest <= 1e-6 * largest ? 1 : 0;
    vtkInformation* keys = actor->GetPropertyKeys();
    if (!keys && flat)
    {
      vtkInformation* fresh = vtkInformation::New();
      actor->SetPropertyKeys(fresh);
      fresh->Delete();
      keys = fresh;
    }
    if (keys && keys->Get(vtkShadowPassBase::RECEIVER()) != flat)
    {
      keys->Set(vtkShadowPassBase::RECEIVER(), flat);
    }
  }
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::Render(bool interactive, bool skip_rendering)
{
  if (this->Pass)
  {
    this->MarkPlanarReceivers();
  }
  // csm's reductions run inside IceT's draw callback, which IceT skips on a
  // rank with nothing on screen (its "empty images" optimisation): the other
  // ranks would then wait in the reduction for ever. Every rank draws, as
  // ParaView does for Surface LIC's collectives. (The flag is recomputed
  // from the representations in Update, so it is set before every render.)
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (this->Pass && controller && controller->GetNumberOfProcesses() > 1)
  {
    this->RenderEmptyImages = true;
  }
  this->Superclass::Render(interactive, skip_rendering);
}

//------------------------------------------------------------------------------
const char* vtkPVRenderViewWithShadows::GetShadowStatus()
{
  std::ostringstream out;
  out << "{\"technique\": \"" << this->Technique << "\"";
  if (!this->Fallback.empty())
  {
    out << ", \"fallback\": \"" << this->Fallback << "\"";
  }
  const std::string stats = this->Pass ? this->Pass->GetStatsJSON(this->GetRenderer()) : "";
  if (!stats.empty())
  {
    out << ", " << stats;
  }
  out << "}";
  this->Status = out.str();
  return this->Status.c_str();
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithShadows::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowTechnique: " << this->Technique << "\n";
  os << indent << "ShadowMaxError: " << this->MaxError << "\n";
  os << indent << "ShadowCascades: " << this->Cascades << "\n";
  os << indent << "ShadowMapResolution: " << this->MapResolution << "\n";
  os << indent << "ShadowFilter: " << this->Filter << "\n";
}
