/* test_csm.c - unit tests of vsh_csm: split depths against their closed
 * forms, the default cascade count, the visible depth range (exact clipping
 * against known answers and dense sampling), directional fits (coverage of
 * the slice, depth range reaching the casters, stability under camera
 * rotation and sub-texel translation, a world-anchored texel grid at 1e6),
 * perspective fits (cone boundary, depth range, cube-face coverage), the
 * texel-size measure, bias and the resolution/count chooser against a brute
 * force search. Every degenerate input the header names is included: light
 * parallel to the view direction, zero-volume bounds, empty scenes. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_csm.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- helpers ------------------------------------------------------------ */

static vsh_camera make_camera(double ex, double ey, double ez, double fx, double fy, double fz,
                              double ux, double uy, double uz, double angle) {
  vsh_camera c = {{ex, ey, ez}, {fx, fy, fz}, {ux, uy, uz}, angle};
  return c;
}

/* A camera at E looking along the unit direction dir (random non-parallel up). */
static vsh_camera camera_looking(const double E[3], const double dir[3], double angle) {
  double up[3];
  do {
    vsh_test_rnd_unit(up);
  } while (vsh_vec3_parallel(up, dir, 0.2));
  return make_camera(E[0], E[1], E[2], E[0] + dir[0], E[1] + dir[1], E[2] + dir[2], up[0], up[1],
                     up[2], angle);
}

static vsh_bounds box(double x0, double x1, double y0, double y1, double z0, double z1) {
  vsh_bounds b = {{x0, y0, z0}, {x1, y1, z1}};
  return b;
}

static double tan_half(double angle_deg) { return tan(angle_deg * 0.5 * PI / 180.0); }

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

/* ---- splits ------------------------------------------------------------- */

static void check_split_invariants(const double *s, int count, double n, double f) {
  CHECK(s[0] == n);
  CHECK(s[count] == f);
  for (int i = 0; i < count; ++i) CHECK(s[i + 1] > s[i]);
}

/* PRACTICAL with max_ratio: where the count allows it, every cascade's
 * far/near stays within the ratio, the splits never fall below the
 * logarithmic ones, and they equal the plain blend wherever the blend keeps
 * the ratio anyway; where the count cannot (ratio^count < f/n) or no ratio
 * is given, the result is the plain blend. Bad ratios are refused. */
static void test_splits_max_ratio(void) {
  vsh_test_seed(4242);
  for (int trial = 0; trial < 4000; ++trial) {
    const double n = pow(10.0, vsh_test_rnd(-6.0, 3.0));
    const double f = n * pow(10.0, vsh_test_rnd(0.01, 7.0));
    const double ratio = vsh_test_rnd(1.5, 50.0);
    const double lambda = vsh_test_rnd(0.0, 1.0);
    const int count = 1 + (int)(vsh_test_rnd(0.0, 1.0) * VSH_CSM_MAX_CASCADES) %
                              VSH_CSM_MAX_CASCADES;
    double capped[VSH_CSM_MAX_CASCADES + 1], plain[VSH_CSM_MAX_CASCADES + 1];
    CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = count,
        .near_depth = n, .far_depth = f, .lambda = lambda, .max_ratio = ratio}, capped) ==
          VSH_CSM_OK);
    CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = count,
        .near_depth = n, .far_depth = f, .lambda = lambda}, plain) == VSH_CSM_OK);
    check_split_invariants(capped, count, n, f);
    const int reachable = count * log(ratio) >= log(f / n);
    for (int i = 1; i <= count; ++i) {
      const double logarithmic = n * pow(f / n, (double)i / count);
      if (!reachable) {
        CHECK(capped[i] == plain[i]);
        continue;
      }
      CHECK(capped[i] / capped[i - 1] <= ratio * (1 + 1e-12));
      CHECK(capped[i] >= logarithmic * (1 - 1e-12));
      CHECK(capped[i] <= plain[i]);
      if (plain[i] <= capped[i - 1] * ratio)
        CHECK(capped[i] == plain[i]);
    }
  }
  /* The near-far-1e5 shape: 6 cascades of ratio 8 over [1, 1e5], lambda
   * 0.75: the plain blend's first cascade is ~4000 deep, the capped one 8. */
  double s[VSH_CSM_MAX_CASCADES + 1];
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = 6,
      .near_depth = 1, .far_depth = 1e5, .lambda = 0.75}, s) == VSH_CSM_OK);
  CHECK(s[1] > 4000);
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = 6,
      .near_depth = 1, .far_depth = 1e5, .lambda = 0.75, .max_ratio = 8}, s) == VSH_CSM_OK);
  CHECK_NEAR(s[1], 8.0, 1e-12);
  const double bad[] = {-1.0, 0.5, 1.0, NAN, INFINITY};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    s[0] = -7;
    CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = 3,
        .near_depth = 1, .far_depth = 100, .lambda = 0.5, .max_ratio = bad[k]}, s) ==
          VSH_CSM_BAD_INPUT);
    CHECK(s[0] == -7); /* untouched */
  }
}

