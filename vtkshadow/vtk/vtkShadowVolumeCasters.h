// vtkShadowVolumeCasters.h - the renderer's vtkVolumes as shadow casters
// for ray-traced shadows (vtkRayTracedShadowPass, docs/raytraced-shadows.md
// "Volumes").
//
// A volume lets through the transmittance of its scalar opacity along a
// shadow ray, with VTK's opacity correction (vsh_volume_march.h): the
// tracer asks, for each shadow ray Embree did not find blocked by an opaque
// caster, what fraction of its light the volumes keep, and multiplies the
// ray's transmittance by it.
//
// Supported: a visible vtkVolume among the renderer's props (not inside an
// assembly; not a vtkMultiVolume) whose mapper is a
// vtkVolumeMapper in composite blend mode without cropping or clipping
// planes, on a vtkImageData with an identity direction matrix and
// single-component point scalars (the mapper's scalar selection), through
// the property's scalar opacity function of component 0, interpolated
// linearly whatever the property's interpolation type. Anything else is
// skipped, with the reason in GetSkipped (the pass's stats). Gradient
// opacity is not applied.
//
// The scalars (as float) and the transfer function's table are kept per
// volume and rebuilt only when the data or the function change.
#ifndef vtkShadowVolumeCasters_h
#define vtkShadowVolumeCasters_h

#include "vsh_volume_march.h"
#include "vsh_volume_opacity_map.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

class vtkRenderer;
class vtkVolume;

class vtkShadowVolumeCasters
{
public:
  vtkShadowVolumeCasters();
  ~vtkShadowVolumeCasters();
  vtkShadowVolumeCasters(const vtkShadowVolumeCasters&) = delete;
  void operator=(const vtkShadowVolumeCasters&) = delete;

  /**
   * The renderer's visible volumes that cast, with what a still frame
   * depends on appended to `key` (nothing at all when the renderer has no
   * volume): each volume's data, scalars and mapper times, its matrix, and
   * its property's and opacity function's times and unit distance.
   */
  void Gather(vtkRenderer* renderer, std::vector<double>& key);

  /**
   * Where the tracer's rays are: points relative to `centre` (world), the
   * Embree top levels' origin.
   */
  void Place(const double centre[3]);

  /**
   * The gathered volumes for the opacity shadow map
   * (vtkShadowVolumeOpacityMap): each one's grid, unit distance, sampler and
   * matrix from world relative to `origin` to its data coordinates. The
   * samplers stay valid until the next Gather.
   */
  void Describe(const double origin[3], std::vector<vsh_volume_map_volume>& out) const;

  /**
   * The world bounds of the gathered volumes (xmin, xmax, ...); false when
   * there are none.
   */
  bool GetBounds(double bounds[6]) const;

  bool IsEmpty() const { return this->Active.empty(); }
  int GetNumberOfVolumes() const { return static_cast<int>(this->Active.size()); }
  // Why each skipped volume casts nothing ("vtkVolume 2: cell scalars ...").
  const std::vector<std::string>& GetSkipped() const { return this->Skipped; }

  /**
   * `start` times the fraction of light the volumes keep along the ray
   * origin + t dir, t in [0, tmax] (Place's frame; dir a unit vector; tmax
   * may be infinite); 0 once under 1/1024, as the translucent casters'
   * rays. `samples` counts the opacity samples taken.
   */
  double Transmittance(const double origin[3], const double dir[3], double tmax, double start,
    long long& samples) const;

private:
  struct Volume;
  bool Collect(vtkVolume* volume, int index, std::vector<double>& key);
  std::map<vtkVolume*, std::unique_ptr<Volume>> Cache;
  std::vector<const Volume*> Active;
  double Bounds[6];
  std::vector<std::string> Skipped;
};

#endif
