/* test_rt_adaptive.c - unit tests of vsh_rt_adaptive: the size of the first
 * batch (degenerate sample counts, adaptivity off), the order of the
 * spiral's indices (a permutation whose batch covers the whole disk, unlike
 * the spiral's first indices), the decision to trace the rest (all agree,
 * mixed), and the expected rays per pixel for the cost model. */
#include "vsh_check.h"
#include "vsh_raytrace.h"
#include "vsh_rt_adaptive.h"

#include <math.h>

#define PI 3.14159265358979323846

static void test_first(void)
{
  CHECK(vsh_rt_adaptive_first(64, 1, 8) == 8);
  CHECK(vsh_rt_adaptive_first(64, 0, 8) == 64); /* adaptivity off: always N */
  CHECK(vsh_rt_adaptive_first(1, 1, 8) == 1);   /* hard light */
  CHECK(vsh_rt_adaptive_first(5, 1, 8) == 5);   /* samples < batch */
  CHECK(vsh_rt_adaptive_first(8, 1, 8) == 8);   /* samples == batch: nothing left */
  CHECK(vsh_rt_adaptive_first(9, 1, 8) == 8);
  CHECK(vsh_rt_adaptive_first(64, 1, 0) == 64); /* no batch */
  CHECK(vsh_rt_adaptive_first(0, 1, 8) == 1);
  CHECK(vsh_rt_adaptive_first(-3, 0, 8) == 1);
  CHECK(vsh_rt_adaptive_first(1024, 7, VSH_RT_ADAPTIVE_BATCH) == VSH_RT_ADAPTIVE_BATCH);
}

/* The largest distance from a point of the unit disk to its nearest
 * sample among `count` spiral indices idx[] of an n-point spiral. */
static double cover_radius(const int *idx, int count, int n)
{
  double worst = 0;
  for (int a = 0; a < 64; ++a) {
    for (int r = 1; r <= 16; ++r) {
      const double rho = r / 16.0, phi = 2 * PI * a / 64;
      const double x = rho * cos(phi), y = rho * sin(phi);
      double best = 1e9;
      for (int j = 0; j < count; ++j) {
        double q[2];
        vsh_rt_disk_sample(idx[j], n, 0.0, q);
        best = fmin(best, hypot(q[0] - x, q[1] - y));
      }
      worst = fmax(worst, best);
    }
  }
  return worst;
}

static void test_order(void)
{
  static int order[1024], seen[1024];
  const int cases[][2] = { { 64, 8 }, { 9, 8 }, { 16, 8 }, { 256, 8 }, { 1024, 8 }, { 100, 7 },
    { 1, 1 }, { 5, 8 }, { 64, 64 }, { 64, 0 }, { 1024, 1 } };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
    const int n = cases[c][0], first = cases[c][1];
    CHECK(vsh_rt_adaptive_order(n, first, order) == 0);
    for (int k = 0; k < n; ++k) {
      seen[k] = 0;
    }
    int ok = 1;
    for (int k = 0; k < n; ++k) {
      ok = ok && order[k] >= 0 && order[k] < n && !seen[order[k]];
      if (order[k] >= 0 && order[k] < n) {
        seen[order[k]] = 1;
      }
    }
    CHECK(ok); /* a permutation: the penumbra pixel traces the same N points */
    if (first >= n || first < 1) {
      for (int k = 0; k < n; ++k) {
        CHECK(order[k] == k);
      }
    } else {
      /* The rest keeps increasing order. */
      for (int k = first + 1; k < n; ++k) {
        CHECK(order[k] > order[k - 1]);
      }
    }
  }
  /* The batch of 8 of 64 covers the disk as well as an 8-point spiral of
   * its own (every disk point within 0.64 of a batch point; the 8-point
   * spiral: 0.67); the 64-point spiral's first 8 indices (radii up to 0.36)
   * leave the rim 0.82 away and would miss an edge there. */
  {
    int naive[8];
    for (int k = 0; k < 8; ++k) {
      naive[k] = k;
    }
    CHECK(vsh_rt_adaptive_order(64, 8, order) == 0);
    const double spread = cover_radius(order, 8, 64), bunched = cover_radius(naive, 8, 64);
    CHECK(spread < 0.66);
    CHECK(bunched > 0.8);
    /* Every half of the disk (any line through the centre) holds a batch
     * point: a straight shadow edge over the centre is always seen. */
    for (int a = 0; a < 360; ++a) {
      int in = 0;
      for (int j = 0; j < 8; ++j) {
        double q[2];
        vsh_rt_disk_sample(order[j], 64, 0.0, q);
        in += q[0] * cos(a * PI / 180) + q[1] * sin(a * PI / 180) > 0;
      }
      CHECK(in >= 2 && in <= 6);
    }
  }
  CHECK(vsh_rt_adaptive_order(0, 8, order) == -1);
  CHECK(vsh_rt_adaptive_order(8, 8, NULL) == -1);
}

