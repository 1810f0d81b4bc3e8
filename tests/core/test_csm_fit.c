/* test_csm_fit.c - unit tests of vsh_csm_fit.c: directional fits (coverage
 * of the slice, depth range reaching the casters, stability under camera
 * rotation and sub-texel translation, a world-anchored texel grid at 1e6),
 * perspective fits (cone boundary, depth range, cube-face coverage, the
 * depth terms). Every degenerate input the header names is included: light
 * parallel to the view direction, zero-volume bounds, empty scenes. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_csm.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"
#include "csm_test_common.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* Clip coordinates (after the divide) of the camera-relative point rel. */
static double clip_of(const double M[16], const double rel[3], double out[3]) {
  return vsh_mat4_transform_point(M, rel, out);
}

/* Clip coordinates of the world point P for a map with origin `origin`. */
static double clip_world(const double M[16], const double origin[3], const double P[3],
                         double out[3]) {
  double rel[3];
  vsh_vec3_sub(P, origin, rel);
  return clip_of(M, rel, out);
}

/* Camera-relative corner k of the view slice [n, f] (bit 0 right, bit 1 up,
 * bit 2 far), computed from the camera basis independently of the code. */
static void slice_corner(const vsh_camera *c, double aspect, double n, double f, int k,
                         double out[3]) {
  double r[3], u[3], fw[3];
  vsh_camera_basis(c, r, u, fw);
  const double t = tan_half(c->view_angle), d = (k & 4) ? f : n;
  const double sx = (k & 1) ? 1 : -1, sy = (k & 2) ? 1 : -1;
  for (int i = 0; i < 3; ++i) out[i] = d * (fw[i] + sx * t * aspect * r[i] + sy * t * u[i]);
}

/* Is the world point P inside the view slice [n, f] (with a relative slack)? */
static int in_slice(const vsh_camera *c, double aspect, double n, double f, const double P[3],
                    double slack) {
  double r[3], u[3], fw[3], rel[3];
  vsh_camera_basis(c, r, u, fw);
  vsh_vec3_sub(P, c->position, rel);
  const double t = tan_half(c->view_angle), d = vsh_vec3_dot(rel, fw);
  return d >= n * (1 + slack) && d <= f * (1 - slack) &&
         fabs(vsh_vec3_dot(rel, r)) <= t * aspect * d * (1 - slack) &&
         fabs(vsh_vec3_dot(rel, u)) <= t * d * (1 - slack);
}

static int view_is_finite(const vsh_shadow_view *v) {
  return vsh_mat4_is_finite(v->world_to_clip) && isfinite(v->texel_world) &&
         v->texel_world > 0 && isfinite(v->depth_extent) && v->depth_extent > 0 &&
         isfinite(v->near_far[0]) && isfinite(v->near_far[1]);
}

/* ---- directional fit ------------------------------------------------------ */

/* All checks of one fit: finite; slice corners inside [-1,1]^2 (when
 * `slice_covered`); caster corners at clip z >= -1; receiver points inside
 * the slice mapped inside the unit cube. */
static void check_directional(const vsh_camera *c, double aspect, double n, double f,
                              const vsh_bounds *receivers, const vsh_bounds *casters,
                              int slice_covered, const vsh_shadow_view *v, double *worst_xy) {
  CHECK(view_is_finite(v));
  CHECK(v->perspective == 0);
  const double *M = v->world_to_clip;
  /* Orthographic: the last row is (0,0,0,1). */
  CHECK(M[12] == 0 && M[13] == 0 && M[14] == 0 && M[15] == 1);
  const double eps = 1e-9;
  if (slice_covered)
    for (int k = 0; k < 8; ++k) {
      double rel[3], q[3];
      slice_corner(c, aspect, n, f, k, rel);
      clip_of(M, rel, q);
      if (worst_xy) *worst_xy = fmax(*worst_xy, fmax(fabs(q[0]), fabs(q[1])));
      CHECK(fabs(q[0]) <= 1 + eps && fabs(q[1]) <= 1 + eps);
    }
  if (casters && !vsh_bounds_is_empty(casters)) {
    double corners[8][3];
    vsh_bounds_corners(casters, corners);
    for (int k = 0; k < 8; ++k) {
      double q[3];
      clip_world(M, c->position, corners[k], q);
      CHECK(q[2] >= -1 - eps);
    }
  }
  if (receivers && !vsh_bounds_is_empty(receivers)) {
    const int N = 6;
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j <= N; ++j)
        for (int k = 0; k <= N; ++k) {
          const double P[3] = {receivers->min[0] + (receivers->max[0] - receivers->min[0]) * i / N,
                               receivers->min[1] + (receivers->max[1] - receivers->min[1]) * j / N,
                               receivers->min[2] + (receivers->max[2] - receivers->min[2]) * k / N};
          if (!in_slice(c, aspect, n, f, P, 1e-12)) continue;
          double q[3];
          clip_world(M, c->position, P, q);
          CHECK(q[2] <= 1 + eps);
          CHECK(fabs(q[0]) <= 1 + eps && fabs(q[1]) <= 1 + eps);
        }
  }
}

