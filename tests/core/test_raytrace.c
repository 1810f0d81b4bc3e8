/* test_raytrace.c - unit tests of vsh_raytrace.h: depth -> point, the
 * refinement ray's interval, the origin offset, light directions, cones and
 * samples, the cost estimate; offsets of 1e6, scales of 1e-6, 4:3 and 16:9,
 * parallel projections and the degenerate inputs. */
#include "vsh_check.h"
#include "vsh_camera.h"
#include "vsh_mat4.h"
#include "vsh_raytrace.h"
#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

/* A camera looking at `target` from `eye` (both world), its view matrix and
 * a perspective projection; the view for vsh_rt_view_init. */
static void make_view(const double eye[3], const double target[3], double near_dist,
                      double far_dist, int width, int height, vsh_rt_view *view, double clip[16])
{
  vsh_camera c;
  memcpy(c.position, eye, sizeof c.position);
  memcpy(c.focal_point, target, sizeof c.focal_point);
  c.view_up[0] = 0, c.view_up[1] = 0, c.view_up[2] = 1;
  c.view_angle = 30;
  double v[16], p[16], rel[16];
  CHECK(vsh_camera_view_matrix(&c, v) == 0);
  CHECK(vsh_camera_projection_matrix(30, (double)width / height, near_dist, far_dist, p) == 0);
  CHECK(vsh_rt_view_init(p, v, width, height, view) == VSH_RT_OK);
  CHECK(vsh_camera_view_matrix_relative(&c, rel) == 0);
  vsh_mat4_multiply(p, rel, clip);
}

/* Window coordinates (x, y, depth) of a camera-relative point. */
static void project(const double clip[16], int width, int height, const double p[3],
                    double win[3])
{
  const double in[4] = { p[0], p[1], p[2], 1.0 };
  double c[4];
  vsh_mat4_transform_point4(clip, in, c);
  win[0] = (c[0] / c[3] + 1.0) * 0.5 * width;
  win[1] = (c[1] / c[3] + 1.0) * 0.5 * height;
  win[2] = (c[2] / c[3] + 1.0) * 0.5;
}

/* Points projected and unprojected come back, at the origin, 1e6 away and
 * at 1e-6 scale (camera-relative: the eye's offset never enters). */
static void test_unproject(double offset, double scale, int width, int height)
{
  const double eye[3] = { offset, offset - 8 * scale, offset + 5 * scale };
  const double target[3] = { offset, offset, offset + 0.5 * scale };
  vsh_rt_view view;
  double clip[16];
  make_view(eye, target, 3 * scale, 14 * scale, width, height, &view, clip);
  for (int k = 0; k < 50; ++k) {
    /* Points on a floor patch, relative to the eye. */
    const double world[3] = { offset + scale * (-2 + 0.08 * k), offset + scale * (1.5 - 0.05 * k),
                              offset };
    double rel[3], win[3], back[3];
    vsh_vec3_sub(world, eye, rel);
    project(clip, width, height, rel, win);
    CHECK(vsh_rt_unproject(&view, win[0], win[1], win[2], back) == VSH_RT_OK);
    CHECK(vsh_vec3_length(rel) > 0);
    double d[3];
    vsh_vec3_sub(back, rel, d);
    CHECK_NEAR(vsh_vec3_length(d) / vsh_vec3_length(rel), 0, 1e-9);
  }
}

/* The pixel ray passes through the pixel's point at every depth; a depth
 * quantized to 24 bits keeps the true distance inside [lo, hi]. */
