/**
 * @class   vtkCascadedShadowMapPass
 * @brief   Cascaded shadow maps for directional lights, perspective maps for
 *          spot lights, cube maps for point lights: fitted, stable, auto-biased.
 *
 * All shadow math comes from vtkshadow's C core (vsh_csm.h) in double
 * precision, camera-relative. Per frame the pass:
 *  1. measures the depth range of the visible geometry (scene bounds clipped
 *     to the view frustum) and picks the cascade count from its ratio
 *     (or CascadeCount), and the split depths (SplitScheme);
 *  2. fits each cascade to its view slice clipped to the receivers, with the
 *     near plane pulled back to every caster (casters outside the view still
 *     cast); in Stable mode the size does not change when the camera turns
 *     and the map is snapped to whole texels of a world-anchored grid;
 *  3. renders only the maps whose matrix, light or casters changed into one
 *     depth-texture atlas (a still camera over a still scene renders none);
 *  4. while its delegate renders the scene, multiplies each light's diffuse
 *     and specular term by the filtered shadow lookup (hardware 2x2 PCF, NxN
 *     PCF or a Poisson disc), with a slope/normal bias from the texel size,
 *     a blend band between cascades and a fade at MaxShadowDistance.
 *
 * The on-screen size of one shadow texel is computed per cascade
 * (GetCascadeTexelPixels); with MaxTexelPixels > 0 the pass chooses map
 * resolution and cascade count to keep it under the target within
 * MemoryBudget.
 *
 * @code{.py}
 * csm = vtkshadow.vtkCascadedShadowMapPass()
 * csm.SetMapResolution(2048)
 * renderer.SetPass(csm)   # delegate defaults to vtkRenderStepsPass
 * @endcode
 */
#ifndef vtkCascadedShadowMapPass_h
#define vtkCascadedShadowMapPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkMultiProcessController;
class vtkOpenGLRenderWindow;
class vtkRenderer;
struct vsh_csm_settings;
struct vsh_csm_tile;
namespace vtkshadow
{
struct ShadowActor;
}