static void test_splits_closed_forms(void) {
  const double ranges[][2] = {{1, 100}, {0.1, 1000}, {1e-3, 1e6}, {5, 6}, {0.5, 0.5000001}};
  for (size_t q = 0; q < sizeof ranges / sizeof ranges[0]; ++q) {
    const double n = ranges[q][0], f = ranges[q][1];
    for (int c = 1; c <= VSH_CSM_MAX_CASCADES; ++c) {
      double u[VSH_CSM_MAX_CASCADES + 1], l[VSH_CSM_MAX_CASCADES + 1];
      double p0[VSH_CSM_MAX_CASCADES + 1], p1[VSH_CSM_MAX_CASCADES + 1];
      double ph[VSH_CSM_MAX_CASCADES + 1];
      CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_UNIFORM, .count = c,
          .near_depth = n, .far_depth = f, .lambda = 0.0, .fractions = NULL}, u) == VSH_CSM_OK);
      CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_LOG, .count = c,
          .near_depth = n, .far_depth = f, .lambda = 0.0, .fractions = NULL}, l) == VSH_CSM_OK);
      CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = c,
          .near_depth = n, .far_depth = f, .lambda = 0.0, .fractions = NULL}, p0) == VSH_CSM_OK);
      CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = c,
          .near_depth = n, .far_depth = f, .lambda = 1.0, .fractions = NULL}, p1) == VSH_CSM_OK);
      CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = c,
          .near_depth = n, .far_depth = f, .lambda = 0.5, .fractions = NULL}, ph) == VSH_CSM_OK);
      check_split_invariants(u, c, n, f);
      check_split_invariants(l, c, n, f);
      check_split_invariants(p0, c, n, f);
      check_split_invariants(p1, c, n, f);
      check_split_invariants(ph, c, n, f);
      for (int i = 0; i <= c; ++i) {
        const double x = (double)i / c;
        const double wu = n + (f - n) * x, wl = n * pow(f / n, x);
        CHECK_NEAR(u[i], wu, 1e-15 * f);
        CHECK_NEAR(l[i], wl, 1e-14 * wl);
        CHECK_NEAR(l[i] / n, exp(x * log(f / n)), 1e-13 * l[i] / n); /* n (f/n)^x */
        CHECK_NEAR(p0[i], wu, 1e-15 * f); /* lambda 0: uniform */
        CHECK_NEAR(p1[i], wl, 1e-14 * wl); /* lambda 1: logarithmic */
        CHECK_NEAR(ph[i], 0.5 * (wu + wl), 1e-14 * f);
        /* The log split is below the uniform one (f/n > 1): PSSM in between. */
        CHECK(l[i] <= u[i] * (1 + 1e-15));
        CHECK(ph[i] >= l[i] * (1 - 1e-15) && ph[i] <= u[i] * (1 + 1e-15));
      }
    }
  }
  /* Exact decades: log over [1, 1e4] in 4 steps. */
  double s[VSH_CSM_MAX_CASCADES + 1];
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_LOG, .count = 4, .near_depth = 1,
      .far_depth = 1e4, .lambda = 0, .fractions = NULL}, s) == VSH_CSM_OK);
  CHECK_NEAR(s[1], 10, 1e-13);
  CHECK_NEAR(s[2], 100, 1e-12);
  CHECK_NEAR(s[3], 1000, 1e-11);
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_UNIFORM, .count = 4,
      .near_depth = 2, .far_depth = 10, .lambda = 0, .fractions = NULL}, s) == VSH_CSM_OK);
  CHECK(s[0] == 2 && s[1] == 4 && s[2] == 6 && s[3] == 8 && s[4] == 10);
  /* Uniform ignores lambda (only PRACTICAL reads it). */
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_UNIFORM, .count = 4,
      .near_depth = 2, .far_depth = 10, .lambda = 7.0, .fractions = NULL}, s) == VSH_CSM_OK);
  CHECK(s[2] == 6);
  /* Explicit fractions. */
  const double fr[3] = {0.1, 0.3, 0.7};
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_EXPLICIT, .count = 4,
      .near_depth = 10, .far_depth = 110, .lambda = 0, .fractions = fr}, s) == VSH_CSM_OK);
  check_split_invariants(s, 4, 10, 110);
  CHECK_NEAR(s[1], 20, 1e-13);
  CHECK_NEAR(s[2], 40, 1e-13);
  CHECK_NEAR(s[3], 80, 1e-13);
  /* Explicit with one cascade reads no fractions. */
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_EXPLICIT, .count = 1,
      .near_depth = 10, .far_depth = 110, .lambda = 0, .fractions = fr}, s) == VSH_CSM_OK);
  CHECK(s[0] == 10 && s[1] == 110);
  /* All 8 explicit. */
  const double fr8[7] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8};
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_EXPLICIT, .count = 8,
      .near_depth = 1, .far_depth = 101, .lambda = 0, .fractions = fr8}, s) == VSH_CSM_OK);
  check_split_invariants(s, 8, 1, 101);
  for (int i = 1; i < 8; ++i) CHECK_NEAR(s[i], 1 + 100 * fr8[i - 1], 1e-13);
  /* Seeded random lambdas: monotone and between log and uniform. */
  for (int k = 0; k < 500; ++k) {
    const double n = exp(vsh_test_rnd(log(1e-3), log(10))), f = n * exp(vsh_test_rnd(0.01, log(1e6)));
    const int c = 1 + (int)vsh_test_rnd(0, 8);
    const double lam = vsh_test_rnd(0, 1);
    double p[VSH_CSM_MAX_CASCADES + 1];
    CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_PRACTICAL, .count = c,
        .near_depth = n, .far_depth = f, .lambda = lam, .fractions = NULL}, p) == VSH_CSM_OK);
    check_split_invariants(p, c, n, f);
  }
}

static void test_splits_bad_input(void) {
  const double good_fr[3] = {0.2, 0.5, 0.8};
  const double not_inc[3] = {0.2, 0.2, 0.8}, dec[3] = {0.2, 0.6, 0.4};
  const double at0[3] = {0.0, 0.5, 0.8}, at1[3] = {0.2, 0.5, 1.0}, neg[3] = {-0.1, 0.5, 0.8};
  const double big[3] = {0.2, 0.5, 1.5}, nanf[3] = {0.2, NAN, 0.8};
  struct {
    vsh_split_scheme scheme;
    int count;
    double n, f, lambda;
    const double *fr;
  } cases[] = {
      {VSH_SPLIT_UNIFORM, 0, 1, 100, 0, NULL},
      {VSH_SPLIT_UNIFORM, -1, 1, 100, 0, NULL},
      {VSH_SPLIT_UNIFORM, 9, 1, 100, 0, NULL},
      {VSH_SPLIT_LOG, INT_MAX, 1, 100, 0, NULL},
      {VSH_SPLIT_LOG, 4, 0, 100, 0, NULL},
      {VSH_SPLIT_LOG, 4, -1, 100, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, -1, 100, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, 100, 100, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, 100, 10, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, NAN, 100, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, 1, NAN, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, 1, INFINITY, 0, NULL},
      {VSH_SPLIT_LOG, 4, 1, INFINITY, 0, NULL},
      {VSH_SPLIT_UNIFORM, 4, INFINITY, INFINITY, 0, NULL},
      {VSH_SPLIT_PRACTICAL, 4, 1, 100, -0.01, NULL},
      {VSH_SPLIT_PRACTICAL, 4, 1, 100, 1.01, NULL},
      {VSH_SPLIT_PRACTICAL, 4, 1, 100, NAN, NULL},
      {VSH_SPLIT_PRACTICAL, 4, 1, 100, INFINITY, NULL},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, NULL},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, not_inc},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, dec},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, at0},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, at1},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, neg},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, big},
      {VSH_SPLIT_EXPLICIT, 4, 1, 100, 0, nanf},
      {VSH_SPLIT_EXPLICIT, 4, 0, 100, 0, good_fr},
      {(vsh_split_scheme)4, 4, 1, 100, 0, good_fr},
      {(vsh_split_scheme)-1, 4, 1, 100, 0, good_fr},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    double out[VSH_CSM_MAX_CASCADES + 2];
    for (int i = 0; i < VSH_CSM_MAX_CASCADES + 2; ++i) out[i] = -7.25;
    const vsh_csm_status st = vsh_csm_splits(&(vsh_csm_split_params){.scheme = cases[k].scheme,
        .count = cases[k].count, .near_depth = cases[k].n, .far_depth = cases[k].f,
        .lambda = cases[k].lambda, .fractions = cases[k].fr}, out);
    if (st == VSH_CSM_OK) fprintf(stderr, "splits bad case %zu accepted\n", k);
    CHECK(st == VSH_CSM_BAD_INPUT);
    int untouched = 1;
    for (int i = 0; i < VSH_CSM_MAX_CASCADES + 2; ++i) untouched &= out[i] == -7.25;
    CHECK(untouched);
  }
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_UNIFORM, .count = 4,
      .near_depth = 1, .far_depth = 100, .lambda = 0, .fractions = NULL}, NULL) != VSH_CSM_OK);
  /* The good explicit fractions are accepted (so the cases above fail for
   * the reason they name). */
  double out[VSH_CSM_MAX_CASCADES + 1];
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_EXPLICIT, .count = 4,
      .near_depth = 1, .far_depth = 100, .lambda = 0, .fractions = good_fr}, out) == VSH_CSM_OK);
}