static void test_pixel_ray(double offset, double scale)
{
  const int width = 640, height = 360;
  const double eye[3] = { offset, offset - 8 * scale, offset + 5 * scale };
  const double target[3] = { offset, offset, offset };
  vsh_rt_view view;
  double clip[16];
  make_view(eye, target, 0.5 * scale, 40 * scale, width, height, &view, clip);
  int inside = 0;
  for (int j = 0; j < height; j += 17) {
    for (int i = 0; i < width; i += 23) {
      /* The floor z = offset hit by the ray through the pixel centre. */
      double p0[3], p1[3], dir[3];
      CHECK(vsh_rt_unproject(&view, i + 0.5, j + 0.5, 0.2, p0) == 0);
      CHECK(vsh_rt_unproject(&view, i + 0.5, j + 0.5, 0.9, p1) == 0);
      vsh_vec3_sub(p1, p0, dir);
      const double floor_rel = offset - eye[2];
      if (dir[2] >= 0) {
        continue;
      }
      const double s = (floor_rel - p0[2]) / dir[2];
      double hit[3], win[3];
      for (int c = 0; c < 3; ++c) hit[c] = p0[c] + s * dir[c];
      project(clip, width, height, hit, win);
      if (!(win[2] > 0 && win[2] < 1)) {
        continue;
      }
      const double quantized = floor(win[2] / VSH_RT_DEPTH_QUANTUM + 0.5) * VSH_RT_DEPTH_QUANTUM;
      vsh_rt_pixel_ray r;
      CHECK(vsh_rt_pixel_ray_init(&view, i, j, quantized, 2 * VSH_RT_DEPTH_QUANTUM, &r) == 0);
      CHECK_NEAR(vsh_vec3_length(r.direction), 1, 1e-12);
      double to_hit[3];
      vsh_vec3_sub(hit, r.origin, to_hit);
      const double t = vsh_vec3_dot(to_hit, r.direction);
      /* On the ray (perpendicular distance relative to t) ... */
      double foot[3], miss[3];
      for (int c = 0; c < 3; ++c) foot[c] = r.origin[c] + t * r.direction[c];
      vsh_vec3_sub(foot, hit, miss);
      CHECK_NEAR(vsh_vec3_length(miss) / t, 0, 1e-9);
      /* ... and within the interval, which is small. */
      CHECK(r.lo <= t && t <= r.hi);
      CHECK(r.lo <= r.distance && r.distance <= r.hi);
      CHECK((r.hi - r.lo) / t < 1e-3);
      ++inside;
    }
  }
  CHECK(inside > 100);
}

static void test_parallel_and_degenerate(void)
{
  /* A parallel projection: every pixel ray has the view direction. */
  double ortho[16], view_m[16];
  vsh_mat4_identity(ortho);
  ortho[0] = 1.0 / 4, ortho[5] = 1.0 / 3, ortho[10] = -2.0 / 9, ortho[11] = -11.0 / 9;
  vsh_mat4_identity(view_m);
  vsh_rt_view view;
  CHECK(vsh_rt_view_init(ortho, view_m, 400, 300, &view) == 0);
  vsh_rt_pixel_ray a, b;
  CHECK(vsh_rt_pixel_ray_init(&view, 0, 0, 0.5, 0, &a) == 0);
  CHECK(vsh_rt_pixel_ray_init(&view, 399, 299, 0.25, 0, &b) == 0);
  CHECK_NEAR(a.direction[2], -1, 1e-15);
  CHECK_NEAR(b.direction[2], -1, 1e-15);
  CHECK_NEAR(a.point[2], -5.5, 1e-12); /* near 1, far 10: depth 0.5 -> z = -5.5 */
  CHECK_NEAR(a.distance, 4.5, 1e-12);
  CHECK(a.lo == a.distance && a.hi == a.distance);
  /* Background, bad depth, bad tolerance, a singular camera. */
  CHECK(vsh_rt_pixel_ray_init(&view, 3, 3, 1.0, 0, &a) == VSH_RT_BACKGROUND);
  CHECK(vsh_rt_pixel_ray_init(&view, 3, 3, NAN, 0, &a) == VSH_RT_BACKGROUND);
  CHECK(vsh_rt_pixel_ray_init(&view, 3, 3, -0.1, 0, &a) == VSH_RT_DEGENERATE);
  CHECK(vsh_rt_pixel_ray_init(&view, 3, 3, 0.5, -1, &a) == VSH_RT_DEGENERATE);
  double zero[16] = { 0 };
  CHECK(vsh_rt_view_init(zero, view_m, 400, 300, &view) == VSH_RT_DEGENERATE);
  CHECK(view.inv_clip[0] == 1 && view.inv_clip[5] == 1);
  CHECK(vsh_rt_view_init(ortho, view_m, 0, 300, &view) == VSH_RT_DEGENERATE);
  /* w <= 0: a point behind a perspective eye. */
  double p[16];
  CHECK(vsh_camera_projection_matrix(30, 1, 1, 10, p) == 0);
  CHECK(vsh_rt_view_init(p, view_m, 100, 100, &view) == 0);
  double out[3] = { 7, 7, 7 };
  CHECK(vsh_rt_unproject(&view, 50, 50, 5.0, out) == VSH_RT_DEGENERATE);
  CHECK(out[0] == 0 && out[1] == 0 && out[2] == 0);
}

