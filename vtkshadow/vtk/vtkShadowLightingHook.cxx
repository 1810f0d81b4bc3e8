#include "vtkShadowLightingHook.h"

#include "vtkLightCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>

namespace vtkshadow
{
void UpdateLights(vtkRenderer* renderer)
{
  if (renderer->GetLights()->GetNumberOfItems() == 0 && renderer->GetAutomaticLightCreation())
  {
    renderer->CreateLight();
  }
  renderer->UpdateLightsGeometryToFollowCamera();
}

bool InjectLightFactors(std::string& fs, const std::string& factor, const std::string& prepare,
  int maxLights)
{
  size_t first = std::string::npos;
  for (int i = 0; i < maxLights; ++i)
  {
    const std::string n = std::to_string(i);
    std::string f = factor;
    for (size_t at = f.find("%d"); at != std::string::npos; at = f.find("%d", at + n.size()))
    {
      f.replace(at, 2, n);
    }
    const std::string terms[3][2] = {
      { "diffuse += (df * lightColor" + n + ");", "diffuse += (df * lightColor" + n + " * " + f + ");" },
      { "specular += (sf * lightColor" + n + ");",
        "specular += (sf * lightColor" + n + " * " + f + ");" },
      { "radiance = lightColor" + n + ";", "radiance = lightColor" + n + " * " + f + ";" }
    };
    for (const auto& term : terms)
    {
      first = std::min(first, fs.find(term[0]));
      vtkShaderProgram::Substitute(fs, term[0], term[1], true);
    }
  }
  if (first == std::string::npos)
  {
    return false;
  }
  const size_t line = fs.rfind('\n', first);
  fs.insert(line == std::string::npos ? 0 : line + 1, "  " + prepare + "\n");
  return true;
}
}
