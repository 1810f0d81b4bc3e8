#include "vtkShadowRayTracer.h"

#include "vsh_rt_adaptive.h"
#include "vsh_rt_weight.h"
#include "vsh_transmit.h"
#include "vtkShadowEmbreeScene.h"
#include "vtkShadowVolumeCasters.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace
{
constexpr int TileSize = 64;
// Pixels go to the workers in blocks of Block x Block (TileSize pixels):
// the classifier decides a whole block at once where it can.
constexpr int Block = 8;

// One shadow ray's query through translucent casters: the context filter
// (Transmit) sees every hit of the ray in the "casters" top level, in no
// particular order. A translucent one multiplies the transmittance, per
// colour channel, by its crossing's (vtkShadowEmbreeScene's
// GetCasterTransmit, the core's vsh_transmit_crossing: tinted where a
// filter colours it) and is ignored, so the traversal goes on; an opaque
// one is kept and ends the ray (transmittance 0). A triangle reported
// twice counts once.
struct TransmitContext
{
  RTCIntersectContext Base; // first: Embree hands the filter this pointer
  const float* Opacity;     // per caster instance id
  const float* Transmit;    // 3 per caster instance id
  unsigned int Count;
  double Transmittance[3];
  static constexpr int MaxSeen = 64;
  unsigned int Seen[MaxSeen][2]; // (instance, primitive) already crossed
  int SeenCount;
};

void Transmit(const RTCFilterFunctionNArguments* args)
{
  auto* context = reinterpret_cast<TransmitContext*>(args->context);
  for (unsigned int i = 0; i < args->N; ++i)
  {
    if (args->valid[i] == 0)
    {
      continue;
    }
    const unsigned int instance = RTCHitN_instID(args->hit, args->N, i, 0);
    const unsigned int primitive = RTCHitN_primID(args->hit, args->N, i);
    const double opacity = instance < context->Count ? context->Opacity[instance] : 1.0;
    if (!vsh_transmit_passes(opacity))
    {
      std::fill_n(context->Transmittance, 3, 0.0); // opaque: the hit stands, the ray stops
      continue;
    }
    bool seen = false;
    for (int k = 0; k < context->SeenCount && !seen; ++k)
    {
      seen = context->Seen[k][0] == instance && context->Seen[k][1] == primitive;
    }
    if (!seen)
    {
      if (context->SeenCount < TransmitContext::MaxSeen)
      {
        context->Seen[context->SeenCount][0] = instance;
        context->Seen[context->SeenCount][1] = primitive;
        ++context->SeenCount;
      }
      for (int k = 0; k < 3; ++k)
      {
        context->Transmittance[k] *= context->Transmit[3 * instance + k];
      }
    }
    // Below what an 8-bit mask channel holds: the ray counts as blocked.
    if (*std::max_element(context->Transmittance, context->Transmittance + 3) < 1.0 / 1024)
    {
      std::fill_n(context->Transmittance, 3, 0.0);
      continue;
    }
    args->valid[i] = 0;
  }
}

// A pixel's surface point in the top levels' frame (relative to the centre).
struct Surface
{
  int Pixel = -1;
  double Point[3];
  double Normal[3]; // unit, facing the camera
  double Offset;    // how far the shadow rays start off the surface
  bool HasNormal;   // false: the refinement missed, no facing test
  // Per light (the first MaxDecided), what the classifier decided
  // (VSH_RT_CLASSIFY_*): UNDECIDED ones are traced.
  static constexpr int MaxDecided = 8;
  signed char Decided[MaxDecided];
};

// One (surface, light) pair whose rays are traced: its rays so far.
struct Pair
{
  Surface S;
  int Light;
  double Rotation;
  // Its rays so far, each weighted by max(0, N.L) with the surface's
  // geometric normal (vsh_rt_weight.h: v = I_on / I_off of the light).
  vsh_rt_visibility Vis;
};

// Everything one thread needs, reused from tile to tile.
struct Worker
{
  const vtkShadowEmbreeScene* Scene;
  const vtkShadowRayTracer::Frame* Frame;
  const vtkShadowVolumeCasters* Volumes; // null when no volume casts
  std::vector<std::vector<float>>* Out;
  std::vector<std::vector<float>>* Tint; // 3 per pixel per light, or null
  double EyeToCentre[3];                 // eye - centre: camera-relative -> the top levels' frame
  std::vector<RTCRayHit> Hits;
  std::vector<float> Limits; // the refinement rays' intervals
  std::vector<vsh_rt_pixel_ray> Pixels;
  std::vector<Surface> Surfaces;
  std::vector<RTCRay> Rays;
  std::vector<Pair> Pairs;   // this batch's
  std::vector<Pair> Pending; // adaptive pairs of every tile, for the second pass
  std::vector<int> RayPair;
  // Per light and pixel, the first batch's vsh_rt_adaptive_state (shared,
  // each pixel written by the thread of its tile).
  std::vector<std::vector<unsigned char>>* States;
  vtkShadowRayTracer::Counters Count;

  void Tile(int block);
  double Tolerance(int x, int y) const;
  // The block's pixels' depth tolerances, computed once by Refine and
  // read by ClassifyBlock (whole and quarters) and RefinePixels.
  double Tolerances[TileSize];
  int ToleranceX0 = 0, ToleranceY0 = 0;
  void ComputeTolerances(int x0, int y0, int x1, int y1);
  double BlockTolerance(int x, int y) const
  {
    return this->Tolerances[(y - this->ToleranceY0) * Block + (x - this->ToleranceX0)];
  }
  bool ClassifyBlock(int x0, int y0, int x1, int y1, bool whole);
  void DecideBlock(int x0, int y0, int x1, int y1);
  bool Classify(const vsh_rt_pixel_ray& ray, Surface& s);
  // Light l's map (null: not classified, or beyond Surface::MaxDecided).
  const vsh_rt_classify_map* MapOf(size_t l) const
  {
    const vtkShadowRayTracer::Frame& f = *this->Frame;
    return l < f.Classify.size() && l < size_t(Surface::MaxDecided) ? f.Classify[l] : nullptr;
  }
  // Light l's impostors the map does not hold (null: none).
  const vsh_rt_classify_occluders* OccludersOf(size_t l) const
  {
    const std::vector<const vsh_rt_classify_occluders*>& o = this->Frame->Occluders;
    return l < o.size() ? o[l] : nullptr;
  }
  // Whether the policy lets light l be asked (an empty policy: every light).
  static bool Allowed(const std::vector<bool>& policy, size_t l)
  {
    return policy.empty() || (l < policy.size() && policy[l]);
  }
  // This block's classes per light (UNDECIDED: per pixel), and the whole
  // 8 x 8 block's (its quarters' yield counts only what it left).
  signed char BlockDecided[Surface::MaxDecided];
  signed char WholeDecided[Surface::MaxDecided];
  void Decide(const Surface& s, size_t l);
  void Refine(int x0, int y0, int x1, int y1);
  void RefinePixels(int x0, int y0, int x1, int y1);
  void Intersect();
  void Land(int k);
  void CountLanding(int k, const Surface& s);
  bool Reland(int k, const vtkShadowEmbreeScene::Instance& inst);
  bool RelandFront(int k);
  bool RelandOwn(int k, const vtkShadowEmbreeScene::Instance& inst);
  bool RelandFrom(int k, RTCScene scene, double back, unsigned int instance,
    bool (*accept)(const vtkShadowEmbreeScene::Instance&));
  bool Exact(int k, double n[3], double& len2, double& side);
  void Miss(int k);
  void Queue(const Surface& s, int surface);
  void Push(int pair, int begin, int end);
  void Rest(size_t begin, size_t end);
  void Finish();
  void Occlude();
  void OccludeTranslucent();
  double ThroughVolumes(const Surface& s, const RTCRay& ray, double start);
  void Resolve(bool first);
};

double Worker::Tolerance(int x, int y) const
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  const int w = f.View.width, h = f.View.height;
  const float d = f.Depth[y * w + x];
  double slope = 0;
  const int nx[4] = { x - 1, x + 1, x, x }, ny[4] = { y, y, y - 1, y + 1 };
  for (int k = 0; k < 4; ++k)
  {
    if (nx[k] >= 0 && nx[k] < w && ny[k] >= 0 && ny[k] < h)
    {
      const float n = f.Depth[ny[k] * w + nx[k]];
      if (n < 1.0f)
      {
        slope = std::max(slope, std::fabs(double(n) - double(d)));
      }
    }
  }
  return f.DepthTolerance + f.SlopeTolerance * slope;
}

