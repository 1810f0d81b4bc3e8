// vtkShadowScreenMask.h - per-light visibility of the visible surface, one
// value per pixel, that the mappers' lighting reads once per fragment.
//
// Screen-space techniques (shadow volumes, ray-traced shadows, and the
// per-pixel resolve of shadow maps) work in three stages each frame:
//
//   1. RenderDepth(): the opaque scene's depth (with an 8-bit stencil) at
//      the viewport's size, into the mask's own framebuffer. The mappers
//      draw it with their usual vertex shaders, so the main pass produces the
//      same depths afterwards.
//   2. The technique writes each light's visibility of the surface at every
//      pixel: on the GPU with the framebuffer bound (BeginDraw/EndDraw, then
//      e.g. ResolveStencil() after stencil counting), or on the CPU from
//      ReadDepth() and UploadLight().
//   3. The scene is rendered as usual with the owning pass's shader hooks
//      forwarding to PreReplaceShaderValues/PostReplaceShaderValues/
//      SetShaderParameters here: light I's diffuse and specular terms are
//      multiplied by channel I of the mask at the fragment's pixel.
//
// Only opaque actors read the mask (translucent surfaces are not in the
// depth pass, so the mask says nothing about them); actors with lighting off
// have no light terms to multiply. Lights past MaxLights stay unshadowed and
// GetLightCount() says how many are covered.
//
// A second mask with SetTranslucentSurfaces(true) is the translucent layer:
// its depth is the nearest surface, translucent ones included, and only
// translucent actors read it. An owner computes it exactly as the opaque
// one (so translucent surfaces receive shadows on their own fragments) and
// forwards each prop's hooks to the mask of its kind (ReadBy).
#ifndef vtkShadowScreenMask_h
#define vtkShadowScreenMask_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderPass;
class vtkRenderState;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkShadowScreenMask
{
public:
  // Four lights per RGBA8 texture, two textures.
  static constexpr int MaxLights = 8;

  vtkShadowScreenMask();
  ~vtkShadowScreenMask();
  vtkShadowScreenMask(const vtkShadowScreenMask&) = delete;
  void operator=(const vtkShadowScreenMask&) = delete;

  /**
   * Size the framebuffer to the renderer's viewport for `lightCount` lights
   * (mapper numbering; clamped to MaxLights) and render the opaque scene's
   * depth into it (colour writes off). Every channel then reads 1 (lit) and
   * the stencil 0. Returns false (with a reason in GetError()) when the
   * window is not an OpenGL window or the framebuffer is incomplete.
   * The depth is drawn with no colour attachment and the visibility
   * textures activated (bound to units of their own): an owner may register
   * its shader hooks around this call, so the mappers draw with the same
   * shaders as in the main pass instead of rebuilding them twice a frame.
   */
  bool RenderDepth(const vtkRenderState* s, int lightCount);

  /**
   * The translucent layer (default false): RenderDepth() also draws the
   * translucent actors' depth (the nearest of all surfaces), and the shader
   * hooks go into translucent actors instead of opaque ones. Deeper
   * translucent layers at a pixel read the nearest one's visibility.
   */
  void SetTranslucentSurfaces(bool translucent) { this->TranslucentSurfaces = translucent; }
  bool GetTranslucentSurfaces() const { return this->TranslucentSurfaces; }

  /**
   * Whether `prop` reads this mask: an opaque prop the opaque mask, a prop
   * with only translucent geometry the translucent layer.
   */
  bool ReadBy(vtkProp* prop) const;

  /**
   * Whether the renderer draws a prop with translucent geometry, i.e.
   * whether a translucent layer has anything to receive shadows.
   */
  static bool HasTranslucentProps(const vtkRenderState* s);

  /**
   * Bind the mask's framebuffer (depth, stencil and the light's texture as
   * colour attachment 0) with the viewport set to the whole mask; EndDraw
   * restores the previous bindings. Between them a technique draws with
   * depth test on and depth writes off, for instance stencil volumes.
   * With `depthAttached` false only the colour texture is attached, so a
   * shader may sample GetDepthTexture() (a full-screen resolve).
   */
  void BeginDraw(int light, bool depthAttached = true);
  void EndDraw();

  /**
   * Inside BeginDraw(light): set the light's channel to 0 (blocked) where
   * the stencil is not 0, 1 elsewhere, and leave the stencil as it was.
   */
  void ResolveStencil(int light);

  /**
   * Inside BeginDraw(light), for a light sampled N times (a light with a
   * size; vtkShadowVolumePass's soft_samples): FillLight(light, 0) once,
   * then per sample, after its stencil count, AccumulateStencil(light,
   * AccumulationLevels(sample, N)) adds that many 1/255 steps to the
   * light's channel where the stencil is 0 (lit), by additive blending.
   * Integer steps summing to 255 over the N samples keep the 8-bit sum
   * exact: all samples lit is exactly 1, none 0, and k of N lit is within
   * 1/255 of k/N (a weight of 1/N would round per sample: N = 24 gives
   * 11/255 a sample, and 23 lit samples 0.99 instead of 0.96).
   * N is at most 255 (every sample at least one step).
   */
  void FillLight(int light, float value);
  // `ref`: add where the stencil equals ref instead (the pixels MarkBatch
  // marked with ref 0x80 whose low 7 bits counted lit).
  void AccumulateStencil(int light, int levels, int ref = 0);
  static int AccumulationLevels(int sample, int samples);