static void test_offset(void)
{
  CHECK_NEAR(vsh_rt_offset_distance(1.0), VSH_RT_OFFSET_RELATIVE, 0);
  CHECK_NEAR(vsh_rt_offset_distance(-1e6), 1e6 * VSH_RT_OFFSET_RELATIVE, 1e-9);
  CHECK_NEAR(vsh_rt_offset_distance(1e-6) / 1e-6, VSH_RT_OFFSET_RELATIVE, 1e-18);
  CHECK(vsh_rt_offset_distance(0) > 0);
  CHECK(vsh_rt_offset_distance(NAN) > 0 && vsh_rt_offset_distance(NAN) < 1e-200);
  CHECK(isfinite(vsh_rt_offset_distance(INFINITY)));
  /* Larger than float rounding at the magnitude, smaller than 1e-4 of it. */
  CHECK(VSH_RT_OFFSET_RELATIVE >= 4 * 5.96e-8 && VSH_RT_OFFSET_RELATIVE < 1e-5);
  const double p[3] = { 1e6, 2, 3 }, n[3] = { 0, 0, 1 };
  double o[3];
  vsh_rt_offset_origin(p, n, 1e6, o);
  CHECK(o[0] == 1e6 && o[1] == 2);
  CHECK_NEAR(o[2] - 3, 1e6 * VSH_RT_OFFSET_RELATIVE, 1e-12);
}

/* The float frame stays while the eye is within the near distance of its
 * origin (at 1e6 offsets and 1e-6 scales alike), and moves otherwise. */
static void test_frame_usable(void)
{
  const double at_eye[3] = { 0, 0, 0 };
  const double near_far_1e6[3] = { 0, 1e5, 4e3 }; /* hard/near-far-1e6's centre */
  CHECK(vsh_rt_frame_usable(at_eye, 0.1));
  CHECK(vsh_rt_frame_usable(at_eye, 0.0));
  CHECK(!vsh_rt_frame_usable(near_far_1e6, 0.1));
  CHECK(vsh_rt_frame_usable(near_far_1e6, 2e5));
  for (double scale = 1e-6; scale <= 1e6; scale *= 1e3) {
    const double on[3] = { 0.6 * scale, 0.0, 0.8 * scale };  /* |.| = scale */
    const double off[3] = { 0.6 * scale, 1e-9 * scale, 0.8 * scale * (1 + 1e-6) };
    CHECK(vsh_rt_frame_usable(on, scale * (1 + 1e-12)));
    CHECK(!vsh_rt_frame_usable(off, scale));
  }
  const double bad[3] = { NAN, 0, 0 };
  const double inf[3] = { INFINITY, 0, 0 };
  CHECK(!vsh_rt_frame_usable(bad, 1.0));
  CHECK(!vsh_rt_frame_usable(inf, INFINITY));
  CHECK(!vsh_rt_frame_usable(near_far_1e6, NAN));
  CHECK(!vsh_rt_frame_usable(near_far_1e6, -1.0));
  CHECK(!vsh_rt_frame_usable(near_far_1e6, INFINITY));
}