static void test_directional_basic(void) {
  vsh_shadow_view v;
  const vsh_camera c = make_camera(0, 2, 10, 0, 0, 0, 0, 1, 0, 50);
  const double sun[3] = {0.3, -1, -0.2};
  const vsh_bounds floor_ = box(-30, 30, 0, 0, -30, 30), tower = box(-1, 1, 0, 25, -1, 1);
  vsh_bounds scene = floor_;
  vsh_bounds_merge(&scene, &tower);
  for (int stable = 0; stable <= 1; ++stable) {
    /* No receivers, no casters. */
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
        .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 2048}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.5, 1, 20, NULL, NULL, 1, &v, NULL);
    /* Casters = the scene (the tower reaches above the slice). */
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
        .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = NULL,
        .casters = &scene, .stable = stable, .resolution = 2048}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.5, 1, 20, NULL, &scene, 1, &v, NULL);
    /* Receivers: the floor (zero volume); casters: the scene. */
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
        .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = &floor_,
        .casters = &scene, .stable = stable, .resolution = 2048}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.5, 1, 20, &floor_, &scene, stable, &v, NULL);
    CHECK(v.depth_extent > 0);
    /* Empty receivers and casters mean "none given". */
    vsh_bounds empty;
    vsh_bounds_init_empty(&empty);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
        .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = &empty,
        .casters = &empty, .stable = stable, .resolution = 2048}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.5, 1, 20, NULL, NULL, 1, &v, NULL);
    /* A caster far outside the slice (behind the camera, towards the sun)
     * still gets clip z >= -1. */
    const vsh_bounds far_caster = box(-40, -38, 0, 80, 60, 62);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
        .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = &floor_,
        .casters = &far_caster, .stable = stable, .resolution = 2048}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.5, 1, 20, &floor_, &far_caster, stable, &v, NULL);
    /* Casters entirely below the receivers: finite, nothing breaks. */
    const vsh_bounds under = box(-5, 5, -10, -9, -5, 5);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
        .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = &floor_,
        .casters = &under, .stable = stable, .resolution = 2048}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.5, 1, 20, &floor_, NULL, stable, &v, NULL);
  }
  /* Orthographic map depth: the caster top maps to -1 (up to the margin),
   * the lowest receiver point in the slice to +1 (same). Light straight
   * down, camera looking down at a floor at y = 0 from y = 10. */
  const vsh_camera top = make_camera(0, 10, 0, 0, 0, 0, 0, 0, -1, 60);
  const double down[3] = {0, -1, 0};
  const vsh_bounds tall = box(-1, 1, 0, 4, -1, 1);
  CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &top, .aspect = 1.0,
      .slice_near = 5, .slice_far = 10, .light_direction = down, .receivers = &floor_,
      .casters = &tall, .stable = 0, .resolution = 1024}, &v) == VSH_CSM_OK);
  check_directional(&top, 1.0, 5, 10, &floor_, &tall, 0, &v, NULL);
  double q[3];
  clip_world(v.world_to_clip, top.position, (double[3]){0, 4, 0}, q);
  CHECK(q[2] >= -1 && q[2] < -0.99);
  clip_world(v.world_to_clip, top.position, (double[3]){0, 0, 0}, q);
  CHECK(q[2] <= 1 && q[2] > 0.99);
  CHECK_NEAR(v.depth_extent, 4, 0.01);
  /* Non-stable without receivers: the map is the tight light-space box of
   * the slice, so some corner reaches |x| = 1 and some |y| = 1. */
  CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
      .slice_near = 1, .slice_far = 20, .light_direction = sun, .receivers = NULL, .casters = NULL,
      .stable = 0, .resolution = 1000}, &v) == VSH_CSM_OK);
  double mx = 0, my = 0;
  for (int k = 0; k < 8; ++k) {
    double rel[3];
    slice_corner(&c, 1.5, 1, 20, k, rel);
    clip_of(v.world_to_clip, rel, q);
    mx = fmax(mx, fabs(q[0]));
    my = fmax(my, fabs(q[1]));
  }
  CHECK_NEAR(mx, 1, 1e-12);
  CHECK_NEAR(my, 1, 1e-12);
}

static void test_directional_random(void) {
  double worst_stable = 0, worst_tight = 0;
  int fitted = 0, skipped = 0;
  for (int s = 0; s < 2000; ++s) {
    double E[3], dir[3], L[3];
    for (int k = 0; k < 3; ++k) E[k] = vsh_test_rnd(-50, 50);
    vsh_test_rnd_unit(dir);
    vsh_test_rnd_unit(L);
    const vsh_camera c = camera_looking(E, dir, vsh_test_rnd(20, 110));
    const double aspect = vsh_test_rnd(0.5, 2.5), n = vsh_test_rnd(0.1, 10), f = n * vsh_test_rnd(1.2, 100);
    const int stable = s & 1;
    static const int resolutions[] = {2, 64, 256, 1024, 2048, 4096};
    const int res = resolutions[(int)vsh_test_rnd(0, 6)];
    vsh_bounds rec, cas;
    const vsh_bounds *rp = NULL, *cp = NULL;
    if (vsh_test_rnd(0, 1) < 0.7) {
      for (int k = 0; k < 3; ++k) {
        const double a = E[k] + vsh_test_rnd(-60, 60), w = vsh_test_rnd(0, 1) < 0.3 ? 0 : vsh_test_rnd(0, 80);
        rec.min[k] = a;
        rec.max[k] = a + w;
      }
      rp = &rec;
    }
    if (vsh_test_rnd(0, 1) < 0.7) {
      for (int k = 0; k < 3; ++k) {
        const double a = E[k] + vsh_test_rnd(-100, 100), w = vsh_test_rnd(0, 100);
        cas.min[k] = a;
        cas.max[k] = a + w;
      }
      cp = &cas;
    }
    vsh_shadow_view v;
    const vsh_csm_status st = vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c,
        .aspect = aspect, .slice_near = n, .slice_far = f, .light_direction = L, .receivers = rp,
        .casters = cp, .stable = stable, .resolution = res}, &v);
    CHECK(st == VSH_CSM_OK || st == VSH_CSM_EMPTY);
    if (st == VSH_CSM_OK) {
      ++fitted;
      double w = 0;
      check_directional(&c, aspect, n, f, rp, cp, stable || !rp, &v, &w);
      if (stable)
        worst_stable = fmax(worst_stable, w);
      else if (!rp)
        worst_tight = fmax(worst_tight, w);
    } else {
      ++skipped;
      /* 1 only when no receiver point is in the slice. */
      CHECK(rp != NULL);
      if (rp) {
        const int N = 8;
        int inside = 0;
        for (int i = 0; i <= N; ++i)
          for (int j = 0; j <= N; ++j)
            for (int k = 0; k <= N; ++k) {
              const double P[3] = {rec.min[0] + (rec.max[0] - rec.min[0]) * i / N,
                                   rec.min[1] + (rec.max[1] - rec.min[1]) * j / N,
                                   rec.min[2] + (rec.max[2] - rec.min[2]) * k / N};
              inside |= in_slice(&c, aspect, n, f, P, 1e-9);
            }
        CHECK(!inside);
      }
    }
  }
  CHECK(fitted > 1000);
  CHECK(skipped > 10);
  CHECK(worst_stable <= 1 + 1e-9);
  CHECK_NEAR(worst_tight, 1, 1e-9);
}