void Worker::ComputeTolerances(int x0, int y0, int x1, int y1)
{
  this->ToleranceX0 = x0;
  this->ToleranceY0 = y0;
  const float* depth = this->Frame->Depth;
  const int width = this->Frame->View.width;
  for (int y = y0; y <= y1; ++y)
  {
    for (int x = x0; x <= x1; ++x)
    {
      this->Tolerances[(y - y0) * Block + (x - x0)] =
        depth[y * width + x] < 1.0f ? this->Tolerance(x, y) : 0.0;
    }
  }
}

// The block's pixels: decided whole (classifier), else in quarters, else
// each pixel on its own.
void Worker::Refine(int x0, int y0, int x1, int y1)
{
  this->Hits.clear();
  this->Pixels.clear();
  this->Surfaces.clear();
  this->Limits.clear();
  this->ComputeTolerances(x0, y0, x1, y1);
  if (this->ClassifyBlock(x0, y0, x1, y1, true))
  {
    return; // every pixel decided for every light
  }
  std::copy_n(this->BlockDecided, Surface::MaxDecided, this->WholeDecided);
  const bool split = !this->Frame->Classify.empty() && x1 - x0 >= 3 && y1 - y0 >= 3;
  if (!split)
  {
    this->RefinePixels(x0, y0, x1, y1);
    this->Intersect();
    return;
  }
  const int xm = (x0 + x1 + 1) / 2, ym = (y0 + y1 + 1) / 2;
  const int qx[4][2] = { { x0, xm - 1 }, { xm, x1 }, { x0, xm - 1 }, { xm, x1 } };
  const int qy[4][2] = { { y0, ym - 1 }, { y0, ym - 1 }, { ym, y1 }, { ym, y1 } };
  for (int q = 0; q < 4; ++q)
  {
    if (!this->ClassifyBlock(qx[q][0], qy[q][0], qx[q][1], qy[q][1], false))
    {
      this->RefinePixels(qx[q][0], qy[q][0], qx[q][1], qy[q][1]);
    }
  }
  this->Intersect();
}

// Each pixel's refinement ray (and its classification where the block's
// left its lights undecided), appended to this tile's lists.
void Worker::RefinePixels(int x0, int y0, int x1, int y1)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  const int width = f.View.width;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
    {
      vsh_rt_pixel_ray ray;
      const int p = y * width + x;
      if (vsh_rt_pixel_ray_init(&f.View, x, y, f.Depth[p], this->BlockTolerance(x, y), &ray) !=
        VSH_RT_OK)
      {
        ++this->Count.Background;
        continue;
      }
      // Start at the near end of the interval: float keeps the precision of
      // the surface's position, not of the far-away camera's.
      Surface s;
      s.Pixel = p;
      if (this->Classify(ray, s))
      {
        continue; // every light decided: no ray
      }
      RTCRayHit rh;
      const double start = ray.lo;
      rh.ray.org_x = static_cast<float>(ray.origin[0] + start * ray.direction[0] + EyeToCentre[0]);
      rh.ray.org_y = static_cast<float>(ray.origin[1] + start * ray.direction[1] + EyeToCentre[1]);
      rh.ray.org_z = static_cast<float>(ray.origin[2] + start * ray.direction[2] + EyeToCentre[2]);
      rh.ray.dir_x = static_cast<float>(ray.direction[0]);
      rh.ray.dir_y = static_cast<float>(ray.direction[1]);
      rh.ray.dir_z = static_cast<float>(ray.direction[2]);
      rh.ray.tnear = 0.0f;
      // The interval, widened by float rounding of the origin.
      // Unbounded: at a grazing angle far away the float ray can pass the
      // interval and meet the right triangle further on; Land keeps a hit
      // beyond the interval only where the double landing on its plane falls
      // inside it.
      this->Limits.push_back(static_cast<float>(vsh_rt_refine_reach(&ray)));
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = 0xffffffffu;
      rh.ray.time = 0.0f;
      rh.ray.id = 0;
      rh.ray.flags = 0;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      this->Hits.push_back(rh);
      this->Pixels.push_back(ray);
      this->Surfaces.push_back(s);
    }
}

