/**
 * @class   vtkPlanarShadowPass
 * @brief   Exact shadows of every opaque actor on flat receivers.
 *
 * vtkPlanarShadowPass projects the casters onto each receiver plane from each
 * light (the classic "ground shadow" matrix, computed in double precision by
 * vtkshadow's C core, camera-relative) and rasterizes them into a screen-space
 * bit mask, one bit per (receiver, light) pair. While its delegate renders the
 * scene, the receivers' lighting code multiplies each light's diffuse and
 * specular term by that light's bit: a shadow removes exactly its light's
 * contribution and nothing else. The shadow is therefore exact on the
 * receiver, appears only on the receiver's visible fragments (never off its
 * edges), never darkens twice where casters overlap, and cannot z-fight (the
 * mask draw uses no depth test).
 *
 * Receivers: actors marked with RECEIVER() or added with AddReceiverActor()
 * (their flat geometry defines the plane and the area), or explicit planes
 * (AddReceiverPlane()), which receive on every opaque fragment lying on them.
 * When no actor is marked or added and no plane is given, every flat surface
 * actor (all its points on one plane: a floor, a cut plane, a slice) is
 * detected as a receiver,
 * unless it carries RECEIVER() = 0 or detection is off (DetectReceivers,
 * option detect_receivers); GetDetectedReceiver() lists them. The flat
 * parts of the other opaque meshes are detected too (vsh_flat_parts: a
 * plane holding at least 5 % of a mesh's area, such as a box's top or a
 * slab floor) and receive like explicit planes, the largest ones whose
 * visible side a casting light reaches first (8 plane slots); a mesh's own
 * points on a part do not shadow it. The stats count them
 * (detected_flat_parts).
 * Casters: every visible opaque actor except receivers onto themselves and
 * actors marked with NO_CAST(). A translucent actor (property opacity a < 1)
 * casts a partial shadow: its projected triangles multiply the light by
 * (1 - a) each, so the receiver keeps (1 - a) per crossing of the ray to the
 * light (docs/translucency.md), for up to 4 pairs a frame. Lights: every switched-on scene light
 * (directional, point, spot); the headlight only with CastHeadlightShadowsOn().
 * At most 128 (receiver, light) pairs.
 *
 * @code{.py}
 * planar = vtkshadow.vtkPlanarShadowPass()
 * planar.AddReceiverActor(floor_actor)
 * renderer.SetPass(planar)      # delegate defaults to vtkRenderStepsPass
 * @endcode
 */
#ifndef vtkPlanarShadowPass_h
#define vtkPlanarShadowPass_h

#include "vtkShadowPassBase.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkActor;
class vtkInformationIntegerKey;
class vtkProp;
class vtkRenderPass;
class vtkTextureObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkShaderProgram;
class vtkShadowCasterGeometry;
struct vsh_planar_pair;
struct vsh_planar_rect;
#ifndef __VTK_WRAP__
namespace vtkshadow
{
class ReceiverPlaneCache;
struct ReceiverChoice;
struct ShadowActor;
}
#endif

