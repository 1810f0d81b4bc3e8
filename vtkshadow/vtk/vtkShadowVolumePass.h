/**
 * @class   vtkShadowVolumePass
 * @brief   Exact hard shadows by stencil shadow volumes, on every surface.
 *
 * Per frame: the opaque scene's depth (vtkShadowScreenMask), then for each
 * casting light the volumes of every caster counted in the stencil and
 * resolved into that light's channel of the screen mask, then the scene
 * once, its lighting multiplying light I by channel I. The scene is never
 * drawn once per light.
 *
 * Volumes come from the caster's mesh topology on the CPU (vsh_volume.h):
 * silhouette edges extruded to infinity plus caps, with dark caps for
 * closed meshes and per-edge multiplicities for open and non-manifold ones.
 * A (caster, light) volume is rebuilt only when the light moved relative to
 * the caster or the caster's mesh changed. Counting is z-pass where the
 * near-plane region lies outside the caster's shadow (vsh_volume_zpass_safe)
 * and z-fail (Carmack's reverse, far cap at infinity via depth clamping)
 * elsewhere; each volume is scissored to its projected bounds and culled
 * when it cannot reach the view. A translucent caster (opacity a < 1)
 * counts its crossings with the volumes of all its faces (z-fail), and the
 * light's channel is multiplied by (1 - a) per crossing.
 * docs/shadow-volumes.md has the details.
 */
#ifndef vtkShadowVolumePass_h
#define vtkShadowVolumePass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for SampleOrder

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkShadowScreenMask;
#ifndef __VTK_WRAP__
namespace vtkshadow
{
struct ShadowActor;
}
#endif