// The tile's refinement rays, in one stream.
void Worker::Intersect()
{
  if (!this->Hits.empty())
  {
    // Incoherent: with RTC_INTERSECT_CONTEXT_FLAG_COHERENT, Embree 3.13's
    // packets of a partly filled stream (a tile whose other pixels the
    // classifier decided) missed a floor a ray through a sphere cloud meets
    // when traced alone (particle-cloud, 800x600): the landing then fell
    // back to the depth point and its shadow differed. Incoherent streams
    // give the single ray's hit; the trace stage costs the same within
    // the noise.
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1M(this->Scene->GetVisible(), &context, this->Hits.data(),
      static_cast<unsigned int>(this->Hits.size()), sizeof(RTCRayHit));
    this->Count.PrimaryRays += static_cast<long long>(this->Hits.size());
  }
}

// What the lights' maps decide for the whole block [x0, x1] x [y0, y1]
// (BlockDecided): its region is the hull of its corner pixels' rays
// between the block's smallest and largest depth, widened by three times
// its largest depth tolerance (every pixel's interval, two, and the half
// interval of slack the landing keeps, vsh_rt_classify_tube_init, with one
// to spare for the curvature of depth against distance), grown by the
// tube's radius and 2e-5 of the distance (the slack's terms in distance). True when every
// light is decided: its pixels' visibilities are then written.
bool Worker::ClassifyBlock(int x0, int y0, int x1, int y1, bool whole)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  std::fill_n(
    this->BlockDecided, Surface::MaxDecided, static_cast<signed char>(VSH_RT_CLASSIFY_UNDECIDED));
  // Nothing to ask when every light's blocks stand aside (the policy).
  if (f.Classify.empty() ||
    (!f.ClassifyBlocks.empty() &&
      std::none_of(f.ClassifyBlocks.begin(), f.ClassifyBlocks.end(), [](bool b) { return b; })))
  {
    return false;
  }
  const int width = f.View.width;
  double dmin = 2, dmax = -1, tol = 0;
  long long drawn = 0;
  for (int y = y0; y <= y1; ++y)
  {
    for (int x = x0; x <= x1; ++x)
    {
      const float d = f.Depth[y * width + x];
      if (d < 1.0f)
      {
        dmin = std::min(dmin, double(d));
        dmax = std::max(dmax, double(d));
        tol = std::max(tol, this->BlockTolerance(x, y));
        ++drawn;
      }
    }
  }
  if (drawn == 0)
  {
    return false; // the pixels count themselves as background
  }
  vsh_rt_classify_region region;
  const double lo = std::max(0.0, dmin - 3 * tol), hi = std::min(1.0, dmax + 3 * tol);
  const int cx[4] = { x0, x1, x0, x1 }, cy[4] = { y0, y0, y1, y1 };
  double magnitude = 0, distance = 0, span = 0;
  for (int k = 0; k < 4; ++k)
  {
    double a[3], b[3];
    if (vsh_rt_unproject(&f.View, cx[k] + 0.5, cy[k] + 0.5, lo, a) != VSH_RT_OK ||
      vsh_rt_unproject(&f.View, cx[k] + 0.5, cy[k] + 0.5, hi, b) != VSH_RT_OK)
    {
      return false;
    }
    double d2 = 0, c2a = 0, c2b = 0;
    for (int r = 0; r < 3; ++r)
    {
      region.dir[k][r] = b[r] - a[r];
      d2 += region.dir[k][r] * region.dir[k][r];
      region.corner[k][r] = a[r] + f.Eye[r] - f.ClassifyAnchor[r];
      region.corner[k + 4][r] = b[r] + f.Eye[r] - f.ClassifyAnchor[r];
      c2a += (a[r] + this->EyeToCentre[r]) * (a[r] + this->EyeToCentre[r]);
      c2b += (b[r] + this->EyeToCentre[r]) * (b[r] + this->EyeToCentre[r]);
    }
    const double len = std::sqrt(d2);
    if (!(len > 0))
    {
      return false; // a slab of no thickness: no view direction
    }
    for (int r = 0; r < 3; ++r)
    {
      region.dir[k][r] /= len;
    }
    span = std::max(span, len);
    magnitude = std::max(magnitude, std::sqrt(std::max(c2a, c2b)));
    distance = std::max(distance, std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  }
  region.radius =
    5.0 * vsh_rt_offset_distance(magnitude + span + f.InstanceRadius) + 2e-5 * distance;
  region.reland = f.ImpostorReland;
  bool all = true;
  for (size_t l = 0; l < f.Lights.size(); ++l)
  {
    const vsh_rt_classify_map* map = this->MapOf(l);
    const bool blocks = Allowed(f.ClassifyBlocks, l);
    const int c = map && blocks ? vsh_rt_classify_block_among(map, this->OccludersOf(l), &region)
                                : VSH_RT_CLASSIFY_UNDECIDED;
    if (map && blocks && l < this->Count.BlockAsked.size())
    {
      // Yield: the drawn pixels of whole blocks asked, those any block
      // (whole or quarter) decided.
      const bool fresh = whole || l >= size_t(Surface::MaxDecided) ||
        this->WholeDecided[l] == VSH_RT_CLASSIFY_UNDECIDED;
      this->Count.BlockAsked[l] += whole ? drawn : 0;
      this->Count.BlockDecided[l] += c != VSH_RT_CLASSIFY_UNDECIDED && fresh ? drawn : 0;
    }
    if (l < size_t(Surface::MaxDecided))
    {
      this->BlockDecided[l] = static_cast<signed char>(c);
    }
    all = all && c != VSH_RT_CLASSIFY_UNDECIDED;
  }
  if (!all)
  {
    return false;
  }
  this->DecideBlock(x0, y0, x1, y1);
  return true;
}

