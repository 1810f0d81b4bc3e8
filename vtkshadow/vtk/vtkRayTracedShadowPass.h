/**
 * @class   vtkRayTracedShadowPass
 * @brief   Exact hard (or sampled soft) shadows of any geometry: one Embree
 *          occlusion ray per visible pixel and light.
 *
 * Each frame: the opaque scene's depth goes into a screen-space mask
 * (vtkShadowScreenMask) at the viewport's size; the CPU reads it back and,
 * for every pixel showing a surface, lands a short primary ray exactly on the
 * rasterized triangle and traces occlusion rays towards each light the
 * surface faces (inside spot cones), with Embree 3 over all cores
 * (vtkShadowRayTracer); each light's visibility goes into its channel of the
 * mask, and the scene is rendered with the mappers' lighting multiplying
 * light I by channel I, in the same frame.
 *
 * The casters are Embree scenes (vtkShadowEmbreeScene): one per actor mesh,
 * rebuilt only when its mesh data changes, instanced by the actors' matrices,
 * so moving an actor re-commits the top level only. A still camera over a
 * still scene traces nothing (the mask keeps the last frame's result).
 *
 * Settings (SetOption): samples (rays per pixel and light, 1 = hard),
 * adaptive (1, the default: a pixel traces a first batch of 8 rays spread
 * over the light and the rest of `samples` only where they disagree, i.e.
 * in the penumbra; 0: every pixel traces `samples`),
 * light_radius (world radius of point and spot lights when samples > 1),
 * light_angle (angular diameter in degrees of directional lights when
 * samples > 1), threads (0 = every core), and the base's cast_headlight.
 * Up to vtkShadowScreenMask::MaxLights (8) lights cast.
 *
 * @code{.py}
 * rt = vtkshadow.vtkRayTracedShadowPass()
 * renderer.SetPass(rt)      # delegate defaults to vtkRenderStepsPass
 * @endcode
 */
#ifndef vtkRayTracedShadowPass_h
#define vtkRayTracedShadowPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr

struct vsh_rt_cost_model;
struct vsh_rt_cost_input;

class VTKSHADOW_EXPORT vtkRayTracedShadowPass : public vtkShadowPassBase
{
public:
  static vtkRayTracedShadowPass* New();
  vtkTypeMacro(vtkRayTracedShadowPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Rays per pixel for a light with a size (1..1024, default 128): towards
   * stratified points on the light, turned per pixel. A light without a size
   * always gets one ray (hard shadows).
   */
  vtkSetClampMacro(Samples, int, 1, 1024);
  vtkGetMacro(Samples, int);

  /**
   * Adaptive ray counts (default 1, on): a pixel under a light with a size
   * first traces VSH_RT_ADAPTIVE_BATCH (8) of its Samples rays, spread over
   * the whole light; if they all agree (all blocked or all free) that is its
   * visibility, else it traces the rest (vsh_rt_adaptive.h). Lit and umbra
   * pixels then cost 8 rays, penumbra pixels Samples. 0: Samples everywhere.
   */
  vtkSetClampMacro(Adaptive, int, 0, 1);
  vtkGetMacro(Adaptive, int);
  vtkBooleanMacro(Adaptive, int);

  /**
   * A size for lights that have none of their own (a scene light's `radius`
   * / `angle`, vtkShadowPassBase::GetLightRadius / GetLightAngle, wins):
   * radius (world units) of point and spot lights, angular diameter
   * (degrees) of directional lights. Default 0.
   */
  vtkSetClampMacro(LightRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightRadius, double);
  vtkSetClampMacro(LightAngle, double, 0.0, 180.0);
  vtkGetMacro(LightAngle, double);

  /**
   * Decide without rays the pixels a light-space map proves lit or
   * shadowed (default 1, on): the image is the one every pixel's ray gives
   * (vsh_rt_classify.h says why), at the cost of the pixels the map leaves
   * undecided. Hard lights only, and not while volumes cast; spheres,
   * tubes and flat quads are the maps' per-frame occluders. 0: every
   * pixel traced.
   * ClassifyResolution: texels a side of each light's map (64..4096,
   * default 1024; point lights and wide spots have six).
   */
  vtkSetClampMacro(Classify, int, 0, 1);
  vtkGetMacro(Classify, int);
  vtkBooleanMacro(Classify, int);
  vtkSetClampMacro(ClassifyResolution, int, 64, 4096);
  vtkGetMacro(ClassifyResolution, int);

  /**
   * Worker threads for the rays (0, the default: one per core).
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 256);
  vtkGetMacro(NumberOfThreads, int);

  /**
   * Counters: meshes (re)built and top-level commits since creation; rays
   * traced in the last frame (0 for a still frame) and frames that traced.
   */
  int GetNumberOfMeshBuilds() const;
  int GetNumberOfTopLevelCommits() const;
  vtkGetMacro(NumberOfRaysTraced, vtkIdType);
  vtkIdType GetNumberOfCasterTriangles() const;
  vtkGetMacro(NumberOfTracedFrames, int);

  /**
   * The estimated milliseconds of shadow work for a moving frame of
   * `pixels` viewport pixels, `coverage` of them (0..1) showing lit
   * surfaces, `lights` lights at the current threads, from the rays per
   * second this pass measured so far (vsh_rt_cost_ms). Lights with a size
   * (`sized`) trace Samples rays per pixel (with Adaptive, 8 plus the rest
   * on the fraction of pixels measured to be in a penumbra, 0.25 until
   * measured), hard lights one, on the fraction of pixels the classifier
   * leaves to rays (with Classify: measured, 0.5 until measured).
   */
  double EstimateFrameMilliseconds(double pixels, double coverage, int lights, bool sized) const;

#ifndef __VTK_WRAP__
  /**
   * The cost model and frame EstimateFrameMilliseconds uses (rays per
   * second measured so far, threads, the measured penumbra fraction, the
   * first batch for Samples): auto's choice for a light with a size
   * (vsh_auto_soft) prices other sample counts with it.
   */
  void GetCostInputs(double pixels, double coverage, int lights, bool sized,
    vsh_rt_cost_model* model, vsh_rt_cost_input* input) const;
#endif

  long long GetMemoryBytes() const override;
  /**
   * One still-frame state (mask, last key) per world key: a mirror's
   * reflection keeps its own, so a still frame traces in neither world.
   */
  void ReleaseWorlds(vtkWindow* w, int first) override;
  long long GetWorldsMemoryBytes() const override;
  /**
   * The settings (SetOption keys, ranges, docs) of this pass: its table in
   * the .cxx, listed by `vtkshadow-render --list-settings`.
   */
  vtkShadowSettingsMacro();
  std::string GetStatsJSON(vtkRenderer* renderer) const override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkRayTracedShadowPass();
  ~vtkRayTracedShadowPass() override;

  int Samples;
  int Adaptive;
  int Classify;
  int ClassifyResolution;
  double LightRadius;
  double LightAngle;
  int NumberOfThreads;
  vtkIdType NumberOfRaysTraced;
  int NumberOfTracedFrames;

private:
  vtkRayTracedShadowPass(const vtkRayTracedShadowPass&) = delete;
  void operator=(const vtkRayTracedShadowPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
  struct Frame;
  // The stages of Render(), in order.
  void GatherFrame(Frame& frame);
  bool Trace(const vtkRenderState* s, Frame& frame);
  void Upload(const Frame& frame);
};

#endif
