/* test_csm_split.c - unit tests of vsh_csm_split.c: split depths against
 * their closed forms (with and without a far/near ratio per cascade), the
 * default cascade count, and the visible depth range (exact clipping
 * against known answers, degenerate and bad input, far from the origin,
 * dense sampling). */
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
  return vsh_check_report("core.csm_split");
}