// Every drawn pixel of a block whose lights are all decided (BlockDecided):
// its visibilities and counts.
void Worker::DecideBlock(int x0, int y0, int x1, int y1)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  const int width = f.View.width;
  Surface s;
  std::copy_n(this->BlockDecided, Surface::MaxDecided, s.Decided);
  for (int y = y0; y <= y1; ++y)
  {
    for (int x = x0; x <= x1; ++x)
    {
      s.Pixel = y * width + x;
      if (f.Depth[s.Pixel] >= 1.0f)
      {
        ++this->Count.Background;
        continue;
      }
      for (size_t l = 0; l < f.Lights.size(); ++l)
      {
        ++this->Count.Classifiable[l];
        this->Count.ClassifiedLit[l] += s.Decided[l] != VSH_RT_CLASSIFY_SHADOWED;
        this->Count.ClassifiedShadowed[l] += s.Decided[l] == VSH_RT_CLASSIFY_SHADOWED;
        this->Decide(s, l);
      }
      ++this->Count.PixelsWithoutRays;
      ++this->Count.BlockPixels;
    }
  }
}

// What the lights' maps decide for the pixel of `ray` (s.Decided); true
// when they decide every light, whose visibilities are then written.
bool Worker::Classify(const vsh_rt_pixel_ray& ray, Surface& s)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  std::fill_n(s.Decided, Surface::MaxDecided, static_cast<signed char>(VSH_RT_CLASSIFY_UNDECIDED));
  if (f.Classify.empty())
  {
    return false;
  }
  // Nothing to ask when no light's pixels are asked and its block decided
  // nothing: count the pixel and leave it to the rays.
  bool ask = f.ClassifyPixels.empty();
  for (size_t l = 0; l < f.Lights.size() && !ask; ++l)
  {
    ask = (l < f.ClassifyPixels.size() && f.ClassifyPixels[l]) ||
      (l < size_t(Surface::MaxDecided) && this->BlockDecided[l] != VSH_RT_CLASSIFY_UNDECIDED);
  }
  if (!ask)
  {
    for (size_t l = 0; l < f.Lights.size() && l < f.Classify.size(); ++l)
    {
      this->Count.Classifiable[l] += f.Classify[l] != nullptr;
    }
    return false;
  }
  double eyeToAnchor[3], magnitude = 0;
  for (int r = 0; r < 3; ++r)
  {
    eyeToAnchor[r] = f.Eye[r] - f.ClassifyAnchor[r];
    const double c = ray.point[r] + this->EyeToCentre[r];
    magnitude += c * c;
  }
  // The tracer's offset uses the landed point's magnitude plus its
  // instance's radius: bound both (the point is within the interval).
  magnitude = std::sqrt(magnitude) + std::fabs(ray.distance - ray.lo) +
    std::fabs(ray.hi - ray.distance) + f.InstanceRadius;
  vsh_rt_classify_tube tube;
  vsh_rt_classify_tube_init(&ray, eyeToAnchor, magnitude, &tube);
  tube.reland = f.ImpostorReland;
  bool all = true;
  const size_t lights = f.Lights.size();
  for (size_t l = 0; l < lights; ++l)
  {
    const vsh_rt_classify_map* map = this->MapOf(l);
    const bool byPixel = Allowed(f.ClassifyPixels, l);
    if (!map)
    {
      all = false;
      continue;
    }
    ++this->Count.Classifiable[l];
    if (this->BlockDecided[l] == VSH_RT_CLASSIFY_UNDECIDED && !byPixel)
    {
      all = false;
      continue;
    }
    int c = this->BlockDecided[l];
    if (c == VSH_RT_CLASSIFY_UNDECIDED)
    {
      c = vsh_rt_classify_pixel_among(map, this->OccludersOf(l), &tube);
      ++this->Count.PixelAsked[l];
      this->Count.PixelDecided[l] += c != VSH_RT_CLASSIFY_UNDECIDED;
    }
    s.Decided[l] = static_cast<signed char>(c);
    this->Count.ClassifiedLit[l] += c == VSH_RT_CLASSIFY_LIT || c == VSH_RT_CLASSIFY_OUTSIDE_CONE;
    this->Count.ClassifiedShadowed[l] += c == VSH_RT_CLASSIFY_SHADOWED;
    all = all && c != VSH_RT_CLASSIFY_UNDECIDED;
  }
  if (!all)
  {
    return false;
  }
  for (size_t l = 0; l < lights; ++l)
  {
    this->Decide(s, l);
  }
  ++this->Count.PixelsWithoutRays;
  return true;
}

// A decided (pixel, light) pair's visibility, as its ray would give it.
void Worker::Decide(const Surface& s, size_t l)
{
  if (s.Decided[l] == VSH_RT_CLASSIFY_SHADOWED)
  {
    (*this->Out)[l][s.Pixel] = 0.0f;
  }
  this->Count.OutsideCone += s.Decided[l] == VSH_RT_CLASSIFY_OUTSIDE_CONE;
}

// The surface point of refinement ray k: on the triangle it hit, or the
// depth point pulled towards the camera by the depth error.
void Worker::Land(int k)
{
  const RTCRayHit& rh = this->Hits[k];
  Surface& s = this->Surfaces[k];
  const double dir[3] = { rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z };
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID && rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID)
  {
    const vtkShadowEmbreeScene::Instance& inst = this->Scene->GetInstance(rh.hit.instID[0]);
    bool inside = rh.ray.tfar <= this->Limits[k];
    if (inst.Impostors)
    {
      inside = this->Reland(k, inst) || inside;
    }
    const vtkShadowEmbreeScene::Instance& landed = this->Scene->GetInstance(rh.hit.instID[0]);
    const double org[3] = { rh.ray.org_x, rh.ray.org_y, rh.ray.org_z };
    const double t = rh.ray.tfar;
    const double ng[3] = { rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z };
    double n[3], len2 = 0, side = 0;
    for (int r = 0; r < 3; ++r)
    {
      s.Point[r] = org[r] + t * dir[r];
      n[r] = landed.Normal[3 * r] * ng[0] + landed.Normal[3 * r + 1] * ng[1] +
        landed.Normal[3 * r + 2] * ng[2];
      len2 += n[r] * n[r];
      side += n[r] * dir[r];
    }
    if (!this->Exact(k, n, len2, side) && !inside)
    {
      this->Miss(k);
      return;
    }
    const double scale = len2 > 0 ? (side > 0 ? -1.0 : 1.0) / std::sqrt(len2) : 0.0;
    for (int r = 0; r < 3; ++r)
    {
      s.Normal[r] = n[r] * scale;
    }
    s.HasNormal = len2 > 0;
    if (!landed.Impostors)
    {
      this->CountLanding(k, s);
    }
    const double magnitude =
      std::sqrt(s.Point[0] * s.Point[0] + s.Point[1] * s.Point[1] + s.Point[2] * s.Point[2]) +
      landed.Radius;
    s.Offset = vsh_rt_offset_distance(magnitude);
    return;
  }
  this->Miss(k);
}

