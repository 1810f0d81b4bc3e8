#include "vtkShadowDefaultLights.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderer.h"

#include <cmath>
#include <vector>

namespace
{
// vtkLightKit's defaults (vtkLightKit.cxx): key light angle and intensity,
// and the key-to-head ratio.
constexpr double KeyElevation = 50.0;
constexpr double KeyAzimuth = 10.0;
constexpr double KeyIntensity = 0.75;
constexpr double KeyToHeadRatio = 3.0;
constexpr double Head = KeyIntensity / KeyToHeadRatio;

// What a light is to the default lights (in the light's information).
enum Role
{
  Own = 0,    // the application's
  Key = 1,    // the key light added
  Fill = 2,   // the fill headlight added
  Dimmed = 3, // an application headlight dimmed to be the fill
};

// The keys: on a light its Role and, when dimmed, its own intensity; on a
// renderer whether it keeps the default lights.
struct vtkShadowDefaultLightKeys
{
  static vtkInformationIntegerKey* ROLE();
  static vtkInformationDoubleKey* OWN_INTENSITY();
  static vtkInformationIntegerKey* AUTO_KEY_LIGHT();
};
vtkInformationKeyMacro(vtkShadowDefaultLightKeys, ROLE, Integer);
vtkInformationKeyMacro(vtkShadowDefaultLightKeys, OWN_INTENSITY, Double);
vtkInformationKeyMacro(vtkShadowDefaultLightKeys, AUTO_KEY_LIGHT, Integer);

Role RoleOf(vtkLight* light)
{
  vtkInformation* info = light->GetInformation();
  return info && info->Has(vtkShadowDefaultLightKeys::ROLE())
    ? static_cast<Role>(info->Get(vtkShadowDefaultLightKeys::ROLE()))
    : Own;
}

vtkInformation* InformationOf(vtkLight* light)
{
  if (!light->GetInformation())
  {
    vtkNew<vtkInformation> info;
    light->SetInformation(info);
  }
  return light->GetInformation();
}

void AddLight(vtkRenderer* renderer, Role role)
{
  vtkNew<vtkLight> light;
  if (role == Key)
  {
    // A camera light, as in vtkLightKit: it keeps its place above and to
    // the right of the view as the camera moves, so its shadows stay in
    // sight (falling below and to the left of the casters) from every
    // viewpoint.
    light->SetLightTypeToCameraLight();
    light->SetDirectionAngle(KeyElevation, KeyAzimuth);
    light->SetIntensity(KeyIntensity);
  }
  else
  {
    light->SetLightTypeToHeadlight();
    light->SetIntensity(Head);
  }
  InformationOf(light)->Set(vtkShadowDefaultLightKeys::ROLE(), role);
  renderer->AddLight(light);
}

void Dim(vtkLight* light)
{
  vtkInformation* info = InformationOf(light);
  info->Set(vtkShadowDefaultLightKeys::ROLE(), Dimmed);
  info->Set(vtkShadowDefaultLightKeys::OWN_INTENSITY(), light->GetIntensity());
  light->SetIntensity(light->GetIntensity() * Head);
}

// Its own intensity back, unless the application has set another since.
void Undim(vtkLight* light)
{
  vtkInformation* info = light->GetInformation();
  const double own = info->Get(vtkShadowDefaultLightKeys::OWN_INTENSITY());
  if (std::abs(light->GetIntensity() - own * Head) <= 1e-12 * std::abs(own))
  {
    light->SetIntensity(own);
  }
  info->Remove(vtkShadowDefaultLightKeys::ROLE());
  info->Remove(vtkShadowDefaultLightKeys::OWN_INTENSITY());
}

// The renderer's lights by role.
struct Lights
{
  std::vector<vtkLight*> AddedLights;    // key and fill
  std::vector<vtkLight*> DimmedLights;   // the application's, dimmed
  std::vector<vtkLight*> UndimmedLights; // the application's others
  int Keys = 0, Fills = 0, OwnCount = 0;
  bool OwnOnlyHeadlights = true;

  explicit Lights(vtkRenderer* renderer)
  {
    vtkLightCollection* lights = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      const Role role = RoleOf(light);
      this->Keys += role == Key ? 1 : 0;
      this->Fills += role == Fill ? 1 : 0;
      if (role == Key || role == Fill)
      {
        this->AddedLights.push_back(light);
        continue;
      }
      ++this->OwnCount;
      this->OwnOnlyHeadlights = this->OwnOnlyHeadlights && light->LightTypeIsHeadlight();
      (role == Dimmed ? this->DimmedLights : this->UndimmedLights).push_back(light);
    }
  }
};

