// vtkShadowFacingTest.h - the facing test shared by the passes that leave a
// closed caster's own dark side to the lighting (volume, planar): a facet of
// a closed caster that faces away from a light is in that caster's shadow
// (glsl/vtkShadowFacingFS.glsl; docs/shadow-volumes.md, "The terminator").
#ifndef vtkShadowFacingTest_h
#define vtkShadowFacingTest_h

#include <string>
#include <vector>

class vtkProp;
class vtkRenderer;
class vtkShaderProgram;

namespace vtkshadow
{
struct ShadowFrame;

/**
 * The per-frame inputs of the test, as the shader reads them: each light in
 * the mappers' view coordinates ((position, 1) or (towards the light, 0)),
 * and its size: the radius of a positional light or tan(angle / 2) of a
 * directional one where the pass samples the light, else 0 (counted hard).
 */
struct FacingLights
{
  static constexpr int MaxLights = 8;
  float LightVC[MaxLights][4] = {};
  float SizeVC[MaxLights] = {};
};

/**
 * The frame's lights in the view coordinates of the renderer's camera (its
 * model-view matrix, in double, so camera-relative), with their sizes
 * (ShadowFrameLight::Size) when the pass samples lights with a size
 * (`sampled`), else every light counted hard.
 */
FacingLights FacingLightsOf(vtkRenderer* renderer, const ShadowFrame& frame, bool sampled);

/**
 * The test's GLSL (declarations and functions, to go after VTK's lighting
 * declarations) with every name beginning "vshFacing" renamed to begin with
 * `prefix`: vshFacingLights, vshFacingLightVC, vshFacingLightSize,
 * vshFacingPrepare(positionVC), vshFacingLit(light, positionVC) and
 * vshFacingCombine(light, positionVC, mask). Two passes in one shader use
 * two prefixes.
 */
std::string FacingShaderCode(const std::string& prefix);

/**
 * Set the test's uniforms (under `prefix`) for one draw: `closedLights` has
 * bit I set where the actor drawn is a closed caster of light I (0: no
 * test). Does nothing when the program does not use them.
 */
void SetFacingUniforms(vtkShaderProgram* program, const std::string& prefix, int closedLights,
  const FacingLights& lights);

/**
 * The actors whose shaders carry the test's code. Only a closed caster's
 * fragments need it: in any other fragment it multiplies every light by 1
 * and still costs its derivatives and per-light tests, as llvmpipe runs a
 * branch on a uniform both ways. A pass lists this frame's set between
 * Begin() and Commit(); Commit() says whether it changed, and then the pass
 * bumps its shader time so that the mappers rebuild their shaders. Has()
 * answers for the set last committed, in the pass's shader replacements.
 */
class FacingShaderSet
{
public:
  void Begin() { this->Next.clear(); }
  void Add(vtkProp* prop) { this->Next.push_back(prop); }
  bool Commit();
  bool Has(vtkProp* prop) const;

private:
  std::vector<vtkProp*> Props; // sorted, unique
  std::vector<vtkProp*> Next;  // kept to reuse its storage frame to frame
};
}

#endif
