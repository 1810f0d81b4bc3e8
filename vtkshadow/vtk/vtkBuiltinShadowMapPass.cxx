#include "vtkBuiltinShadowMapPass.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowSettings.h"
#include "vtkShadowStageProfile.h"

#include "vtkActor.h"
#include "vtkCameraPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOverlayPass.h"
#include "vtkProperty.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShadowFrame.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkVolumetricPass.h"

#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkBuiltinShadowMapPass);

namespace
{
/**
 * VTK's vtkShadowMapPass with two changes made from outside its code:
 *
 * - No shader without vertexVC gets its shadow code. VTK's pass puts
 *   `calcShadow(vertexVC, ...)` into every shader it is registered with,
 *   but a polydata mapper declares vertexVC only when its light complexity
 *   is not 0: an actor with lighting off (an outline, say), or lit lines
 *   and points without normals (the cube axes' lines). Such a shader fails
 *   to compile and VTK 9.1 crashes drawing with the missing program.
 *   Actors with lighting off and other mappers (volumes) keep their own
 *   shaders; a lit actor whose primitive is drawn unlit gets a dummy
 *   vertexVC (its factors then go into no light term).
 * - The residual light: VTK's own per-light vtkLight::ShadowAttenuation a
 *   gives the factor 1 - a + a * visibility; scaling a by (1 - residual)
 *   leaves `residual` of the light in full shadow, as in every vtkshadow
 *   technique.
 */
class vtkShadowMapPassGuarded : public vtkShadowMapPass
{
public:
  static vtkShadowMapPassGuarded* New();
  vtkTypeMacro(vtkShadowMapPassGuarded, vtkShadowMapPass);

  double Residual = 0.0;

  static bool Shadowable(vtkAbstractMapper* mapper, vtkProp* prop)
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    return actor && actor->GetProperty() && actor->GetProperty()->GetLighting() &&
      vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  }

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override
  {
    return !Shadowable(mapper, prop) ||
      this->Superclass::PreReplaceShaderValues(
        vertexShader, geometryShader, fragmentShader, mapper, prop);
  }

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override
  {
    if (!Shadowable(mapper, prop))
    {
      return true;
    }
    const std::string call = "calcShadow(vertexVC";
    const size_t first = fragmentShader.find(call);
    if (first != std::string::npos && fragmentShader.find("vec4 vertexVC =") == std::string::npos)
    {
      const size_t line = fragmentShader.rfind('\n', first);
      const size_t at = fragmentShader.rfind("vec2 factor", first);
      const size_t where = at != std::string::npos && (line == std::string::npos || at > line)
        ? at
        : (line == std::string::npos ? 0 : line + 1);
      fragmentShader.insert(where, "vec4 vertexVC = vec4(0.0, 0.0, 0.0, 1.0); // unlit: unused\n");
    }
    return this->Superclass::PostReplaceShaderValues(
      vertexShader, geometryShader, fragmentShader, mapper, prop);
  }

  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao) override
  {
    if (!Shadowable(mapper, prop))
    {
      return true;
    }
    const std::vector<float> attenuation = this->ShadowAttenuation;
    for (float& a : this->ShadowAttenuation)
    {
      a = static_cast<float>(a * (1.0 - this->Residual));
    }
    const bool ok = this->Superclass::SetShaderParameters(program, mapper, prop, vao);
    this->ShadowAttenuation = attenuation;
    return ok;
  }

protected:
  vtkShadowMapPassGuarded() = default;
  ~vtkShadowMapPassGuarded() override = default;

private:
  vtkShadowMapPassGuarded(const vtkShadowMapPassGuarded&) = delete;
  void operator=(const vtkShadowMapPassGuarded&) = delete;
};
vtkStandardNewMacro(vtkShadowMapPassGuarded);

// Marks the end of VTK's map baking in the stage profile
// (vtkShadowStageProfile.h): the baker and the lit draw are two passes of
// the sequence, and only this one sits between them.
class vtkShadowMapsBakedMark : public vtkRenderPass
{
public:
  static vtkShadowMapsBakedMark* New();
  vtkTypeMacro(vtkShadowMapsBakedMark, vtkRenderPass);
  void Render(const vtkRenderState*) override { vtkshadow::MarkStage("vtk.maps"); }

protected:
  vtkShadowMapsBakedMark() = default;
  ~vtkShadowMapsBakedMark() override = default;

private:
  vtkShadowMapsBakedMark(const vtkShadowMapsBakedMark&) = delete;
  void operator=(const vtkShadowMapsBakedMark&) = delete;
};
vtkStandardNewMacro(vtkShadowMapsBakedMark);
}

//------------------------------------------------------------------------------
vtkBuiltinShadowMapPass::vtkBuiltinShadowMapPass()
  : Shadows(vtkShadowMapPassGuarded::New())
  , MapResolution(2048)
  , ShadowingLights(0)
{
  this->Shadows->GetShadowMapBakerPass()->SetResolution(this->MapResolution);
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(this->Shadows->GetShadowMapBakerPass());
  vtkNew<vtkShadowMapsBakedMark> baked;
  passes->AddItem(baked);
  passes->AddItem(this->Shadows);
  // VTK's assembly (TestShadowMapPass) draws opaque geometry only; volumes
  // and 2D overlays (scalar bars, text) follow as in vtkRenderStepsPass, so
  // the baseline runs ordinary scenes without losing them. (Volumes cast no
  // shadow here either.)
  vtkNew<vtkVolumetricPass> volumes;
  vtkNew<vtkOverlayPass> overlays;
  passes->AddItem(volumes);
  passes->AddItem(overlays);
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
// The settings, once (vtkShadowSettings.h).
const vtkshadow::Settings& vtkBuiltinShadowMapPass::SettingsTable()
{
  using P = vtkBuiltinShadowMapPass;
  static const vtkshadow::Settings table(&vtkShadowPassBase::SettingsTable(),
    { vtkshadow::Row("map_resolution", vtkshadow::MapResolutionRange(), &P::SetMapResolution,
      &P::GetMapResolution, "edge of VTK's shadow map in texels") });
  return table;
}

//------------------------------------------------------------------------------
void vtkBuiltinShadowMapPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkshadow::MarkStage("setup");
  // The attenuation is a uniform in VTK's code: no shader rebuild needed.
  static_cast<vtkShadowMapPassGuarded*>(this->Shadows)->Residual = this->ResidualLight;
  // The lights as every technique places them, before VTK's baker reads
  // them (VTK's lights pass places them only when LightFollowCamera is on):
  // the frame updates them.
  const vtkshadow::ShadowFrame& frame = this->BeginFrame(s, false);
  // The lights VTK's baker gives a map: switched on, not the headlight, and
  // directional or a spot (VTK's pass skips point lights).
  this->ShadowingLights = 0;
  for (const vtkshadow::ShadowFrameLight& l : frame.Lights)
  {
    this->ShadowingLights += (!l.Headlight && (!l.Positional || l.ConeAngle < 90.0)) ? 1 : 0;
  }
  // VTK's baker draws opaque geometry only.
  if (!vtkshadow::TranslucentShadowActors(frame.Renderer).empty())
  {
    for (size_t l = 0; l < frame.Lights.size(); ++l)
    {
      this->AddLightNote(static_cast<int>(l),
        "translucent actors cast no shadow (VTK's vtkShadowMapPass draws opaque casters only)");
    }
  }
  this->NoteUncastVolumes(frame);
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
  this->Superclass::PrintSelf(os, indent); // map_resolution: a setting, printed there
}