class VTKSHADOW_EXPORT vtkPlanarShadowPass : public vtkShadowPassBase
{
public:
  static vtkPlanarShadowPass* New();
  vtkTypeMacro(vtkPlanarShadowPass, vtkShadowPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Receivers given as actors with flat geometry.
   */
  void AddReceiverActor(vtkActor* actor);
  void RemoveReceiverActor(vtkActor* actor);

  /**
   * Receivers given as planes (a point and a normal, world coordinates).
   * Every opaque fragment within the tolerance (relative to its distance from
   * the camera, default 1e-5) of the plane receives the shadow.
   */
  void AddReceiverPlane(
    double originX, double originY, double originZ, double normalX, double normalY, double normalZ);
  void RemoveAllReceivers();
  vtkSetMacro(PlaneTolerance, double);
  vtkGetMacro(PlaneTolerance, double);

  /**
   * Whether flat surface actors receive when no actor is marked (default on).
   */
  vtkSetMacro(DetectReceivers, bool);
  vtkGetMacro(DetectReceivers, bool);
  vtkBooleanMacro(DetectReceivers, bool);

  /**
   * The receivers detected in the last frame (none when some actor was
   * marked or detection is off), in the order of the render state's props.
   */
  int GetNumberOfDetectedReceivers() const override;
  vtkActor* GetDetectedReceiver(int index) const override;

  /**
   * Light samples per (receiver, light) pair for a light with a size (a
   * point or spot light's radius, a directional light's angle): N hard
   * shadows from stratified points on the light, averaged (the sampled area
   * light, docs/soft-shadows.md). 1 draws the hard shadow of the light's
   * centre (the hard path, unchanged). Default 16; lights without a size
   * always take the hard path. At most 4 soft pairs per frame (the others
   * are drawn hard, with a warning).
   */
  vtkSetClampMacro(SoftSamples, int, 1, 1024);
  vtkGetMacro(SoftSamples, int);

  /**
   * Adaptive sample counts for the sampled area light (docs/soft-shadows.md,
   * "planar: adaptive sample counts"): with SoftSamples N > 8, a batch of 8
   * samples (the light's centre and 7 rim points) is drawn for every pixel,
   * and the other N - 8 only where the batch disagrees within a pixel's 3x3
   * neighbourhood (within the bounding box of those pixels); the others get
   * exactly 0 or 1. Default off (the draw of before).
   */
  vtkSetMacro(Adaptive, bool);
  vtkGetMacro(Adaptive, bool);
  vtkBooleanMacro(Adaptive, bool);

  /**
   * Darken the facets of closed casters that face away from a light
   * (default on). Planar shadows only receivers and leaves a caster's own
   * dark side to the lighting, whose interpolated normals still light
   * facets facing away from the light along the terminator; a ray tracer
   * given the same triangles does not (docs/planar-shadows.md, "The
   * casters' own dark side").
   */
  vtkSetMacro(FacingTest, bool);
  vtkGetMacro(FacingTest, bool);
  vtkBooleanMacro(FacingTest, bool);

  /**
   * Pixels that got all N samples in the last frame, summed over its soft
   * pairs (-1 when no soft pair was adaptive).
   */
  vtkGetMacro(NumberOfRefinedPixels, vtkIdType);

  /**
   * Number of (receiver, light) pairs that cast in the last frame, and the
   * number of caster triangles drawn into the mask in it.
   */
  vtkGetMacro(NumberOfShadowPairs, int);
  vtkGetMacro(NumberOfMaskTriangles, vtkIdType);

  /**
   * How many times caster geometry was (re)built since creation: stays
   * constant while neither props nor their data change.
   */
  vtkGetMacro(NumberOfGeometryBuilds, int);

  /**
   * Bytes of GPU memory the pass holds (mask texture and caster copies).
   */
  long long GetMemoryBytes() const override;

  /**
   * The settings (SetOption keys, ranges, docs) of this pass: its table in
   * the .cxx, listed by `vtkshadow-render --list-settings`.
   */
  vtkShadowSettingsMacro();

  /**
   * shadow_pairs, mask_triangles, geometry_builds, soft_pairs,
   * soft_samples, soft_batch (8 when adaptive, else 0), soft_adaptive (per
   * soft pair: light, refined_px, box_px) and detected_receivers (indices
   * in the renderer's actor list) of the last frame.
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

#ifndef __VTK_WRAP__
  /**
   * The planes of the receiver actors, by actor (vtkShadowReceiverPlane.h):
   * vtkAutoShadowPass reads the cache of its planar pass.
   */
  vtkshadow::ReceiverPlaneCache& GetReceiverPlaneCache();

  /**
   * The receivers among a frame's opaque actors under this pass's marks,
   * added actors and detection setting (vtkshadow::ChooseReceivers):
   * vtkAutoShadowPass decides with the receivers this pass will use.
   */
  vtkshadow::ReceiverChoice ChooseReceivers(const std::vector<vtkshadow::ShadowActor>& actors);
#endif

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkPlanarShadowPass();
  ~vtkPlanarShadowPass() override;

  double PlaneTolerance;
  bool DetectReceivers;
  int NumberOfShadowPairs;
  vtkIdType NumberOfMaskTriangles;
  int NumberOfGeometryBuilds;
  int SoftSamples;
  int NumberOfSoftPairs;
  bool Adaptive;
  bool FacingTest;
  vtkIdType NumberOfRefinedPixels;

private:
  vtkPlanarShadowPass(const vtkPlanarShadowPass&) = delete;
  void operator=(const vtkPlanarShadowPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;

  // A frame's plain data: the shared frame (vtkShadowFrame.h) and the
  // lights, receivers and casters planar plans from it.
  struct Frame;
  struct Fan;
  // The stages of Render(), in order.
#ifndef __VTK_WRAP__
  void GatherReceivers(const std::vector<vtkshadow::ShadowActor>& actors, Frame& frame);
  // Detected flat parts of the other meshes as plane receivers; how many.
  int GatherFlatParts(const std::vector<vtkshadow::ShadowActor>& actors,
    const vtkshadow::ReceiverChoice& choice, Frame& frame);
  bool PartCanShowShadow(const double plane[4], const Frame& frame) const;
  void GatherCasters(const std::vector<vtkshadow::ShadowActor>& actors, Frame& frame);
#endif
  // Which lights' facing test each closed caster gets this frame.
  void NoteClosedCasters(vtkRenderer* renderer, const Frame& frame);
  // The explicit planes in view coordinates, for the receivers' shaders.
  void SetUpPlanes(const Frame& frame);
  void DrawMask(vtkOpenGLRenderWindow* window, const Frame& frame,
    const std::vector<vsh_planar_pair>& pairs, const std::vector<vsh_planar_pair>& softPairs,
    const std::vector<vsh_planar_pair>& transmitPairs);
  void ForgetRemovedCasters(vtkOpenGLRenderWindow* window);
  // Sampled area lights (vtkPlanarShadowSoft.cxx): which pairs are soft,
  // and their accumulation.
  std::vector<vsh_planar_pair> SplitSoftPairs(
    const Frame& frame, std::vector<vsh_planar_pair>& pairs);
  void DrawSoftPairs(vtkOpenGLRenderWindow* window, vtkOpenGLState* state, const Frame& frame,
    const std::vector<vsh_planar_pair>& softPairs);
  void DrawSoftSample(vtkShaderProgram* program, vtkOpenGLState* state, const Frame& frame,
    const vsh_planar_pair& pair, int sample, const float weight[4]);
  // Adaptive sample counts: the order of the samples (the batch first),
  // the mark after the batch, and the rest within it.
  const std::vector<int>& SoftOrder(bool adaptive);
  long MarkSoftBatch(vtkOpenGLRenderWindow* window, vtkOpenGLState* state, const Frame& frame,
    int channel, int box[4]);
  void DrawSoftRest(vtkShaderProgram* program, vtkOpenGLState* state, const Frame& frame,
    const vsh_planar_pair& pair, const int box[4], const float weight[4]);
  // Pair bits of a four-channel texture's channels (soft, transmittance),
  // and whether the receivers' shaders look them up.
  void SetPairChannels(const std::vector<vsh_planar_pair>& pairs, int channelPair[4], bool& lookup);
  // RGBA16F, a pair per channel, at the viewport's size (the soft
  // accumulation, the translucent casters' transmittance): allocated when
  // needed, attached as the mask framebuffer's colour and cleared to
  // clearValue.
  void AttachPairChannels(vtkTextureObject*& texture, int textureSize[2],
    vtkOpenGLRenderWindow* window, const Frame& frame, float clearValue);
  // Translucent casters (vtkPlanarShadowTranslucent.cxx): which ones cast,
  // the pairs that get a transmittance channel, and its drawing.
#ifndef __VTK_WRAP__
  void GatherTranslucentCasters(Frame& frame);
#endif
  bool TransmitReachesView(const Frame& frame, const vsh_planar_pair& pair) const;
  std::vector<vsh_planar_pair> TransmitPairs(const Frame& frame,
    const std::vector<vsh_planar_pair>& pairs, const std::vector<vsh_planar_pair>& softPairs);
  void DrawTransmitPairs(vtkOpenGLRenderWindow* window, vtkOpenGLState* state, const Frame& frame,
    const std::vector<vsh_planar_pair>& transmitPairs);
  // Parts of them.
  void UpdateReceivingSet();
  void AllocateMask(vtkOpenGLRenderWindow* window, const Frame& frame);
  void AttachStencil(const Frame& frame);
  void DrawPair(vtkShaderProgram* program, vtkOpenGLState* state, const Frame& frame,
    const vsh_planar_pair& pair);
  vtkShadowCasterGeometry* CasterGeometry(vtkActor* actor);
#ifndef __VTK_WRAP__
  void DrawCaster(vtkShaderProgram* program, const Frame& frame, const vsh_planar_pair& pair,
    const double light[4], const double shadowDC[16], const vtkshadow::ShadowActor& caster,
    vtkShadowCasterGeometry& geometry, std::vector<Fan>* fans, vsh_planar_rect* fanRect);
#endif
  void FillFans(vtkShaderProgram* program, vtkOpenGLState* state, const Frame& frame,
    const std::vector<Fan>& fans, const vsh_planar_rect& fanRect, const unsigned int bits[4]);
  // Every fan's silhouette triangles, counted into the stencil as the
  // caller's stencil state says.
  void DrawFans(vtkShaderProgram* program, const std::vector<Fan>& fans);
  void DrawViewportQuad(vtkShaderProgram* program);
  void ClearWritten(vtkOpenGLState* state);
};

#endif
