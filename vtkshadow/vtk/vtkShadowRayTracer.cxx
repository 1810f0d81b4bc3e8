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

  void Tile(int begin, int end);
  double Tolerance(int x, int y) const;
  void Refine(int begin, int end);
  void Land(int k);
  bool Reland(int k, const vtkShadowEmbreeScene::Instance& inst);
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

void Worker::Refine(int begin, int end)
{
  const vtkShadowRayTracer::Frame& f = *this->Frame;
  this->Hits.clear();
  this->Pixels.clear();
  this->Surfaces.clear();
  this->Limits.clear();
  const int width = f.View.width;
  for (int p = begin; p < end; ++p)
  {
    vsh_rt_pixel_ray ray;
    const int x = p % width, y = p / width;
    if (vsh_rt_pixel_ray_init(&f.View, x, y, f.Depth[p], this->Tolerance(x, y), &ray) != VSH_RT_OK)
    {
      ++this->Count.Background;
      continue;
    }
    // Start at the near end of the interval: float keeps the precision of
    // the surface's position, not of the far-away camera's.
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
    this->Limits.push_back(static_cast<float>((ray.hi - ray.lo) + 1e-5 * (ray.hi - ray.lo) +
      4 * VSH_RT_OFFSET_RELATIVE * std::fabs(ray.distance)));
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xffffffffu;
    rh.ray.time = 0.0f;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    this->Hits.push_back(rh);
    this->Pixels.push_back(ray);
    Surface s;
    s.Pixel = p;
    this->Surfaces.push_back(s);
  }
  if (!this->Hits.empty())
  {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect1M(this->Scene->GetVisible(), &context, this->Hits.data(),
      static_cast<unsigned int>(this->Hits.size()), sizeof(RTCRayHit));
    this->Count.PrimaryRays += static_cast<long long>(this->Hits.size());
  }
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
    if (!inside && inst.Impostors)
    {
      inside = this->Reland(k, inst);
    }
    const double org[3] = { rh.ray.org_x, rh.ray.org_y, rh.ray.org_z };
    const double t = rh.ray.tfar;
    const double ng[3] = { rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z };
    double n[3], len2 = 0, side = 0;
    for (int r = 0; r < 3; ++r)
    {
      s.Point[r] = org[r] + t * dir[r];
      n[r] = inst.Normal[3 * r] * ng[0] + inst.Normal[3 * r + 1] * ng[1] +
        inst.Normal[3 * r + 2] * ng[2];
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
    const double magnitude =
      std::sqrt(s.Point[0] * s.Point[0] + s.Point[1] * s.Point[1] + s.Point[2] * s.Point[2]) +
      inst.Radius;
    s.Offset = vsh_rt_offset_distance(magnitude);
    return;
  }
  this->Miss(k);
}

// A pixel on a sphere or tube (an impostor instance): VTK's impostor depth
// is near the Embree solid, not on it (the mapper moves the sprite's depth
// by the radius times the sprite's own normal), so the refinement ray,
// which starts at the depth point, may start inside the solid and meet its
// far side, or pass in front of it. Trace the impostor's own scene again
// (an identity placement: the same frame) from twice its largest radius
// before the depth point: a hit up to the interval's end is the pixel's
// surface, with its normal. False (no change) when that misses.
bool Worker::Reland(int k, const vtkShadowEmbreeScene::Instance& inst)
{
  RTCRayHit& rh = this->Hits[k];
  const float back = static_cast<float>(2 * inst.Slack);
  RTCRayHit again = rh;
  again.ray.org_x = rh.ray.org_x - back * rh.ray.dir_x;
  again.ray.org_y = rh.ray.org_y - back * rh.ray.dir_y;
  again.ray.org_z = rh.ray.org_z - back * rh.ray.dir_z;
  again.ray.tnear = 0.0f;
  again.ray.tfar = 2 * back + this->Limits[k];
  again.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  again.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(inst.Impostors, &context, &again);
  ++this->Count.PrimaryRays;
  if (again.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return false;
  }
  const unsigned int instance = rh.hit.instID[0];
  rh.hit = again.hit;
  rh.hit.instID[0] = instance;
  rh.ray.tfar = again.ray.tfar - back; // from the refinement ray's origin
  return true;
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
  const double slack = 0.5 * (ray.hi - ray.lo) + 1e-6 * std::fabs(ray.distance);
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
    const vsh_rt_light& light = f.Lights[l];
    double toLight[3], distance;
    if (vsh_rt_light_direction(&light, p, toLight, &distance) != VSH_RT_OK)
    {
      continue;
    }
    // A facet whose geometric normal faces away from the light is still
    // traced: the mapper shades it with interpolated normals, which near a
    // curved surface's terminator still face the light, so VTK lights it
    // where a ray from the facet meets the mesh itself (as POV-Ray's does on
    // the same mesh) or another caster (a floor between it and the light).
    // The origin stays on the camera's side of the facet; the ray crosses
    // the facet or the mesh behind it, so a surface that truly faces away
    // gets 0 and its lighting is 0 anyway. Skipping is exact only where the
    // mapper's lighting is zero: outside a spot cone (below).
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
    RTCRay ray;
    ray.org_x = static_cast<float>(s.Point[0] + s.Offset * s.Normal[0]);
    ray.org_y = static_cast<float>(s.Point[1] + s.Offset * s.Normal[1]);
    ray.org_z = static_cast<float>(s.Point[2] + s.Offset * s.Normal[2]);
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
    origin[k] = s.Point[k] + s.Offset * s.Normal[k];
    dir[k] /= norm;
  }
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

void Worker::Tile(int begin, int end)
{
  this->Refine(begin, end);
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
  counters = Counters();
  counters.Pixels = pixels;
  const size_t lights = frame.Lights.size();
  counters.LightPixels.assign(lights, 0);
  counters.LightRays.assign(lights, 0);
  counters.LightRefined.assign(lights, 0);
  const int tiles = (pixels + TileSize - 1) / TileSize;
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
      w->Tile(t * TileSize, std::min(pixels, (t + 1) * TileSize));
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
    w.Count.LightPixels.assign(lights, 0);
    w.Count.LightRays.assign(lights, 0);
    w.Count.LightRefined.assign(lights, 0);
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
    counters.Background += w.Count.Background;
    counters.PrimaryRays += w.Count.PrimaryRays;
    counters.RefineMisses += w.Count.RefineMisses;
    counters.FacingAway += w.Count.FacingAway;
    counters.OutsideCone += w.Count.OutsideCone;
    counters.ShadowRays += w.Count.ShadowRays;
    counters.VolumeSamples += w.Count.VolumeSamples;
    for (size_t l = 0; l < lights; ++l)
    {
      counters.LightPixels[l] += w.Count.LightPixels[l];
      counters.LightRays[l] += w.Count.LightRays[l];
      counters.LightRefined[l] += w.Count.LightRefined[l];
    }
  }
  counters.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