  /**
   * Inside BeginDraw(light), after a count in the stencil of the triangles
   * of one translucent caster the ray to the light crosses (its crossings
   * volumes, z-fail): multiply the light's channel by `transmit` once per
   * unit of the count, giving transmit^count, and take the stencil back to
   * 0 (each step multiplies where the stencil is not 0 and decrements it
   * there; an occlusion query stops the steps when no pixel is left). At
   * most `maxSteps` steps: later ones change no 8-bit value. Returns the
   * steps drawn; the stencil is 0 everywhere unless that is maxSteps.
   */
  int MultiplyStencilCount(int light, float transmit, int maxSteps);

  /**
   * Inside BeginDraw(light, false): multiply the light's channel by what
   * `program` writes over the whole mask (the caller readied the program,
   * whose vertex shader is vtkShadowScreenQuadVS, and set its uniforms),
   * the other channels, the depth and the stencil untouched: the volumes'
   * opacity shadow maps (vtkShadowVolumeOpacityMap).
   */
  void MultiplyLight(int light, vtkShaderProgram* program);

  /**
   * Inside BeginDraw(light), for adaptive sample counts (vtkShadowVolumePass's
   * adaptive): the light's channel holds its first batch of samples, whose
   * levels sum to `batchLevels` (vsh_soft_batch_levels). Sets the stencil
   * bits `ref` (REPLACE, write mask ref) where refine is true: at the pixels
   * whose 3x3 neighbourhood holds a mixed batch or both all-lit and
   * all-blocked ones (vsh_rt_adaptive_rest_near's rule); refine false: at
   * the other pixels whose batch is all lit. Other stencil bits are kept.
   * The channel is read as a texture, so the colour attachment is detached
   * meanwhile.
   */
  void MarkBatch(int light, int batchLevels, bool refine, int ref);

  /**
   * Copy the depth of the last RenderDepth() to `depth` (window depth in
   * [0,1], row 0 at the bottom, width * height values).
   */
  void ReadDepth(std::vector<float>& depth);

  /**
   * Set a light's channel from the CPU: `visibility` holds width * height
   * values in [0,1], row 0 at the bottom. The upload happens once per
   * texture in FinishUploads(), so four lights cost one transfer.
   */
  void UploadLight(int light, const float* visibility);
  void FinishUploads();

  /**
   * A light's tint from the CPU, after its UploadLight: 3 values per pixel
   * in [0,1] (row 0 at the bottom), channel k's visibility being the
   * light's visibility times tint k (coloured shadows of filtering
   * translucent casters, vsh_rt_visibility_tint). Lights without a tint
   * this frame stay white; a frame without any costs nothing.
   */
  void UploadTint(int light, const float* tint);

  /**
   * Inside BeginDraw: draw a quad over the whole mask with `program`, whose
   * vertex shader takes the clip-space corner as `vec4 vertexMC` (e.g.
   * vtkShadowScreenQuadVS). The caller sets the state and uniforms.
   */
  void DrawFullScreen(vtkShaderProgram* program);

  /**
   * The depth-stencil texture of the last RenderDepth() (window depth in
   * [0,1] as the red channel of a sampler2D, nearest filtering), or null.
   */
  vtkTextureObject* GetDepthTexture() const;

  // Shader hooks, forwarded from the owning pass. Pass the owner's
  // GetResidualLight() as `residual` (the light left in shadow,
  // vtkShadowPassBase::SetResidualLight).
  bool PreReplaceShaderValues(std::string& fragmentShader, vtkProp* prop);
  // `factor` and `prepare` (vtkshadow::InjectLightFactors) let the owner
  // multiply its own per-light term into the mask's.
  bool PostReplaceShaderValues(std::string& fragmentShader, double residual = 0.0,
    const std::string& factor = "vshScreenLight(%d)",
    const std::string& prepare = "vshScreenPrepare();");
  void SetShaderParameters(vtkShaderProgram* program);

  /**
   * Textures bound to texture units for the main pass (around the delegate).
   */
  void Activate();
  void Deactivate();

  const int* GetSize() const { return this->Size; }
  const int* GetOrigin() const { return this->Origin; }
  int GetLightCount() const { return this->LightCount; }
  long long GetMemoryBytes() const;
  const std::string& GetError() const { return this->Error; }
  // Number of mapper shaders the hook went into (since the last Reset).
  vtkIdType GetNumberOfHookedShaders() const { return this->HookedShaders; }

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  bool Allocate(vtkOpenGLRenderWindow* window);
  // One value into the light's channel: over the pixels whose stencil is
  // not 0 (ResolveStencil; StencilCount: multiplied, decrementing the
  // stencil there), is 0 (AccumulateStencil, added) or everywhere.
  enum class Where
  {
    StencilSet,
    StencilZero,
    Everywhere,
    StencilCount
  };
  // `program`: draw it instead of the constant value, multiplying.
  void DrawChannel(int light, float value, Where where, bool add, int ref = 0,
    vtkShaderProgram* program = nullptr);

  struct Internals;
  Internals* Impl;
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  int LightCount = 0;
  bool TranslucentSurfaces = false;
  vtkIdType HookedShaders = 0;
  std::string Error;
};

#endif
