/**
 * @class   vtkShadowTechnique
 * @brief   Builds the render-pass pipeline of one shadow technique.
 *
 * vtkShadowTechnique turns a technique name into the render pass that a
 * vtkOpenGLRenderer runs, so that tools, tests and applications switch
 * techniques without knowing how each is assembled:
 *
 * - "none": VTK's standard passes (vtkRenderStepsPass), no shadows.
 * - "vtk":  VTK 9.1's own vtkShadowMapBakerPass + vtkShadowMapPass under a
 *           vtkCameraPass, as VTK's TestShadowMapPass sets them up, with the
 *           map resolution set by SetMapResolution() (default 2048). This is
 *           the baseline every vtkshadow technique is measured against.
 *
 * - "planar": vtkPlanarShadowPass, exact shadows on the actors marked with
 *           vtkPlanarShadowPass::RECEIVER() (vtkShadowScene marks the scene's
 *           "receiver": true planes).
 *
 * - "csm":    vtkCascadedShadowMapPass (cascaded, spot and cube maps).
 * - "auto":   vtkAutoShadowPass: per light none, planar or csm, chosen by an
 *           error target (option max_error, or max_texel_px).
 *
 * @code{.py}
 * technique = vtkshadow.vtkShadowTechnique()
 * technique.SetName("vtk")
 * technique.Install(renderer)
 * @endcode
 */
#ifndef vtkShadowTechnique_h
#define vtkShadowTechnique_h

#include "vtkObject.h"
#include "vtkshadowModule.h" // for export macro

#include <string> // for std::string

class vtkCascadedShadowMapPass;
class vtkRenderPass;
class vtkRenderer;

class VTKSHADOW_EXPORT vtkShadowTechnique : public vtkObject
{
public:
  static vtkShadowTechnique* New();
  vtkTypeMacro(vtkShadowTechnique, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The technique name (default "none"). Unknown names are rejected by
   * IsValid() and CreatePass().
   */
  vtkSetStringMacro(Name);
  vtkGetStringMacro(Name);

  /**
   * Shadow map edge length in texels for map-based techniques (default 2048).
   */
  vtkSetClampMacro(MapResolution, int, 16, 16384);
  vtkGetMacro(MapResolution, int);

  /**
   * The settings of the "csm" technique: CreatePass() copies them into each
   * new vtkCascadedShadowMapPass (MapResolution comes from this object).
   */
  vtkCascadedShadowMapPass* GetCascadedSettings();

  /**
   * Set a technique setting by name (command lines, the C API). Keys:
   * map_resolution, and for "csm" (and auto's cascaded pass): cascades, ratio_per_cascade, split
   * (0 uniform, 1 log, 2 practical, 3 explicit), lambda, split_fraction_<i>,
   * stable, max_texel_px, memory_budget, bias_scale, filter (0 hardware 2x2,
   * 1 PCF, 2 Poisson), pcf_size, poisson_radius, blend_band, max_distance,
   * fade, debug_cascades; for "auto": max_error (its wrong_pct target,
   * default 0.5) and max_texel_px (a texel-size target instead). Returns false for an unknown key or a value out of
   * range (nothing is changed then).
   */
  bool SetOption(const char* key, double value);

  /**
   * Technique details of the last frame rendered on `renderer` as a JSON
   * object (cascades and their on-screen texel sizes for "csm", shadow pairs
   * and caster triangles for "planar"; for "auto" its choice, reason,
   * light_choices, texel_target_px, texel_stretch and edge_length_px, then
   * the details of the cascaded pass if it is used, else of the planar
   * pass), "{}" otherwise.
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const;

  /**
   * True when Name is one of the techniques this build provides.
   */
  bool IsValid() const;
  static bool IsKnownTechnique(const char* name);

  /**
   * The techniques this build provides, separated by spaces.
   */
  static const char* GetKnownTechniques();

  /**
   * A new pass pipeline for the technique (caller owns it), or nullptr with an
   * error for an unknown name.
   */
  vtkRenderPass* CreatePass();

  /**
   * Set the technique's pipeline on an OpenGL renderer. Returns false for an
   * unknown technique or a renderer that is not a vtkOpenGLRenderer.
   */
  bool Install(vtkRenderer* renderer);

  /**
   * Bytes of shadow-map memory the technique uses for the lights of
   * `renderer` (0 for "none").
   */
  long long GetShadowMapMemory(vtkRenderer* renderer) const;

protected:
  vtkShadowTechnique();
  ~vtkShadowTechnique() override;

  char* Name;
  int MapResolution;
  double MaxError; // auto's wrong_pct target
  vtkCascadedShadowMapPass* CascadedSettings;

private:
  vtkShadowTechnique(const vtkShadowTechnique&) = delete;
  void operator=(const vtkShadowTechnique&) = delete;
};

#endif