static void test_lights(void)
{
  vsh_rt_light l;
  const double p[3] = { 1, 2, 0 }, zero3[3] = { 0, 0, 0 };
  double dir[3], dist;
  /* Directional: unit direction towards the light, infinite distance. */
  CHECK(vsh_rt_light_init((double[4]){ 3, 0, 4, 0 }, zero3, 30, 1, 0, &l) == 0);
  CHECK(l.kind == VSH_RT_DIRECTIONAL && l.radius == 1);
  CHECK(vsh_rt_light_direction(&l, p, dir, &dist) == 0);
  CHECK_NEAR(dir[0], 0.6, 1e-15);
  CHECK_NEAR(dir[2], 0.8, 1e-15);
  CHECK(isinf(dist) && vsh_rt_light_in_cone(&l, dir));
  CHECK(vsh_rt_light_init((double[4]){ 0, 0, 0, 0 }, zero3, 30, 0, 0, &l) == VSH_RT_DEGENERATE);
  CHECK(l.direction[2] == 1);
  /* Point (cone >= 90): distance and direction; a point at the light. */
  CHECK(vsh_rt_light_init((double[4]){ 1, 2, 5, 1 }, zero3, 90, 0, 0, &l) == 0);
  CHECK(l.kind == VSH_RT_POINT);
  CHECK(vsh_rt_light_direction(&l, p, dir, &dist) == 0);
  CHECK_NEAR(dist, 5, 1e-15);
  CHECK_NEAR(dir[2], 1, 1e-15);
  CHECK(vsh_rt_light_direction(&l, (double[3]){ 1, 2, 5 }, dir, &dist) == VSH_RT_DEGENERATE);
  CHECK(dist == 0);
  /* Homogeneous w other than 1. */
  CHECK(vsh_rt_light_init((double[4]){ 2, 4, 10, 2 }, zero3, 120, 0, 0, &l) == 0);
  CHECK_NEAR(l.position[2], 5, 1e-15);
  /* Spot: axis towards the focal point, the cone's edge as VTK tests it. */
  CHECK(vsh_rt_light_init((double[4]){ 0, 0, 10, 1 }, zero3, 30, 0, 0, &l) == 0);
  CHECK(l.kind == VSH_RT_SPOT);
  CHECK_NEAR(l.direction[2], -1, 1e-15);
  CHECK_NEAR(l.cos_cone, cos(PI / 6), 1e-15);
  const double in_edge = 10 * tan(PI / 6) * 0.999, out_edge = 10 * tan(PI / 6) * 1.001;
  CHECK(vsh_rt_light_direction(&l, (double[3]){ in_edge, 0, 0 }, dir, &dist) == 0);
  CHECK(vsh_rt_light_in_cone(&l, dir));
  CHECK(vsh_rt_light_direction(&l, (double[3]){ 0, out_edge, 0 }, dir, &dist) == 0);
  CHECK(!vsh_rt_light_in_cone(&l, dir));
  /* Behind the spot: never in the cone. */
  CHECK(vsh_rt_light_direction(&l, (double[3]){ 0, 0, 20 }, dir, &dist) == 0);
  CHECK(!vsh_rt_light_in_cone(&l, dir));
  /* Spot whose focal point is its position: degenerate, finite axis. */
  CHECK(vsh_rt_light_init((double[4]){ 1, 1, 1, 1 }, (double[3]){ 1, 1, 1 }, 30, 0, 0, &l) ==
        VSH_RT_DEGENERATE);
  CHECK(l.direction[2] == -1);
  /* Camera-relative at 1e6: the same numbers as at the origin. */
  CHECK(vsh_rt_light_init((double[4]){ 0, 0, 10, 1 }, zero3, 30, 0, 0, &l) == 0);
}

static void test_disk(void)
{
  double s[2];
  vsh_rt_disk_sample(0, 1, 1.0, s);
  CHECK(s[0] == 0 && s[1] == 0);
  for (int n = 2; n <= 256; n *= 2) {
    double mx = 0, my = 0;
    int inner = 0;
    for (int k = 0; k < n; ++k) {
      vsh_rt_disk_sample(k, n, 0.3, s);
      const double r = hypot(s[0], s[1]);
      CHECK(r <= 1.0);
      inner += r < sqrt(0.5);
      mx += s[0] / n;
      my += s[1] / n;
    }
    /* Area-uniform: half the samples inside radius sqrt(1/2); centred. */
    CHECK(inner == n / 2);
    if (n >= 16) {
      CHECK(hypot(mx, my) < 0.1);
    }
  }
}

