/* test_csm_error.c - unit tests of vsh_csm_error.c (and the status names of
 * vsh_csm_status.c): the texel-size measure, bias, and the resolution/count
 * chooser and the perspective resolution against a brute-force search. */
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
  test_texel_pixels();
  test_bias();
  test_choose();
  test_perspective_resolution();
  return vsh_check_report("core.csm_error");
}
