/**
 * @class   vtkShadowPassBase
 * @brief   What every vtkshadow technique's render pass shares.
 *
 * Each shadow technique is one render pass deriving from this class and one
 * line in vtkShadowTechniqueRegistry. The base holds what every pass needs,
 * so no pass repeats it:
 *
 * - the delegate that renders the scene (a vtkRenderStepsPass unless set);
 * - which lights cast: SkippedLights (bit i = light i in the mapper's
 *   numbering) and the headlight rule (CastHeadlightShadows, default off:
 *   the headlight's shadows hide behind their casters); LightCasts();
 * - the receiver / no-cast property keys every pass reads;
 * - the renderer's viewport in the render target (GetViewport);
 * - the shader-stage time: passes whose generated code changes call
 *   BumpShaderTime() so VTK's mappers rebuild their shaders;
 * - virtuals for the GPU memory it holds, the last frame's details as JSON,
 *   and named options (SetOption), so the CLI, the C API, Python, the
 *   harness and the bench treat every technique alike;
 * - the residual light (option residual_light): how much of a light remains
 *   in its shadow, applied where every pass's factor enters the lighting
 *   (InjectLightFactors);
 * - the receivers a pass detected (GetDetectedReceiver), for passes with
 *   plane receivers.
 */
#ifndef vtkShadowPassBase_h
#define vtkShadowPassBase_h

#include "vtkOpenGLRenderPass.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

/**
 * In a pass's class: its settings table (SettingsTable(), defined in the
 * .cxx from rows, vtkShadowSettings.h) and the virtual that SetOption and
 * PrintSelf read it through.
 */
#ifndef __VTK_WRAP__
#define vtkShadowSettingsMacro()                                                                   \
  static const vtkshadow::Settings& SettingsTable();                                               \
  const vtkshadow::Settings& GetSettings() const override                                          \
  {                                                                                                \
    return SettingsTable();                                                                        \
  }
#else
#define vtkShadowSettingsMacro()
#endif

class vtkActor;
class vtkInformationDoubleKey;
namespace vtkshadow
{
class Settings;
struct ShadowFrame;
}
class vtkInformationIntegerKey;
class vtkLight;
class vtkRenderer;
class vtkShadowScreenMask;
class vtkShadowVolumeOpacityMap;
class vtkShadowVolumeReceiver;
class vtkShaderProgram;
class vtkProp;