/* ---- default count -------------------------------------------------------- */

static void test_default_count(void) {
  CHECK(vsh_csm_default_count(1, 8, 8) == 1);
  CHECK(vsh_csm_default_count(0.25, 2, 8) == 1);
  CHECK(vsh_csm_default_count(1, 64, 8) == 2);
  CHECK(vsh_csm_default_count(0.1, 6.4, 8) == 2); /* 64 with rounding in the ratio */
  CHECK(vsh_csm_default_count(1, 65, 8) == 3);
  CHECK(vsh_csm_default_count(1, 1.0001, 8) == 1);
  CHECK(vsh_csm_default_count(1, 1e6, 8) == 7); /* log8(1e6) = 6.64 */
  CHECK(vsh_csm_default_count(1, 1e6, 2) == 8); /* 19.9: clamped */
  CHECK(vsh_csm_default_count(1, 1e9, 8) == 8); /* 9.97: clamped */
  CHECK(vsh_csm_default_count(1e-3, 1e300, 1.5) == 8);
  for (int k = 1; k <= 8; ++k) {
    const double r = pow(8, k);
    CHECK(vsh_csm_default_count(1, r, 8) == k);
    CHECK(vsh_csm_default_count(0.5, 0.5 * r, 8) == k);
    CHECK(vsh_csm_default_count(3, 3 * r * 1.001, 8) == (k + 1 > 8 ? 8 : k + 1));
    CHECK(vsh_csm_default_count(3, 3 * r * 0.999, 8) == k);
  }
  /* Bad input: 1. */
  const double bad[][3] = {{1, 1, 8},     {1, 0.5, 8},   {0, 10, 8},      {-1, 10, 8},
                           {NAN, 10, 8},  {1, NAN, 8},   {1, INFINITY, 8}, {1, 100, 1},
                           {1, 100, 0.5}, {1, 100, -8},  {1, 100, NAN},
                           {INFINITY, INFINITY, 8}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    CHECK(vsh_csm_default_count(bad[k][0], bad[k][1], bad[k][2]) == 1);
  CHECK(vsh_csm_default_count(1, 100, INFINITY) == 1); /* one cascade covers any ratio */
}

/* ---- visible depth range -------------------------------------------------- */

/* Camera at the origin looking down -z, +y up (so depth = -z, right = +x). */
static vsh_camera axis_camera(double angle) {
  return make_camera(0, 0, 0, 0, 0, -1, 0, 1, 0, angle);
}

static vsh_bounds shifted(vsh_bounds b, const double s[3]) {
  for (int k = 0; k < 3; ++k) {
    b.min[k] += s[k];
    b.max[k] += s[k];
  }
  return b;
}

static vsh_camera shifted_camera(vsh_camera c, const double s[3]) {
  for (int k = 0; k < 3; ++k) {
    c.position[k] += s[k];
    c.focal_point[k] += s[k];
  }
  return c;
}

static void test_visible_depth_known(void) {
  double nf[2];
  const vsh_camera c60 = axis_camera(60), c90 = axis_camera(90);
  const double t90 = tan_half(90);
  /* Fully inside: exactly the corner depths. */
  vsh_bounds b = box(-1, 1, -0.5, 0.5, -20, -5);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 5 && nf[1] == 20);
  /* Straddling the near plane (and the eye): clipped to clip_near. */
  b = box(-0.1, 0.1, -0.1, 0.1, -20, 5);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 0.1, 1e-15);
  CHECK(nf[1] == 20);
  /* Beyond the far plane: clipped to clip_far. */
  b = box(-1, 1, -1, 1, -200, -50);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 50);
  CHECK_NEAR(nf[1], 100, 1e-13);
  /* A long thin box along the view axis, partly outside the LEFT plane
   * (aspect 2, 90 degrees: visible where x >= -2 t d): its inner edge
   * x = -3.8 enters at depth 1.9 / t. */
  b = box(-4, -3.8, -0.1, 0.1, -10, -1);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 2.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 1.9 / t90, 1e-13);
  CHECK(nf[1] == 10);
  /* ... and mirrored outside the RIGHT plane. */
  b = box(3.8, 4, -0.1, 0.1, -10, -1);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 2.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 1.9 / t90, 1e-13);
  CHECK(nf[1] == 10);
  /* ... above the TOP plane (y <= t d, aspect does not matter). */
  b = box(-0.1, 0.1, 2.5, 2.7, -10, -1);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 3.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 2.5 / t90, 1e-13);
  CHECK(nf[1] == 10);
  /* ... below the BOTTOM plane. */
  b = box(-0.1, 0.1, -2.7, -2.5, -10, -1);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 0.5,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 2.5 / t90, 1e-13);
  /* Box in a corner: must pass BOTH the right and the top plane:
   * x = 3 enters at 3 / (t a), y = 5 at 5 / t; the later one wins. */
  b = box(3, 3.5, 5, 5.5, -30, -1);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 1.5,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 5 / t90, 1e-13);
  CHECK(nf[1] == 30);
  /* A box whose near face is partly outside: the visible depth is the
   * clipped polygon's (the far face is inside, the side face x = -3 enters
   * at depth 3 / t). */
  b = box(-3, 0, -0.1, 0.1, -6, -2);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 2); /* the near face's part with x >= -2 t is inside */
  CHECK(nf[1] == 6);
  /* The camera inside a big box: [clip_near, the far face]. */
  b = box(-10, 10, -10, 10, -10, 10);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c90, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 0.1, 1e-15);
  CHECK(nf[1] == 10);
  /* A box containing the whole view frustum: [clip_near, clip_far]. */
  b = box(-1e4, 1e4, -1e4, 1e4, -1e4, 1e4);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.5,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 0.1, 1e-15);
  CHECK_NEAR(nf[1], 100, 1e-13);
  /* A slab crossing the whole view at depths 30..40 (no corner visible). */
  b = box(-1e4, 1e4, -1e4, 1e4, -40, -30);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.5,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 30 && nf[1] == 40);
  /* A box containing the far part of the frustum only. */
  b = box(-1e4, 1e4, -1e4, 1e4, -1e4, -30);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.5,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 30);
  CHECK_NEAR(nf[1], 100, 1e-13);
}

