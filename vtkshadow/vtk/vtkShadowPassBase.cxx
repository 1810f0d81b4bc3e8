#include "vtkShadowPassBase.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowStageProfile.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShadowFrame.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowRendererSteps.h"
#include "vtkShadowScreenMask.h"
#include "vtkShadowSettings.h"
#include "vtkShadowVolumeOpacityMap.h"
#include "vtkShadowVolumeReceiver.h"

#include "vtkOpenGLRenderWindow.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

vtkInformationKeyMacro(vtkShadowPassBase, RECEIVER, Integer);
vtkInformationKeyMacro(vtkShadowPassBase, NO_CAST, Integer);
vtkInformationKeyMacro(vtkShadowPassBase, FILTER, Double);
vtkInformationKeyMacro(vtkShadowPassBase, LIGHT_RADIUS, Double);
vtkInformationKeyMacro(vtkShadowPassBase, LIGHT_ANGLE, Double);

namespace
{
// A size key's value, or 0 when the light has none or an unusable one (a
// light made by hand could carry anything; a pass must never see NaN).
double LightSizeValue(vtkLight* light, vtkInformationDoubleKey* key, double limit)
{
  vtkInformation* info = light ? light->GetInformation() : nullptr;
  if (!info || !info->Has(key))
  {
    return 0.0;
  }
  const double v = info->Get(key);
  return (v >= 0.0 && v < limit) ? v : 0.0;
}
}

double vtkShadowPassBase::GetLightRadius(vtkLight* light)
{
  return LightSizeValue(light, LIGHT_RADIUS(), std::numeric_limits<double>::infinity());
}

double vtkShadowPassBase::GetLightAngle(vtkLight* light)
{
  return LightSizeValue(light, LIGHT_ANGLE(), 180.0);
}

void vtkShadowPassBase::SetLightSize(vtkLight* light, double radius, double angleDegrees)
{
  if (!light)
  {
    return;
  }
  if (!light->GetInformation())
  {
    vtkNew<vtkInformation> info;
    light->SetInformation(info);
  }
  light->GetInformation()->Set(LIGHT_RADIUS(), radius);
  light->GetInformation()->Set(LIGHT_ANGLE(), angleDegrees);
  light->Modified();
}
//------------------------------------------------------------------------------
void vtkShadowPassBase::SetDelegatePass(vtkRenderPass* pass)
{
  if (pass != this->DelegatePass)
  {
    vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, pass);
    this->DelegateIsApplicationScene = false;
  }
}