static void test_light_samples(void)
{
  vsh_rt_light l;
  const double p[3] = { 0.5, -1, 0 }, zero3[3] = { 0, 0, 0 };
  double centre[3], dir[3], dist, cdist;
  /* Point light of radius 0.5 at 10: sample targets on the disk facing p. */
  CHECK(vsh_rt_light_init((double[4]){ 0, 0, 10, 1 }, zero3, 180, 0.5, 0, &l) == 0);
  CHECK(vsh_rt_light_direction(&l, p, centre, &cdist) == 0);
  double spread = 0;
  for (int k = 0; k < 16; ++k) {
    CHECK(vsh_rt_light_sample(&l, p, k, 16, 1.0, dir, &dist) == 0);
    CHECK_NEAR(vsh_vec3_length(dir), 1, 1e-14);
    double target[3], off[3];
    for (int c = 0; c < 3; ++c) target[c] = p[c] + dist * dir[c] - l.position[c];
    CHECK(vsh_vec3_length(target) <= 0.5 + 1e-12);
    CHECK_NEAR(vsh_vec3_dot(target, centre), 0, 1e-12); /* on the disk facing p */
    vsh_vec3_sub(dir, centre, off);
    spread = fmax(spread, vsh_vec3_length(off));
  }
  CHECK(spread > 0.02);
  /* One sample, or radius 0: the centre. */
  CHECK(vsh_rt_light_sample(&l, p, 0, 1, 1.0, dir, &dist) == 0);
  CHECK_NEAR(dir[0], centre[0], 0);
  CHECK_NEAR(dist, cdist, 0);
  /* Directional light of angular diameter 10 degrees: within 5 degrees. */
  CHECK(vsh_rt_light_init((double[4]){ 1, 1, 1, 0 }, zero3, 0, 0, 10 * PI / 180, &l) == 0);
  double widest = 0;
  for (int k = 0; k < 64; ++k) {
    CHECK(vsh_rt_light_sample(&l, p, k, 64, 0.0, dir, &dist) == 0);
    const double a = acos(fmin(1.0, vsh_vec3_dot(dir, l.direction)));
    CHECK(a <= 5 * PI / 180 + 1e-12);
    widest = fmax(widest, a);
    CHECK(isinf(dist));
  }
  CHECK(widest > 4 * PI / 180);
  /* At the light: degenerate, finite outputs. */
  CHECK(vsh_rt_light_init((double[4]){ 0, 0, 1, 1 }, zero3, 180, 0.5, 0, &l) == 0);
  CHECK(vsh_rt_light_sample(&l, (double[3]){ 0, 0, 1 }, 2, 8, 0.0, dir, &dist) != 0);
  CHECK(vsh_vec3_is_finite(dir) && dist == 0);
}

static void test_rotation(void)
{
  int differ = 0;
  for (unsigned y = 0; y < 32; ++y) {
    for (unsigned x = 0; x < 32; ++x) {
      const double r = vsh_rt_pixel_rotation(x, y);
      CHECK(r >= 0 && r < 2 * PI);
      CHECK(r == vsh_rt_pixel_rotation(x, y));
      differ += fabs(r - vsh_rt_pixel_rotation(x + 1, y)) > 0.1;
    }
  }
  CHECK(differ > 900);
}

static void test_cost(void)
{
  vsh_rt_cost_model m;
  vsh_rt_cost_model_default(&m);
  CHECK(m.rays_per_second_per_thread > 0 && m.pixel_ns > 0 && m.frame_ms >= 0);
  vsh_rt_cost_input in = { 640.0 * 480, 0.5, 2, 1, 2, 0, 0.0, 0.0 };
  CHECK_NEAR(vsh_rt_cost_rays(&in), 0.5 * 640 * 480 * 3, 1e-6);
  const double base = vsh_rt_cost_ms(&m, &in);
  CHECK(base > m.frame_ms);
  vsh_rt_cost_input more = in;
  more.pixels *= 4;
  CHECK(vsh_rt_cost_ms(&m, &more) > 3 * (base - m.frame_ms));
  more = in;
  more.lights = 4;
  CHECK(vsh_rt_cost_ms(&m, &more) > base);
  more = in;
  more.samples = 16;
  CHECK(vsh_rt_cost_ms(&m, &more) > 5 * base);
  /* Adaptive counts: 8 rays everywhere, the other 56 of 64 on the 10% of
   * pixels in the penumbra: 13.6 rays per pixel and light, not 64. */
  more = in;
  more.samples = 64;
  more.first = 8;
  more.penumbra = 0.1;
  CHECK_NEAR(vsh_rt_cost_rays(&more), 0.5 * 640 * 480 * (1 + 2 * 13.6), 1e-6);
  more.penumbra = 1.0; /* every pixel in the penumbra: the full count */
  CHECK_NEAR(vsh_rt_cost_rays(&more), 0.5 * 640 * 480 * (1 + 2 * 64), 1e-6);
  /* The classifier leaves 30% of the pairs to rays: 30% of the rays;
   * out of range counts as no classifier (0) or everything (> 1). */
  more = in;
  more.traced = 0.3;
  CHECK_NEAR(vsh_rt_cost_rays(&more), 0.3 * 0.5 * 640 * 480 * 3, 1e-6);
  more.traced = 0.0;
  CHECK_NEAR(vsh_rt_cost_rays(&more), 0.5 * 640 * 480 * 3, 1e-6);
  more.traced = 7.0;
  CHECK_NEAR(vsh_rt_cost_rays(&more), 0.5 * 640 * 480 * 3, 1e-6);
  more = in;
  more.samples = 64;
  more.first = 8;
  more.penumbra = 1.0;
  more.first = 0; /* not adaptive */
  more.penumbra = 0.0;
  CHECK_NEAR(vsh_rt_cost_rays(&more), 0.5 * 640 * 480 * (1 + 2 * 64), 1e-6);
  more = in;
  more.threads = 4;
  CHECK(vsh_rt_cost_ms(&m, &more) < base);
  more = in;
  more.lights = 0;
  CHECK(vsh_rt_cost_ms(&m, &more) == 0);
  more = in;
  more.coverage = 7; /* clamped to 1 */
  CHECK_NEAR(vsh_rt_cost_rays(&more), 640.0 * 480 * 3, 1e-6);
  more.threads = -3; /* as 1 */
  more.coverage = 1;
  in.coverage = 1;
  in.threads = 1;
  CHECK_NEAR(vsh_rt_cost_ms(&m, &more), vsh_rt_cost_ms(&m, &in), 1e-12);
  /* Observing a measured rate moves the model towards it. */
  const double before = m.rays_per_second_per_thread;
  vsh_rt_cost_model_observe(&m, 4e7, 1.0, 2); /* 2e7 per thread */
  CHECK(m.rays_per_second_per_thread > before);
  CHECK_NEAR(m.rays_per_second_per_thread, 0.75 * before + 0.25 * 2e7, 1e-3);
  const double kept = m.rays_per_second_per_thread;
  vsh_rt_cost_model_observe(&m, 0, 1.0, 2);
  vsh_rt_cost_model_observe(&m, 1e6, 0, 2);
  vsh_rt_cost_model_observe(&m, 1e6, 1, 0);
  vsh_rt_cost_model_observe(&m, NAN, 1, 1);
  CHECK(m.rays_per_second_per_thread == kept);
}

