/**
 * @class   vtkNoShadowPass
 * @brief   The "none" technique: VTK's standard passes, no shadows.
 *
 * Renders the scene through its delegate (a vtkRenderStepsPass unless set)
 * and nothing else; the reference every technique's cost is measured
 * against.
 */
#ifndef vtkNoShadowPass_h
#define vtkNoShadowPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

class VTKSHADOW_EXPORT vtkNoShadowPass : public vtkShadowPassBase
{
public:
  static vtkNoShadowPass* New();
  vtkTypeMacro(vtkNoShadowPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;

protected:
  vtkNoShadowPass() = default;
  ~vtkNoShadowPass() override = default;

private:
  vtkNoShadowPass(const vtkNoShadowPass&) = delete;
  void operator=(const vtkNoShadowPass&) = delete;
};

#endif