//------------------------------------------------------------------------------
bool vtkShadowPassBase::SetApplicationScene(vtkRenderPass* scene)
{
  this->SetDelegatePass(scene);
  this->DelegateIsApplicationScene = scene != nullptr;
  return true;
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkShadowPassBase::GetApplicationScene() const
{
  return this->DelegateIsApplicationScene ? this->DelegatePass : nullptr;
}

//------------------------------------------------------------------------------
vtkShadowPassBase::vtkShadowPassBase()
  : DelegatePass(nullptr)
  , CastHeadlightShadows(false)
  , ResidualLight(0.0)
  , SkippedLights(0)
  , ShaderTime(0)
  , WorldKey(0)
  , OwnFrame(new vtkshadow::ShadowFrame)
  , VolumeReceiver(new vtkShadowVolumeReceiver)
{
  this->BumpShaderTime();
}

//------------------------------------------------------------------------------
vtkShadowPassBase::~vtkShadowPassBase()
{
  this->SetDelegatePass(nullptr);
}

//------------------------------------------------------------------------------
const vtkshadow::ShadowFrame& vtkShadowPassBase::BeginFrame(const vtkRenderState* s, bool actors)
{
  vtkshadow::ShadowFrame& frame = *this->OwnFrame;
  if (this->GivenFrame && this->GivenFrame->State == s)
  {
    frame = *this->GivenFrame;
    if (actors && !frame.HasActors)
    {
      vtkshadow::GatherShadowFrameActors(s, frame);
    }
  }
  else
  {
    vtkshadow::GatherShadowFrame(s, actors, frame);
  }
  for (size_t l = 0; l < frame.Lights.size(); ++l)
  {
    frame.Lights[l].Casts = this->LightCasts(frame.Lights[l].Light, static_cast<int>(l));
  }
  this->LightNotes.assign(frame.Lights.size(), std::string());
  return frame;
}

//------------------------------------------------------------------------------
const char* vtkShadowPassBase::GetLightNote(int light) const
{
  return light >= 0 && light < this->GetNumberOfLightNotes() ? this->LightNotes[light].c_str() : "";
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::AddLightNote(int light, const std::string& note)
{
  if (light < 0 || light >= this->GetNumberOfLightNotes())
  {
    return;
  }
  std::string& text = this->LightNotes[light];
  if (text.find(note) == std::string::npos)
  {
    text += (text.empty() ? "" : "; ") + note;
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::NoteUncastVolumes(
  const vtkshadow::ShadowFrame& frame, const vtkShadowVolumeOpacityMap* maps)
{
  for (size_t l = 0; frame.ShowsVolumes && l < frame.Lights.size(); ++l)
  {
    const int light = static_cast<int>(l);
    const std::string note =
      maps ? maps->GetLightNote(light) : "volumes cast no shadow (raytrace casts them)";
    if (frame.Lights[l].Casts && !note.empty())
    {
      this->AddLightNote(light, note);
    }
  }
  // Passes without the volumes' receiver maps (planar, vtk) say so too.
  const bool shaded = !this->VolumesReceive && frame.ShowsVolumes &&
    vtkShadowVolumeReceiver::ShowsShadedVolume(frame.Renderer);
  for (size_t l = 0; shaded && l < frame.Lights.size(); ++l)
  {
    if (frame.Lights[l].Casts)
    {
      this->AddLightNote(static_cast<int>(l),
        "shaded volumes receive no shadow (raytrace, csm and volume darken them)");
    }
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::NoteGreyFilters(const vtkshadow::ShadowFrame& frame)
{
  const bool tinted = vtkshadow::HasTintingCaster(frame.Translucent, NO_CAST());
  for (size_t l = 0; tinted && l < frame.Lights.size(); ++l)
  {
    if (frame.Lights[l].Casts)
    {
      this->AddLightNote(static_cast<int>(l),
        "the filter colour of translucent casters is drawn grey (raytrace draws it)");
    }
  }
}

//------------------------------------------------------------------------------
const vtkshadow::ShadowFrame& vtkShadowPassBase::GetFrame() const
{
  return *this->OwnFrame;
}

//------------------------------------------------------------------------------
bool vtkShadowPassBase::LightCasts(vtkLight* light, int index) const
{
  const bool skipped = index >= 0 && index < 32 && ((this->SkippedLights >> index) & 1u);
  return light && !skipped && (!light->LightTypeIsHeadlight() || this->CastHeadlightShadows);
}

//------------------------------------------------------------------------------
std::string vtkShadowPassBase::GetStatsJSON(vtkRenderer*) const
{
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkShadowPassBase::SetOption(const char* key, double value)
{
  return this->GetSettings().Apply(*this, key, value);
}

//------------------------------------------------------------------------------
// The settings every pass has (vtkShadowSettings.h).
const vtkshadow::Settings& vtkShadowPassBase::SettingsTable()
{
  using P = vtkShadowPassBase;
  static const vtkshadow::Settings table(nullptr,
    {
      vtkshadow::Row("cast_headlight", vtkshadow::Flag(), &P::SetCastHeadlightShadows,
        &P::GetCastHeadlightShadows, "the headlight casts shadows too (they hide behind casters)"),
      vtkshadow::Row("residual_light", vtkshadow::Closed(0, 1), &P::SetResidualLight,
        &P::GetResidualLight, "how much of a light remains in its shadow (1 = no shadow)"),
      vtkshadow::Row("early_depth", vtkshadow::Integers(P::EARLY_DEPTH_OFF, P::EARLY_DEPTH_ALWAYS),
        &P::SetEarlyDepth, &P::GetEarlyDepth,
        "volume, raytrace, csm's screen resolve: the lit draw starts from the depth pre-pass's "
        "depth, so hidden fragments are not shaded (same image); 0 never, 1 where measured to "
        "pay, 2 every frame"),
    });
  return table;
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::SetResidualLight(double residual)
{
  // NaN fails both tests: kept out like any value out of range.
  const double clamped = residual >= 0.0 ? (residual <= 1.0 ? residual : 1.0) : 0.0;
  if (clamped != this->ResidualLight)
  {
    this->ResidualLight = clamped;
    this->BumpShaderTime(); // the value is a constant in the shaders
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkShadowPassBase::InjectLightFactors(std::string& fragmentShader, const std::string& factor,
  const std::string& prepare, int maxLights) const
{
  return vtkshadow::InjectLightFactors(
    fragmentShader, factor, prepare, maxLights, this->ResidualLight);
}

//------------------------------------------------------------------------------
std::string vtkShadowPassBase::DetectedReceiversJSON(vtkRenderer* renderer) const
{
  std::string out = "[";
  vtkActorCollection* actors = renderer ? renderer->GetActors() : nullptr;
  for (int i = 0; i < this->GetNumberOfDetectedReceivers(); ++i)
  {
    const int index = actors ? actors->IsItemPresent(this->GetDetectedReceiver(i)) - 1 : -1;
    out += (i ? ", " : "") + std::to_string(index);
  }
  return out + "]";
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkShadowPassBase::EnsureDelegatePass()
{
  if (!this->DelegatePass)
  {
    // The renderer's own translucency and FXAA settings, which a renderer
    // with a pass no longer applies itself.
    vtkRenderStepsPass* steps = vtkshadow::NewRendererSteps();
    this->SetDelegatePass(steps);
    steps->Delete();
  }
  return this->DelegatePass;
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::RenderDelegate(const vtkRenderState* s)
{
  this->RenderDelegate(s, nullptr);
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::RenderDelegate(const vtkRenderState* s, vtkShadowScreenMask* seed)
{
  vtkRenderPass* delegate = this->EnsureDelegatePass();
  // Only the opaque mask's depth is the opaque scene's (the translucent
  // layer's holds the nearest translucent surface).
  vtkTextureObject* depth =
    this->EarlyDepth != EARLY_DEPTH_OFF && seed && !seed->GetTranslucentSurfaces()
    ? seed->GetDepthTexture()
    : nullptr;
  vtkshadow::SetSeedDepth(delegate, depth, this->EarlyDepth == EARLY_DEPTH_ALWAYS);
  delegate->Render(s);
  vtkshadow::SetSeedDepth(delegate, nullptr); // the mask's texture is not kept
  vtkshadow::MarkStage("scene");
  this->NumberOfRenderedProps += delegate->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkShadowPassBase::GetDepthSeeded() const
{
  bool seeded = false;
  double hiddenPerPixel = -1.0;
  vtkshadow::GetDepthSeedState(this->DelegatePass, seeded, hiddenPerPixel);
  return seeded;
}

//------------------------------------------------------------------------------
std::string vtkShadowPassBase::DepthSeedStatsJSON() const
{
  bool seeded = false;
  double hiddenPerPixel = -1.0;
  vtkshadow::GetDepthSeedState(this->DelegatePass, seeded, hiddenPerPixel);
  std::ostringstream out;
  out << "\"depth_seeded\": " << (seeded ? "true" : "false")
      << ", \"depth_seed_hidden_per_px\": " << hiddenPerPixel;
  return out.str();
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::RenderDelegateWithShaderHooks(const vtkRenderState* s)
{
  this->RenderDelegateWithShaderHooks(s, nullptr);
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::RenderDelegateWithShaderHooks(
  const vtkRenderState* s, vtkShadowScreenMask* seed)
{
  this->BeginVolumeReceiver(s);
  this->PreRender(s);
  this->RenderDelegate(s, seed);
  this->PostRender(s);
  this->EndVolumeReceiver();
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::BeginVolumeReceiver(const vtkRenderState* s)
{
  if (this->VolumesReceive)
  {
    const vtkshadow::ShadowFrame& frame = this->GetFrame();
    this->VolumeReceiver->Update(
      frame, vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow()));
    if (frame.ShowsVolumes)
    {
      vtkshadow::MarkStage("volume_receiver"); // a stage only when there is work
    }
    for (size_t l = 0; l < frame.Lights.size(); ++l)
    {
      const int light = static_cast<int>(l);
      const std::string note = this->VolumeReceiver->GetLightNote(light, frame.Lights[l].Casts);
      if (!note.empty())
      {
        this->AddLightNote(light, note);
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::EndVolumeReceiver()
{
  this->VolumeReceiver->EndDraw();
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::ReceiveVolumeShadows(std::string& fragmentShader, vtkProp* prop)
{
  if (this->VolumesReceive)
  {
    this->VolumeReceiver->PostReplaceShaderValues(fragmentShader, prop);
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::SetVolumeShadowParameters(vtkShaderProgram* program)
{
  if (this->VolumesReceive)
  {
    this->VolumeReceiver->SetShaderParameters(program, this->ResidualLight);
  }
}

//------------------------------------------------------------------------------
std::string vtkShadowPassBase::VolumeReceiverStatsJSON() const
{
  return this->VolumeReceiver->StatsJSON();
}

//------------------------------------------------------------------------------
long long vtkShadowPassBase::GetVolumeReceiverMemoryBytes() const
{
  return this->VolumeReceiver->GetMemoryBytes();
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::GetViewport(const vtkRenderState* s, int size[2], int origin[2])
{
  origin[0] = origin[1] = 0;
  if (s->GetFrameBuffer() == nullptr)
  {
    s->GetRenderer()->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  }
  else
  {
    s->GetWindowSize(size);
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::BumpShaderTime()
{
  vtkTimeStamp t;
  t.Modified();
  this->ShaderTime = t.GetMTime();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkShadowPassBase::GetShaderStageMTime()
{
  return this->ShaderTime;
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::ReleaseGraphicsResources(vtkWindow* w)
{
  this->VolumeReceiver->ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  // The settings, from the pass's table: one line per row.
  for (const vtkshadow::Setting& row : this->GetSettings().GetRows())
  {
    os << indent << "Setting " << row.Key << ": "
       << (row.Get ? vtkshadow::FormatNumber(row.Get(*this)) : "(unused)") << "\n";
  }
  os << indent << "SkippedLights: " << this->SkippedLights << "\n";
  os << indent << "WorldKey: " << this->WorldKey << "\n";
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    os << "\n";
    this->DelegatePass->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none)\n";
  }
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::SetWorldKey(int key)
{
  // Not Modified(): switching worlds twice a frame must not look like a
  // change of settings to anything that watches the pass's MTime.
  this->WorldKey = key > 0 ? key : 0;
}

//------------------------------------------------------------------------------
void vtkShadowPassBase::ReleaseWorlds(vtkWindow*, int) {}