class VTKSHADOW_EXPORT vtkCascadedShadowMapPass : public vtkShadowPassBase
{
public:
  static vtkCascadedShadowMapPass* New();
  vtkTypeMacro(vtkCascadedShadowMapPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SplitSchemes
  {
    UNIFORM = 0,
    LOGARITHMIC = 1,
    PRACTICAL = 2,
    EXPLICIT = 3
  };
  enum Filters
  {
    HARDWARE_2X2 = 0,
    PCF = 1,
    POISSON = 2
  };

  /**
   * Cascades for directional lights: 0 (default) picks 1..8 from the depth
   * ratio of the visible geometry (RatioPerCascade per cascade).
   */
  vtkSetClampMacro(CascadeCount, int, 0, 8);
  vtkGetMacro(CascadeCount, int);
  vtkSetClampMacro(RatioPerCascade, double, 1.5, 1e6);
  vtkGetMacro(RatioPerCascade, double);

  /**
   * Split scheme (default PRACTICAL with lambda 0.75) and its parameters.
   * Explicit fractions: SetSplitFraction(i, f) for the split between
   * cascade i and i+1, as a fraction of the visible depth range.
   */
  vtkSetClampMacro(SplitScheme, int, UNIFORM, EXPLICIT);
  vtkGetMacro(SplitScheme, int);
  vtkSetClampMacro(SplitLambda, double, 0.0, 1.0);
  vtkGetMacro(SplitLambda, double);
  void SetSplitFraction(int i, double fraction);
  double GetSplitFraction(int i) const;

  /**
   * Stable cascades (default on): rotation-invariant size, texel snapping.
   */
  vtkSetMacro(Stable, bool);
  vtkGetMacro(Stable, bool);
  vtkBooleanMacro(Stable, bool);

  /**
   * Edge length of each map in texels (default 2048). Clamped to what the
   * GL allows for the atlas, with a warning.
   */
  vtkSetClampMacro(MapResolution, int, 16, 16384);
  vtkGetMacro(MapResolution, int);

  /**
   * Error target: when > 0, resolution and cascade count are chosen so that
   * one shadow texel covers at most this many pixels on screen, within
   * MemoryBudget bytes (default 0: off; budget 256 MiB).
   */
  vtkSetMacro(MaxTexelPixels, double);
  vtkGetMacro(MaxTexelPixels, double);
  vtkSetMacro(MemoryBudget, long long);
  vtkGetMacro(MemoryBudget, long long);

  /**
   * Scale of the automatic bias (slope-scaled depth offset plus normal
   * offset, both from the texel size; default 1).
   */
  vtkSetClampMacro(BiasScale, double, 0.0, 100.0);
  vtkGetMacro(BiasScale, double);

  /**
   * Filter (default HARDWARE_2X2), the NxN size for PCF (default 3) and the
   * Poisson disc radius in texels (default 1.5).
   */
  vtkSetClampMacro(Filter, int, HARDWARE_2X2, POISSON);
  vtkGetMacro(Filter, int);
  vtkSetClampMacro(PCFSize, int, 1, 9);
  vtkGetMacro(PCFSize, int);
  vtkSetClampMacro(PoissonRadius, double, 0.0, 16.0);
  vtkGetMacro(PoissonRadius, double);

  /**
   * Width of the blend band between cascades as a fraction of each cascade
   * (default 0.1; 0 = hard switch).
   */
  vtkSetClampMacro(BlendBand, double, 0.0, 0.5);
  vtkGetMacro(BlendBand, double);

  /**
   * Shadows end at this view depth, fading out over the last FadeFraction
   * of the shadowed depth range (default 0.1). Default 0: no cut-off and no
   * fade, shadows reach the visible receivers' far end.
   */
  vtkSetMacro(MaxShadowDistance, double);
  vtkGetMacro(MaxShadowDistance, double);
  vtkSetClampMacro(FadeFraction, double, 0.0, 1.0);
  vtkGetMacro(FadeFraction, double);

  enum Resolves
  {
    FORWARD = 0,
    SCREEN = 1,
    CHOOSE = 2
  };

  /**
   * Where the lookups run. FORWARD: in every mapper's fragment shader, for
   * every fragment rasterized (hidden ones included). SCREEN: once per
   * visible pixel after a depth pre-pass (vtkShadowScreenMask): one
   * full-screen draw reconstructs each pixel's position and normal from the
   * depth, looks up every light and writes its visibility to the mask; the
   * mappers read one texel per light. CHOOSE: SCREEN unless the depth
   * buffer is too coarse for the bias at the far end of the view,
   * DebugCascades is on, or forward measures cheaper: now and then (every
   * 64 frames) a screen frame counts, with queries, the fragment-shader
   * invocations (what forward lookups run for) per covered pixel (what the
   * resolve runs for); the costs measured on llvmpipe turn that and the
   * number of casting lights into the choice. Default FORWARD: the normals
   * the resolve reconstructs from the depth are wrong on geometry a few
   * pixels wide (glyphs, tubes), which costs wrong pixels there
   * (docs/cascaded-shadow-maps.md).
   */
  vtkSetClampMacro(Resolve, int, FORWARD, CHOOSE);
  vtkGetMacro(Resolve, int);
  /** Whether the last frame used the screen-space resolve. */
  vtkGetMacro(UsedScreenResolve, bool);

  /**
   * PCF and Poisson filters take their taps only where one shadow texel
   * covers at most this many pixels (default 4); where texels are larger
   * the hardware 2x2 comparison alone ramps across the edge.
   */
  vtkSetClampMacro(TapTexelPixels, double, 0.0, 1e6);
  vtkGetMacro(TapTexelPixels, double);

  /**
   * Screen resolve only: decide per 16x16-pixel tile, from the depth
   * pre-pass, which lookups the tile needs (vsh_csm_screen_tile_needs):
   * none where it is beyond the shadows or no caster is near it in the
   * maps, one cascade (no per-pixel choice, no blend) where its depths fall
   * in one, and draw each kind of tile with a shader compiled for it
   * (default on). Off: one full-screen draw with the per-pixel code.
   */
  vtkSetMacro(TileCull, bool);
  vtkGetMacro(TileCull, bool);
  vtkBooleanMacro(TileCull, bool);
  /** Tiles (of any light) the last screen frame decided without the per-pixel code. */
  vtkGetMacro(NumberOfTilesCulled, int);

  enum SoftModes
  {
    SOFT_OFF = 0,
    SOFT_PCSS = 1,
    SOFT_SAMPLED = 2
  };

  /**
   * Lights with a size (vtkShadowPassBase::GetLightRadius / GetLightAngle).
   * SOFT_PCSS (default): percentage-closer soft shadows for every casting
   * light with a size, a blocker search over the region the light's size
   * and the receiver's depth in the map span, then a filter as wide as the
   * penumbra the blockers' mean depth gives (vsh_pcss.h), with
   * PCSSBlockerTaps and PCSSFilterTaps samples on a per-pixel rotated Vogel
   * disk, the kernel at most PCSSMaxTexels texels in radius and inside the
   * map's tile. Lights without a size keep the hard lookup, and a frame
   * without any light with a size compiles the same shader as SOFT_OFF.
   * SOFT_SAMPLED: the lecture's sampled area light: SoftSamples hard maps
   * per map of each casting light with a size, one from each of SoftSamples
   * stratified points on the light (vsh_csm_sampled.h), and the lookup
   * averages their hard comparisons. SoftSamples 1 or a light without a
   * size is the hard path, byte for byte.
   * SOFT_OFF: the hard shadow of every light's centre.
   * (docs/soft-shadows.md)
   */
  vtkSetClampMacro(Soft, int, SOFT_OFF, SOFT_SAMPLED);
  vtkGetMacro(Soft, int);
  vtkSetClampMacro(PCSSBlockerTaps, int, 1, 64);
  vtkGetMacro(PCSSBlockerTaps, int);
  vtkSetClampMacro(PCSSFilterTaps, int, 1, 64);
  vtkGetMacro(PCSSFilterTaps, int);
  vtkSetClampMacro(PCSSMaxTexels, double, 1.0, 256.0);
  vtkGetMacro(PCSSMaxTexels, double);
  /** Whether the last frame compiled PCSS in (a casting light had a size). */
  vtkGetMacro(UsedPCSS, bool);
  /** SOFT_SAMPLED: maps (points on the light) per map of a light with a size, 1..64. */
  vtkSetClampMacro(SoftSamples, int, 1, 64);
  vtkGetMacro(SoftSamples, int);
  /** Whether the last frame sampled a light (SOFT_SAMPLED with a sized light, N > 1). */
  vtkGetMacro(UsedSampled, bool);
  /**
   * SOFT_SAMPLED with SoftSamples > 8: adaptive sample counts per pixel.
   * The lookup compares the first batch of 8 samples (the light's centre
   * and 7 points near its rim, vsh_soft_batch_order) and stops there where
   * they agree (every comparison fully lit or fully blocked); elsewhere it
   * takes all SoftSamples, the non-adaptive answer. The slots hold the same
   * samples in that order, so only the count per pixel changes. Off by
   * default: an occluder whose blocked part of the light lies between the
   * batch's points is missed (docs/soft-shadows.md).
   */
  vtkSetMacro(Adaptive, bool);
  vtkGetMacro(Adaptive, bool);
  vtkBooleanMacro(Adaptive, bool);

  /**
   * Tint each cascade with its own colour (debug view).
   */
  vtkSetMacro(DebugCascades, bool);
  vtkGetMacro(DebugCascades, bool);
  vtkBooleanMacro(DebugCascades, bool);

  /**
   * Ranks that draw one image together (ParaView's pvbatch or pvserver
   * under MPI, sort-last compositing): with a controller of more than one
   * process every rank plans its maps from the bounds of all ranks' casters
   * and receivers and the real camera, draws its own casters, and the maps
   * it bakes are min-reduced over the ranks, so a caster on one rank
   * shadows a receiver on another. Maps are reduced only in frames that
   * bake them (the same frames on every rank: the plan's inputs are
   * reduced). Every rank must render every frame. Default none: one process.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController() const;

  /**
   * Copy every setting (not the delegate, not the GL state) from `other`.
   */
  void CopySettings(vtkCascadedShadowMapPass* other);

  /**
   * The settings (SetOption keys, ranges, docs) of this pass: its table in
   * the .cxx, listed by `vtkshadow-render --list-settings`.
   */
  vtkShadowSettingsMacro();

  /**
   * resolution, maps rendered (total) and reused (last frame), and per
   * light its cascades, their far depths and on-screen texel sizes.
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const override;

  /**
   * What the last frame used: cascades of directional light `light`
   * (mapper numbering), their far split depths and the on-screen size of a
   * shadow texel at the near end of each, the resolution, the number of maps
   * rendered in that frame and since creation, and the atlas bytes.
   */
  int GetNumberOfCascades(int light) const;
  double GetCascadeFar(int light, int cascade) const;
  double GetCascadeTexelPixels(int light, int cascade) const;
  vtkGetMacro(UsedResolution, int);
  vtkGetMacro(NumberOfMapsRendered, int);
  /** Cascades whose earlier map still covered every lookup of the last frame. */
  vtkGetMacro(NumberOfMapsReused, int);
  vtkGetMacro(TotalMapsRendered, int);
  /** Every world's atlas (and the screen mask when used). */
  long long GetMemoryBytes() const override;

  /**
   * One set of held maps (atlas, what its tiles hold, the casters' key) per
   * world key: a mirror's reflection keeps its own maps, so a still frame
   * bakes nothing in either world (docs/reflections.md).
   */
  void ReleaseWorlds(vtkWindow* w, int first) override;
  long long GetWorldsMemoryBytes() const override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkCascadedShadowMapPass();
  ~vtkCascadedShadowMapPass() override;

  int CascadeCount;
  double RatioPerCascade;
  int SplitScheme;
  double SplitLambda;
  bool Stable;
  int MapResolution;
  double MaxTexelPixels;
  long long MemoryBudget;
  double BiasScale;
  int Filter;
  int PCFSize;
  double PoissonRadius;
  double BlendBand;
  double MaxShadowDistance;
  double FadeFraction;
  bool DebugCascades;
  int Resolve;
  double TapTexelPixels;
  bool TileCull;
  int NumberOfTilesCulled;
  int Soft;
  int PCSSBlockerTaps;
  int PCSSFilterTaps;
  double PCSSMaxTexels;
  bool UsedPCSS;
  int SoftSamples;
  bool UsedSampled;
  bool Adaptive;
  bool UsedScreenResolve;
  int UsedResolution;
  int NumberOfMapsRendered;
  int NumberOfMapsReused;
  int TotalMapsRendered;

private:
  vtkCascadedShadowMapPass(const vtkCascadedShadowMapPass&) = delete;
  void operator=(const vtkCascadedShadowMapPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;

  // The stages of Render(), in order. Planning (depth range, resolution,
  // tiles per light kind, reuse) is plain C in vsh_csm_plan.h; these turn
  // VTK's state into its inputs and its plan into GL work.
  struct Frame;
  void SelectWorld(int world);
  void GatherScene(Frame& frame);
  void GatherLights(Frame& frame);
  void GatherSettings(vsh_csm_settings& out) const;
  void PlanMaps(const Frame& frame);
  void UpdateShaderState(const Frame& frame);
  int AllocateAtlas(vtkOpenGLRenderWindow* window);
  void SelectReusable(const Frame& frame, int resolution, std::vector<int>& bake);
  double LookupReachTexels() const;
  void BakeMaps(vtkOpenGLRenderWindow* window, const Frame& frame, const std::vector<int>& bake,
    int resolution);
  void DrawCasters(vtkShaderProgram* program, const std::vector<vtkshadow::ShadowActor>& casters,
    const Frame& frame, const vsh_csm_tile& tile);
  // Translucent casters (vtkCascadedShadowMapTranslucent.cxx): their
  // nearest-depth and transmittance atlases, allocated only while the scene
  // has one, and their bake into the tiles BakeMaps renders.
  void AllocateTransmit(vtkOpenGLRenderWindow* window);
  void BakeTranslucent(vtkOpenGLRenderWindow* window, const Frame& frame,
    const std::vector<int>& bake, int resolution);
  void ReleaseRemovedCasters(vtkOpenGLRenderWindow* window, const Frame& frame);
  // The screen-space resolve (vtkCascadedShadowMapResolve.cxx).
  bool ChooseScreenResolve(const Frame& frame) const;
  bool DepthPreciseEnough(const Frame& frame) const;
  void UpdateResolveSources();
  void RenderScreenResolved(
    const vtkRenderState* s, vtkOpenGLRenderWindow* window, const Frame& frame);
  bool ResolveScreen(const vtkRenderState* s, vtkOpenGLRenderWindow* window, const Frame& frame);
  void PlanScreenTiles(const Frame& frame, const double ndcToView[16]);
  bool DrawResolveTiles(vtkOpenGLRenderWindow* window, int layer, const float ndcToView[16]);
  void SetResolveUniforms(vtkShaderProgram* program, const float ndcToView[16]);
  void SetLookupUniforms(vtkShaderProgram* program);
  // SOFT_SAMPLED (vtkCascadedShadowMapSampled.cxx): each sized light's
  // sample frame and atlas slots (capping the resolution to the memory
  // budget), the sample maps derived from this frame's maps and the bake
  // list that renders them, the uniforms the sampled lookups read.
  void PlanSamples(const Frame& frame);
  void OrderSamples(int n);
  void BuildSampleTiles(std::vector<int>& bake);
  void SetSampledUniforms(vtkShaderProgram* program);
  const vsh_csm_tile& BakeTile(int t) const;
  // The #defines of vtkShadowMapLightFS (filter, PCSS), forward and resolve.
  std::string LookupDefines() const;
  // PCSS's blocker search reads raw depths: the atlas bound a second time
  // through a sampler object without depth comparison.
  void BindRawAtlas(vtkOpenGLRenderWindow* window);
  void UnbindRawAtlas(vtkOpenGLRenderWindow* window);
};

#endif
