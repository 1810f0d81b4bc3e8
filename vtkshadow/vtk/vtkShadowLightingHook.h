// vtkShadowLightingHook.h - put per-light shadow factors into the lighting
// code of VTK 9.1's polydata mapper shaders.
#ifndef vtkShadowLightingHook_h
#define vtkShadowLightingHook_h

#include "vtkShadowDefaultLights.h" // for UpdateLights, which every pass calls with these

#include <string>
#include <vector>

class vtkLight;
class vtkRenderer;

namespace vtkshadow
{
/**
 * The renderer's switched-on lights in order: the numbering VTK's mappers
 * give the lights (lightColor0, lightColor1, ...) and every shadow pass uses.
 */
std::vector<vtkLight*> SwitchedOnLights(vtkRenderer* renderer);

/**
 * The light as a homogeneous point in world coordinates: (position, 1) for
 * point and spot lights, (direction towards the light, 0) for directional
 * ones (from the focal point back to the position).
 */
void LightHomogeneous(vtkLight* light, double out[4]);

/**
 * VTK 9.1's mapper adds each light I as
 *   diffuse += (df * lightColorI);   specular += (sf * lightColorI);
 * (Phong and Gouraud) or sets `radiance = lightColorI;` (PBR). Multiply
 * exactly those terms by `factor(I)`, where `factor` is a GLSL expression
 * with "%d" standing for the light index, and insert `prepare` (a GLSL
 * statement) once, at main's top level just before the first light term,
 * so per-fragment work (texture lookups) happens once, not per term.
 * Returns false (shader unchanged) when the shader has no light terms, e.g.
 * for actors with lighting off.
 *
 * `residual` (0..1) is how much of a light remains in its shadow: with
 * residual > 0 the factor goes in as mix(residual, 1.0, factor) per colour
 * channel, a constant in the code (0: the factor as given, the hard
 * shadow). A factor may be a float or a vec3 (a tinted shadow).
 */
bool InjectLightFactors(std::string& fragmentShader, const std::string& factor,
  const std::string& prepare, int maxLights = 16, double residual = 0.0);

/**
 * The GLSL of `factor` with `residual` of the light left in shadow:
 * "mix(<residual>, 1.0, <factor>)", or `factor` itself for residual <= 0.
 */
std::string ResidualFactor(const std::string& factor, double residual);

/**
 * The GLSL expression of the fragment's surface point in view coordinates
 * for a forward shadow lookup. "vertexVC.xyz" for surfaces. VTK 9.1's
 * impostors do not move vertexVC onto the solid they draw: a point drawn as
 * a sphere is one GL point, so vertexVC is its centre for every fragment,
 * and a line drawn as a tube is widened in clip space only, so vertexVC is
 * on the line. Both compute the solid's normal per fragment: the surface
 * is the centre plus the impostor's radius (ZCalcR times the clip w, VTK's
 * own depth correction) along it. Looked up at vertexVC, the impostor sits
 * inside its own shadow proxy and goes black.
 */
std::string SurfacePositionVC(const std::string& fragmentShader);
}

#endif