class VTKSHADOW_EXPORT vtkShadowVolumePass : public vtkShadowPassBase
{
public:
  static vtkShadowVolumePass* New();
  vtkTypeMacro(vtkShadowVolumePass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Depth bias of the volume faces in units of 2^-24 of the depth range
   * (default 2), and the fraction of the depth's slope per pixel added to it
   * (default 0.001); see glsl/vtkShadowVolumeFS.glsl.
   */
  vtkSetMacro(DepthBias, double);
  vtkGetMacro(DepthBias, double);
  vtkSetMacro(SlopeBias, double);
  vtkGetMacro(SlopeBias, double);

  /**
   * Count every volume with z-fail, never z-pass (default off).
   */
  vtkSetMacro(ForceZFail, bool);
  vtkGetMacro(ForceZFail, bool);

  /**
   * Count the volumes of casters that are not closed (open, non-manifold)
   * with z-fail where the camera sees one of their faces from the side
   * turned away from the light (default on; off: z-pass where safe, as for
   * closed casters). There z-pass leaves false shadows (an open bowl: 0.059
   * wrong_pct against POV-Ray, 0.002 z-fail); z-fail draws a cap per face
   * (docs/shadow-volumes.md). Applies only with UnlitCaps off.
   */
  vtkSetMacro(OpenZFail, bool);
  vtkGetMacro(OpenZFail, bool);

  /**
   * Count the volumes of casters that are not closed z-pass (where z-pass
   * is safe) with the caps of the faces the camera sees from their unlit
   * side: those caps lie on the visible surface and leave the volume there,
   * which is what z-pass missed (default on). The caps are drawn with the
   * front faces culled, so the lit side's caps cost no fill
   * (docs/shadow-volumes.md).
   */
  vtkSetMacro(UnlitCaps, bool);
  vtkGetMacro(UnlitCaps, bool);

  /**
   * Darken the facets of closed casters that face away from a light
   * (default on): the volumes leave them lit, a ray tracer given the same
   * triangles does not (docs/shadow-volumes.md, "The terminator").
   */
  vtkSetMacro(FacingTest, bool);
  vtkGetMacro(FacingTest, bool);
  vtkBooleanMacro(FacingTest, bool);

  /**
   * Bias the volumes' sides by a clamped polygon offset, the same bias as
   * the fragment shader's, so that depth and stencil are tested before
   * shading (vtkShadowVolumeSides; default on). Off, or where the context
   * lacks GL_EXT_polygon_offset_clamp, the shader writes the biased depth.
   */
  vtkSetMacro(OffsetSides, bool);
  vtkGetMacro(OffsetSides, bool);
  vtkBooleanMacro(OffsetSides, bool);

  /**
   * The sampled area light (docs/soft-shadows.md): a light with a size
   * (radius or angle) is counted from SoftSamples points (directions) on it,
   * each adding its share of lit into the light's channel of the screen
   * mask. 1 renders the hard shadow of the light's centre, as does a light
   * without a size. 1..255 (the mask's 8-bit channel has 255 steps), default
   * 16.
   */
  vtkSetClampMacro(SoftSamples, int, 1, 255);
  vtkGetMacro(SoftSamples, int);

  /**
   * Adaptive sample counts for a sampled light (docs/soft-shadows.md): a
   * first batch of VSH_SOFT_ADAPTIVE_BATCH samples (the light's centre and
   * rim) is counted everywhere, the other SoftSamples - batch only at the
   * pixels where the batch disagrees or borders a disagreement; the others
   * keep the batch's answer (0 or 1). Off by default.
   */
  vtkSetMacro(Adaptive, bool);
  vtkGetMacro(Adaptive, bool);
  vtkBooleanMacro(Adaptive, bool);

  /**
   * The settings (SetOption keys, ranges, docs) of this pass: its table in
   * the .cxx, listed by `vtkshadow-render --list-settings`.
   */
  vtkShadowSettingsMacro();

  /**
   * Per light: casters counted by z-pass / z-fail / culled, silhouette edges,
   * volume quads, cap triangles, fill (pixels of the scissor rectangles, an
   * upper bound of the pixels each volume layer touches); volume rebuilds
   * and glyph instances.
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const override;

  /**
   * How many (caster, light) volumes were built since creation: constant
   * while neither casters nor lights move and no mesh changes (a camera
   * orbit rebuilds nothing).
   */
  vtkIdType GetNumberOfVolumeBuilds() const;
  long long GetMemoryBytes() const override;

  /**
   * Whether the volumes give this caster's exact shadows: it is drawn
   * without front-face culling (the dark caps of a closed caster assume its
   * inside is never seen). Such casters still cast, inexactly;
   * vtkAutoShadowPass counts them among the casters volumes cannot draw, so
   * it never picks volume for them. (Actors drawn as a wireframe or points
   * cast nothing here, as in every exact technique:
   * vtkshadow::CastsAsSurface.)
   */
  static bool CastsExactly(vtkActor* actor);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // Shader hooks: the screen mask's lighting factors.
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkShadowVolumePass();
  ~vtkShadowVolumePass() override;

  double DepthBias = 2.0;
  double SlopeBias = 0.001;
  bool ForceZFail = false;
  bool OpenZFail = true;
  bool UnlitCaps = true;
  bool FacingTest = true;
  bool OffsetSides = true;
  int SoftSamples = 16;
  bool Adaptive = false;

private:
  vtkShadowVolumePass(const vtkShadowVolumePass&) = delete;
  void operator=(const vtkShadowVolumePass&) = delete;

  struct Internals;
  struct Frame;
  struct Volume;
  std::unique_ptr<Internals> Impl;

  void SetUpFrame(const vtkRenderState* s, Frame& frame);
  // One layer of the screen mask (the opaque surfaces, or translucent ones
  // where they are nearest): its depth, then every casting light counted.
  // False when its depth pass fails.
  bool CountLayer(const vtkRenderState* s, vtkOpenGLRenderWindow* window, const Frame& frame,
    vtkShadowScreenMask& layer);
  void CountLight(
    vtkOpenGLRenderWindow* window, vtkShaderProgram* program, const Frame& frame, int light);
#ifndef __VTK_WRAP__
  // Counts one light (sample < 0) or one of its SoftSamples samples; with
  // `refining`, only at the pixels MarkRefined marked (stencil bit 7); with
  // `translucent`, only that caster's crossings volume.
  void CountVolumes(vtkShaderProgram* program, const Frame& frame, int light, int sample,
    bool refining = false, const vtkshadow::ShadowActor* translucent = nullptr);
#endif
  // After a light's opaque count: each translucent caster's crossings
  // counted and multiplied into the light's channel as (1 - opacity)^count.
  void CountTranslucent(vtkShaderProgram* program, const Frame& frame, int light);
  // After an adaptive light's first batch: the batch's all-lit pixels to 1,
  // and stencil bit 7 at the pixels to refine.
  void MarkRefined(int light, int batchLevels);
  // vsh_soft_batch_order(samples, batch), cached: the identity when
  // batch >= samples.
  const std::vector<int>& SampleOrder(int samples, int batch);
#ifndef __VTK_WRAP__
  // `crossings`: the volume of every face (a translucent caster), z-fail.
  // Whether a caster's volume for one light is counted z-pass (no caps)
  // rather than z-fail: bounds and light camera-relative.
  bool CountsZPass(const Frame& frame, const vtkshadow::ShadowActor& caster, const Volume& volume,
    const double bounds[6], const double lightRelative[4], bool crossings) const;
  // Whether the camera sees a face of the caster's mesh from the side that
  // faces away from the volume's light (vsh_silhouette_seen_unlit).
  bool SeenUnlit(
    const Frame& frame, const vtkshadow::ShadowActor& caster, const Volume& volume) const;
  // Rebuild the shaders when the set of actors that need the facing test
  // (closed casters of some light this frame) changed.
  void UpdateFacingShaders();
  void DrawCaster(vtkShaderProgram* program, const Frame& frame, int light, int sample,
    const vtkshadow::ShadowActor& caster, bool crossings = false);
  // The bound volume's `sides` vertices, then its `caps` vertices (all of
  // them, or with `leavingCaps` only those leaving the volume: the back
  // faces), each with its bias.
  void DrawFaces(vtkShaderProgram* program, const float volumeMCDC[16], int sides, int caps,
    bool leavingCaps, vtkActor* actor);
  Volume* UpdateVolume(const vtkshadow::ShadowActor& caster, int light, int sample,
    const double lightWorld[4], bool crossings);
#endif
  // Soft volumes of lights counted hard this frame, and of casters gone.
  void ReleaseUnusedVolumes(vtkOpenGLRenderWindow* window);
  void LightsInViewCoordinates(vtkRenderer* renderer, const Frame& frame);
  // Bit I set when `prop` is a closed caster counted for light I this frame.
  int ClosedCasterLights(vtkProp* prop) const;
};

#endif
