// vtkShadowRayClassifier.h - the light-space maps that let the ray tracer
// skip the pixels they prove lit or shadowed (vsh_rt_classify.h), kept
// while the lights and the casters stay still.
//
// One map per hard light, rasterized on the CPU from the Embree scene's
// triangles in double precision (vtkShadowEmbreeScene::CollectTriangles).
// Maps live in world space (anchored at the casters' centre when built),
// so a camera that only moves keeps them: they are rebuilt only when a
// light moves or changes, or the top levels or a mesh are rebuilt, and
// then only once the new state has held for a few frames (Wait: longer
// while maps keep being dropped soon after their build, as in a scene
// edited every few frames, where tracing every pixel is cheaper).
// Spheres, tubes and flat quads (no triangles) are not in the maps: the
// tracer asks the maps among per-frame occluders built from their bounds
// (vsh_rt_classify_occluders), and the maps follow the world's placements,
// not the camera that sizes them. Volumes are not in them either: a scene
// with volumes gets no maps and every pixel is traced.
#ifndef vtkShadowRayClassifier_h
#define vtkShadowRayClassifier_h

#include "vsh_rt_classify.h"

#include <vector>

class vtkShadowEmbreeScene;

class vtkShadowRayClassifier
{
public:
  vtkShadowRayClassifier() = default;
  ~vtkShadowRayClassifier();
  vtkShadowRayClassifier(const vtkShadowRayClassifier&) = delete;
  void operator=(const vtkShadowRayClassifier&) = delete;

  /**
   * Bring the maps up to date for `lights` (camera-relative, as the tracer
   * takes them, with the camera at world `eye`); `hard[l]` false leaves
   * light l without a map (lights with a size are traced). `resolution`
   * texels a side. The maps (null for lights without one) and the anchor
   * are then in GetMaps / GetAnchor.
   */
  void Update(const vtkShadowEmbreeScene& scene, const std::vector<vsh_rt_light>& lights,
    const std::vector<bool>& hard, const double eye[3], int resolution);

  const std::vector<const vsh_rt_classify_map*>& GetMaps() const { return this->Pointers; }
  const double* GetAnchor() const { return this->Anchor; }

  /**
   * Whether each light's pixels are worth classifying in blocks, and those
   * its blocks leave undecided one by one: blocks while the fraction of
   * their pixels they decide stays at or above BlockWorth, pixels while
   * the fraction of those asked that decide stays at or above PixelWorth
   * (exponential averages over frames, Observe); both on every
   * ProbeEvery-th frame to measure again. Asking costs texel reads: where
   * the map seldom decides (many small casters) tracing alone is cheaper.
   */
  void Policy(std::vector<bool>& blocks, std::vector<bool>& pixels);
  void Observe(const std::vector<long long>& blockAsked, const std::vector<long long>& blockDecided,
    const std::vector<long long>& pixelAsked, const std::vector<long long>& pixelDecided);
  static constexpr double BlockWorth = 0.35;
  const std::vector<double>& GetBlockYield() const { return this->BlockRate; }
  const std::vector<double>& GetPixelYield() const { return this->PixelRate; }
  static constexpr double PixelWorth = 0.5;
  static constexpr int ProbeEvery = 16;

  // Maps built since creation, and their total seconds; bytes held now.
  int GetBuilds() const { return this->Builds; }
  double GetBuildSeconds() const { return this->BuildSeconds; }
  bool BuiltLastUpdate() const { return this->Rebuilt; }
  // Updates a new key waits before its maps are built (0, or MinWait..MaxWait).
  int GetWait() const { return static_cast<int>(this->Wait); }
  static constexpr long long MinWait = 2, MaxWait = 256;
  long long GetMemoryBytes() const;
  void Clear();

private:
  std::vector<double> Key;     // of the maps held (empty: none)
  std::vector<double> Pending; // the newest key, waiting for maps
  long long Updates = 0, PendingSince = 0, BuiltAt = 0, Wait = 0;
  std::vector<vsh_rt_classify_map> Maps;
  std::vector<bool> Built;
  std::vector<const vsh_rt_classify_map*> Pointers;
  double Anchor[3] = { 0, 0, 0 };
  int Builds = 0;
  double BuildSeconds = 0;
  bool Rebuilt = false;
  std::vector<double> BlockRate, PixelRate; // per light; start at 1 (try)
  int Frames = 0;
};

#endif
