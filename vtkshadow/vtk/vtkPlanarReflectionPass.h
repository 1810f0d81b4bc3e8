/**
 * @class   vtkPlanarReflectionPass
 * @brief   Planar mirrors drawn with the stencil, around any shadow technique.
 *
 * Not a shadow technique but a pass that wraps one: its delegate is the
 * technique's pass (vtkShadowTechnique::CreatePass, or any vtkRenderPass),
 * so mirrors compose with every technique, and the reflection shows that
 * technique's shadows. An actor is a mirror when its property keys hold
 * MIRROR() = R > 0 (vtkShadowScene sets it from the scene's "mirror": R);
 * its plane is fitted to its points. Per frame:
 *
 * 1. the delegate renders the scene as it always does;
 * 2. for each mirror whose reflecting face the camera sees (the side its
 *    normals point to; a camera below the mirror or in its plane gets no
 *    reflection), the delegate renders the mirrored scene into an
 *    offscreen target of the viewport's size: every other actor's matrix
 *    and every scene light (position and focal point) reflected through
 *    the plane by a matrix composed in double precision relative to the
 *    eye, triangles wound clockwise (a reflection flips winding, so the
 *    outside of the mirrored geometry stays front-facing), the clipping
 *    range refitted, and a clip plane at the mirror (a fragment test in
 *    view coordinates) so nothing between the eye and the mirror, i.e.
 *    nothing from behind the mirror, shows through. The technique bakes
 *    its shadows for this mirrored world, so the reflection has shadows;
 *    with ReflectShadows off a plain vtkRenderStepsPass draws it instead;
 * 3. the mirror is drawn again into the stencil, depth-tested against the
 *    scene (its visible pixels only), and R x the reflection is added to
 *    those pixels: the mirrors seen are shaded at (1 - R) in step 1 (a
 *    factor in the fragment shader), so colour = (1 - R) mirror + R
 *    reflection, clamped once.
 *
 * One bounce: other mirrors appear in a reflection at (1 - R) of their
 * shading (their own reflection is the bounce not drawn, as in a ray
 * tracer stopped at that depth). Camera and headlights are not mirrored. The render target must
 * have a stencil buffer (vtkRenderWindow::StencilCapableOn() before the
 * first render); without one the mirrors are drawn without reflections and
 * GetStatsJSON says so.
 */
#ifndef vtkPlanarReflectionPass_h
#define vtkPlanarReflectionPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkInformationDoubleKey;

class VTKSHADOW_EXPORT vtkPlanarReflectionPass : public vtkShadowPassBase
{
public:
  static vtkPlanarReflectionPass* New();
  vtkTypeMacro(vtkPlanarReflectionPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Property key: reflectance R in (0, 1] of a planar mirror actor.
   */
  static vtkInformationDoubleKey* MIRROR();

  /**
   * Whether the mirrored scene is drawn by the delegate (the technique,
   * with its shadows; default) or by a plain vtkRenderStepsPass (no
   * shadows in the reflection, cheaper).
   */
  vtkSetMacro(ReflectShadows, bool);
  vtkGetMacro(ReflectShadows, bool);
  vtkBooleanMacro(ReflectShadows, bool);

  /**
   * Switch the reflections off without removing the pass (default on).
   */
  vtkSetMacro(Reflections, bool);
  vtkGetMacro(Reflections, bool);
  vtkBooleanMacro(Reflections, bool);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /**
   * The delegate's memory plus the offscreen target's.
   */
  long long GetMemoryBytes() const override;
  /**
   * The delegate's details and "reflections": mirrors found, drawn, why not,
   * and mirror_worlds_bytes, the GPU memory the technique holds for the
   * mirrored worlds (its second set of maps or masks: each mirror's
   * reflection is drawn with world key 1 + its index among the mirrors seen,
   * vtkShadowPassBase::SetWorldKey; freed when the mirror is no longer seen
   * or its reflection is drawn without the technique).
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const override;
  /**
   * Settings go to the delegate (the technique's pass).
   */
  bool SetOption(const char* key, double value) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkPlanarReflectionPass();
  ~vtkPlanarReflectionPass() override;

  bool ReflectShadows;
  bool Reflections;

private:
  vtkPlanarReflectionPass(const vtkPlanarReflectionPass&) = delete;
  void operator=(const vtkPlanarReflectionPass&) = delete;

  struct Internals;
  struct Mirror;
  std::unique_ptr<Internals> Impl;

  void FindMirrors(const vtkRenderState* s);
  bool RenderMirrored(const vtkRenderState* s, const Mirror& mirror);
  void Composite(const vtkRenderState* s, const Mirror& mirror);
  void ReleaseUnusedWorlds(const vtkRenderState* s);
  bool IsCameraViewDraw(bool atOrigin) const;
  double MirrorShade(vtkProp* prop) const;
};

#endif