/* The stable fit's map must cover the slice even when the radius sits
 * exactly on the 2^(1/8) grid (no quantization slack) and the centre snap
 * moves the map by up to half a texel. The camera is oriented so that a far
 * corner's offset from the sphere's centre is the world +x axis, and the
 * light travels along -z, so that corner projects at exactly the radius
 * along one of the map's axes. */
static void test_directional_stable_tight_radius(void) {
  /* 90 degrees, aspect 1: r^2 = ((f - n)/2)^2 + 2 t^2 f^2 = 1 with n = f/2. */
  const double f = 4.0 / sqrt(33.0), n = 0.5 * f, t = tan_half(90);
  /* The far corner's offset in camera coordinates (right, up, forward). */
  double a[3] = {f * t, f * t, 0.5 * (f - n)}, b2[3], b3[3];
  vsh_vec3_normalize(a, a);
  vsh_vec3_cross(a, (double[3]){0, 0, 1}, b2);
  vsh_vec3_normalize(b2, b2);
  vsh_vec3_cross(a, b2, b3);
  /* World axes of the camera: a -> +x, b2 -> +y, b3 -> +z. */
  const double fw[3] = {a[2], b2[2], b3[2]}, up[3] = {a[1], b2[1], b3[1]};
  const double L[3] = {0, 0, -1};
  double worst = 0;
  int covered = 1, finite = 1;
  for (int s = 0; s < 600; ++s) {
    const double E[3] = {vsh_test_rnd(-3, 3), vsh_test_rnd(-3, 3), vsh_test_rnd(-3, 3)};
    const vsh_camera c = make_camera(E[0], E[1], E[2], E[0] + fw[0], E[1] + fw[1], E[2] + fw[2],
                                     up[0], up[1], up[2], 90);
    vsh_shadow_view v;
    const int res = (s % 3 == 0) ? 16 : (s % 3 == 1) ? 256 : 2048;
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.0,
        .slice_near = n, .slice_far = f, .light_direction = L, .receivers = NULL, .casters = NULL,
        .stable = 1, .resolution = res}, &v) == VSH_CSM_OK);
    finite &= view_is_finite(&v);
    for (int i = 0; i < 8; ++i) {
      double rel[3], q[3];
      slice_corner(&c, 1.0, n, f, i, rel);
      clip_of(v.world_to_clip, rel, q);
      const double m = fmax(fabs(q[0]), fabs(q[1]));
      worst = fmax(worst, m);
      covered &= m <= 1 + 1e-9;
    }
  }
  if (!covered) fprintf(stderr, "stable tight radius: worst |xy| = %.17g\n", worst);
  CHECK(finite);
  CHECK(covered);
  CHECK(worst > 0.99); /* the construction does reach the map's edge */
}

/* Light-space phase of the texel centres of map v along matrix row `row`
 * (0: x, 1: y), in texels, relative to the world origin: frac((q + a) / texel)
 * for the centre q of texel 0. Also returns the texel size along the row. */
static double texel_phase(const vsh_shadow_view *v, const double origin[3], int row, int res,
                          double *texel_out) {
  const double *m = v->world_to_clip + 4 * row;
  const double s = vsh_vec3_length(m); /* 2 / width */
  double axis[3];
  vsh_vec3_scale(m, 1.0 / s, axis);
  const double width = 2.0 / s, texel = width / res;
  const double clip_centre0 = -1.0 + 1.0 / res;
  const double q = (clip_centre0 - m[3]) / s;       /* camera-relative light coordinate */
  const double anchor = vsh_vec3_dot(origin, axis); /* of the camera position */
  const double cells = (q + anchor) / texel;
  if (texel_out) *texel_out = texel;
  return cells - floor(cells);
}

static double phase_diff(double a, double b) {
  double d = fabs(a - b);
  return fmin(d, 1 - d);
}

