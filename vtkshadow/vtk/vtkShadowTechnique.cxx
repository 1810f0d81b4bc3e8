#include "vtkShadowTechnique.h"

#include "vtkCameraPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPlanarShadowPass.h"
#include "vtkAutoShadowPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"

#include <cmath>
#include <cstring>
#include <sstream>

vtkStandardNewMacro(vtkShadowTechnique);

namespace
{
const char* const KnownTechniques[] = { "none", "vtk", "planar", "csm", "auto" };
}

//------------------------------------------------------------------------------
vtkShadowTechnique::vtkShadowTechnique()
  : Name(nullptr)
  , MapResolution(2048)
  , MaxError(0.5)
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
  return "none vtk planar csm auto";
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
  if (std::strcmp(this->Name, "auto") == 0)
  {
    vtkAutoShadowPass* automatic = vtkAutoShadowPass::New();
    automatic->GetCascadedPass()->CopySettings(this->CascadedSettings);
    automatic->GetCascadedPass()->SetMapResolution(this->MapResolution);
    // auto meets an error target: a texel size given directly, or wrong_pct.
    automatic->SetMaxTexelPixels(this->CascadedSettings->GetMaxTexelPixels());
    automatic->SetMaxError(this->MaxError);
    return automatic;
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
  auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
  vtkRenderPass* pass = gl ? gl->GetPass() : nullptr;
  if (auto* automatic = vtkAutoShadowPass::SafeDownCast(pass))
  {
    return automatic->GetMemoryBytes();
  }
  if (auto* planar = vtkPlanarShadowPass::SafeDownCast(pass))
  {
    // The mask and caster copies of the installed pass, as of its last frame.
    return planar->GetMemoryBytes();
  }
  if (auto* csm = vtkCascadedShadowMapPass::SafeDownCast(pass))
  {
    return csm->GetMemoryBytes();
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
bool vtkShadowTechnique::SetOption(const char* key, double v)
{
  if (!key || !std::isfinite(v))
  {
    return false;
  }
  const std::string k = key;
  vtkCascadedShadowMapPass* c = this->CascadedSettings;
  auto in = [&](double lo, double hi) { return v >= lo && v <= hi; };
  auto integral = [&](double lo, double hi) { return in(lo, hi) && v == std::floor(v); };
  if (k == "map_resolution" && integral(16, 16384))
  {
    this->SetMapResolution(static_cast<int>(v));
  }
  else if (k == "cascades" && integral(0, 8))
  {
    c->SetCascadeCount(static_cast<int>(v));
  }
  else if (k == "ratio_per_cascade" && in(1.5, 1e6))
  {
    c->SetRatioPerCascade(v);
  }
  else if (k == "split" && integral(0, 3))
  {
    c->SetSplitScheme(static_cast<int>(v));
  }
  else if (k == "lambda" && in(0, 1))
  {
    c->SetSplitLambda(v);
  }
  else if (k.rfind("split_fraction_", 0) == 0 && k.size() == 16 && k[15] >= '0' && k[15] <= '6' &&
    v > 0 && v < 1)
  {
    c->SetSplitFraction(k[15] - '0', v);
  }
  else if (k == "stable" && integral(0, 1))
  {
    c->SetStable(v != 0);
  }
  else if (k == "max_error" && in(0, 100))
  {
    this->MaxError = v;
  }
  else if (k == "max_texel_px" && in(0, 1e6))
  {
    c->SetMaxTexelPixels(v);
  }
  else if (k == "memory_budget" && in(1 << 16, 1e12))
  {
    c->SetMemoryBudget(static_cast<long long>(v));
  }
  else if (k == "bias_scale" && in(0, 100))
  {
    c->SetBiasScale(v);
  }
  else if (k == "filter" && integral(0, 2))
  {
    c->SetFilter(static_cast<int>(v));
  }
  else if (k == "pcf_size" && integral(1, 9))
  {
    c->SetPCFSize(static_cast<int>(v));
  }
  else if (k == "poisson_radius" && in(0, 16))
  {
    c->SetPoissonRadius(v);
  }
  else if (k == "blend_band" && in(0, 0.5))
  {
    c->SetBlendBand(v);
  }
  else if (k == "max_distance" && in(0, 1e300))
  {
    c->SetMaxShadowDistance(v);
  }
  else if (k == "fade" && in(0, 1))
  {
    c->SetFadeFraction(v);
  }
  else if (k == "debug_cascades" && integral(0, 1))
  {
    c->SetDebugCascades(v != 0);
  }
  else
  {
    return false;
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkShadowTechnique::GetStatsJSON(vtkRenderer* renderer) const
{
  auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
  std::ostringstream out;
  out.precision(6);
  vtkRenderPass* pass = gl ? gl->GetPass() : nullptr;
  std::string prefix;
  if (auto* automatic = vtkAutoShadowPass::SafeDownCast(pass))
  {
    const std::string choice = automatic->GetChoice();
    std::string reason = automatic->GetReason();
    for (size_t at = reason.find('"'); at != std::string::npos; at = reason.find('"', at + 2))
    {
      reason.insert(at, "\\");
    }
    prefix = "\"choice\": \"" + choice + "\", \"reason\": \"" + reason + "\"";
    std::ostringstream perLight;
    perLight.precision(6);
    perLight << ", \"texel_target_px\": " << automatic->GetUsedTexelTarget()
             << ", \"texel_stretch\": " << automatic->GetUsedStretch()
             << ", \"edge_length_px\": " << automatic->GetUsedEdgeLength()
             << ", \"light_choices\": [";
    for (int l = 0; l < automatic->GetNumberOfLightChoices(); ++l)
    {
      perLight << (l ? ", " : "") << "\"" << automatic->GetLightChoice(l) << "\"";
    }
    prefix += perLight.str() + "]";
    // Details of the map pass when there is one, else of the planar pass.
    pass = choice.find("csm") != std::string::npos
      ? static_cast<vtkRenderPass*>(automatic->GetCascadedPass())
      : choice == "planar" ? static_cast<vtkRenderPass*>(automatic->GetPlanarPass())
                           : nullptr;
    if (!pass)
    {
      return "{" + prefix + "}";
    }
    prefix += ", ";
  }
  if (auto* csm = vtkCascadedShadowMapPass::SafeDownCast(pass))
  {
    out << "{" << prefix;
    out << "\"resolution\": " << csm->GetUsedResolution()
        << ", \"maps_rendered_total\": " << csm->GetTotalMapsRendered()
        << ", \"maps_reused_last_frame\": " << csm->GetNumberOfMapsReused() << ", \"lights\": [";
    const int lights = renderer->GetLights()->GetNumberOfItems();
    for (int l = 0; l < lights; ++l)
    {
      out << (l ? ", " : "") << "{\"cascades\": " << csm->GetNumberOfCascades(l)
          << ", \"far\": [";
      for (int c = 0; c < csm->GetNumberOfCascades(l); ++c)
      {
        out << (c ? ", " : "") << csm->GetCascadeFar(l, c);
      }
      out << "], \"texel_px\": [";
      for (int c = 0; c < csm->GetNumberOfCascades(l); ++c)
      {
        out << (c ? ", " : "") << csm->GetCascadeTexelPixels(l, c);
      }
      out << "]}";
    }
    out << "]}";
    return out.str();
  }
 if (auto* planar = vtkPlanarShadowPass::SafeDownCast(pass))
  {
    out << "{" << prefix << "\"shadow_pairs\": " << planar->GetNumberOfShadowPairs()
        << ", \"mask_triangles\": " << planar->GetNumberOfMaskTriangles()
        << ", \"geometry_builds\": " << planar->GetNumberOfGeometryBuilds() << "}";
    return out.str();
  }
  return "{}";
}

//------------------------------------------------------------------------------
void vtkShadowTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << (this->Name ? this->Name : "(null)") << "\n";
  os << indent << "MapResolution: " << this->MapResolution << "\n";
  os << indent << "MaxError: " << this->MaxError << "\n";
}
