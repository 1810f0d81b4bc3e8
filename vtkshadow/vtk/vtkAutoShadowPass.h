/**
 * @class   vtkAutoShadowPass
 * @brief   Chooses, per light, the cheapest shadow technique whose predicted
 *          error meets a target.
 *
 * Every frame (cheaply, from bounds, with vtkshadow's core tests) each light
 * that is switched on gets one of:
 * - "none": no caster can shadow anything visible under it (a
 *   conservative bounding-box / bounding-sphere test against every other
 *   object inside the view frustum, and every caster is convex, so none
 *   shadows itself), or it is the headlight: no shadow work for it at all;
 * - "planar": every shadow it casts falls on plane receivers and every
 *   non-receiver caster is convex: vtkPlanarShadowPass, exact and cheapest;
 * - otherwise the cheapest of the general candidates whose predicted error
 *   meets the target (vsh_auto_general.h): "csm" (vtkCascadedShadowMapPass,
 *   one fitted map when the visible depth ratio is small and more cascades
 *   when it is large, with the map resolution and count chosen by the
 *   core's error estimate so that the on-screen texel size meets the
 *   target), predicted to meet it unless a caster part is narrower than two
 *   texels (the thin-caster term), "volume" (vtkShadowVolumePass, exact
 *   for polygonal casters, costed by vsh_volume_cost_ms from the
 *   silhouette edges and the volumes' scissored fill) or "raytrace"
 *   (vtkRayTracedShadowPass, exact), costed by its own model of measured
 *   rays per second.
 * Lights of several kinds in one scene are drawn in one frame: the chosen
 * passes delegate to each other, each skipping the others' lights
 * (SkippedLights), and all multiply their factor into the lighting.
 *
 * The target is MaxError (wrong_pct, the percentage of pixels whose shadow
 * state is wrong outside a one-pixel band; default 0.5), turned into an
 * on-screen texel size by vsh_auto_texel_target (for the casters' own
 * shadow outline length, from their silhouettes, and allowing for shadows
 * stretched by grazing light on plane receivers), or MaxTexelPixels directly
 * when it is > 0. GetChoice(), GetReason() and, per light,
 * GetLightChoice(i) / GetLightReason(i) say what was chosen and why.
 */
#ifndef vtkAutoShadowPass_h
#define vtkAutoShadowPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkCascadedShadowMapPass;
class vtkRenderer;
class vtkPlanarShadowPass;
class vtkRayTracedShadowPass;
class vtkShadowVolumePass;
class vtkProp;
struct vsh_volume_ms_input;
struct vsh_auto_general_light;
namespace vtkshadow
{
struct ShadowFrame;
struct ShadowFrameLight;
struct ShadowActor;
}
struct vsh_auto_candidate;