/* The impostor radius: half the pixel width at the point's depth, the same
 * whichever pixel the point projects to, in perspective (tan(15 deg) d /
 * height per pixel) and parallel (parallel scale / height per pixel). */
static void test_impostor_radius(void)
{
  double view_m[16], p[16];
  vsh_mat4_identity(view_m);
  view_m[11] = -2.0; /* the eye at world z = 2, looking down -z */
  CHECK(vsh_camera_projection_matrix(30, 640.0 / 480.0, 0.1, 100, p) == 0);
  const double centre[3] = { 0, 0, -8 }, aside[3] = { 3, -2, -8 }, behind[3] = { 0, 0, 12 };
  const double expected = 18 * 10 * tan(15 * PI / 180) / 480; /* d = 10 */
  CHECK_NEAR(vsh_rt_impostor_radius(p, view_m, 640, 18, centre), expected, 1e-12);
  CHECK_NEAR(vsh_rt_impostor_radius(p, view_m, 640, 18, aside), expected, 1e-12);
  CHECK_NEAR(vsh_rt_impostor_radius(p, view_m, 640, 18, behind), expected, 1e-12);
  double ortho[16];
  vsh_mat4_identity(ortho);
  ortho[0] = 1.0 / (3.0 * 640 / 480), ortho[5] = 1.0 / 3, ortho[10] = -2.0 / 9; /* scale 3 */
  CHECK_NEAR(vsh_rt_impostor_radius(ortho, view_m, 640, 16, aside), 16 * 3.0 / 480, 1e-12);
  CHECK(vsh_rt_impostor_radius(ortho, view_m, 0, 16, aside) == 0);
  CHECK(vsh_rt_impostor_radius(ortho, view_m, 640, NAN, aside) == 0);
  const double far_away[3] = { NAN, 0, 0 };
  CHECK(vsh_rt_impostor_radius(p, view_m, 640, 18, far_away) == 0);
}

int main(void)
{
  test_unproject(0, 1, 640, 480);
  test_unproject(0, 1, 640, 360);
  test_unproject(1e6, 1, 640, 480);
  test_unproject(0, 1e-6, 640, 480);
  test_unproject(1e6, 1e-6, 640, 360);
  test_pixel_ray(0, 1);
  test_pixel_ray(1e6, 1);
  test_pixel_ray(0, 1e-6);
  test_parallel_and_degenerate();
  test_offset();
  test_frame_usable();
  test_lights();
  test_disk();
  test_light_samples();
  test_rotation();
  test_cost();
  test_impostor_radius();
  return vsh_check_report("core.raytrace");
}