static void test_directional_stable(void) {
  const double L[3] = {0.4, -0.8, 0.3};
  const double aspect = 1.6, n = 2, f = 400;
  const int res = 1024;
  /* (1) Width independent of the camera's rotation: yaw 0..360 and pitch. */
  double width0 = 0;
  int first = 1;
  for (int yaw = 0; yaw <= 360; yaw += 15)
    for (int pitch = -80; pitch <= 80; pitch += 40) {
      const double y = yaw * PI / 180, p = pitch * PI / 180;
      const double E[3] = {3, 4, 5};
      const vsh_camera c = make_camera(E[0], E[1], E[2], E[0] + cos(p) * sin(y),
                                       E[1] + sin(p), E[2] - cos(p) * cos(y), 0, 1, 0, 55);
      vsh_shadow_view v;
      CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = aspect,
          .slice_near = n, .slice_far = f, .light_direction = L, .receivers = NULL, .casters = NULL,
          .stable = 1, .resolution = res}, &v) == VSH_CSM_OK);
      check_directional(&c, aspect, n, f, NULL, NULL, 1, &v, NULL);
      const double w = v.texel_world * res;
      if (first) width0 = w, first = 0;
      CHECK(w == width0); /* bit for bit */
      /* Both light-space axes have the same width: square texels. */
      const double sx = vsh_vec3_length(v.world_to_clip), sy = vsh_vec3_length(v.world_to_clip + 4);
      CHECK_NEAR(sx, sy, 1e-12 * sx);
      CHECK_NEAR(2 / sx, w, 1e-12 * w);
    }
  /* The width is at least the slice's bounding sphere's diameter and at
   * most 2^(1/8) times it (geometric quantization). */
  const double t = tan_half(55), half = 0.5 * (f - n);
  const double r0 = sqrt(half * half + f * f * t * t * (1 + aspect * aspect));
  CHECK(width0 >= 2 * r0 * (1 - 1e-12));
  CHECK(width0 <= 2 * r0 * exp2(1.0 / 8) * (1 + 1e-12));
  /* (2) Small changes of the slice depths within one quantization step
   * keep the width; a large change changes it by a power of 2^(1/8). */
  const vsh_camera c0 = make_camera(3, 4, 5, 3.2, 3.9, 4, 0, 1, 0, 55);
  vsh_shadow_view v0, v1;
  CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c0, .aspect = aspect,
      .slice_near = n, .slice_far = f, .light_direction = L, .receivers = NULL, .casters = NULL,
      .stable = 1, .resolution = res}, &v0) == VSH_CSM_OK);
  const double step0 = ceil(8 * log2(r0) - 1e-9);
  int same_step_cases = 0;
  for (int k = -20; k <= 20; ++k) {
    const double n1 = n * (1 + 1e-4 * k), f1 = f * (1 - 3e-5 * k);
    const double h1 = 0.5 * (f1 - n1);
    const double r1 = sqrt(h1 * h1 + f1 * f1 * t * t * (1 + aspect * aspect));
    if (ceil(8 * log2(r1) - 1e-9) != step0) continue;
    ++same_step_cases;
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c0, .aspect = aspect,
        .slice_near = n1, .slice_far = f1, .light_direction = L, .receivers = NULL, .casters = NULL,
        .stable = 1, .resolution = res}, &v1) == VSH_CSM_OK);
    CHECK(v1.texel_world == v0.texel_world);
  }
  CHECK(same_step_cases >= 30);
  CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c0, .aspect = aspect,
      .slice_near = n, .slice_far = f * 1.5, .light_direction = L, .receivers = NULL,
      .casters = NULL, .stable = 1, .resolution = res}, &v1) == VSH_CSM_OK);
  const double steps = 8 * log2(v1.texel_world / v0.texel_world);
  CHECK(steps > 0.5);
  CHECK_NEAR(steps, round(steps), 1e-9);
}

/* The texel grid is anchored to the world: moving the camera by fractions
 * of a texel moves the map by whole texels only, so the world positions of
 * texel centres stay on one lattice; also with everything at 1e6. */
static void test_directional_texel_grid(void) {
  const double lights[][3] = {{0.4, -0.8, 0.3}, {0, -1, 0}, {0, 0, -1}, {1, -1e-3, 0}};
  const double offsets[][3] = {{0, 0, 0}, {1e6, 1e6, 1e6}, {-3e6, 1e6, 2.5e6}};
  const int resolutions[] = {1024, 2048, 1000};
  for (size_t li = 0; li < sizeof lights / sizeof lights[0]; ++li)
    for (size_t oi = 0; oi < sizeof offsets / sizeof offsets[0]; ++oi)
      for (size_t ri = 0; ri < sizeof resolutions / sizeof resolutions[0]; ++ri) {
        const int res = resolutions[ri];
        double ref_phase[2] = {0, 0}, ref_texel = 0;
        double worst = 0, worst_ref = 0;
        int moved = 0;
        double first_m3 = 0, first_m7 = 0, ref_texel_world = 0;
        for (int step = 0; step < 80; ++step) {
          /* Sub-texel moves (texel ~ 1.2 or 0.6 here), ~0.05 of a world unit
           * each, > 2 texels in all. */
          const double E[3] = {offsets[oi][0] + 10 + 0.037 * step,
                               offsets[oi][1] + 5 + 0.029 * step,
                               offsets[oi][2] - 7 - 0.013 * step};
          const vsh_camera c = make_camera(E[0], E[1], E[2], E[0] + 0.3, E[1] - 0.2, E[2] - 1,
                                           0, 1, 0, 60);
          vsh_shadow_view v;
          CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.5,
              .slice_near = 1, .slice_far = 500, .light_direction = lights[li], .receivers = NULL,
              .casters = NULL, .stable = 1, .resolution = res}, &v) == VSH_CSM_OK);
          CHECK(view_is_finite(&v));
          check_directional(&c, 1.5, 1, 500, NULL, NULL, 1, &v, NULL);
          for (int row = 0; row < 2; ++row) {
            double texel;
            const double ph = texel_phase(&v, c.position, row, res, &texel);
            if (step == 0) {
              ref_phase[row] = ph;
              ref_texel = texel;
              /* Even resolutions put the texel boundaries on the lattice k
               * texel, the centres at half-integers. */
              if (res % 2 == 0) worst_ref = fmax(worst_ref, phase_diff(ph, 0.5));
            }
            worst = fmax(worst, phase_diff(ph, ref_phase[row]));
            CHECK_NEAR(texel, ref_texel, 1e-12 * ref_texel);
            if (step > 0) CHECK(v.texel_world == ref_texel_world);
          }
          if (step == 0) {
            first_m3 = v.world_to_clip[3];
            first_m7 = v.world_to_clip[7];
            ref_texel_world = v.texel_world;
          }
          /* One texel is 2 / res in clip units. */
          moved |= fabs(v.world_to_clip[3] - first_m3) > 1.0 / res ||
                   fabs(v.world_to_clip[7] - first_m7) > 1.0 / res;
        }
        /* 1e-9 of a texel up to 1e6 from the origin; further out the
         * world coordinates themselves (ulp(4e6) = 4.7e-10, texel 0.6 at
         * res 2048) limit what double can resolve. */
        const double far_ =
            fmax(fabs(offsets[oi][0]), fmax(fabs(offsets[oi][1]), fabs(offsets[oi][2])));
        const double tol = 1e-9 * fmax(1.0, far_ / 1e6);
        if (worst > tol || worst_ref > tol || !moved)
          fprintf(stderr, "texel grid: light %zu offset %zu res %d: drift %.3g ref %.3g moved %d\n",
                  li, oi, res, worst, worst_ref, moved);
        CHECK(worst <= tol);
        CHECK(worst_ref <= tol);
        CHECK(moved); /* the camera moved > 2 texels: the map followed */
      }
}

