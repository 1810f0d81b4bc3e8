// vtkShadowRayTracer.h - per-pixel shadow rays from a depth buffer, traced
// with Embree over all cores (vtkRayTracedShadowPass's CPU stage).
//
// For every pixel of the depth buffer that shows a surface: a short primary
// ray through the pixel centre, limited to the distances the depth buffer's
// error allows (vsh_rt_pixel_ray_init), lands exactly on the rasterized
// triangle and gives its geometric normal (the depth point itself when it
// misses, e.g. at a silhouette); then, for each light the surface faces and
// whose cone holds it, `samples` occlusion rays from the point, offset along
// the normal by vsh_rt_offset_distance, towards points on the light (with
// adaptive counts, a first batch and the rest only where it disagrees). The
// pixels go in blocks of 8 x 8 to worker threads; each tile's rays go to Embree
// as streams (rtcIntersect1M, rtcOccluded1M). A ray through translucent
// casters multiplies its transmittance in a context filter, and one that
// reaches the light marches the volumes on its way (Frame::Volumes).
#ifndef vtkShadowRayTracer_h
#define vtkShadowRayTracer_h

#include "vsh_raytrace.h"
#include "vsh_rt_classify.h"

#include <vector>

class vtkShadowEmbreeScene;
class vtkShadowVolumeCasters;

class vtkShadowRayTracer
{
public:
  struct Frame
  {
    const float* Depth = nullptr; // window depth, row 0 at the bottom
    vsh_rt_view View;             // the depth buffer's camera (camera-relative)
    double Eye[3] = { 0, 0, 0 };  // world position of the camera-relative origin
    std::vector<vsh_rt_light> Lights;
    std::vector<int> Samples; // rays per pixel for each of Lights (1 = hard)
    // Adaptive counts (vsh_rt_adaptive.h), per light: the first batch's size
    // (Samples for none) and the order of the spiral's indices, the batch
    // first. Empty: every pixel traces Samples rays in spiral order.
    std::vector<int> First;
    std::vector<std::vector<int>> Order;
    // The depth buffer's error around a pixel's depth: DepthTolerance plus
    // SlopeTolerance times the largest depth step to a drawn neighbour
    // (llvmpipe interpolates depth in float across whole triangles: its
    // error reaches hundreds of 24-bit steps, in proportion to the depth
    // gradient: at most a 32nd of the step to a neighbour on the library
    // and hard scenes, a quarter on a floor 2e5 long clipped at the camera;
    // render.raytrace.depth_error). Half a step keeps a margin of two. The
    // classifier's tubes are as long as this interval: the tighter, the
    // more pixels it decides.
    double DepthTolerance = 64 * VSH_RT_DEPTH_QUANTUM;
    double SlopeTolerance = 0.5;
    // The volumes that cast (placed in the scene's frame), or null: a ray
    // no opaque caster blocks keeps the fraction of its light they let
    // through (vtkShadowVolumeCasters).
    const vtkShadowVolumeCasters* Volumes = nullptr;
    // Per light of Lights, the light-space map that decides the pixels it
    // can prove lit or shadowed without a ray (vsh_rt_classify.h), or null
    // (every pixel traced); its anchor in world coordinates. A pixel every
    // light's map decides traces no ray at all, not even its primary one.
    std::vector<const vsh_rt_classify_map*> Classify;
    // Per light, whether its pixels are classified in blocks and whether
    // those its blocks leave undecided are classified one by one (empty:
    // both); off where that seldom decides (vtkShadowRayClassifier).
    std::vector<bool> ClassifyBlocks, ClassifyPixels;
    double ClassifyAnchor[3] = { 0, 0, 0 };
    // Per light of Classify, this frame's spheres, tubes and flat quads the
    // map does not hold (null or empty: none): a LIT class stands only
    // where they are all farther from the light than the pixel.
    std::vector<const vsh_rt_classify_occluders*> Occluders;
    // The largest radius of the scene's instances: the tracer's offset
    // grows with it (the classifier's tube covers that).
    double InstanceRadius = 0;
    // How far a landing on an impostor may move a pixel's surface point
    // along its ray: twice the largest impostor slack
    // (vtkShadowEmbreeScene::GetLargestImpostorSlack), from where the
    // tracer re-traces a pixel that meets one; the classifier's tubes reach
    // that far where an impostor may be near them. 0 without impostors.
    double ImpostorReland = 0;
  };

  struct Counters
  {
    long long Pixels = 0;       // in the viewport
    long long Background = 0;   // nothing drawn
    long long PrimaryRays = 0;  // refinement rays
    long long RefineMisses = 0; // refinement found no triangle: the depth point is used
    // Refinement hits landed on a mesh's triangle, and those farther from
    // the depth point than half the depth tolerance (how near the depth
    // buffer's error comes to the tolerance: render.raytrace.depth_error).
    long long Landed = 0, LandedBeyondHalfTolerance = 0;
    long long FacingAway = 0;  // (pixel, light) pairs traced whose facet faces away from the light
    long long OutsideCone = 0; // (pixel, light) pairs outside a spot cone
    long long ShadowRays = 0;
    long long VolumeSamples = 0; // opacity samples the shadow rays took in volumes
    // Per light: (pixel, light) pairs traced, their shadow rays, and the
    // pairs whose first batch disagreed and traced the rest.
    std::vector<long long> LightPixels, LightRays, LightRefined;
    // Per light, (pixel, light) pairs its map decided: lit, shadowed (no
    // ray), and the pairs it was asked about (pixels showing a surface).
    std::vector<long long> ClassifiedLit, ClassifiedShadowed, Classifiable;
    // Per light, the drawn pixels of the blocks asked and of those that
    // decided, and the pixels classified one by one and those that decided.
    std::vector<long long> BlockAsked, BlockDecided, PixelAsked, PixelDecided;
    long long PixelsWithoutRays = 0; // every light decided: no primary ray either
    long long BlockPixels = 0;       // of those, decided with their whole 8 x 8 block
    double Seconds = 0;
    int Threads = 0;

    // Zero, with the per-light counters sized for `lights`.
    void Reset(size_t lights);
    // Add another thread's counts (not Seconds or Threads).
    void Add(const Counters& other);
  };

  /**
   * Visibility in [0, 1] of every light at every pixel: `out[l]` gets
   * width * height values (1 where nothing was traced). With `tint`, also
   * each pixel's tint, 3 values per pixel (vsh_rt_visibility_tint: channel
   * k's visibility is out x tint[k]; (1, 1, 1) where nothing filters).
   */
  static void Trace(const vtkShadowEmbreeScene& scene, const Frame& frame, int threads,
    std::vector<std::vector<float>>& out, Counters& counters,
    std::vector<std::vector<float>>* tint = nullptr);
};

#endif