/* Zero-volume boxes (floors, walls, points, segments) and nothing visible. */
static void test_visible_depth_degenerate(void) {
  double nf[2];
  const vsh_camera c60 = axis_camera(60);
  /* Zero-volume: a flat floor 1 below the eye, 60 degrees: the bottom plane
   * y >= -t d meets it at d = 1 / t; its far edge (z = -50) is inside. */
  vsh_bounds b = box(-50, 50, -1, -1, -50, 50);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 1 / tan_half(60), 1e-13);
  CHECK(nf[1] == 50);
  /* A flat wall facing the camera: a single depth. */
  b = box(-1, 1, -1, 1, -7, -7);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 7 && nf[1] == 7);
  /* ... and much larger than the view: still a single depth. */
  b = box(-1e3, 1e3, -1e3, 1e3, -7, -7);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 7 && nf[1] == 7);
  /* A single point inside / outside. */
  b = box(0.3, 0.3, -0.2, -0.2, -7, -7);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK(nf[0] == 7 && nf[1] == 7);
  b = box(30, 30, -0.2, -0.2, -7, -7);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_EMPTY);
  /* A line segment along the view axis. */
  b = box(0, 0, 0, 0, -9, 4);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60, .aspect = 1.0,
      .clip_near = 0.5, .clip_far = 1000, .bounds = &b}, nf) == VSH_CSM_OK);
  CHECK_NEAR(nf[0], 0.5, 1e-15);
  CHECK(nf[1] == 9);
  /* Nothing visible: 1. */
  const vsh_bounds invisible[] = {
      box(-1, 1, -1, 1, 5, 10),          /* behind the camera */
      box(-100, -90, -1, 1, -10, -5),    /* left of the frustum */
      box(-1, 1, 50, 60, -10, -5),       /* above */
      box(-1, 1, -1, 1, -300, -200),     /* beyond clip_far */
      box(-0.01, 0.01, 0, 0, -0.05, -0.01), /* between the eye and clip_near */
      box(-50, 50, -1, -1, 0.5, 50),     /* a floor behind the eye */
  };
  for (size_t k = 0; k < sizeof invisible / sizeof invisible[0]; ++k) {
    const vsh_csm_status st = vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c60,
        .aspect = 1.0, .clip_near = 0.1, .clip_far = 100, .bounds = &invisible[k]}, nf);
    if (st != VSH_CSM_EMPTY) fprintf(stderr, "invisible case %zu: %d\n", k, st);
    CHECK(st == VSH_CSM_EMPTY);
  }
}

static void test_visible_depth_bad_input(void) {
  double nf[2];
  const vsh_camera good = axis_camera(60);
  const vsh_bounds b = box(-1, 1, -1, 1, -10, -5);
  vsh_bounds empty;
  vsh_bounds_init_empty(&empty);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &empty}, nf) == VSH_CSM_BAD_INPUT);
  const vsh_bounds nanb = box(NAN, 1, -1, 1, -10, -5), infb = box(-1, INFINITY, -1, 1, -10, -5);
  const vsh_bounds inverted = box(1, -1, -1, 1, -10, -5);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &nanb}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &infb}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &inverted}, nf) == VSH_CSM_BAD_INPUT);
  const vsh_camera bad_cams[] = {
      make_camera(0, 0, 0, 0, 0, -1, 0, 0, 1, 60),   /* view_up parallel */
      make_camera(0, 0, 0, 0, 0, -1, 0, 0, -3, 60),  /* anti-parallel */
      make_camera(0, 0, 0, 0, 0, 0, 0, 1, 0, 60),    /* position == focal point */
      make_camera(0, 0, 0, 0, 0, -1, 0, 0, 0, 60),   /* zero view_up */
      make_camera(NAN, 0, 0, 0, 0, -1, 0, 1, 0, 60), /* NaN position */
      make_camera(0, 0, 0, 0, 0, -1, 0, 1, 0, 0),    /* zero angle */
      make_camera(0, 0, 0, 0, 0, -1, 0, 1, 0, 180),
      make_camera(0, 0, 0, 0, 0, -1, 0, 1, 0, NAN),
      make_camera(0, 0, 0, 0, 0, -1, 0, 1, 0, -30),
  };
  for (size_t k = 0; k < sizeof bad_cams / sizeof bad_cams[0]; ++k)
    CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &bad_cams[k],
        .aspect = 1.0, .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 0.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = -1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = NAN,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good,
      .aspect = INFINITY, .clip_near = 0.1, .clip_far = 100, .bounds = &b},
      nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.0, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = -1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = NAN, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 0.1, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 0.05, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = NAN, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = INFINITY, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = NULL, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = NULL}, nf) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, NULL) == VSH_CSM_BAD_INPUT);
  /* ... and the good call works. */
  CHECK(vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &good, .aspect = 1.0,
      .clip_near = 0.1, .clip_far = 100, .bounds = &b}, nf) == VSH_CSM_OK);
}

