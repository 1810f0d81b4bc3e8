#include "vtkShadowFrame.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowPassBase.h"

#include "vsh_mat4.h"

#include <algorithm>

namespace vtkshadow
{
namespace
{
void GatherCamera(vtkCamera* camera, ShadowFrame& frame)
{
  camera->GetPosition(frame.Eye);
  camera->GetFocalPoint(frame.FocalPoint);
  camera->GetViewUp(frame.ViewUp);
  frame.ViewAngle = camera->GetViewAngle();
  camera->GetClippingRange(frame.ClippingRange);
  vtkMatrix4x4::DeepCopy(frame.View, camera->GetViewTransformMatrix());
  vtkMatrix4x4::DeepCopy(frame.ViewRotation, frame.View);
  frame.ViewRotation[3] = frame.ViewRotation[7] = frame.ViewRotation[11] = 0.0;
  vtkMatrix4x4::DeepCopy(
    frame.Projection, camera->GetProjectionTransformMatrix(frame.Aspect, -1, 1));
  vsh_mat4_multiply(frame.Projection, frame.ViewRotation, frame.CameraRelative);
}

ShadowFrameLight GatherLight(vtkLight* light)
{
  ShadowFrameLight out;
  out.Light = light;
  out.Positional = light->GetPositional() != 0;
  out.Headlight = light->LightTypeIsHeadlight();
  LightHomogeneous(light, out.Homogeneous);
  light->GetTransformedPosition(out.Position);
  light->GetTransformedFocalPoint(out.FocalPoint);
  out.ConeAngle = light->GetConeAngle();
  out.Radius = vtkShadowPassBase::GetLightRadius(light);
  out.Angle = vtkShadowPassBase::GetLightAngle(light);
  out.Size = out.Positional ? out.Radius : out.Angle;
  return out;
}
}

//------------------------------------------------------------------------------
void GatherShadowFrame(const vtkRenderState* s, bool actors, ShadowFrame& frame)
{
  vtkRenderer* renderer = s->GetRenderer();
  frame.Renderer = renderer;
  frame.State = s;
  UpdateLights(renderer);
  vtkShadowPassBase::GetViewport(s, frame.Size, frame.Origin);
  frame.Aspect = static_cast<double>(std::max(frame.Size[0], 1)) / std::max(frame.Size[1], 1);
  GatherCamera(renderer->GetActiveCamera(), frame);
  frame.Lights.clear();
  for (vtkLight* light : SwitchedOnLights(renderer))
  {
    frame.Lights.push_back(GatherLight(light));
  }
  frame.ShowsVolumes = HasVisibleVolumes(renderer);
  frame.HasActors = false;
  frame.Drawn.clear();
  frame.Actors.clear();
  frame.Translucent.clear();
  if (actors)
  {
    GatherShadowFrameActors(s, frame);
  }
}

//------------------------------------------------------------------------------
void EyeHomogeneous(const ShadowFrame& frame, double out[4])
{
  // A parallel projection's bottom row is (0, 0, 0, 1).
  const bool parallel = frame.Projection[14] == 0.0;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = parallel ? frame.Eye[k] - frame.FocalPoint[k] : frame.Eye[k];
  }
  out[3] = parallel ? 0.0 : 1.0;
}

//------------------------------------------------------------------------------
void GatherShadowFrameActors(const vtkRenderState* s, ShadowFrame& frame)
{
  frame.Drawn = ShadowActors(s);
  frame.Actors = ShadowActors(s->GetRenderer());
  frame.Translucent = TranslucentShadowActors(s->GetRenderer());
  frame.HasActors = true;
}
}
