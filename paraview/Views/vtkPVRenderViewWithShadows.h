/**
 * @class   vtkPVRenderViewWithShadows
 * @brief   ParaView's render view with a vtkshadow technique.
 *
 * The view builds the technique's pass from vtkShadowTechniqueRegistry and
 * puts it into the view's synchronized renderers (SetRenderPass), the place
 * ParaView keeps for a geometry pass: IceT's compositing pass, the camera
 * pass and FXAA stay around it. The technique's scene pass is a
 * vtkPVDefaultPass, so lights, translucent geometry (depth peeling),
 * volumes and hidden-line removal are rendered exactly as in the plain view.
 * "none" removes the pass: the view is then ParaView's own.
 *
 * Flat actors (one extent at most 1e-6 of the largest) are marked as planar
 * receivers (vtkShadowPassBase::RECEIVER) every frame, because ParaView's
 * representations cannot carry the flag themselves.
 *
 * With more than one process (pvbatch or pvserver under MPI) the view gives
 * the pass the global controller: csm reduces its bounds and min-reduces
 * its maps over the ranks; the techniques that cannot be made right across
 * ranks fall back to csm and say so in ShadowStatus.
 */
#ifndef vtkPVRenderViewWithShadows_h
#define vtkPVRenderViewWithShadows_h

#include "vtkPVRenderView.h"
#include "vtkshadowParaViewModule.h" // for export macro

#include <string> // for std::string

class vtkShadowPassBase;
class vtkStringArray;

class VTKSHADOWPARAVIEW_EXPORT vtkPVRenderViewWithShadows : public vtkPVRenderView
{
public:
  static vtkPVRenderViewWithShadows* New();
  vtkTypeMacro(vtkPVRenderViewWithShadows, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The technique, a name from vtkShadowTechniqueRegistry (default "csm").
   * An unknown name is reported and leaves the technique unchanged.
   */
  void SetShadowTechnique(const char* name);
  const char* GetShadowTechnique() const { return this->Technique.c_str(); }

  /**
   * The registry's technique names, for the property panel's list.
   */
  vtkStringArray* GetShadowTechniqueNames();

  /**
   * auto's error target in percent of wrongly lit pixels (max_error).
   */
  void SetShadowMaxError(double percent);
  /**
   * csm's (and auto's maps') cascades (0 = as many as the depth range asks
   * for), map edge length in texels and filter (0 hardware 2x2, 1 PCF,
   * 2 Poisson).
   */
  void SetShadowCascades(int cascades);
  void SetShadowMapResolution(int texels);
  void SetShadowFilter(int filter);

  /**
   * What the technique did in the last frame, as JSON (the pass's
   * GetStatsJSON), with "fallback" when the technique was replaced.
   */
  const char* GetShadowStatus();

protected:
  vtkPVRenderViewWithShadows();
  ~vtkPVRenderViewWithShadows() override;

  void Render(bool interactive, bool skip_rendering) override;

  /**
   * Build the pass for the current technique and settings and give it to
   * the synchronized renderers (nullptr for "none").
   */
  void RebuildPass();
  void MarkPlanarReceivers();

  std::string Technique;
  std::string Fallback;
  std::string Status;
  double MaxError;
  int Cascades;
  int MapResolution;
  int Filter;
  vtkShadowPassBase* Pass;
  vtkStringArray* Names;

private:
  vtkPVRenderViewWithShadows(const vtkPVRenderViewWithShadows&) = delete;
  void operator=(const vtkPVRenderViewWithShadows&) = delete;
};

#endif