/* Translating the camera and the box together by 1e6 changes nothing. */
static void test_visible_depth_offset(void) {
  const double shifts[][3] = {{1e6, 1e6, 1e6}, {-1e6, 2e6, 3e6}, {1e6, 0, 0}};
  const vsh_bounds boxes[] = {
      box(-1, 1, -0.5, 0.5, -20, -5), box(-0.1, 0.1, -0.1, 0.1, -20, 5),
      box(-4, -3.8, -0.1, 0.1, -10, -1), box(-50, 50, -1, -1, -50, 50),
      box(0.25, 0.25, -0.5, -0.5, -7, -7), box(-10, 10, -10, 10, -10, 10)};
  const vsh_camera cams[] = {axis_camera(60), axis_camera(90),
                             make_camera(0, 0, 0, 0.25, -0.125, -1, 0, 1, 0.25, 75)};
  for (size_t s = 0; s < sizeof shifts / sizeof shifts[0]; ++s)
    for (size_t c = 0; c < sizeof cams / sizeof cams[0]; ++c)
      for (size_t k = 0; k < sizeof boxes / sizeof boxes[0]; ++k) {
        double a[2], b[2];
        const vsh_csm_status sa = vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &cams[c],
            .aspect = 1.5, .clip_near = 0.1, .clip_far = 100, .bounds = &boxes[k]}, a);
        const vsh_camera cs = shifted_camera(cams[c], shifts[s]);
        const vsh_bounds bs = shifted(boxes[k], shifts[s]);
        const vsh_csm_status sb = vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &cs,
            .aspect = 1.5, .clip_near = 0.1, .clip_far = 100, .bounds = &bs}, b);
        CHECK(sa == sb);
        if (sa == VSH_CSM_OK && sb == VSH_CSM_OK) {
          CHECK_NEAR(a[0], b[0], 1e-9 * a[0]);
          CHECK_NEAR(a[1], b[1], 1e-9 * a[1]);
        }
      }
}

/* Random cameras and boxes against dense sampling of the box's faces: every
 * sampled visible point lies in the range, and the range is not wider than
 * the samples (up to the sampling step). */
static void test_visible_depth_sampled(void) {
  int visible_cases = 0;
  for (int s = 0; s < 300; ++s) {
    double E[3], dir[3];
    for (int k = 0; k < 3; ++k) E[k] = vsh_test_rnd(-5, 5);
    vsh_test_rnd_unit(dir);
    const vsh_camera c = camera_looking(E, dir, vsh_test_rnd(20, 120));
    const double aspect = vsh_test_rnd(0.5, 2.5), cn = vsh_test_rnd(0.05, 1), cf = cn * vsh_test_rnd(5, 100);
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      const double a = vsh_test_rnd(-15, 15), w = vsh_test_rnd(0, 1) < 0.2 ? 0 : vsh_test_rnd(0, 10);
      lo[k] = a;
      hi[k] = a + w;
    }
    const vsh_bounds b = box(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
    double nf[2] = {0, 0};
    const vsh_csm_status st = vsh_csm_visible_depth_range(&(vsh_csm_depth_range_params){.camera = &c,
        .aspect = aspect, .clip_near = cn, .clip_far = cf, .bounds = &b}, nf);
    CHECK(st == VSH_CSM_OK || st == VSH_CSM_EMPTY);
    double r[3], u[3], f[3];
    vsh_camera_basis(&c, r, u, f);
    const double t = tan_half(c.view_angle);
    const int N = 40;
    double smin = INFINITY, smax = -INFINITY;
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      for (int i = 0; i <= N; ++i)
        for (int j = 0; j <= N; ++j) {
          double P[3], rel[3];
          P[axis] = (face & 1) ? hi[axis] : lo[axis];
          const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
          P[a1] = lo[a1] + (hi[a1] - lo[a1]) * i / N;
          P[a2] = lo[a2] + (hi[a2] - lo[a2]) * j / N;
          vsh_vec3_sub(P, c.position, rel);
          const double d = vsh_vec3_dot(rel, f);
          if (d < cn || d > cf || fabs(vsh_vec3_dot(rel, r)) > t * aspect * d ||
              fabs(vsh_vec3_dot(rel, u)) > t * d)
            continue;
          smin = fmin(smin, d);
          smax = fmax(smax, d);
        }
    }
    if (smin <= smax) {
      ++visible_cases;
      CHECK(st == VSH_CSM_OK);
      if (st != VSH_CSM_OK) continue;
      const double tol = 1e-9 * cf;
      CHECK(nf[0] <= smin + tol && nf[1] >= smax - tol);
      CHECK(nf[0] >= cn && nf[1] <= cf && nf[0] <= nf[1]);
      /* Not wider than the samples: one sampling step of slack. */
      const double step = vsh_bounds_diagonal_length(&b) / N * 2 + tol;
      CHECK(nf[0] >= smin - step);
      CHECK(nf[1] <= smax + step);
    }
  }
  CHECK(visible_cases > 30);
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

/* ---- texel size, bias ----------------------------------------------------- */