class VTKSHADOW_EXPORT vtkAutoShadowPass : public vtkShadowPassBase
{
public:
  static vtkAutoShadowPass* New();
  vtkTypeMacro(vtkAutoShadowPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The passes it chooses between (configure them directly, e.g.
   * GetCascadedPass()->SetFilter(1)). auto itself sets the cascaded pass's
   * MaxTexelPixels (use this class's SetMaxError / SetMaxTexelPixels), both
   * passes' SkippedLights and their delegates every frame: the chosen
   * passes are chained in front of this pass's own delegate.
   */
  vtkGetObjectMacro(PlanarPass, vtkPlanarShadowPass);
  vtkGetObjectMacro(CascadedPass, vtkCascadedShadowMapPass);
  vtkGetObjectMacro(RayTracedPass, vtkRayTracedShadowPass);
  vtkGetObjectMacro(VolumePass, vtkShadowVolumePass);

  /**
   * The error target: wrong_pct (percent of the frame's pixels; default
   * 0.5), or, when MaxTexelPixels > 0 (default 0), the on-screen size of a
   * shadow-map texel in pixels.
   */
  vtkSetClampMacro(MaxError, double, 0.0, 100.0);
  vtkGetMacro(MaxError, double);
  vtkSetClampMacro(MaxTexelPixels, double, 0.0, 1e6);
  vtkGetMacro(MaxTexelPixels, double);
  /**
   * The target for lights with a size (radius or angle): pen_mae, the mean
   * absolute visibility error inside the penumbra (docs/metrics.md; default
   * 0.03; the option `penumbra_target` takes 0 < t <= 1). Such a light gets
   * the cheapest of planar (soft_samples N, when its shadows fall on plane
   * receivers only), csm with PCSS and raytrace (samples N) whose predicted
   * pen_mae meets it, and that technique's N (vsh_auto_soft.h); when none
   * does, the lowest predicted error. Lights without a size ignore it.
   */
  vtkSetClampMacro(PenumbraTarget, double, 0.0, 1.0);
  vtkGetMacro(PenumbraTarget, double);

  /**
   * Where every light given an exact technique could take either shadow
   * volumes or ray tracing within the target (the two draw the same
   * image), 1 (default): auto times a few frames of each on this machine
   * and keeps the faster (vsh_auto_trial.h; timed again every 300 frames);
   * 0: the cost models alone decide. The option is `time_exact`.
   */
  vtkSetClampMacro(TimeExact, int, 0, 1);
  vtkGetMacro(TimeExact, int);

  /**
   * "none", "planar", "csm", "volume", "raytrace" or a combination such
   * as "planar+csm" for the last frame, and why;
   * per light (mapper numbering: switched-on lights in order) "none",
   * "planar", "csm", "volume" or "raytrace" and why.
   */
  const char* GetChoice() const;
  const char* GetReason() const { return this->Reason.c_str(); }
  int GetNumberOfLightChoices() const { return static_cast<int>(this->LightReasons.size()); }
  const char* GetLightChoice(int light) const;
  const char* GetLightReason(int light) const;

  /**
   * The texel target the cascaded pass was given in the last frame (pixels),
   * and the shadow stretch it allowed for: 1 / cos of the steepest incidence
   * of a map light on a plane receiver in view (at most 64).
   */
  vtkGetMacro(UsedTexelTarget, double);
  vtkGetMacro(UsedStretch, double);
  /**
   * The shadow-boundary length the texel target assumed, in pixels: the
   * casters' silhouettes seen from the map lights, at their distance from
   * the camera (the longest over the map lights).
   */
  vtkGetMacro(UsedEdgeLength, double);

  /**
   * The narrowest caster part in view in the last frame, in pixels (+inf
   * when there was none or no light needed a map): a map whose texels are
   * wider than half of it may lose that part's shadow, so auto draws such
   * lights exactly instead (raytrace) when that is the cheapest way to meet
   * the target.
   */
  vtkGetMacro(UsedThinnestPixels, double);

  /**
   * The wrong_pct the last frame's maps were predicted to lose on tapered
   * caster parts (cone and arrow tips narrower than two texels of the texel
   * target: vsh_auto_taper_error summed over the casters in view), 0 when
   * no light needed a map.
   */
  vtkGetMacro(UsedTaperErrorPct, double);

  /**
   * The plane receivers detected in the last frame (its planar pass's
   * detection: flat surface actors when none is marked).
   */
  int GetNumberOfDetectedReceivers() const override;
  vtkActor* GetDetectedReceiver(int index) const override;

  /**
   * Also given to every pass it chooses between.
   */
  void SetResidualLight(double residual) override;
  void SetEarlyDepth(int mode) override;

  /**
   * GL memory of the passes in use, as of the last frame.
   */
  long long GetMemoryBytes() const override;
  /**
   * The world key goes to every technique pass auto chains, and so do
   * ReleaseWorlds and the worlds' memory (vtkShadowPassBase::SetWorldKey).
   */
  void SetWorldKey(int key) override;
  void ReleaseWorlds(vtkWindow* w, int first) override;
  long long GetWorldsMemoryBytes() const override;

  /**
   * The settings (SetOption keys, ranges, docs) of this pass: its table in
   * the .cxx, listed by `vtkshadow-render --list-settings`.
   */
  vtkShadowSettingsMacro();

  /**
   * choice, reason, texel_target_px, texel_stretch, edge_length_px and
   * light_choices, detected_receivers, then the details of the cascaded pass when it is used,
   * else of the planar pass; thinnest_caster_px and general (per light given maps, every
   * candidate's predicted error and ms, volume's inputs and the pick); the volume and
   * ray-traced passes' own stats when used.
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkAutoShadowPass();
  ~vtkAutoShadowPass() override;

  vtkPlanarShadowPass* PlanarPass;
  vtkCascadedShadowMapPass* CascadedPass;
  vtkRayTracedShadowPass* RayTracedPass;
  vtkShadowVolumePass* VolumePass;
  std::string Reason;
  std::vector<std::string> LightReasons;
  double MaxError;
  double MaxTexelPixels;
  double UsedTexelTarget;
  double UsedStretch;
  double UsedEdgeLength;
  double UsedThinnestPixels = 0.0;
  double PenumbraTarget = 0.03;
  int TimeExact = 1;
  double UsedTaperErrorPct = 0.0;
  // The choices (typed: vtkShadowTechniqueSet.h), the frame's objects and
  // the casters' meshes (convexity, silhouettes), kept between frames.
  struct Internals;
  std::unique_ptr<Internals> Impl;

private:
  vtkAutoShadowPass(const vtkAutoShadowPass&) = delete;
  void operator=(const vtkAutoShadowPass&) = delete;

  // The stages of a frame's choice: the objects (bounds, receiver planes,
  // in view), the first caster in view that is not convex, per light the
  // technique (vsh_auto_choose_light) and for a map light the shadow outline
  // and stretch, then the passes' light masks and the texel target.
#ifndef __VTK_WRAP__
  void Decide(const vtkshadow::ShadowFrame& frame);
  void GatherObjects(const vtkshadow::ShadowFrame& frame);
  // Lights with a tinting translucent caster or a volume go to raytrace;
  // the reason (empty when neither is in the frame).
  void ChooseRaytraceOnly(const vtkshadow::ShadowFrame& frame);
  std::string RaytraceOnlyReason(const vtkshadow::ShadowFrame& frame) const;
#endif
  int FindConcaveCaster();
  std::string LightReasonText(int reason, int a, int b) const;
  void ApplyLightMasks();
  void ChooseTexelTarget(vtkRenderer* renderer, double edgeLength, double stretch);
  // For light number `l` with a size, given `technique` (a VSH_AUTO_*
  // value) by the hard-light rules: weighs the soft candidates against the
  // penumbra target (vsh_auto_soft), kept per light for ChooseSoft.
  void WeighSoft(vtkRenderer* renderer, size_t l, int technique);
  // Settles the weighed lights: volume lights choose again without volumes
  // when other lights with a size took raytrace (one screen mask per
  // frame), then each light's pick is applied (ApplySoftPick).
  void ChooseSoft();
  // Light `l`'s soft pick: its samples kept for the frame, the weighed
  // candidates in the stats and the reason; returns the light's technique
  // (`technique`, the hard rules', when nothing was picked).
  int ApplySoftPick(size_t l, int technique);
  void ApplySoftSamples();
  // csm's soft mode is one per pass: the user's setting is recalled at the
  // start of a frame (RecallCsmSoft) and auto's choice applied at its end
  // (ApplyCsmSoft); EstimateCsmTiles is the maps csm will plan for a light.
  void RecallCsmSoft();
  void ApplyCsmSoft();
#ifndef __VTK_WRAP__
  int EstimateCsmTiles(const vtkshadow::ShadowFrameLight& light, size_t l) const;
#endif
  // For the lights given maps: keep the map when its predicted error meets
  // the target and it is the cheapest such candidate, else an exact one.
  void ChooseGeneral(vtkRenderer* renderer, const std::vector<double>& edgeLengths);
  // The exact lights of `lights` (light numbers `index`) to the exact
  // technique timed faster on this machine (vsh_auto_trial), when they can
  // all take either; sets whether this frame is timed.
  void TimeExactLights(vsh_auto_general_light* lights, const int* index, int count);
  // What the trial timed, for the lights' reasons and the stats.
  std::string TrialNote() const;
  std::string TrialJSON() const;
  // Renders `chain`, timed when the trial asks for this frame.
  void RenderTimed(vtkRenderPass* chain, const vtkRenderState* s);
  double ThinnestCasterPixels(vtkRenderer* renderer);
  // What the casters in view lose on tapered parts under the frame's texel
  // target (wrong_pct over `pixels`).
  double TaperErrorPct(vtkRenderer* renderer, double pixels);
  // Shadow volumes for light number `index` (`light` homogeneous, world):
  // the cost model's inputs (silhouette edges, scissored fill) and how many
  // casters volumes cannot draw exactly (no triangles, translucent, not
  // vtkShadowVolumePass::CastsExactly).
  // `openQuads` (may be null) gets the open casters' quads
  // (VolumeSilhouette): [0] of those counted z-pass, [1] z-fail.
  int VolumeInputs(vtkRenderer* renderer, const double light[4], int index,
    vsh_volume_ms_input& input, double* openQuads = nullptr);
  // The volume silhouette of one caster for one light: its quads (sum of
  // multiplicities; -1 when the caster has no mesh to extrude) and the
  // same count again for a caster that is not closed (0 for a closed one),
  // which volume's error model charges (vsh_auto_volume_floor_error).
  // CapTriangles: its caps, drawn when the pass counts it z-fail.
  struct VolumeSilhouette
  {
    double Quads = -1.0;
    double OpenQuads = 0.0;
    double CapTriangles = 0.0;
    // Not closed, and the camera sees one of its faces from the side turned
    // from the light (vsh_silhouette_seen_unlit): without unlit_caps the
    // pass counts it z-fail.
    bool SeenUnlit = false;
  };
  // VolumeSilhouette of caster `object` (an index into the frame's objects)
  // for light number `index`, cached per light while light and mesh stay put.
  VolumeSilhouette VolumeEdges(size_t object, const double light[4], int index);
  int TranslucentCasters(vtkRenderer* renderer) const;
  // Records the weighed candidates of map light `l` in the stats and, when
  // an exact technique won, the light's new choice and why.
  void ApplyGeneralPick(size_t l, const vsh_auto_candidate* candidates,
    const vsh_volume_ms_input& volume, int unsupported, int pick);
  // Light l's entry of the stats' "general" list, with the pick's
  // predicted error and whether it meets MaxError ("met").
  std::string GeneralPickJSON(size_t l, const vsh_auto_candidate* candidates,
    const vsh_volume_ms_input& volume, int unsupported, int pick) const;
  // "; none is predicted to meet ..." when `pick` (named `name`) misses
  // MaxError, else empty.
  std::string UnmetNote(size_t l, const char* name, const vsh_auto_candidate& pick) const;
  double PixelWorldSize(vtkRenderer* renderer, const double center[3]) const;
  void DescribeChoice();
  // Pixels of shadow outline the casters in view throw under light number
  // `index` (`light` homogeneous, world coordinates), and of one object.
  // Of them, the outlines of the points drawn as spheres, splats and
  // squares (*points, outline[0]) and the lines drawn as tubes and bands
  // (*lines, outline[1]): ImpostorOutlinePixels.
  double MapOutlinePixels(
    const double light[4], int index, vtkRenderer* renderer, double* points, double* lines);
  void ImpostorOutlinePixels(
    size_t object, const double light[4], vtkRenderer* renderer, double outline[2]);
  // ImpostorOutlinePixels for light number `index`, cached per caster and
  // light until the light, the placement, the shapes or the camera change.
  void CachedImpostorOutline(
    size_t object, const double light[4], int index, vtkRenderer* renderer, double outline[2]);
#ifndef __VTK_WRAP__
  double SegmentOutlinePixels(const std::vector<double>& vertices,
    const std::vector<unsigned int>& segments, const vtkshadow::ShadowActor& actor,
    const double light[4], vtkRenderer* renderer);
#endif
  double OutlinePixels(size_t object, const double light[4], int index, vtkRenderer* renderer);
};

#endif