class VTKSHADOW_EXPORT vtkShadowPassBase : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkShadowPassBase, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Property key: an actor with RECEIVER() = 1 receives planar shadows
   * (vtkShadowScene marks the scene's "receiver": true objects).
   */
  static vtkInformationIntegerKey* RECEIVER();

  /**
   * Property key: an actor with NO_CAST() = 1 casts no shadow.
   */
  static vtkInformationIntegerKey* NO_CAST();

  /**
   * What this pass leaves out of a light's shadow in the last frame, per
   * light (mapper numbering), "" where it draws everything: a technique
   * that cannot render some caster says so per light rather than silently,
   * e.g. "the filter colour of translucent casters is drawn grey (raytrace
   * draws it)". GetNumberOfLightNotes() is the frame's light count.
   */
  int GetNumberOfLightNotes() const { return static_cast<int>(this->LightNotes.size()); }
  const char* GetLightNote(int light) const;

  /**
   * Property key: of the light a translucent actor (property opacity a < 1)
   * lets through, (1 - a) per crossing, the fraction FILTER() (0..1) is
   * tinted by the property's diffuse colour, as POV-Ray's filter: channel
   * k keeps (1 - a) ((1 - f) + f c_k) (docs/translucency.md). Absent or 0:
   * grey partial shadows. vtkShadowScene sets it from the scene's "filter".
   */
  static vtkInformationDoubleKey* FILTER();

  ///@{
  /**
   * A light's size, kept in the vtkLight's information
   * (vtkLight::GetInformation): LIGHT_RADIUS() is the radius of a point or
   * spot light's disk (world units; the disk is centred on the light's
   * position and faces the shaded point, as Cycles 3.4 samples it),
   * LIGHT_ANGLE() the angular diameter of a directional light in degrees
   * (shadow rays leave within a cone of half-angle ANGLE/2 around the
   * direction to the light). Absent or 0: a hard light. vtkShadowScene sets
   * them from the scene's "radius" and "angle". Passes read them with
   * GetLightRadius / GetLightAngle, which return 0 for a light without the
   * key (any vtkLight made elsewhere) or with a value that is not finite and
   * >= 0 (and, for the angle, < 180).
   */
  static vtkInformationDoubleKey* LIGHT_RADIUS();
  static vtkInformationDoubleKey* LIGHT_ANGLE();
  static double GetLightRadius(vtkLight* light);
  static double GetLightAngle(vtkLight* light);
  static void SetLightSize(vtkLight* light, double radius, double angleDegrees);
  ///@}

  /**
   * The pass that renders the scene (default: a vtkRenderStepsPass, made on
   * the first frame).
   */
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);

  /**
   * The application's own scene pass (a vtkRenderStepsPass it set on the
   * renderer, vtkShadowPassComposition.h) as the delegate. Returns false,
   * changing nothing, for a pass that draws the scene with steps of its own
   * (the vtk technique). GetApplicationScene() is that pass, nullptr while
   * the delegate is the pass's own.
   */
  virtual bool SetApplicationScene(vtkRenderPass* scene);
  vtkRenderPass* GetApplicationScene() const;

  /**
   * Whether the headlight casts shadows too (default off: they hide behind
   * the objects that cast them).
   */
  vtkSetMacro(CastHeadlightShadows, bool);
  vtkGetMacro(CastHeadlightShadows, bool);
  vtkBooleanMacro(CastHeadlightShadows, bool);

  /**
   * Whether the techniques with a depth pre-pass (volume, raytrace, csm's
   * screen resolve) write its depth into the main pass's depth buffer before
   * the lit draw, so that hidden fragments are rejected before shading
   * (vtkShadowDepthSeed; option early_depth). The image is the same either
   * way. EARLY_DEPTH_OFF: never; EARLY_DEPTH_WHERE_IT_PAYS (default): where
   * the fragments it saves, counted now and then, outweigh its own draw
   * (vsh_depth_seed.h); EARLY_DEPTH_ALWAYS: every frame. It applies only
   * with the pass's own delegate and a single-sampled framebuffer;
   * GetDepthSeeded() says whether the last frame's lit draw was seeded.
   */
  enum EarlyDepthModes
  {
    EARLY_DEPTH_OFF = 0,
    EARLY_DEPTH_WHERE_IT_PAYS = 1,
    EARLY_DEPTH_ALWAYS = 2
  };
  vtkSetClampMacro(EarlyDepth, int, EARLY_DEPTH_OFF, EARLY_DEPTH_ALWAYS);
  vtkGetMacro(EarlyDepth, int);
  bool GetDepthSeeded() const;

  /**
   * Lights this pass leaves unshadowed, as bits: bit i for light i in the
   * mapper's numbering (the renderer's switched-on lights, in order).
   * Default 0, every light casts. vtkAutoShadowPass uses it to give each
   * light its own technique, or none when it casts no visible shadow.
   */
  vtkSetMacro(SkippedLights, unsigned int);
  vtkGetMacro(SkippedLights, unsigned int);

  /**
   * True when switched-on light number `index` (mapper numbering) casts in
   * this pass: not skipped, and not the headlight unless it is asked to.
   */
  bool LightCasts(vtkLight* light, int index) const;

  /**
   * How much of a light remains where it is shadowed: 0 (default) is the
   * physical hard shadow (the light's diffuse and specular terms removed),
   * 0.3 keeps 30% of them, 1 shows no shadow. Each light's shadow factor f
   * becomes mix(ResidualLight, 1, f). Option residual_light (0..1).
   * Changing it rebuilds the mappers' shaders (the value is a constant in
   * them).
   */
  virtual void SetResidualLight(double residual);
  vtkGetMacro(ResidualLight, double);

  /**
   * Actors the pass detected as plane receivers in its last frame (because
   * none was marked with RECEIVER()); none for passes without receivers.
   */
  virtual int GetNumberOfDetectedReceivers() const { return 0; }
  virtual vtkActor* GetDetectedReceiver(int) const { return nullptr; }

  /**
   * Bytes of GPU memory the pass holds for shadows, as of its last frame.
   */
  virtual long long GetMemoryBytes() const { return 0; }

  ///@{
  /**
   * The world the next Render() draws: 0 (default) is the scene itself,
   * K > 0 another view of it that comes back every frame, such as the scene
   * mirrored through mirror K (vtkPlanarReflectionPass sets it around its
   * mirrored draws and sets 0 back). Passes that keep state from frame to
   * frame (csm's held maps, raytrace's still-frame mask) keep one set per
   * world, so two worlds drawn in turn do not overwrite each other's and a
   * still frame re-does nothing in either. Negative keys are taken as 0.
   */
  virtual void SetWorldKey(int key);
  int GetWorldKey() const { return this->WorldKey; }
  /**
   * Free the state kept for every world key >= `first` (never world 0): the
   * mirrors went away. GetWorldsMemoryBytes is the part of GetMemoryBytes()
   * held for worlds other than 0.
   */
  virtual void ReleaseWorlds(vtkWindow* w, int first);
  virtual long long GetWorldsMemoryBytes() const { return 0; }
  ///@}

  /**
   * Details of the last frame rendered on `renderer` as the members of a
   * JSON object, without braces ("" when there is nothing to say).
   */
  virtual std::string GetStatsJSON(vtkRenderer* renderer) const;

  /**
   * Set a setting by name (command lines, the C API, vtkShadowTechnique).
   * Returns false for a key this pass does not have or a value out of its
   * range; nothing changes then. The keys and ranges are the rows of the
   * pass's settings table (GetSettings); the base's are cast_headlight and
   * residual_light. Virtual for passes that hand settings on
   * (vtkPlanarReflectionPass).
   */
  virtual bool SetOption(const char* key, double value);