static void test_texel_pixels(void) {
  /* texel / (2 d tan(a/2) / H). */
  const double want = 0.1 / (2 * 10 * tan(30 * PI / 180) / 1000);
  CHECK_NEAR(vsh_csm_texel_pixels(0.1, 10, 60, 1000), want, 1e-13 * want);
  CHECK_NEAR(want, 8.660254037844386, 1e-12);
  /* 90 degrees, H = 2: pixel world size at depth 1 is 1. */
  CHECK_NEAR(vsh_csm_texel_pixels(1, 1, 90, 2), 1, 1e-15);
  for (int s = 0; s < 200; ++s) {
    const double tw = exp(vsh_test_rnd(-8, 3)), d = exp(vsh_test_rnd(-3, 8)), a = vsh_test_rnd(1, 170);
    const int H = 1 + (int)vsh_test_rnd(0, 4000);
    const double w = tw * H / (2 * d * tan(a * PI / 360));
    const double got = vsh_csm_texel_pixels(tw, d, a, H);
    CHECK_NEAR(got, w, 1e-13 * w);
    /* Linear in texel and H, inverse in depth. */
    CHECK_NEAR(vsh_csm_texel_pixels(2 * tw, d, a, H), 2 * got, 1e-13 * got);
    CHECK_NEAR(vsh_csm_texel_pixels(tw, 2 * d, a, H), 0.5 * got, 1e-13 * got);
  }
  const double bad[][3] = {{0, 10, 60},  {-1, 10, 60},       {NAN, 10, 60}, {INFINITY, 10, 60},
                           {1, 0, 60},   {1, -10, 60},       {1, NAN, 60},  {1, INFINITY, 60},
                           {1, 10, 0},   {1, 10, 180},       {1, 10, -5},   {1, 10, NAN},
                           {1, 10, 200}, {1, 10, INFINITY}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    CHECK(vsh_csm_texel_pixels(bad[k][0], bad[k][1], bad[k][2], 1000) == 0);
  CHECK(vsh_csm_texel_pixels(1, 10, 60, 0) == 0);
  CHECK(vsh_csm_texel_pixels(1, 10, 60, -100) == 0);
}

static void test_bias(void) {
  double db, no;
  vsh_csm_bias(0.02, 50, 1, &db, &no);
  CHECK_NEAR(db, 0.5 * 0.02 / 50, 1e-18);
  CHECK_NEAR(no, 1.5 * 0.02, 1e-17);
  /* Proportional to the texel and the scale. */
  double db2, no2;
  vsh_csm_bias(0.04, 50, 1, &db2, &no2);
  CHECK_NEAR(db2, 2 * db, 1e-18);
  CHECK_NEAR(no2, 2 * no, 1e-17);
  vsh_csm_bias(0.02, 50, 3, &db2, &no2);
  CHECK_NEAR(db2, 3 * db, 1e-18);
  CHECK_NEAR(no2, 3 * no, 1e-17);
  vsh_csm_bias(0.02, 100, 1, &db2, &no2); /* deeper range: smaller normalized bias */
  CHECK_NEAR(db2, 0.5 * db, 1e-18);
  CHECK_NEAR(no2, no, 1e-17);
  /* Scale 0: no bias. */
  vsh_csm_bias(0.02, 50, 0, &db2, &no2);
  CHECK(db2 == 0 && no2 == 0);
  /* Scale NaN (and Inf, negative): falls back to 1. */
  const double fallback[] = {NAN, INFINITY, -INFINITY};
  for (size_t k = 0; k < sizeof fallback / sizeof fallback[0]; ++k) {
    vsh_csm_bias(0.02, 50, fallback[k], &db2, &no2);
    CHECK(db2 == db && no2 == no);
  }
  vsh_csm_bias(0.02, 50, -2, &db2, &no2);
  CHECK(isfinite(db2) && isfinite(no2) && db2 >= 0 && no2 >= 0);
  /* Zero / negative / NaN / Inf texel or depth range: 0, never NaN. */
  const double bad[][2] = {{0, 50},    {-0.02, 50}, {NAN, 50}, {INFINITY, 50}, {0.02, 0},
                           {0.02, -50}, {0.02, NAN}, {0.02, INFINITY}, {NAN, NAN}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    for (int sc = 0; sc < 2; ++sc) {
      db2 = no2 = NAN;
      vsh_csm_bias(bad[k][0], bad[k][1], sc ? NAN : 1.0, &db2, &no2);
      CHECK(db2 == 0 && no2 == 0);
    }
  /* NULL outputs are allowed. */
  vsh_csm_bias(0.02, 50, 1, NULL, &no2);
  CHECK(no2 == no);
  vsh_csm_bias(0.02, 50, 1, &db2, NULL);
  CHECK(db2 == db);
  vsh_csm_bias(0.02, 50, 1, NULL, NULL);
}

/* ---- choose ----------------------------------------------------------------- */

/* The worst on-screen texel size of `count` log cascades at resolution
 * `res`, with the texel sizes taken from the stable directional fit itself. */
static double predicted_px(double n, double f, double angle, double aspect, int H, int res,
                           int count) {
  double s[VSH_CSM_MAX_CASCADES + 1];
  if (vsh_csm_splits(&(vsh_csm_split_params){.scheme = VSH_SPLIT_LOG, .count = count,
      .near_depth = n, .far_depth = f, .lambda = 0, .fractions = NULL},
      s) != VSH_CSM_OK) return INFINITY;
  const vsh_camera c = make_camera(1, 2, 3, 1.5, 1.75, 2, 0, 1, 0, angle);
  const double L[3] = {0.2, -1, 0.4};
  double worst = 0;
  for (int i = 0; i < count; ++i) {
    vsh_shadow_view v;
    if (vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &c, .aspect = aspect,
        .slice_near = s[i], .slice_far = s[i + 1], .light_direction = L, .receivers = NULL,
        .casters = NULL, .stable = 1, .resolution = res}, &v) != VSH_CSM_OK)
      return INFINITY;
    worst = fmax(worst, vsh_csm_texel_pixels(v.texel_world, s[i], angle, H));
  }
  return worst;
}

static int is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

static void check_choose(double n, double f, double angle, double aspect, int H, double target,
                         long long budget, int min_res, int max_res, int max_count) {
  vsh_csm_choice choice = {-1, -1, -1};
  const vsh_csm_status st = vsh_csm_choose(
      &(vsh_csm_choose_params){.near_depth = n, .far_depth = f, .view_angle_deg = angle,
                               .aspect = aspect, .viewport_height = H, .max_texel_px = target,
                               .budget_bytes = budget, .min_res = min_res, .max_res = max_res,
                               .max_count = max_count},
      &choice);
  const int res = choice.resolution, count = choice.count;
  const double px = choice.texel_px;
  /* Brute force over the documented space. */
  double best_mem = INFINITY, best_px_any = INFINITY;
  int any_in_budget = 0;
  const int mc = max_count > VSH_CSM_MAX_CASCADES ? VSH_CSM_MAX_CASCADES : max_count;
  for (int cnt = 1; cnt <= mc; ++cnt)
    for (long long r = 1; r <= max_res; r *= 2) {
      if (r < min_res) continue;
      const double mem = 4.0 * cnt * (double)r * (double)r;
      if (mem > (double)budget) continue;
      any_in_budget = 1;
      const double p = predicted_px(n, f, angle, aspect, H, (int)r, cnt);
      best_px_any = fmin(best_px_any, p);
      if (p <= target) best_mem = fmin(best_mem, mem);
    }
  CHECK(st == VSH_CSM_OK || st == VSH_CSM_TARGET_MISSED);
  CHECK(is_pow2(res) && res >= min_res && res <= max_res);
  CHECK(count >= 1 && count <= mc);
  CHECK(isfinite(px));
  const double mem = 4.0 * count * (double)res * (double)res;
  const double p = predicted_px(n, f, angle, aspect, H, res, count);
  if (isfinite(best_mem)) {
    if (st != VSH_CSM_OK)
      fprintf(stderr, "choose: target %g reachable with %g bytes but status %s\n", target,
              best_mem, vsh_csm_status_name(st));
    CHECK(st == VSH_CSM_OK);
    CHECK(p <= target * (1 + 1e-12));
    CHECK(mem == best_mem);
  } else {
    CHECK(st == VSH_CSM_TARGET_MISSED);
  }
  if (any_in_budget) {
    CHECK(mem <= (double)budget);
    CHECK_NEAR(px, p, 1e-9 * p);
    /* When the target is out of reach: the best achievable within budget. */
    if (st == VSH_CSM_TARGET_MISSED) CHECK(p <= best_px_any * (1 + 1e-12));
  }
}