// How far the exact surface point of refinement ray k lies from its depth
// point, against the depth tolerance (the interval's half width).
void Worker::CountLanding(int k, const Surface& s)
{
  const vsh_rt_pixel_ray& ray = this->Pixels[k];
  double t = 0;
  for (int r = 0; r < 3; ++r)
  {
    t += (s.Point[r] - ray.origin[r] - this->EyeToCentre[r]) * ray.direction[r];
  }
  ++this->Count.Landed;
  this->Count.LandedBeyondHalfTolerance += std::fabs(t - ray.distance) > 0.25 * (ray.hi - ray.lo);
}

// A pixel on a sphere or tube (an impostor instance): VTK's impostor depth
// is near the solids, not on them (the mapper moves the sprite's depth by
// the radius times the sprite's own normal), so the refinement ray, which
// starts at the depth point, may start inside a solid and meet its far
// side, pass in front of it, or meet another solid inside it: a bond's
// tube inside its atom's sphere, where a point is in the sphere's own
// shadow. The surface is the front-most solid near the depth point: the
// visible top level traced again from twice the largest impostor radius
// before it (RelandFront). Where that first meets a mesh in front, the hit
// instance's own scene again from twice its radius (RelandOwn). False (no
// change) when both miss.
bool Worker::Reland(int k, const vtkShadowEmbreeScene::Instance& inst)
{
  return this->RelandFront(k) || this->RelandOwn(k, inst);
}

// Refinement ray k's hit replaced by the first hit of `scene` on the same
// line from `back` before its origin, up to `back` past the end of its
// interval; `instance` names the placement when `scene` is one instance's
// own (RTC_INVALID_GEOMETRY_ID: the hit's, `scene` is a top level). False
// (no change) when it misses, or when `accept` refuses the hit's instance.
bool Worker::RelandFrom(int k, RTCScene scene, double back, unsigned int instance,
  bool (*accept)(const vtkShadowEmbreeScene::Instance&))
{
  RTCRayHit& rh = this->Hits[k];
  const float b = static_cast<float>(back);
  RTCRayHit again = rh;
  again.ray.org_x = rh.ray.org_x - b * rh.ray.dir_x;
  again.ray.org_y = rh.ray.org_y - b * rh.ray.dir_y;
  again.ray.org_z = rh.ray.org_z - b * rh.ray.dir_z;
  again.ray.tnear = 0.0f;
  again.ray.tfar = 2 * b + this->Limits[k];
  again.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  again.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &again);
  ++this->Count.PrimaryRays;
  const unsigned int id = instance != RTC_INVALID_GEOMETRY_ID ? instance : again.hit.instID[0];
  if (again.hit.geomID == RTC_INVALID_GEOMETRY_ID || id == RTC_INVALID_GEOMETRY_ID ||
    (accept && !accept(this->Scene->GetInstance(id))))
  {
    return false;
  }
  rh.hit = again.hit;
  rh.hit.instID[0] = id;
  rh.ray.tfar = again.ray.tfar - b; // from the refinement ray's origin
  return true;
}

bool Worker::RelandFront(int k)
{
  const double back = this->Frame->ImpostorReland;
  return back > 0 &&
    this->RelandFrom(k, this->Scene->GetVisible(), back, RTC_INVALID_GEOMETRY_ID,
      [](const vtkShadowEmbreeScene::Instance& i) { return i.Impostors != nullptr; });
}

bool Worker::RelandOwn(int k, const vtkShadowEmbreeScene::Instance& inst)
{
  return this->RelandFrom(k, inst.Impostors, 2 * inst.Slack, this->Hits[k].hit.instID[0], nullptr);
}

// No triangle at the pixel: the depth point pulled towards the camera by
// the depth error, no facing test.
void Worker::Miss(int k)
{
  const vsh_rt_pixel_ray& ray = this->Pixels[k];
  Surface& s = this->Surfaces[k];
  const double dir[3] = { ray.direction[0], ray.direction[1], ray.direction[2] };
  ++this->Count.RefineMisses;
  const double back = ray.distance - ray.lo;
  for (int r = 0; r < 3; ++r)
  {
    s.Point[r] = ray.point[r] + EyeToCentre[r];
    s.Normal[r] = -dir[r];
  }
  s.HasNormal = false;
  s.Offset = back +
    vsh_rt_offset_distance(
      std::sqrt(s.Point[0] * s.Point[0] + s.Point[1] * s.Point[1] + s.Point[2] * s.Point[2]));
}

