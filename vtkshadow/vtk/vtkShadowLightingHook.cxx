#include "vtkShadowLightingHook.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace vtkshadow
{
std::vector<vtkLight*> SwitchedOnLights(vtkRenderer* renderer)
{
  std::vector<vtkLight*> lights;
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (light->GetSwitch())
    {
      lights.push_back(light);
    }
  }
  return lights;
}

void LightHomogeneous(vtkLight* light, double out[4])
{
  double p[3], f[3];
  light->GetTransformedPosition(p);
  light->GetTransformedFocalPoint(f);
  const bool positional = light->GetPositional() != 0;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = positional ? p[k] : p[k] - f[k];
  }
  out[3] = positional ? 1.0 : 0.0;
}

std::string ResidualFactor(const std::string& factor, double residual)
{
  if (!(residual > 0.0))
  {
    return factor;
  }
  // Nine digits: the float the shader reads is the one asked for.
  char value[32];
  std::snprintf(value, sizeof value, "%.9g", std::min(residual, 1.0));
  std::string literal = value;
  if (literal.find_first_of(".e") == std::string::npos)
  {
    literal += ".0"; // GLSL: "1" is an int, mix() wants floats
  }
  // vec3: a factor may be a colour (a tinted screen mask) or a float.
  return "mix(vec3(" + literal + "), vec3(1.0), vec3(" + factor + "))";
}

std::string SurfacePositionVC(const std::string& fs)
{
  // Both impostors leave vertexVC on the centre (the point, the line: the
  // wide-line geometry shader offsets gl_Position only) and compute the
  // solid's unit normal per fragment, so the surface is one radius out.
  const bool impostor = fs.find("uniform float ZCalcR") != std::string::npos &&
    (fs.find("gl_PointCoord") != std::string::npos || fs.find("tubeBasis2") != std::string::npos);
  if (!impostor)
  {
    return "vertexVC.xyz";
  }
  return "(vertexVC.xyz + normalize(normalVCVSOutput) * "
         "(ZCalcR * (cameraParallel == 0 ? -vertexVC.z : 1.0)))";
}

bool InjectLightFactors(std::string& fs, const std::string& factorExpression,
  const std::string& prepare, int maxLights, double residual)
{
  const std::string factor = ResidualFactor(factorExpression, residual);
  // Each term is found by its head ("diffuse += (df * lightColor3") followed
  // by anything but a digit, and the factor goes right after the head: so a
  // second pass (cascaded maps around planar, say) multiplies its own factor
  // into a term the first one already changed.
  size_t first = std::string::npos;
  for (int i = 0; i < maxLights; ++i)
  {
    const std::string n = std::to_string(i);
    std::string f = factor;
    for (size_t at = f.find("%d"); at != std::string::npos; at = f.find("%d", at + n.size()))
    {
      f.replace(at, 2, n);
    }
    const std::string heads[3] = { "diffuse += (df * lightColor" + n,
      "specular += (sf * lightColor" + n, "radiance = lightColor" + n };
    for (const std::string& head : heads)
    {
      for (size_t at = fs.find(head); at != std::string::npos; at = fs.find(head, at + 1))
      {
        const size_t end = at + head.size();
        if (end < fs.size() && std::isdigit(static_cast<unsigned char>(fs[end])))
        {
          continue; // lightColor1 is not the head of lightColor12
        }
        first = std::min(first, at);
        fs.insert(end, " * " + f);
      }
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
