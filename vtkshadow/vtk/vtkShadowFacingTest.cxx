#include "vtkShadowFacingTest.h"

#include "vtkShadowFacingFS.h"
#include "vtkShadowFrame.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include "vsh_mat4.h"

#include <algorithm>
#include <cmath>

namespace vtkshadow
{
FacingLights FacingLightsOf(vtkRenderer* renderer, const ShadowFrame& frame, bool sampled)
{
  FacingLights out;
  // The mapper's view coordinates (its MCVCMatrix): the camera's model-view
  // transform, in double; a direction (w = 0) loses the translation.
  double view[16];
  vtkMatrix4x4::DeepCopy(view, renderer->GetActiveCamera()->GetModelViewTransformMatrix());
  const int count = std::min(static_cast<int>(frame.Lights.size()), FacingLights::MaxLights);
  for (int light = 0; light < count; ++light)
  {
    double vc[4];
    const double* world = frame.Lights[light].Homogeneous;
    vsh_mat4_transform_point4(view, world, vc);
    for (int k = 0; k < 4; ++k)
    {
      out.LightVC[light][k] = static_cast<float>(vc[k]);
    }
    // The view transform is rigid: a radius keeps its length.
    const double size = sampled ? frame.Lights[light].Size : 0.0;
    out.SizeVC[light] = static_cast<float>(
      world[3] != 0.0 ? size : std::tan(0.5 * size * 3.14159265358979323846 / 180.0));
  }
  return out;
}

std::string FacingShaderCode(const std::string& prefix)
{
  static const std::string stem = "vshFacing";
  std::string code = vtkShadowFacingFS;
  if (prefix == stem)
  {
    return code;
  }
  for (size_t at = code.find(stem); at != std::string::npos; at = code.find(stem, at))
  {
    code.replace(at, stem.size(), prefix);
    at += prefix.size();
  }
  return code;
}

void SetFacingUniforms(vtkShaderProgram* program, const std::string& prefix, int closedLights,
  const FacingLights& lights)
{
  const std::string bits = prefix + "Lights";
  if (!program->IsUniformUsed(bits.c_str()))
  {
    return;
  }
  program->SetUniformi(bits.c_str(), closedLights);
  program->SetUniform4fv((prefix + "LightVC").c_str(), FacingLights::MaxLights, lights.LightVC);
  program->SetUniform1fv((prefix + "LightSize").c_str(), FacingLights::MaxLights, lights.SizeVC);
}

bool FacingShaderSet::Commit()
{
  std::sort(this->Next.begin(), this->Next.end());
  this->Next.erase(std::unique(this->Next.begin(), this->Next.end()), this->Next.end());
  if (this->Next == this->Props)
  {
    return false;
  }
  this->Props.swap(this->Next);
  return true;
}

bool FacingShaderSet::Has(vtkProp* prop) const
{
  return std::binary_search(this->Props.begin(), this->Props.end(), prop);
}
}