// Replaces surface k's point (Embree's float hit) by the pixel ray's
// intersection with the hit triangle's plane, both in double, and n by that
// plane's normal: at a grazing angle the float ray's rounding moves the hit
// along the surface by the rounding over the angle's sine (thousands of
// units on near-far-1e6's far floor).
bool Worker::Exact(int k, double n[3], double& len2, double& side)
{
  const RTCRayHit& rh = this->Hits[k];
  const vsh_rt_pixel_ray& ray = this->Pixels[k];
  double v[3][3];
  if (!this->Scene->GetTriangle(rh.hit.instID[0], rh.hit.primID, v))
  {
    return false;
  }
  double e1[3], e2[3], m[3], o[3];
  for (int r = 0; r < 3; ++r)
  {
    e1[r] = v[1][r] - v[0][r];
    e2[r] = v[2][r] - v[0][r];
    o[r] = ray.origin[r] + EyeToCentre[r];
  }
  m[0] = e1[1] * e2[2] - e1[2] * e2[1];
  m[1] = e1[2] * e2[0] - e1[0] * e2[2];
  m[2] = e1[0] * e2[1] - e1[1] * e2[0];
  double denom = 0, num = 0, m2 = 0;
  for (int r = 0; r < 3; ++r)
  {
    denom += m[r] * ray.direction[r];
    num += m[r] * (v[0][r] - o[r]);
    m2 += m[r] * m[r];
  }
  if (!(m2 > 0) || denom == 0)
  {
    return false;
  }
  const double t = num / denom;
  const double slack = vsh_rt_landing_slack(&ray);
  if (!std::isfinite(t) || t < ray.lo - slack || t > ray.hi + slack)
  {
    return false; // keep Embree's hit
  }
  len2 = m2;
  side = denom;
  for (int r = 0; r < 3; ++r)
  {
    this->Surfaces[k].Point[r] = o[r] + t * ray.direction[r];
    n[r] = m[r];
  }
  return true;
}

// The shadow rays of one surface point towards every light it can see.
void Worker::Queue(const Surface& s, int surface)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  double p[3];
  for (int r = 0; r < 3; ++r)
  {
    p[r] = s.Point[r] - EyeToCentre[r]; // camera-relative, for the lights
  }
  // One turn of the sample spiral per pixel (the same for every light):
  // neighbouring pixels see other points of the light, noise not bands.
  const double rotation = vsh_rt_pixel_rotation(
    static_cast<unsigned>(s.Pixel % f.View.width), static_cast<unsigned>(s.Pixel / f.View.width));
  for (size_t l = 0; l < f.Lights.size(); ++l)
  {
    if (l < size_t(Surface::MaxDecided) && s.Decided[l] != VSH_RT_CLASSIFY_UNDECIDED)
    {
      this->Decide(s, l);
      continue;
    }
    const vsh_rt_light& light = f.Lights[l];
    double toLight[3], distance;
    if (vsh_rt_light_direction(&light, p, toLight, &distance) != VSH_RT_OK)
    {
      continue;
    }
    // A facet whose geometric normal faces away from the light is still
    // traced: the mapper shades it with interpolated normals, which near a
    // curved surface's terminator still face the light, so VTK lights it
    // unless a ray from the facet meets the mesh elsewhere or another
    // caster (a floor between it and the light). The ray starts on the
    // light's side of the facet (Push), so the facet itself never blocks
    // it, as with POV-Ray's and Cycles' rays from the same point: a surface
    // that truly faces away (a closed body's far side) still meets the body.
    // Skipping is exact only where the mapper's lighting is zero: outside a
    // spot cone (below).
    if (s.HasNormal &&
      s.Normal[0] * toLight[0] + s.Normal[1] * toLight[1] + s.Normal[2] * toLight[2] <= 0)
    {
      ++this->Count.FacingAway;
    }
    if (!vsh_rt_light_in_cone(&light, toLight))
    {
      ++this->Count.OutsideCone;
      continue;
    }
    (void)surface;
    this->Pairs.push_back(
      { s, static_cast<int>(l), rotation, { 0.0, 0.0, 0, 0, 0, 0.0, { 0.0, 0.0, 0.0 } } });
    const int pair = static_cast<int>(this->Pairs.size()) - 1;
    this->Push(pair, 0, f.First.empty() ? f.Samples[l] : f.First[l]);
  }
}

// A shadow ray's origin along `dir`: off the surface by its offset, on the
// side the ray leaves by (the camera's side, unless the facet faces away
// from the ray: then the facet is behind the origin, as for a ray tracer's
// ray from the same point).
void ShadowOrigin(const Surface& s, const double dir[3], double out[3])
{
  const double along = s.Normal[0] * dir[0] + s.Normal[1] * dir[1] + s.Normal[2] * dir[2];
  const double side = s.HasNormal && along < 0 ? -s.Offset : s.Offset;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = s.Point[k] + side * s.Normal[k];
  }
}

// Queue the rays of slots [begin, end) of a pair's sample order.
void Worker::Push(int pair, int begin, int end)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  const Pair& q = this->Pairs[pair];
  const Surface& s = q.S;
  const vsh_rt_light& light = f.Lights[q.Light];
  const int samples = f.Samples[q.Light];
  const int* order = f.Order.empty() ? nullptr : f.Order[q.Light].data();
  double p[3];
  for (int r = 0; r < 3; ++r)
  {
    p[r] = s.Point[r] - EyeToCentre[r];
  }
  for (int slot = begin; slot < end; ++slot)
  {
    double dir[3], distance;
    const int k = order ? order[slot] : slot;
    if (vsh_rt_light_sample(&light, p, k, samples, q.Rotation, dir, &distance) != VSH_RT_OK)
    {
      continue;
    }
    double origin[3];
    ShadowOrigin(s, dir, origin);
    RTCRay ray;
    ray.org_x = static_cast<float>(origin[0]);
    ray.org_y = static_cast<float>(origin[1]);
    ray.org_z = static_cast<float>(origin[2]);
    ray.dir_x = static_cast<float>(dir[0]);
    ray.dir_y = static_cast<float>(dir[1]);
    ray.dir_z = static_cast<float>(dir[2]);
    ray.tnear = 0.0f;
    ray.tfar = std::isfinite(distance) ? static_cast<float>(distance)
                                       : std::numeric_limits<float>::infinity();
    ray.mask = 0xffffffffu;
    ray.time = 0.0f;
    ray.id = 0;
    ray.flags = 0;
    this->Rays.push_back(ray);
    this->RayPair.push_back(pair);
  }
}