static void test_directional_degenerate(void) {
  vsh_shadow_view v;
  const vsh_bounds floor_ = box(-100, 100, 0, 0, -100, 100);
  const vsh_bounds stuff = box(-3, 3, 0, 6, -3, 3);
  /* Light travelling exactly along the camera's forward axis. */
  const vsh_camera fwd = make_camera(1, 5, 20, 1, 5, 0, 0, 1, 0, 45);
  const double along[3] = {0, 0, -1};
  for (int stable = 0; stable <= 1; ++stable) {
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &fwd, .aspect = 1.3,
        .slice_near = 0.5, .slice_far = 30, .light_direction = along, .receivers = NULL,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_OK);
    check_directional(&fwd, 1.3, 0.5, 30, NULL, &stuff, 1, &v, NULL);
    /* Looking straight down with the sun straight down (a top view). */
    const vsh_camera topv = make_camera(2, 50, 3, 2, 0, 3, 0, 0, -1, 45);
    const double down[3] = {0, -2, 0};
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &topv, .aspect = 1.3,
        .slice_near = 1, .slice_far = 60, .light_direction = down, .receivers = &floor_,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_OK);
    check_directional(&topv, 1.3, 1, 60, &floor_, &stuff, stable, &v, NULL);
    /* ... and the light coming against the view direction. */
    const double up[3] = {0, 1, 0};
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &topv, .aspect = 1.3,
        .slice_near = 1, .slice_far = 60, .light_direction = up, .receivers = NULL,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_OK);
    check_directional(&topv, 1.3, 1, 60, NULL, &stuff, 1, &v, NULL);
    /* A light nearly (1e-12) off a world axis. */
    const double almost[3] = {1e-12, -1, 0};
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &topv, .aspect = 1.3,
        .slice_near = 1, .slice_far = 60, .light_direction = almost, .receivers = &floor_,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_OK);
    check_directional(&topv, 1.3, 1, 60, &floor_, &stuff, stable, &v, NULL);
    /* Zero-volume receivers: a floor (done above), a point in the slice,
     * a segment. */
    const vsh_camera c = make_camera(0, 3, 10, 0, 0, 0, 0, 1, 0, 50);
    const double sun[3] = {0.3, -1, -0.2};
    const vsh_bounds point = box(0.5, 0.5, 0, 0, 1, 1);
    const vsh_csm_status sp = vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c,
        .aspect = 1.3, .slice_near = 1, .slice_far = 30, .light_direction = sun,
        .receivers = &point, .casters = &stuff, .stable = stable, .resolution = 1024}, &v);
    CHECK(sp == VSH_CSM_OK);
    if (sp == VSH_CSM_OK) check_directional(&c, 1.3, 1, 30, &point, &stuff, stable, &v, NULL);
    const vsh_bounds seg = box(-2, 2, 0, 0, 1, 1);
    const vsh_csm_status ss = vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c,
        .aspect = 1.3, .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = &seg,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v);
    CHECK(ss == VSH_CSM_OK);
    if (ss == VSH_CSM_OK) check_directional(&c, 1.3, 1, 30, &seg, &stuff, stable, &v, NULL);
    /* Casters NULL and receivers NULL. */
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.3,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.3, 1, 30, NULL, NULL, 1, &v, NULL);
    /* A zero-volume caster (a point) at the receivers' level. */
    const vsh_bounds cpt = box(0, 0, 0, 0, 0, 0);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.3,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = &floor_,
        .casters = &cpt, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_OK);
    check_directional(&c, 1.3, 1, 30, &floor_, &cpt, stable, &v, NULL);
    /* Receivers not overlapping the slice: 1. */
    const vsh_bounds away = box(500, 600, -50, -40, 500, 600);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.3,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = &away,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_EMPTY);
    const vsh_bounds behind = box(-1, 1, -1, 1, 200, 210);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.3,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = &behind,
        .casters = &stuff, .stable = stable, .resolution = 1024}, &v) == VSH_CSM_EMPTY);
    /* Resolution 1 and 2: still finite and covering. */
    for (int res = 1; res <= 2; ++res) {
      CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1.3,
          .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
          .casters = NULL, .stable = stable, .resolution = res}, &v) == VSH_CSM_OK);
      check_directional(&c, 1.3, 1, 30, NULL, NULL, 1, &v, NULL);
    }
  }
}

