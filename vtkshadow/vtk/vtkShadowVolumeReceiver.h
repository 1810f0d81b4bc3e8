// vtkShadowVolumeReceiver.h - the renderer's shaded vtkVolumes as shadow
// receivers: the opaque surfaces' shadows darken the volume's lighting
// (docs/raytraced-shadows.md, "Volumes").
//
// Per casting light, a light-space depth map of the opaque casters over the
// boxes of the frame's shaded volumes (vtkVolumeProperty ShadeOn): the
// frame is planned as the volumes' opacity shadow map plans its own
// (vsh_volume_opacity_map_plan: orthographic for a directional light,
// perspective from a point or spot light), and each texel holds the light
// distance of the first opaque caster along its ray
// (vsh_volume_opacity_map_texel_ray), traced with Embree through the casters
// (vtkShadowEmbreeScene, the raytrace technique's scene class, kept here
// with its origin at the volumes' centre so a camera move re-commits
// nothing). A map is computed again only when its key changes (the
// volumes' boxes, the light, or the casters: a mesh rebuilt or the top level
// re-committed); a camera orbiting reuses it. The maps of all lights are
// the rows of one R32F texture.
//
// The GPU ray cast mapper (vtkOpenGLGPUVolumeRayCastMapper, VTK 9.1) calls
// the pass's shader hooks for the volumes too: PostReplaceShaderValues
// multiplies each light's diffuse and specular colour in the volume's
// computeLighting loop (lighting complexity 2 and 3: any light that is not
// the headlight) by a lit test of the ray-march sample against the map
// (a small bias, no filtering), and SetShaderParameters binds the map. A
// light without a map reads 1, and 1 multiplies exactly: a volume nothing
// shadows renders as without shadows. Volumes without shading (ShadeOff,
// VTK's default) have no diffuse or specular term to darken and are left
// alone. Several passes chained on one volume (auto) each add their own
// test for their own lights.
#ifndef vtkShadowVolumeReceiver_h
#define vtkShadowVolumeReceiver_h

#include "vtkShadowEmbreeScene.h"
#include "vtkSmartPointer.h"

#include "vsh_volume_opacity_map.h"

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace vtkshadow
{
struct ShadowFrame;
}

class vtkShadowVolumeReceiver
{
public:
  vtkShadowVolumeReceiver();
  ~vtkShadowVolumeReceiver();
  vtkShadowVolumeReceiver(const vtkShadowVolumeReceiver&) = delete;
  void operator=(const vtkShadowVolumeReceiver&) = delete;

  /**
   * Bring the map of every casting light up to date for the frame's shaded
   * volumes (nothing when it shows none) and upload the changed ones.
   */
  void Update(const vtkshadow::ShadowFrame& frame, vtkOpenGLRenderWindow* window);
  // Release the texture unit taken by SetShaderParameters (after the draw).
  void EndDraw();

  // Whether `light` has a map this frame.
  bool Covers(int light) const;
  /**
   * Why a casting light darkens no shaded volume although the frame shows
   * one (empty otherwise): a point light inside or at a volume's box, or a
   * light past the volume shader's 6.
   */
  std::string GetLightNote(int light, bool casts) const;
  // Whether the renderer shows a visible vtkVolume with ShadeOn.
  static bool ShowsShadedVolume(vtkRenderer* renderer);

  /**
   * The volume mapper's hooks (prop a vtkVolume, the shader its expanded
   * fragment source): the lit test added to computeLighting, and its
   * uniforms. `residual` is the pass's residual light.
   */
  void PostReplaceShaderValues(std::string& fragmentShader, vtkProp* prop) const;
  void SetShaderParameters(vtkShaderProgram* program, double residual);

  // "volume_receiver_maps": ..., for the owning pass's GetStatsJSON.
  std::string StatsJSON() const;
  long long GetNumberOfComputedMaps() const { return this->Computed; }
  long long GetMemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* w);

private:
  struct LightMap
  {
    std::vector<double> Key;
    vsh_volume_map_plan Plan;
    bool Casts = false;
  };
  bool GatherVolumes(const vtkshadow::ShadowFrame& frame);
  void UpdateScene(const vtkshadow::ShadowFrame& frame);
  void Compute(LightMap& map, const double light[4], int row);
  void Upload(vtkOpenGLRenderWindow* window);

  int Id;                                   // the shader names' suffix
  std::vector<vsh_volume_map_volume> Boxes; // the shaded volumes' world boxes
  double Origin[3] = { 0, 0, 0 };           // the maps' frame: world relative to this
  double Bias = 0.0;                        // world units
  vtkShadowEmbreeScene Scene;               // the opaque casters
  long long SceneVersion = 0;               // mesh builds + top-level commits
  std::vector<LightMap> Lights;
  std::vector<float> Texels; // VSH_VOLUME_MAP_SIZE rows per light
  vtkSmartPointer<vtkTextureObject> Texture;
  bool Dirty = true;  // Texels changed since the upload
  bool Shown = false; // a shaded volume this frame
  long long Computed = 0;
  long long FrameComputed = 0;
  double LastSeconds = 0.0;
};

#endif