// The second pass, over Pending[begin, end): the rest of the samples of
// every pair whose first batch or a neighbour's disagreed
// (vsh_rt_adaptive_rest_near: a penumbra narrower than the batch's gaps
// still shows in some pixel around it).
void Worker::Rest(size_t begin, size_t end)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  const int w = f.View.width, h = f.View.height;
  this->Rays.clear();
  this->RayPair.clear();
  this->Pairs.clear();
  for (size_t k = begin; k < end; ++k)
  {
    const Pair& q = this->Pending[k];
    const std::vector<unsigned char>& state = (*this->States)[q.Light];
    const int x = q.S.Pixel % w, y = q.S.Pixel / w;
    unsigned char near[9];
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        if (x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h)
        {
          near[n++] = state[(y + dy) * w + x + dx];
        }
      }
    }
    const int samples = f.Samples[q.Light], first = f.First[q.Light];
    const int rest = vsh_rt_adaptive_rest_near(samples, first, near, n);
    if (rest > 0)
    {
      ++this->Count.LightRefined[q.Light];
      this->Pairs.push_back(q);
      this->Push(static_cast<int>(this->Pairs.size()) - 1, first, first + rest);
    }
  }
}

// The second pass over this thread's pending pairs, in runs of a tile's
// size so the ray streams stay short.
void Worker::Finish()
{
  for (size_t k = 0; k < this->Pending.size(); k += TileSize)
  {
    this->Rest(k, std::min(this->Pending.size(), k + TileSize));
    this->Occlude();
    this->Resolve(false);
  }
  this->Pending.clear();
}

void Worker::Occlude()
{
  if (this->Rays.empty())
  {
    return;
  }
  this->Count.ShadowRays += static_cast<long long>(this->Rays.size());
  if (this->Scene->HasTranslucentCasters())
  {
    this->OccludeTranslucent();
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1M(this->Scene->GetCasters(), &context, this->Rays.data(),
    static_cast<unsigned int>(this->Rays.size()), sizeof(RTCRay));
  const bool volumes = this->Volumes != nullptr;
  for (size_t r = 0; r < this->Rays.size(); ++r)
  {
    Pair& q = this->Pairs[this->RayPair[r]];
    const RTCRay& ray = this->Rays[r];
    const double dir[3] = { ray.dir_x, ray.dir_y, ray.dir_z };
    ++this->Count.LightRays[q.Light];
    // rtcOccluded sets tfar to -inf for a ray that hit something. Without
    // a normal (the refinement missed) every ray weighs the same.
    const double weight = vsh_rt_sample_weight(q.S.HasNormal ? q.S.Normal : nullptr, dir);
    if (volumes)
    {
      // A partial ray where a volume takes some of its light (no volume:
      // the plain blocked / free count, untouched).
      vsh_rt_visibility_add_transmitted(
        &q.Vis, weight, ray.tfar < 0.0f ? 0.0 : this->ThroughVolumes(q.S, ray, 1.0));
      continue;
    }
    vsh_rt_visibility_add(&q.Vis, weight, ray.tfar < 0.0f);
  }
}

// The rays one at a time, each with its own transmittance (the context
// filter's; a stream query's filter may see rays of a packet mixed), then
// through the volumes when they got past the surfaces.
void Worker::OccludeTranslucent()
{
  const std::vector<float>& opacity = this->Scene->GetCasterOpacity();
  const std::vector<float>& transmit = this->Scene->GetCasterTransmit();
  for (size_t r = 0; r < this->Rays.size(); ++r)
  {
    TransmitContext context;
    rtcInitIntersectContext(&context.Base);
    context.Base.filter = &Transmit;
    context.Opacity = opacity.data();
    context.Transmit = transmit.data();
    context.Count = static_cast<unsigned int>(opacity.size());
    std::fill_n(context.Transmittance, 3, 1.0);
    context.SeenCount = 0;
    RTCRay& ray = this->Rays[r];
    const float tmax = ray.tfar; // rtcOccluded1 leaves it or sets -inf
    rtcOccluded1(this->Scene->GetCasters(), &context.Base, &ray);
    Pair& q = this->Pairs[this->RayPair[r]];
    const double dir[3] = { ray.dir_x, ray.dir_y, ray.dir_z };
    ++this->Count.LightRays[q.Light];
    double* t = context.Transmittance;
    const double largest = ray.tfar < 0.0f ? 0.0 : *std::max_element(t, t + 3);
    if (largest <= 0.0)
    {
      std::fill_n(t, 3, 0.0);
    }
    else if (this->Volumes)
    {
      // Volumes are grey: every channel keeps the same fraction; the ray
      // counts as blocked where the product falls under the cutoff.
      RTCRay full = ray;
      full.tfar = tmax;
      const double kept = this->ThroughVolumes(q.S, full, largest) / largest;
      std::for_each(t, t + 3, [kept](double& c) { c *= kept; });
    }
    vsh_rt_visibility_add_coloured(
      &q.Vis, vsh_rt_sample_weight(q.S.HasNormal ? q.S.Normal : nullptr, dir), t);
  }
}

// `start` times what the volumes let through of shadow ray `ray` of
// surface s (the ray's origin again in double, from the surface point).
double Worker::ThroughVolumes(const Surface& s, const RTCRay& ray, double start)
{
  double origin[3], dir[3] = { ray.dir_x, ray.dir_y, ray.dir_z };
  const double norm = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  for (int k = 0; k < 3; ++k)
  {
    dir[k] /= norm;
  }
  ShadowOrigin(s, dir, origin);
  const double tmax =
    std::isfinite(ray.tfar) ? double(ray.tfar) * norm : std::numeric_limits<double>::infinity();
  return this->Volumes->Transmittance(origin, dir, tmax, start, this->Count.VolumeSamples);
}

// Each pair's visibility: the N.L-weighted fraction of its traced rays that
// were free (vsh_rt_visibility_value; 1, the initial value, where no ray
// could be traced). After the first
// batch (`first`), an adaptive pair also records its batch's state and
// waits for the second pass.
void Worker::Resolve(bool first)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  for (const Pair& q : this->Pairs)
  {
    const int pixel = q.S.Pixel;
    if (q.Vis.traced > 0)
    {
      (*this->Out)[q.Light][pixel] = static_cast<float>(vsh_rt_visibility_value(&q.Vis));
      if (this->Tint)
      {
        double tint[3];
        vsh_rt_visibility_tint(&q.Vis, tint);
        std::copy_n(tint, 3, &(*this->Tint)[q.Light][3 * static_cast<size_t>(pixel)]);
      }
    }
    if (!first)
    {
      continue;
    }
    ++this->Count.LightPixels[q.Light];
    if (!f.First.empty() && f.First[q.Light] < f.Samples[q.Light])
    {
      // A batch with partial rays (through translucent casters) is MIXED:
      // its pixel and neighbours trace every sample.
      (*this->States)[q.Light][pixel] = static_cast<unsigned char>(q.Vis.partial > 0
          ? VSH_RT_BATCH_MIXED
          : vsh_rt_adaptive_state(q.Vis.traced, q.Vis.blocked));
      if (q.Vis.traced == f.First[q.Light])
      {
        this->Pending.push_back(q);
      }
    }
  }
}