static void test_choose(void) {
  /* Generous budgets: the cheapest config that meets the target. */
  const double targets[] = {0.5, 1, 2, 4, 10};
  for (size_t k = 0; k < sizeof targets / sizeof targets[0]; ++k) {
    check_choose(0.1, 1000, 60, 1.6, 1080, targets[k], 1LL << 34, 256, 8192, 8);
    check_choose(1, 100, 45, 1.0, 720, targets[k], 1LL << 30, 512, 4096, 4);
    check_choose(0.5, 5000, 90, 2.0, 1440, targets[k], 1LL << 28, 128, 4096, 6);
  }
  /* Tiny budget: one min_res map fits, the target does not. */
  check_choose(0.1, 1000, 60, 1.6, 1080, 1, 4LL * 256 * 256, 256, 8192, 8);
  vsh_csm_choice c;
  const vsh_csm_choose_params wide = {.near_depth = 0.1, .far_depth = 1000, .view_angle_deg = 60,
                                      .aspect = 1.6, .viewport_height = 1080, .max_texel_px = 1,
                                      .budget_bytes = 4LL * 256 * 256, .min_res = 256,
                                      .max_res = 8192, .max_count = 8};
  CHECK(vsh_csm_choose(&wide, &c) == VSH_CSM_TARGET_MISSED);
  CHECK(c.resolution == 256 && c.count == 1 && c.texel_px > 1);
  /* A budget below a single min_res map: the target is missed, finite outputs. */
  vsh_csm_choose_params poor = wide;
  poor.budget_bytes = 1000;
  CHECK(vsh_csm_choose(&poor, &c) == VSH_CSM_TARGET_MISSED);
  CHECK(c.resolution >= 1 && c.count >= 1 && isfinite(c.texel_px));
  poor.budget_bytes = -5;
  CHECK(vsh_csm_choose(&poor, &c) == VSH_CSM_TARGET_MISSED);
  CHECK(c.resolution >= 1 && c.count >= 1 && isfinite(c.texel_px));
  /* min_res / max_res not powers of two: the resolution is one in range. */
  check_choose(1, 100, 45, 1.0, 720, 2, 1LL << 30, 300, 3000, 4);
  check_choose(1, 100, 45, 1.0, 720, 0.5, 1LL << 30, 100, 5000, 8);
  /* max_count above the maximum: clamped. */
  check_choose(0.1, 1e4, 60, 1.6, 1080, 1, 1LL << 34, 256, 8192, 20);
  /* Random cases. */
  for (int s = 0; s < 40; ++s) {
    const double n = exp(vsh_test_rnd(log(0.01), log(5))), f = n * exp(vsh_test_rnd(1, log(1e5)));
    const int minr = 1 << (int)vsh_test_rnd(6, 10), maxr = minr << (int)vsh_test_rnd(0, 5);
    check_choose(n, f, vsh_test_rnd(30, 100), vsh_test_rnd(0.75, 2.5), 400 + (int)vsh_test_rnd(0, 2000), vsh_test_rnd(0.3, 8),
                 (long long)exp(vsh_test_rnd(log(1e5), log(1e10))), minr, maxr, 1 + (int)vsh_test_rnd(0, 8));
  }
  /* Bad input: BAD_INPUT with finite, usable outputs. */
  struct {
    double n, f, angle, aspect;
    int H;
    double target;
    int min_res, max_res, max_count;
  } bad[] = {
      {0, 100, 60, 1, 1000, 1, 256, 4096, 4},     {-1, 100, 60, 1, 1000, 1, 256, 4096, 4},
      {NAN, 100, 60, 1, 1000, 1, 256, 4096, 4},   {1, 1, 60, 1, 1000, 1, 256, 4096, 4},
      {1, INFINITY, 60, 1, 1000, 1, 256, 4096, 4}, {1, NAN, 60, 1, 1000, 1, 256, 4096, 4},
      {1, 100, 0, 1, 1000, 1, 256, 4096, 4},      {1, 100, 180, 1, 1000, 1, 256, 4096, 4},
      {1, 100, NAN, 1, 1000, 1, 256, 4096, 4},    {1, 100, 60, 0, 1000, 1, 256, 4096, 4},
      {1, 100, 60, NAN, 1000, 1, 256, 4096, 4},   {1, 100, 60, INFINITY, 1000, 1, 256, 4096, 4},
      {1, 100, 60, 1, 0, 1, 256, 4096, 4},
      {1, 100, 60, 1, 1000, 0, 256, 4096, 4},     {1, 100, 60, 1, 1000, NAN, 256, 4096, 4},
      {1, 100, 60, 1, 1000, -1, 256, 4096, 4},    {1, 100, 60, 1, 1000, 1, 0, 4096, 4},
      {1, 100, 60, 1, 1000, 1, -256, 4096, 4},    {1, 100, 60, 1, 1000, 1, 4096, 256, 4},
      {1, 100, 60, 1, 1000, 1, 256, 4096, 0},     {1, 100, 60, 1, 1000, 1, 256, 4096, -3},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    c.resolution = c.count = -7;
    c.texel_px = NAN;
    const vsh_csm_status st = vsh_csm_choose(
        &(vsh_csm_choose_params){.near_depth = bad[k].n, .far_depth = bad[k].f,
                                 .view_angle_deg = bad[k].angle, .aspect = bad[k].aspect,
                                 .viewport_height = bad[k].H, .max_texel_px = bad[k].target,
                                 .budget_bytes = 1LL << 30, .min_res = bad[k].min_res,
                                 .max_res = bad[k].max_res, .max_count = bad[k].max_count},
        &c);
    CHECK(st == VSH_CSM_BAD_INPUT);
    CHECK(c.resolution >= 1 && c.count >= 1 && c.count <= VSH_CSM_MAX_CASCADES &&
          isfinite(c.texel_px));
  }
  /* No power of two in [min_res, max_res]: BAD_INPUT, finite outputs. */
  vsh_csm_choose_params small = {.near_depth = 1, .far_depth = 100, .view_angle_deg = 60,
                                 .aspect = 1, .viewport_height = 1000, .max_texel_px = 1,
                                 .budget_bytes = 1LL << 30, .min_res = 300, .max_res = 500,
                                 .max_count = 4};
  CHECK(vsh_csm_choose(&small, &c) == VSH_CSM_BAD_INPUT);
  CHECK(c.resolution >= 1 && c.count >= 1 && isfinite(c.texel_px));
  /* NULL outputs are allowed (and do not change the answer). */
  small.max_texel_px = 4;
  small.min_res = 256;
  small.max_res = 4096;
  CHECK(vsh_csm_choose(&small, &c) == VSH_CSM_OK);
  CHECK(vsh_csm_choose(&small, NULL) == VSH_CSM_OK);
  small.max_texel_px = 0.01;
  CHECK(vsh_csm_choose(&small, NULL) == VSH_CSM_TARGET_MISSED);
  CHECK(vsh_csm_choose(NULL, &c) == VSH_CSM_BAD_INPUT);
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

/* vsh_csm_perspective_resolution's answer for a map of half angle `half`
 * whose texel at `dist` from the light is seen at view depth `depth` (fov
 * degrees, h pixels high), and its status in *status. */
static int perspective_resolution(double half, double dist, double depth, double fov, int h,
                                  double target, int min_res, int max_res,
                                  vsh_csm_status *status) {
  int res = -1;
  *status = vsh_csm_perspective_resolution(
      &(vsh_csm_resolution_params){.half_angle_deg = half, .light_distance = dist,
                                   .view_depth = depth, .view_angle_deg = fov,
                                   .viewport_height = h, .max_texel_px = target,
                                   .min_res = min_res, .max_res = max_res},
      &res);
  return res;
}

static void test_perspective_resolution(void) {
  vsh_csm_status st;
  /* Closed form: a 45-degree half angle, light 10 away, seen at depth 10
   * with a 90-degree view on 512 px, target 1 px: need 512. */
  CHECK(perspective_resolution(45.0, 10.0, 10.0, 90.0, 512, 1.0, 16, 8192, &st) == 512);
  CHECK(st == VSH_CSM_OK);
  CHECK(perspective_resolution(45.0, 10.0, 10.0, 90.0, 513, 1.0, 16, 8192, &st) == 1024);
  CHECK(st == VSH_CSM_OK);
  CHECK(perspective_resolution(45.0, 10.0, 10.0, 90.0, 512, 2.0, 16, 8192, &st) == 256);
  CHECK(st == VSH_CSM_OK);
  /* The result meets the target, and half of it does not (when above min). */
  for (int i = 0; i < 200; ++i) {
    const double half = vsh_test_rnd(5.0, 80.0), dist = vsh_test_rnd(0.1, 100.0), depth = vsh_test_rnd(0.1, 100.0);
    const double fov = vsh_test_rnd(10.0, 120.0), target = vsh_test_rnd(0.5, 5.0);
    const int h = (int)vsh_test_rnd(100.0, 2000.0);
    const int res = perspective_resolution(half, dist, depth, fov, h, target, 64, 8192, &st);
    const double px = 2.0 * tan(half * PI / 180.0) * dist / res /
                      (2.0 * depth * tan(fov * PI / 360.0) / h);
    CHECK(res >= 64 && res <= 8192);
    CHECK(px <= target * (1 + 1e-12) || res == 8192);
    CHECK(st == VSH_CSM_OK || (st == VSH_CSM_TARGET_MISSED && res == 8192));
    if (res > 64) {
      CHECK(2.0 * px > target * (1 - 1e-12));
    }
  }
  /* Bad input: min_res back. */
  CHECK(perspective_resolution(90.0, 1.0, 1.0, 60.0, 100, 1.0, 256, 4096, &st) == 256);
  CHECK(st == VSH_CSM_BAD_INPUT);
  CHECK(perspective_resolution(45.0, 0.0, 1.0, 60.0, 100, 1.0, 256, 4096, &st) == 256);
  CHECK(st == VSH_CSM_BAD_INPUT);
  CHECK(perspective_resolution(45.0, 1.0, NAN, 60.0, 100, 1.0, 256, 4096, &st) == 256);
  CHECK(st == VSH_CSM_BAD_INPUT);
  CHECK(perspective_resolution(45.0, 1.0, 1.0, 60.0, 0, 1.0, 256, 4096, &st) == 256);
  CHECK(st == VSH_CSM_BAD_INPUT);
  CHECK(perspective_resolution(45.0, 1.0, 1.0, 60.0, 100, 0.0, 256, 4096, &st) == 256);
  CHECK(st == VSH_CSM_BAD_INPUT);
  CHECK(perspective_resolution(45.0, 1.0, 1.0, 60.0, 100, 1.0, 512, 256, &st) == 512);
  CHECK(st == VSH_CSM_BAD_INPUT);
  /* Far beyond reach: max_res. */
  CHECK(perspective_resolution(45.0, 1e9, 1e-3, 60.0, 1000, 1.0, 16, 4096, &st) == 4096);
  CHECK(st == VSH_CSM_TARGET_MISSED);
}

int main(void) {
  test_splits_closed_forms();
  test_splits_max_ratio();
  test_splits_bad_input();
  test_default_count();
  test_visible_depth_known();
  test_visible_depth_degenerate();
  test_visible_depth_bad_input();
  test_visible_depth_offset();
  test_visible_depth_sampled();
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
  test_texel_pixels();
  test_bias();
  test_choose();
  test_perspective_resolution();
  test_perspective_depth_terms();
  return vsh_check_report("core.csm");
}