static void test_directional_bad_input(void) {
  vsh_shadow_view v;
  const vsh_camera c = make_camera(0, 3, 10, 0, 0, 0, 0, 1, 0, 50);
  const double sun[3] = {0.3, -1, -0.2};
  const double zero[3] = {0, 0, 0}, nanl[3] = {NAN, -1, 0}, infl[3] = {INFINITY, -1, 0};
  const double tiny[3] = {1e-300, -1e-300, 0}; /* tiny but a direction */
  for (int stable = 0; stable <= 1; ++stable) {
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = zero, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = nanl, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = infl, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = NULL, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = tiny, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_OK);
    CHECK(view_is_finite(&v));
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = NULL, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, NULL) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 0,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = NAN,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = INFINITY,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 0, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = -1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 30, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 30, .slice_far = 1, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = NAN, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = NAN, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = INFINITY, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = 0}, &v) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = NULL, .stable = stable, .resolution = -4}, &v) == VSH_CSM_BAD_INPUT);
    const vsh_camera bad[] = {make_camera(0, 0, 0, 0, -1, 0, 0, 1, 0, 50),
                              make_camera(1, 1, 1, 1, 1, 1, 0, 1, 0, 50),
                              make_camera(0, 3, 10, 0, 0, 0, 0, 1, 0, 0),
                              make_camera(0, 3, 10, 0, 0, 0, 0, 1, 0, 180),
                              make_camera(0, 3, 10, 0, 0, 0, 0, 1, 0, NAN)};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
      CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &bad[k], .aspect = 1,
          .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
          .casters = NULL, .stable = stable, .resolution = 512}, &v) == VSH_CSM_BAD_INPUT);
    /* Non-finite receivers or casters are bad input, not NaN matrices. */
    const vsh_bounds nanb = box(NAN, 1, 0, 1, 0, 1), infb = box(-INFINITY, 1, 0, 1, 0, 1);
    vsh_csm_status st = vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = &nanb,
        .casters = NULL, .stable = stable, .resolution = 512}, &v);
    CHECK(st == VSH_CSM_BAD_INPUT || (st == VSH_CSM_OK && view_is_finite(&v)));
    st = vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = NULL,
        .casters = &infb, .stable = stable, .resolution = 512}, &v);
    CHECK(st == VSH_CSM_BAD_INPUT || (st == VSH_CSM_OK && view_is_finite(&v)));
    st = vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = 1,
        .slice_near = 1, .slice_far = 30, .light_direction = sun, .receivers = &infb,
        .casters = NULL, .stable = stable, .resolution = 512}, &v);
    CHECK(st == VSH_CSM_BAD_INPUT || (st == VSH_CSM_OK && view_is_finite(&v)));
  }
}

/* ---- perspective fit ------------------------------------------------------ */

static void test_perspective(void) {
  vsh_shadow_view v;
  int cases = 0;
  for (int s = 0; s < 500; ++s) {
    double P[3], D[3], O[3];
    for (int k = 0; k < 3; ++k) {
      P[k] = vsh_test_rnd(-20, 20);
      O[k] = P[k] + vsh_test_rnd(-30, 30);
    }
    vsh_test_rnd_unit(D);
    const double half = vsh_test_rnd(5, 85);
    const int res = 512;
    /* Bounds: a box in front of the light. */
    double Cn[3];
    const double dist = vsh_test_rnd(2, 50);
    for (int k = 0; k < 3; ++k) Cn[k] = P[k] + dist * D[k];
    const double w = vsh_test_rnd(0, 0.5) * dist;
    vsh_bounds b = box(Cn[0] - w, Cn[0] + w, Cn[1] - w, Cn[1] + w * vsh_test_rnd(0, 1), Cn[2] - w,
                       Cn[2] + w);
    const vsh_csm_status st = vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P,
        .direction = D, .half_angle_deg = half, .bounds = &b, .origin = O, .resolution = res}, &v);
    double corners[8][3];
    vsh_bounds_corners(&b, corners);
    double dmin = INFINITY;
    for (int k = 0; k < 8; ++k) {
      double rel[3];
      vsh_vec3_sub(corners[k], P, rel);
      dmin = fmin(dmin, vsh_vec3_dot(rel, D));
    }
    CHECK(st == VSH_CSM_OK);
    if (st != VSH_CSM_OK) continue;
    ++cases;
    CHECK(view_is_finite(&v));
    CHECK(v.perspective == 1);
    CHECK(v.near_far[0] > 0 && v.near_far[1] > v.near_far[0]);
    CHECK_NEAR(v.depth_extent, v.near_far[1] - v.near_far[0], 1e-12 * v.near_far[1]);
    CHECK_NEAR(v.texel_world, 2 * tan_half(2 * half) / res, 1e-14);
    /* Bounds corners: in front (w > 0) with clip z in [-1, 1] (when the
     * nearest corner is not closer than the 1e4 depth-ratio floor). */
    for (int k = 0; k < 8; ++k) {
      double q[3];
      const double ww = clip_world(v.world_to_clip, O, corners[k], q);
      CHECK(ww > 0);
      if (dmin > 1e-3 * v.near_far[1]) CHECK(q[2] >= -1 - 1e-9 && q[2] <= 1 + 1e-9);
    }
    /* The light's axis maps to the centre at w = distance. */
    double on_axis[3], q[3];
    for (int k = 0; k < 3; ++k) on_axis[k] = P[k] + 7 * D[k];
    const double wa = clip_world(v.world_to_clip, O, on_axis, q);
    CHECK_NEAR(wa, 7, 1e-9);
    CHECK(fabs(q[0]) < 1e-9 && fabs(q[1]) < 1e-9);
    /* near/far distances map to -1 and +1. */
    for (int e = 0; e < 2; ++e) {
      double p[3];
      for (int k = 0; k < 3; ++k) p[k] = P[k] + v.near_far[e] * D[k];
      clip_world(v.world_to_clip, O, p, q);
      CHECK_NEAR(q[2], e ? 1 : -1, 1e-8);
    }
    /* Points on the cone at the half angle: x^2 + y^2 = 1 (so |x| = 1 or
     * |y| = 1 along the map's axes). */
    for (int j = 0; j < 4; ++j) {
      double e[3], tmp[3], a[3], p[3];
      vsh_test_rnd_unit(a);
      vsh_vec3_cross(D, a, tmp);
      if (vsh_vec3_normalize(tmp, e) == 0) continue;
      const double dd = vsh_test_rnd(1, 40), tn = tan(half * PI / 180);
      for (int k = 0; k < 3; ++k) p[k] = P[k] + dd * (D[k] + tn * e[k]);
      const double wp = clip_world(v.world_to_clip, O, p, q);
      CHECK(wp > 0);
      CHECK_NEAR(hypot(q[0], q[1]), 1, 1e-10);
    }
    /* ... and along the map's own x axis (row 0): |x| = 1, y = 0. */
    double ax[3], p[3];
    vsh_vec3_normalize(v.world_to_clip, ax);
    const double tn = tan(half * PI / 180);
    for (int k = 0; k < 3; ++k) p[k] = P[k] + 3 * (D[k] + tn * ax[k]);
    clip_world(v.world_to_clip, O, p, q);
    CHECK_NEAR(fabs(q[0]), 1, 1e-10);
    CHECK(fabs(q[1]) < 1e-10);
    vsh_vec3_normalize(v.world_to_clip + 4, ax);
    for (int k = 0; k < 3; ++k) p[k] = P[k] + 3 * (D[k] - tn * ax[k]);
    clip_world(v.world_to_clip, O, p, q);
    CHECK_NEAR(fabs(q[1]), 1, 1e-10);
    CHECK(fabs(q[0]) < 1e-10);
  }
  CHECK(cases > 400);
}