#ifndef __VTK_WRAP__
  /**
   * The base's settings table, and the table of this pass (the most
   * derived class that declares one with vtkShadowSettingsMacro).
   */
  static const vtkshadow::Settings& SettingsTable();
  virtual const vtkshadow::Settings& GetSettings() const
  {
    return SettingsTable();
  }
#endif

  void ReleaseGraphicsResources(vtkWindow* w) override;
  vtkMTimeType GetShaderStageMTime() override;

  /**
   * The renderer's viewport in the render target: its tiled size and origin
   * when drawing to the window, the target's size (origin 0) for an FBO.
   */
  static void GetViewport(const vtkRenderState* s, int size[2], int origin[2]);

#ifndef __VTK_WRAP__
  /**
   * A frame the next Render() of this pass reads instead of gathering its
   * own (vtkShadowFrame.h), when it was gathered for the same render state:
   * vtkAutoShadowPass hands its frame to the passes it chains,
   * vtkPlanarReflectionPass to its technique. The caller keeps it alive
   * through that Render() and sets nullptr back after it.
   */
  void SetGivenFrame(const vtkshadow::ShadowFrame* frame)
  {
    this->GivenFrame = frame;
  }
#endif

protected:
  vtkShadowPassBase();
  ~vtkShadowPassBase() override;

  /**
   * The delegate, made a vtkRenderStepsPass when none was set.
   */
  vtkRenderPass* EnsureDelegatePass();

  /**
   * Render the scene through the delegate. The shader-hooking form first
   * registers this pass with the actors (vtkOpenGLRenderPass::PreRender) so
   * the mappers call its Pre/PostReplaceShaderValues and SetShaderParameters.
   */
  void RenderDelegate(const vtkRenderState* s);
  void RenderDelegateWithShaderHooks(const vtkRenderState* s);
  // With the opaque depth of `seed` (this frame's RenderDepth of the same
  // view) written first when EarlyDepth allows it.
  void RenderDelegate(const vtkRenderState* s, vtkShadowScreenMask* seed);
  void RenderDelegateWithShaderHooks(const vtkRenderState* s, vtkShadowScreenMask* seed);

  /**
   * Mark the generated shader code as changed (mappers rebuild).
   */
  void BumpShaderTime();

