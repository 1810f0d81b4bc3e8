/**
 * @class   vtkAutoShadowPass
 * @brief   Chooses the cheapest exact-enough shadow technique for the scene.
 *
 * Every frame (cheaply, from bounds) vtkAutoShadowPass models only what the
 * scene needs:
 * - no light that casts, or nothing that casts: no shadow work at all;
 * - every shadow falls on plane receivers (no caster can shadow another
 *   object that is not a receiver, by a conservative bounding-sphere test
 *   per light from vtkshadow's core): vtkPlanarShadowPass, exact and the
 *   cheapest;
 * - otherwise vtkCascadedShadowMapPass, which itself uses one fitted map when
 *   the visible depth ratio is small and more cascades when it is large
 *   (and, with MaxTexelPixels, the resolution that keeps the on-screen
 *   texel size under a target).
 * GetChoice() and GetReason() say what was chosen and why.
 */
#ifndef vtkAutoShadowPass_h
#define vtkAutoShadowPass_h

#include "vtkRenderPass.h"
#include "vtkshadowModule.h" // for export macro

#include <map>    // for std::map
#include <string> // for std::string
#include <utility> // for std::pair

class vtkCascadedShadowMapPass;
class vtkPlanarShadowPass;
class vtkProp;
class vtkRenderStepsPass;

class VTKSHADOW_EXPORT vtkAutoShadowPass : public vtkRenderPass
{
public:
  static vtkAutoShadowPass* New();
  vtkTypeMacro(vtkAutoShadowPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The passes it chooses between (configure them directly, e.g.
   * GetCascadedPass()->SetMaxTexelPixels(2)).
   */
  vtkGetObjectMacro(PlanarPass, vtkPlanarShadowPass);
  vtkGetObjectMacro(CascadedPass, vtkCascadedShadowMapPass);

  /**
   * "none", "planar" or "csm" for the last frame, and why.
   */
  const char* GetChoice() const { return this->Choice.c_str(); }
  const char* GetReason() const { return this->Reason.c_str(); }

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkAutoShadowPass();
  ~vtkAutoShadowPass() override;

  vtkPlanarShadowPass* PlanarPass;
  vtkCascadedShadowMapPass* CascadedPass;
  vtkRenderStepsPass* PlainPass;
  std::string Choice;
  std::string Reason;
  // Receiver planes by actor, with the time they were computed at.
  struct CachedPlane
  {
    vtkMTimeType Time = 0;
    bool Flat = false;
    double Plane[4] = { 0, 0, 0, 0 };
  };
  std::map<vtkProp*, CachedPlane> Planes;
  // Convexity of non-receivers (a non-convex object may shadow itself).
  std::map<vtkProp*, std::pair<vtkMTimeType, bool>> Convex;

private:
  vtkAutoShadowPass(const vtkAutoShadowPass&) = delete;
  void operator=(const vtkAutoShadowPass&) = delete;

  void Decide(const vtkRenderState* s);
};

#endif