static void test_perspective_offset_and_degenerate(void) {
  vsh_shadow_view v, w;
  const double P[3] = {1, 2, 3}, D[3] = {0.2, -1, 0.1}, O[3] = {4, 5, 6};
  const vsh_bounds b = box(-5, 5, -10, -2, -5, 5);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &b, .origin = O, .resolution = 1024}, &v) == VSH_CSM_OK);
  /* Everything shifted by 1e6: the same camera-relative matrix. */
  const double s[3] = {1e6, -2e6, 1e6};
  double P2[3], O2[3];
  vsh_vec3_add(P, s, P2);
  vsh_vec3_add(O, s, O2);
  const vsh_bounds b2 = shifted(b, s);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P2, .direction = D,
      .half_angle_deg = 40, .bounds = &b2, .origin = O2, .resolution = 1024}, &w) == VSH_CSM_OK);
  for (int k = 0; k < 16; ++k) CHECK_NEAR(w.world_to_clip[k], v.world_to_clip[k], 1e-8);
  CHECK_NEAR(w.near_far[0], v.near_far[0], 1e-9 * v.near_far[0]);
  CHECK_NEAR(w.near_far[1], v.near_far[1], 1e-9 * v.near_far[1]);
  /* Bounds straddling the light: near is the 1e-4 floor, still finite. */
  const vsh_bounds around = box(-10, 10, -10, 10, -10, 10);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &around, .origin = O, .resolution = 1024}, &v) == VSH_CSM_OK);
  CHECK(view_is_finite(&v));
  CHECK_NEAR(v.near_far[0], 1e-4 * v.near_far[1], 1e-12 * v.near_far[1]);
  /* Zero-volume bounds: a point in front, a floor below. */
  const vsh_bounds pt = box(1, 1, -5, -5, 3, 3);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &pt, .origin = O, .resolution = 1024}, &v) == VSH_CSM_OK);
  CHECK(view_is_finite(&v));
  double q[3];
  CHECK(clip_world(v.world_to_clip, O, pt.min, q) > 0);
  CHECK(q[2] >= -1 && q[2] <= 1);
  const vsh_bounds flo = box(-50, 50, -3, -3, -50, 50);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &flo, .origin = O, .resolution = 1024}, &v) == VSH_CSM_OK);
  CHECK(view_is_finite(&v));
  /* All bounds behind the light: 1. Touching its plane from behind: 1. */
  const vsh_bounds behind = box(-5, 5, 10, 20, -5, 5);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P,
      .direction = (double[3]){0, -1, 0}, .half_angle_deg = 40, .bounds = &behind, .origin = O,
      .resolution = 1024}, &v) == VSH_CSM_EMPTY);
  const vsh_bounds touching = box(-5, 5, 2, 20, -5, 5);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P,
      .direction = (double[3]){0, -1, 0}, .half_angle_deg = 40, .bounds = &touching, .origin = O,
      .resolution = 1024}, &v) == VSH_CSM_EMPTY);
  /* Bad input: 2. */
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 0, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 90, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 120, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = -10, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = NAN, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = INFINITY, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P,
      .direction = (double[3]){0, 0, 0}, .half_angle_deg = 40, .bounds = &b, .origin = O,
      .resolution = 1024}, &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P,
      .direction = (double[3]){NAN, 0, 1}, .half_angle_deg = 40, .bounds = &b, .origin = O,
      .resolution = 1024}, &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = (double[3]){NAN, 0, 0},
      .direction = D, .half_angle_deg = 40, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &b, .origin = (double[3]){0, INFINITY, 0},
      .resolution = 1024}, &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &b, .origin = O, .resolution = 0}, &v) == VSH_CSM_BAD_INPUT);
  vsh_bounds empty;
  vsh_bounds_init_empty(&empty);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &empty, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  const vsh_bounds nanb = box(NAN, 1, 0, 1, 0, 1);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &nanb, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = NULL, .direction = D,
      .half_angle_deg = 40, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = NULL,
      .half_angle_deg = 40, .bounds = &b, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = NULL, .origin = O, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &b, .origin = NULL, .resolution = 1024},
      &v) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = P, .direction = D,
      .half_angle_deg = 40, .bounds = &b, .origin = O, .resolution = 1024},
      NULL) == VSH_CSM_BAD_INPUT);
}