void Worker::Tile(int block)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  const int columns = (f.View.width + Block - 1) / Block;
  const int x0 = (block % columns) * Block, y0 = (block / columns) * Block;
  this->Refine(
    x0, y0, std::min(f.View.width, x0 + Block) - 1, std::min(f.View.height, y0 + Block) - 1);
  this->Rays.clear();
  this->RayPair.clear();
  this->Pairs.clear();
  for (size_t k = 0; k < this->Surfaces.size(); ++k)
  {
    this->Land(static_cast<int>(k));
    this->Queue(this->Surfaces[k], static_cast<int>(k));
  }
  this->Occlude();
  this->Resolve(true);
}
}

//------------------------------------------------------------------------------
void vtkShadowRayTracer::Counters::Reset(size_t lights)
{
  *this = Counters();
  for (std::vector<long long>* v : { &this->LightPixels, &this->LightRays, &this->LightRefined,
         &this->ClassifiedLit, &this->ClassifiedShadowed, &this->Classifiable, &this->BlockAsked,
         &this->BlockDecided, &this->PixelAsked, &this->PixelDecided })
  {
    v->assign(lights, 0);
  }
}

//------------------------------------------------------------------------------
void vtkShadowRayTracer::Counters::Add(const Counters& o)
{
  this->Background += o.Background;
  this->PrimaryRays += o.PrimaryRays;
  this->RefineMisses += o.RefineMisses;
  this->Landed += o.Landed;
  this->LandedBeyondHalfTolerance += o.LandedBeyondHalfTolerance;
  this->FacingAway += o.FacingAway;
  this->OutsideCone += o.OutsideCone;
  this->ShadowRays += o.ShadowRays;
  this->VolumeSamples += o.VolumeSamples;
  this->PixelsWithoutRays += o.PixelsWithoutRays;
  this->BlockPixels += o.BlockPixels;
  const std::pair<std::vector<long long>*, const std::vector<long long>*> lists[] = {
    { &this->LightPixels, &o.LightPixels }, { &this->LightRays, &o.LightRays },
    { &this->LightRefined, &o.LightRefined }, { &this->ClassifiedLit, &o.ClassifiedLit },
    { &this->ClassifiedShadowed, &o.ClassifiedShadowed }, { &this->Classifiable, &o.Classifiable },
    { &this->BlockAsked, &o.BlockAsked }, { &this->BlockDecided, &o.BlockDecided },
    { &this->PixelAsked, &o.PixelAsked }, { &this->PixelDecided, &o.PixelDecided }
  };
  for (const auto& list : lists)
  {
    for (size_t l = 0; l < list.first->size() && l < list.second->size(); ++l)
    {
      (*list.first)[l] += (*list.second)[l];
    }
  }
}

//------------------------------------------------------------------------------
void vtkShadowRayTracer::Trace(const vtkShadowEmbreeScene& scene, const Frame& frame, int threads,
  std::vector<std::vector<float>>& out, Counters& counters, std::vector<std::vector<float>>* tint)
{
  const auto start = std::chrono::steady_clock::now();
  const int pixels = frame.View.width * frame.View.height;
  out.resize(frame.Lights.size());
  for (auto& light : out)
  {
    light.assign(static_cast<size_t>(pixels), 1.0f);
  }
  if (tint)
  {
    tint->resize(frame.Lights.size());
    for (auto& light : *tint)
    {
      light.assign(3 * static_cast<size_t>(pixels), 1.0f);
    }
  }
  const size_t lights = frame.Lights.size();
  counters.Reset(lights);
  counters.Pixels = pixels;
  const int tiles =
    ((frame.View.width + Block - 1) / Block) * ((frame.View.height + Block - 1) / Block);
  threads = std::max(1, std::min(threads, tiles));
  counters.Threads = threads;
  if (scene.IsEmpty() || frame.Lights.empty() || !frame.Depth)
  {
    return;
  }
  // First batches everywhere, then (adaptive lights) the rest where a
  // pixel's 3x3 neighbourhood of batches disagrees.
  std::vector<std::vector<unsigned char>> states(lights);
  for (size_t l = 0; l < lights && !frame.First.empty(); ++l)
  {
    if (frame.First[l] < frame.Samples[l])
    {
      states[l].assign(static_cast<size_t>(pixels), VSH_RT_BATCH_NONE);
    }
  }
  std::vector<Worker> workers(static_cast<size_t>(threads));
  std::atomic<int> next(0);
  auto run = [&](Worker* w)
  {
    for (int t = next++; t < tiles; t = next++)
    {
      w->Tile(t);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k)
  {
    Worker& w = workers[static_cast<size_t>(k)];
    w.Scene = &scene;
    w.Frame = &frame;
    w.Volumes = frame.Volumes && !frame.Volumes->IsEmpty() ? frame.Volumes : nullptr;
    w.Out = &out;
    w.Tint = tint;
    w.States = &states;
    w.Count.Reset(lights);
    for (int r = 0; r < 3; ++r)
    {
      w.EyeToCentre[r] = frame.Eye[r] - scene.GetCentre()[r];
    }
    if (k > 0)
    {
      pool.emplace_back(run, &w);
    }
  }
  run(&workers[0]);
  for (std::thread& t : pool)
  {
    t.join();
  }
  pool.clear();
  for (int k = 1; k < threads; ++k)
  {
    pool.emplace_back([](Worker* w) { w->Finish(); }, &workers[static_cast<size_t>(k)]);
  }
  workers[0].Finish();
  for (std::thread& t : pool)
  {
    t.join();
  }
  for (const Worker& w : workers)
  {
    counters.Add(w.Count);
  }
  counters.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