// The lights the renderer should have now (SetAutoKeyLight); what changed,
// "" when nothing did.
std::string ApplyAutoKeyLight(vtkRenderer* renderer)
{
  const Lights lights(renderer);
  if (!vtkshadow::GetAutoKeyLight(renderer) || !lights.OwnOnlyHeadlights)
  {
    if (lights.AddedLights.empty() && lights.DimmedLights.empty())
    {
      return std::string();
    }
    for (vtkLight* light : lights.AddedLights)
    {
      renderer->RemoveLight(light);
    }
    for (vtkLight* light : lights.DimmedLights)
    {
      Undim(light);
    }
    return "removed the key light" + std::string(lights.Fills ? " and the fill" : "") +
      " added for shadows" +
      (lights.DimmedLights.empty() ? "" : ", headlights at their own intensity") +
      (lights.OwnOnlyHeadlights ? ": key_light is off" : ": the renderer has lights of its own");
  }
  const bool keyAdded = lights.Keys == 0;
  if (keyAdded)
  {
    AddLight(renderer, Key);
  }
  // The fill: the application's headlights dimmed, or one of its own.
  for (vtkLight* light : lights.UndimmedLights)
  {
    Dim(light);
  }
  const bool fillWanted = lights.OwnCount == 0;
  for (vtkLight* light : lights.AddedLights)
  {
    if (RoleOf(light) == Fill && !fillWanted)
    {
      renderer->RemoveLight(light);
    }
  }
  if (fillWanted && lights.Fills == 0)
  {
    AddLight(renderer, Fill);
  }
  const bool fillChanged = (lights.Fills > 0) != fillWanted;
  const bool changed = keyAdded || fillChanged || !lights.UndimmedLights.empty();
  return changed ? vtkshadow::DescribeDefaultLights(renderer) : std::string();
}

// Where vtkRenderer::UpdateLightsGeometryToFollowCamera puts a light of
// this type: a headlight at the camera, a camera light in the camera's
// frame; scene lights stay.
void FollowCamera(vtkCamera* camera, vtkLight* light)
{
  if (light->LightTypeIsHeadlight())
  {
    light->SetPosition(camera->GetPosition());
    light->SetFocalPoint(camera->GetFocalPoint());
  }
  else if (light->LightTypeIsCameraLight())
  {
    light->SetTransformMatrix(camera->GetCameraLightTransformMatrix());
  }
}
}

namespace vtkshadow
{
void SetAutoKeyLight(vtkRenderer* renderer, bool on)
{
  if (!renderer->GetInformation())
  {
    vtkNew<vtkInformation> info;
    renderer->SetInformation(info);
  }
  renderer->GetInformation()->Set(vtkShadowDefaultLightKeys::AUTO_KEY_LIGHT(), on ? 1 : 0);
}

bool GetAutoKeyLight(vtkRenderer* renderer)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  return info && info->Has(vtkShadowDefaultLightKeys::AUTO_KEY_LIGHT()) &&
    info->Get(vtkShadowDefaultLightKeys::AUTO_KEY_LIGHT()) != 0;
}

vtkLight* FindKeyLight(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return nullptr;
  }
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (RoleOf(light) == Key)
    {
      return light;
    }
  }
  return nullptr;
}

std::string DescribeDefaultLights(vtkRenderer* renderer)
{
  if (!FindKeyLight(renderer))
  {
    return std::string();
  }
  const Lights lights(renderer);
  return std::string("the renderer has ") +
    (lights.OwnCount ? "only headlights (dimmed to 1/4: a third of the key, vtkLightKit's ratio)"
                     : "no light of its own") +
    ": added vtkLightKit's key light (camera light, elevation 50, azimuth 10, intensity 0.75)" +
    (lights.Fills ? " and a 0.25 headlight as fill" : "") +
    " so shadows are visible; turn this off with AutoKeyLightOff() / key_light=False";
}

bool IsDefaultLight(vtkLight* light)
{
  return light && RoleOf(light) != Own;
}

void UpdateLights(vtkRenderer* renderer)
{
  const std::string change = ApplyAutoKeyLight(renderer);
  if (!change.empty())
  {
    vtkWarningWithObjectMacro(renderer, << "enable shadows: " << change);
  }
  vtkLightCollection* lights = renderer->GetLights();
  if (lights->GetNumberOfItems() == 0 && renderer->GetAutomaticLightCreation())
  {
    renderer->CreateLight();
  }
  if (renderer->GetLightFollowCamera())
  {
    renderer->UpdateLightsGeometryToFollowCamera();
    return;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (IsDefaultLight(light))
    {
      FollowCamera(camera, light);
    }
  }
}
}