static void test_cube_faces(void) {
  static const double want[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    double d[3];
    vsh_csm_cube_face_direction(f, d);
    CHECK(d[0] == want[f][0] && d[1] == want[f][1] && d[2] == want[f][2]);
  }
  /* Out of range: still a unit axis, never garbage. */
  const int bad[] = {-1, 6, 7, INT_MAX, INT_MIN};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    double d[3] = {NAN, NAN, NAN};
    vsh_csm_cube_face_direction(bad[k], d);
    CHECK(vsh_vec3_is_finite(d));
    CHECK(fabs(d[0]) + fabs(d[1]) + fabs(d[2]) == 1);
    CHECK(vsh_vec3_length(d) == 1);
  }
  /* The 6 faces at 45 degrees cover every direction. */
  const double L[3] = {3, -2, 7}, O[3] = {0, 0, 0};
  const vsh_bounds around = box(-7, 13, -12, 8, -3, 17);
  vsh_shadow_view faces[6];
  for (int f = 0; f < 6; ++f) {
    double d[3];
    vsh_csm_cube_face_direction(f, d);
    CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = L, .direction = d,
        .half_angle_deg = 45, .bounds = &around, .origin = O, .resolution = 256},
        &faces[f]) == VSH_CSM_OK);
    CHECK(view_is_finite(&faces[f]));
  }
  int all_covered = 1, multiply = 0;
  for (int s = 0; s < 20000; ++s) {
    double u[3], p[3];
    if (s < 8) { /* the cube's corners: the worst directions */
      u[0] = (s & 1) ? 1 : -1;
      u[1] = (s & 2) ? 1 : -1;
      u[2] = (s & 4) ? 1 : -1;
      vsh_vec3_normalize(u, u);
    } else {
      vsh_test_rnd_unit(u);
    }
    const double dist = vsh_test_rnd(0.5, 8);
    for (int k = 0; k < 3; ++k) p[k] = L[k] + dist * u[k];
    int covered = 0;
    for (int f = 0; f < 6; ++f) {
      double q[3];
      const double w = clip_world(faces[f].world_to_clip, O, p, q);
      if (w > 0 && fabs(q[0]) <= 1 + 1e-12 && fabs(q[1]) <= 1 + 1e-12) ++covered;
    }
    all_covered &= covered >= 1;
    multiply += covered > 1;
  }
  CHECK(all_covered);
  CHECK(multiply >= 8); /* the corners sit on three faces' edges */
}

static void test_perspective_depth_terms(void) {
  /* The near plane maps to ndc -1, the far plane to +1, as the fitted
   * matrix does; anything but a perspective view with a depth range gives
   * zeros. */
  const double pos[3] = {0, 0, 10}, down[3] = {0, 0, -1}, origin[3] = {1, 2, 3};
  const vsh_bounds b = box(-1, 1, -1, 1, 0, 2);
  vsh_shadow_view v;
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = pos, .direction = down,
      .half_angle_deg = 30.0, .bounds = &b, .origin = origin, .resolution = 512},
      &v) == VSH_CSM_OK);
  double t[2];
  vsh_csm_perspective_depth_terms(&v, t);
  CHECK_NEAR(-t[0] + t[1] / v.near_far[0], -1.0, 1e-12);
  CHECK_NEAR(-t[0] + t[1] / v.near_far[1], 1.0, 1e-12);
  /* The same as the matrix: a point on the axis at distance d. */
  for (double d = v.near_far[0]; d <= v.near_far[1]; d += 0.25) {
    const double p[3] = {pos[0] - origin[0], pos[1] - origin[1], pos[2] - d - origin[2]};
    double q[3];
    clip_of(v.world_to_clip, p, q);
    CHECK_NEAR(q[2], -t[0] + t[1] / d, 1e-12);
  }
  vsh_shadow_view flat = v;
  flat.perspective = 0;
  vsh_csm_perspective_depth_terms(&flat, t);
  CHECK(t[0] == 0.0 && t[1] == 0.0);
  flat = v;
  flat.near_far[1] = flat.near_far[0];
  vsh_csm_perspective_depth_terms(&flat, t);
  CHECK(t[0] == 0.0 && t[1] == 0.0);
  vsh_csm_perspective_depth_terms(NULL, t);
  CHECK(t[0] == 0.0 && t[1] == 0.0);
}

int main(void) {
  test_directional_basic();
  test_directional_random();
  test_directional_stable_tight_radius();
  test_directional_stable();
  test_directional_texel_grid();
  test_directional_degenerate();
  test_directional_bad_input();
  test_perspective();
  test_perspective_offset_and_degenerate();
  test_cube_faces();
  test_perspective_depth_terms();
  return vsh_check_report("core.csm_fit");
}
