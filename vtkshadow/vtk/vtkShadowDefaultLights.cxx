#include "vtkShadowDefaultLights.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderer.h"

namespace
{
// vtkLightKit's defaults (vtkLightKit.cxx): key light angle and intensity,
// and the key-to-head ratio.
constexpr double KeyElevation = 50.0;
constexpr double KeyAzimuth = 10.0;
constexpr double KeyIntensity = 0.75;
constexpr double KeyToHeadRatio = 3.0;

// The mark on the lights AddKeyLight added or dimmed (in the light's
// information).
struct vtkShadowDefaultLightKeys
{
  static vtkInformationIntegerKey* DEFAULT_LIGHT();
};
vtkInformationKeyMacro(vtkShadowDefaultLightKeys, DEFAULT_LIGHT, Integer);

void MarkDefault(vtkLight* light)
{
  if (!light->GetInformation())
  {
    vtkNew<vtkInformation> info;
    light->SetInformation(info);
  }
  light->GetInformation()->Set(vtkShadowDefaultLightKeys::DEFAULT_LIGHT(), 1);
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
bool HasOnlyHeadlights(vtkRenderer* renderer)
{
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->LightTypeIsHeadlight())
    {
      return false;
    }
  }
  return true;
}

vtkLight* AddKeyLight(vtkRenderer* renderer, std::string& message)
{
  message.clear();
  if (!renderer || !HasOnlyHeadlights(renderer))
  {
    return nullptr;
  }
  const double head = KeyIntensity / KeyToHeadRatio;
  vtkLightCollection* lights = renderer->GetLights();
  const bool hadHeadlight = lights->GetNumberOfItems() > 0;
  if (hadHeadlight)
  {
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      light->SetIntensity(light->GetIntensity() * head);
      MarkDefault(light);
    }
  }
  else
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    headlight->SetIntensity(head);
    MarkDefault(headlight);
    renderer->AddLight(headlight);
  }
  // A camera light, as in vtkLightKit: it keeps its place above and to the
  // right of the view as the camera moves, so its shadows stay in sight
  // (falling below and to the left of the casters) from every viewpoint.
  vtkNew<vtkLight> key;
  key->SetLightTypeToCameraLight();
  key->SetDirectionAngle(KeyElevation, KeyAzimuth);
  key->SetIntensity(KeyIntensity);
  MarkDefault(key);
  renderer->AddLight(key);
  message = std::string("the renderer had ") +
    (hadHeadlight ? "only headlights (dimmed to 1/4: a third of the key, vtkLightKit's ratio)"
                  : "no light") +
    ": added vtkLightKit's key light (camera light, elevation 50, azimuth 10, intensity 0.75)" +
    (hadHeadlight ? "" : " and a 0.25 headlight as fill") +
    " so shadows are visible; turn this off with AutoKeyLightOff() / key_light=False";
  return key;
}

bool IsDefaultLight(vtkLight* light)
{
  vtkInformation* info = light ? light->GetInformation() : nullptr;
  return info && info->Has(vtkShadowDefaultLightKeys::DEFAULT_LIGHT()) &&
    info->Get(vtkShadowDefaultLightKeys::DEFAULT_LIGHT()) != 0;
}

void UpdateLights(vtkRenderer* renderer)
{
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
