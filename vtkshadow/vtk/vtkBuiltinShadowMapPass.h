/**
 * @class   vtkBuiltinShadowMapPass
 * @brief   The "vtk" technique: VTK 9.1's own shadow maps, the baseline.
 *
 * VTK's vtkShadowMapBakerPass + vtkShadowMapPass under a vtkCameraPass,
 * assembled as VTK's TestShadowMapPass does, at MapResolution texels
 * (default 2048, option map_resolution), followed by VTK's volumetric and
 * overlay passes (volumes and 2D actors are drawn, unshadowed; translucent
 * actors are not drawn). Shaders without a view-space vertex (actors with
 * lighting off, unlit lines) keep VTK's shaders: VTK 9.1's pass alone
 * breaks their compilation and crashes. residual_light scales VTK's own
 * vtkLight::ShadowAttenuation. Every vtkshadow technique is
 * measured against it. Its pipeline is its delegate and renders the scene
 * itself, so SetDelegatePass is not used.
 */
#ifndef vtkBuiltinShadowMapPass_h
#define vtkBuiltinShadowMapPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

class vtkShadowMapPass;

class VTKSHADOW_EXPORT vtkBuiltinShadowMapPass : public vtkShadowPassBase
{
public:
  static vtkBuiltinShadowMapPass* New();
  vtkTypeMacro(vtkBuiltinShadowMapPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Edge length of VTK's maps in texels (default 2048).
   */
  void SetMapResolution(int resolution);
  vtkGetMacro(MapResolution, int);

  /**
   * VTK's baker keeps one single-channel float map per shadowing light and
   * one shared depth attachment of the same size, 4 bytes a texel each.
   */
  long long GetMemoryBytes() const override;

  /**
   * The settings (SetOption keys, ranges, docs) of this pass: its table in
   * the .cxx, listed by `vtkshadow-render --list-settings`.
   */
  vtkShadowSettingsMacro();

  void Render(const vtkRenderState* s) override;

  /**
   * False: VTK's shadow passes draw the scene with steps of their own.
   */
  bool SetApplicationScene(vtkRenderPass*) override { return false; }

protected:
  vtkBuiltinShadowMapPass();
  ~vtkBuiltinShadowMapPass() override;

  vtkShadowMapPass* Shadows;
  int MapResolution;
  int ShadowingLights; // in the last frame

private:
  vtkBuiltinShadowMapPass(const vtkBuiltinShadowMapPass&) = delete;
  void operator=(const vtkBuiltinShadowMapPass&) = delete;
};

#endif