static void test_rest(void)
{
  CHECK(vsh_rt_adaptive_rest(64, 8, 0) == 0);  /* all free: lit */
  CHECK(vsh_rt_adaptive_rest(64, 8, 8) == 0);  /* all blocked: umbra */
  CHECK(vsh_rt_adaptive_rest(64, 8, 1) == 56); /* mixed: the rest */
  CHECK(vsh_rt_adaptive_rest(64, 8, 7) == 56);
  CHECK(vsh_rt_adaptive_rest(1, 1, 1) == 0); /* hard light */
  CHECK(vsh_rt_adaptive_rest(1, 1, 0) == 0);
  CHECK(vsh_rt_adaptive_rest(5, 5, 2) == 0);   /* samples < batch: one batch */
  CHECK(vsh_rt_adaptive_rest(64, 64, 30) == 0); /* adaptivity off */
  /* Visibility from a mixed pixel equals the non-adaptive estimate: the
   * batch and the rest are the N points. */
  {
    int order[64], blocked[64], total = 0, batch = 0;
    CHECK(vsh_rt_adaptive_order(64, 8, order) == 0);
    for (int k = 0; k < 64; ++k) {
      double q[2];
      vsh_rt_disk_sample(k, 64, 0.3, q);
      blocked[k] = q[0] > 0.2; /* a straight edge across the light */
      total += blocked[k];
    }
    for (int j = 0; j < 8; ++j) {
      batch += blocked[order[j]];
    }
    const int rest = vsh_rt_adaptive_rest(64, 8, batch);
    CHECK(rest == 56);
    int sum = batch;
    for (int j = 8; j < 8 + rest; ++j) {
      sum += blocked[order[j]];
    }
    CHECK(sum == total);
  }
}

static void test_near(void)
{
  const unsigned char F = VSH_RT_BATCH_FREE, B = VSH_RT_BATCH_BLOCKED, M = VSH_RT_BATCH_MIXED,
                      N = VSH_RT_BATCH_NONE;
  CHECK(vsh_rt_adaptive_state(8, 0) == F);
  CHECK(vsh_rt_adaptive_state(8, 8) == B);
  CHECK(vsh_rt_adaptive_state(8, 3) == M);
  CHECK(vsh_rt_adaptive_state(0, 0) == N);
  CHECK(vsh_rt_adaptive_state(1, 1) == B); /* hard: never mixed */
  const unsigned char lit[9] = { F, F, F, F, F, F, F, F, F };
  const unsigned char umbra[9] = { B, B, B, B, B, B, B, B, B };
  const unsigned char near_mixed[9] = { F, F, F, F, F, F, F, F, M };
  const unsigned char edge[9] = { F, F, F, F, F, B, B, B, B }; /* agree, but differ */
  const unsigned char background[9] = { N, N, N, F, F, N, N, N, N };
  const unsigned char bg_umbra[9] = { N, B, N, B, B, N, N, N, N };
  CHECK(vsh_rt_adaptive_rest_near(64, 8, lit, 9) == 0);
  CHECK(vsh_rt_adaptive_rest_near(64, 8, umbra, 9) == 0);
  CHECK(vsh_rt_adaptive_rest_near(64, 8, near_mixed, 9) == 56);
  CHECK(vsh_rt_adaptive_rest_near(64, 8, edge, 9) == 56);
  CHECK(vsh_rt_adaptive_rest_near(64, 8, background, 9) == 0);
  CHECK(vsh_rt_adaptive_rest_near(64, 8, bg_umbra, 9) == 0);
  CHECK(vsh_rt_adaptive_rest_near(64, 8, near_mixed, 4) == 0); /* the image's corner: 4 */
  CHECK(vsh_rt_adaptive_rest_near(64, 64, near_mixed, 9) == 0); /* not adaptive */
  CHECK(vsh_rt_adaptive_rest_near(8, 8, edge, 9) == 0);         /* samples == batch */
  CHECK(vsh_rt_adaptive_rest_near(1, 1, edge, 9) == 0);         /* hard light */
  CHECK(vsh_rt_adaptive_rest_near(64, 8, NULL, 0) == 0);
  CHECK(vsh_rt_adaptive_rest_near(9, 8, near_mixed, 9) == 1);
}

static void test_expected(void)
{
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 8, 0.0), 8, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 8, 1.0), 64, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 8, 0.25), 22, 1e-12);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 8, 7.0), 64, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 8, -1.0), 8, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 64, 0.1), 64, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(64, 0, 0.1), 64, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(1, 1, 0.5), 1, 0);
  CHECK_NEAR(vsh_rt_adaptive_expected_rays(0, 8, 0.5), 0, 0);
}

int main(void)
{
  test_first();
  test_order();
  test_rest();
  test_near();
  test_expected();
  return vsh_check_report("rt_adaptive");
}