#ifndef __VTK_WRAP__
  /**
   * This Render()'s frame: the given frame (SetGivenFrame) when it was
   * gathered for `s`, else one gathered now (vtkshadow::GatherShadowFrame,
   * with the shadow actors when `actors`), with each light's Casts set by
   * this pass's LightCasts. Valid until the next BeginFrame; GetFrame() is
   * it.
   */
  const vtkshadow::ShadowFrame& BeginFrame(const vtkRenderState* s, bool actors = true);
  const vtkshadow::ShadowFrame& GetFrame() const;

  /**
   * vtkshadow::InjectLightFactors with this pass's ResidualLight: every
   * pass puts its factors into the lighting through this.
   */
  bool InjectLightFactors(std::string& fragmentShader, const std::string& factor,
    const std::string& prepare, int maxLights = 16) const;
#endif

  /**
   * The detected receivers as a JSON array of their indices in the
   * renderer's actor list, "[]" for none.
   */
  std::string DetectedReceiversJSON(vtkRenderer* renderer) const;

  /**
   * Append `note` to light `light`'s note (GetLightNote) for this frame;
   * BeginFrame clears them. NoteGreyFilters notes, on every casting light,
   * that a translucent caster's filter colour is drawn grey, when the
   * frame has such a caster (the techniques with one value per light).
   */
  void AddLightNote(int light, const std::string& note);
#ifndef __VTK_WRAP__
  void NoteGreyFilters(const vtkshadow::ShadowFrame& frame);
  // On every casting light, that the frame's volumes (vtkVolume) cast no
  // shadow here (raytrace casts them), when it has any; with `maps` (the
  // screen-space techniques' opacity shadow maps) only on the lights they
  // leave out, with their reason. In a pass without VolumesReceive (planar,
  // vtk) also that shaded volumes receive no shadow, when the frame shows
  // one.
  void NoteUncastVolumes(
    const vtkshadow::ShadowFrame& frame, const vtkShadowVolumeOpacityMap* maps = nullptr);
#endif
  std::vector<std::string> LightNotes;

  /**
   * Shaded vtkVolumes receive the opaque surfaces' shadows
   * (vtkShadowVolumeReceiver) in the passes that set VolumesReceive (csm,
   * volume, raytrace; auto through them): RenderDelegateWithShaderHooks
   * brings the maps up to date before the draw (BeginVolumeReceiver; a pass
   * drawing with its hooks otherwise calls it and EndVolumeReceiver around
   * its draw), and the pass's hooks call
   * these two for every mapper (they touch only the volume mapper's
   * shader). VolumeReceiverStatsJSON: "volume_receiver_maps": ... for
   * GetStatsJSON.
   */
  void BeginVolumeReceiver(const vtkRenderState* s);
  void EndVolumeReceiver();
  void ReceiveVolumeShadows(std::string& fragmentShader, vtkProp* prop);
  void SetVolumeShadowParameters(vtkShaderProgram* program);
  std::string VolumeReceiverStatsJSON() const;
  // "depth_seeded": whether the last lit draw started from the pre-pass's
  // depth (EarlyDepth), and "depth_seed_hidden_per_px": the fragments per
  // pixel that saves by the last measurement (-1 before one), for the
  // screen-space passes' GetStatsJSON.
  std::string DepthSeedStatsJSON() const;
  long long GetVolumeReceiverMemoryBytes() const;
  bool VolumesReceive = false;

  vtkRenderPass* DelegatePass;
  bool DelegateIsApplicationScene = false;
  bool CastHeadlightShadows;
  int EarlyDepth = EARLY_DEPTH_WHERE_IT_PAYS;
  double ResidualLight;
  unsigned int SkippedLights;
  vtkMTimeType ShaderTime;
  int WorldKey;

private:
  std::unique_ptr<vtkshadow::ShadowFrame> OwnFrame;
  std::unique_ptr<vtkShadowVolumeReceiver> VolumeReceiver;
  const vtkshadow::ShadowFrame* GivenFrame = nullptr;

  vtkShadowPassBase(const vtkShadowPassBase&) = delete;
  void operator=(const vtkShadowPassBase&) = delete;
};

#endif
