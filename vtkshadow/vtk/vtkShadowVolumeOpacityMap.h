// vtkShadowVolumeOpacityMap.h - the renderer's vtkVolumes as shadow
// casters for the screen-space techniques (csm's resolve and stencil
// shadow volumes; docs/cascaded-shadow-maps.md, "Volumes").
//
// Per casting light, an opacity shadow map (vsh_volume_opacity_map.h): the
// transmittance through every volume along the light's rays over the
// volumes' boxes, with the distances where the rays enter and leave them,
// computed on the CPU (vtkShadowVolumeCasters' samplers, the rows split
// over threads) and uploaded as an RGBA32F texture. It is computed again
// only when its key changes: the volumes' data, scalars, mappers,
// properties, opacity functions, unit distances and matrices
// (vtkShadowVolumeCasters::Gather) and the light's position or direction;
// a camera moving alone reuses it.
//
// After a technique has written a light's channel of its
// vtkShadowScreenMask, Apply multiplies the channel by the map at every
// visible pixel, in one full-screen draw. The same volumes raytrace casts
// are supported (vtkShadowVolumeCasters.h), the same way; a point light
// inside a volume's box (or too close to see all boxes within 80 degrees
// of one axis) gets no map, and a note saying so.
#ifndef vtkShadowVolumeOpacityMap_h
#define vtkShadowVolumeOpacityMap_h

#include "vtkShadowVolumeCasters.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShadowScreenMask;
class vtkTextureObject;
class vtkWindow;

namespace vtkshadow
{
struct ShadowFrame;
}

class vtkShadowVolumeOpacityMap
{
public:
  vtkShadowVolumeOpacityMap();
  ~vtkShadowVolumeOpacityMap();
  vtkShadowVolumeOpacityMap(const vtkShadowVolumeOpacityMap&) = delete;
  void operator=(const vtkShadowVolumeOpacityMap&) = delete;

  /**
   * Gather the frame's volumes (nothing when it shows none) and bring the
   * map of every casting light up to date, uploading the changed ones.
   */
  void Update(const vtkshadow::ShadowFrame& frame, vtkOpenGLRenderWindow* window);

  // Whether `light` has a map this frame (some volume casts under it).
  bool Covers(int light) const;
  // Whether any light does.
  bool CoversAny() const;

  /**
   * Why a casting light gets no volume shadow although the frame shows a
   * volume (empty when it does, or shows none): the light inside a
   * volume's box, or no volume the maps support (with the reasons).
   */
  std::string GetLightNote(int light) const;

  /**
   * Multiply the channel of every covered light below the mask's light
   * count by its map, each in one full-screen draw into the mask (after
   * RenderDepth and the technique's own writes). False when the shader
   * did not compile.
   */
  bool Apply(
    vtkOpenGLRenderWindow* window, vtkShadowScreenMask& mask, const vtkshadow::ShadowFrame& frame);

  // Maps computed since creation (a camera-only change computes none).
  long long GetNumberOfComputedMaps() const { return this->Computed; }
  // "volume_maps": ..., for the owning pass's GetStatsJSON.
  std::string StatsJSON() const;
  long long GetMemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* w);

private:
  struct LightMap;
  bool Compute(LightMap& map, const double light[4]);
  bool ApplyLight(vtkOpenGLRenderWindow* window, vtkShadowScreenMask& mask,
    const vtkshadow::ShadowFrame& frame, int light);

  vtkShadowVolumeCasters Casters;
  std::vector<double> VolumesKey;
  std::vector<LightMap> Lights;
  double Origin[3] = { 0, 0, 0 }; // the maps' frame: world relative to this
  bool Shown = false;             // the frame shows a volume
  long long Computed = 0;
  long long FrameComputed = 0;
  long long LastSamples = 0;
  double LastSeconds = 0.0;
};

#endif
