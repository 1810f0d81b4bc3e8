/* test_soft_adaptive.c - unit tests of vsh_soft_adaptive: the integer
 * levels of the 8-bit mask (sum 255, each at least 1), the batch order (a
 * permutation; centre first, the rest near the rim at spread angles), the
 * batch's level sum and the state a channel level tells, and the largest
 * cap a batch misses: the rim batch against raytrace's spiral-spread batch
 * (vsh_rt_adaptive_order) and against the spiral's first indices. */
#include "vsh_check.h"
#include "vsh_rt_adaptive.h"
#include "vsh_soft.h"
#include "vsh_soft_adaptive.h"

#include <math.h>

static void test_levels(void)
{
  for (int n = 1; n <= 255; ++n) {
    int sum = 0, low = 255;
    for (int i = 0; i < n; ++i) {
      const int l = vsh_soft_levels(i, n);
      sum += l;
      low = l < low ? l : low;
    }
    CHECK(sum == 255);
    CHECK(low >= 1);
  }
  CHECK(vsh_soft_levels(0, 1) == 255);
  CHECK(vsh_soft_levels(-1, 16) == 0);
  CHECK(vsh_soft_levels(16, 16) == 0);
  CHECK(vsh_soft_levels(0, 256) == 0);
  CHECK(vsh_soft_levels(0, 0) == 0);
}

static int is_permutation(const int *order, int n)
{
  int seen[1024] = { 0 };
  for (int k = 0; k < n; ++k) {
    if (order[k] < 0 || order[k] >= n || seen[order[k]]++) {
      return 0;
    }
  }
  return 1;
}

static void test_order(void)
{
  int order[1024];
  CHECK(vsh_soft_batch_order(0, 8, order) == -1);
  CHECK(vsh_soft_batch_order(16, 8, NULL) == -1);
  /* No batch: the identity. */
  CHECK(vsh_soft_batch_order(8, 8, order) == 0);
  for (int k = 0; k < 8; ++k) CHECK(order[k] == k);
  CHECK(vsh_soft_batch_order(16, 1, order) == 0 && order[3] == 3);
  for (int n = 9; n <= 1000; n += 7) {
    CHECK(vsh_soft_batch_order(n, VSH_SOFT_ADAPTIVE_BATCH, order) == 0);
    CHECK(is_permutation(order, n));
    CHECK(order[0] == 0);
    /* The rim points: from the outer part, at spread angles (no angular
     * gap between neighbours above 1.5 times an equal share). */
    double angles[VSH_SOFT_ADAPTIVE_BATCH - 1];
    for (int j = 1; j < VSH_SOFT_ADAPTIVE_BATCH; ++j) {
      double q[2];
      vsh_soft_disk_sample(order[j], n, 0.0, q);
      const double rho = sqrt(q[0] * q[0] + q[1] * q[1]);
      CHECK(rho >= (n >= 64 ? 0.8 : 0.4));
      angles[j - 1] = atan2(q[1], q[0]);
    }
    double largest = 0;
    for (int j = 0; j < VSH_SOFT_ADAPTIVE_BATCH - 1; ++j) {
      /* The gap to the next angle counter-clockwise. */
      double gap = 7.0;
      for (int m = 0; m < VSH_SOFT_ADAPTIVE_BATCH - 1; ++m) {
        double d = angles[m] - angles[j];
        d = d <= 0 ? d + 2 * 3.14159265358979323846 : d;
        gap = m != j && d < gap ? d : gap;
      }
      largest = gap > largest ? gap : largest;
    }
    if (n >= 32) CHECK(largest <= 1.5 * 2 * 3.14159265358979323846 / 7);
    /* The rest keep increasing order. */
    for (int k = VSH_SOFT_ADAPTIVE_BATCH + 1; k < n; ++k) CHECK(order[k] > order[k - 1]);
  }
}

static void test_batch_levels(void)
{
  int order[64];
  vsh_soft_batch_order(64, 8, order);
  const int s = vsh_soft_batch_levels(64, 8, order);
  /* 8 of 64 samples of about 4 levels each. */
  CHECK(s >= 8 * 3 && s <= 8 * 4);
  CHECK(vsh_soft_batch_levels(64, 64, order) == 255);
  CHECK(vsh_soft_batch_levels(256, 8, order) == -1);
  CHECK(vsh_soft_batch_state(0, s) == VSH_RT_BATCH_BLOCKED);
  CHECK(vsh_soft_batch_state(s, s) == VSH_RT_BATCH_FREE);
  CHECK(vsh_soft_batch_state(1, s) == VSH_RT_BATCH_MIXED);
  CHECK(vsh_soft_batch_state(s - 1, s) == VSH_RT_BATCH_MIXED);
  CHECK(vsh_soft_batch_state(s + 1, s) == VSH_RT_BATCH_NONE);
  CHECK(vsh_soft_batch_state(-1, s) == VSH_RT_BATCH_NONE);
  /* Every subset of the batch that is neither empty nor whole reads MIXED:
   * each sample adds at least one level. */
  for (int mask = 1; mask < 255; ++mask) {
    int level = 0;
    for (int j = 0; j < 8; ++j) level += (mask >> j & 1) ? vsh_soft_levels(order[j], 64) : 0;
    CHECK(vsh_soft_batch_state(level, s) == VSH_RT_BATCH_MIXED);
  }
}

static double missed(const int *idx, int count, int n)
{
  double xy[2 * 64];
  for (int j = 0; j < count; ++j) vsh_soft_disk_sample(idx[j], n, 0.0, xy + 2 * j);
  return vsh_soft_batch_missed_cap(xy, count);
}

static void test_missed_cap(void)
{
  /* One point at the centre: half the disk can be blocked unseen. */
  const double centre[2] = { 0, 0 };
  CHECK_NEAR(vsh_soft_batch_missed_cap(centre, 1), 0.5, 1e-6);
  CHECK(vsh_soft_batch_missed_cap(centre, 0) == 1.0);
  /* Points on the unit circle at 4 equal angles: the cap beyond a chord at
   * cos(pi/4) from the centre, (pi/4 - 1/2) / pi. */
  const double square[8] = { 1, 0, 0, 1, -1, 0, 0, -1 };
  CHECK_NEAR(vsh_soft_batch_missed_cap(square, 4), (0.25 * 3.14159265358979323846 - 0.5) /
      3.14159265358979323846, 1e-5);
  /* The rim batch misses less of an edge than the spread batch and the
   * spiral's first 8 indices, at every N the passes use. */
  const int ns[] = { 16, 24, 32, 64, 128, 255 };
  for (int t = 0; t < 6; ++t) {
    const int n = ns[t];
    int rim[256], spread[256], firsts[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
    vsh_soft_batch_order(n, 8, rim);
    vsh_rt_adaptive_order(n, 8, spread);
    const double a = missed(rim, 8, n), b = missed(spread, 8, n), c = missed(firsts, 8, n);
    printf("N=%d: largest cap missed by the batch of 8: rim+centre %.4f, spread %.4f, "
           "spiral's first 8 %.4f\n", n, a, b, c);
    CHECK(a < b && a < c);
    if (n >= 64) CHECK(a < 0.06);
  }
}

/* planar's mark: the state of a float share, and the marks of a small
 * channel with an edge between all lit and all blocked and one mixed pixel. */
static void test_share_state(void)
{
  CHECK(vsh_soft_share_state(0.0, 8, 64) == VSH_RT_BATCH_FREE);
  CHECK(vsh_soft_share_state(8.0 / 64, 8, 64) == VSH_RT_BATCH_BLOCKED);
  CHECK(vsh_soft_share_state(1.0 / 64, 8, 64) == VSH_RT_BATCH_MIXED);
  CHECK(vsh_soft_share_state(7.0 / 64, 8, 64) == VSH_RT_BATCH_MIXED);
  CHECK(vsh_soft_share_state(8.0 / 1024, 8, 1024) == VSH_RT_BATCH_BLOCKED);
  CHECK(vsh_soft_share_state(1.0 / 1024, 8, 1024) == VSH_RT_BATCH_MIXED);
  CHECK(vsh_soft_share_state(0.0, 0, 64) == VSH_RT_BATCH_NONE);
  CHECK(vsh_soft_share_state(0.0, 8, 4) == VSH_RT_BATCH_NONE);
  CHECK(vsh_soft_share_state(NAN, 8, 64) == VSH_RT_BATCH_NONE);
  /* A 1024-sample order (planar's largest N) is a permutation, centre first. */
  static int order[1024];
  CHECK(vsh_soft_batch_order(1024, 8, order) == 0);
  CHECK(is_permutation(order, 1024));
  CHECK(order[0] == 0);
}

static void test_mark_pixels(void)
{
  /* 10 x 6, RGBA with the share in channel 2: columns 0-4 lit, 5-9 blocked
   * (8 of 16), pixel (8, 0) mixed, pixel (0, 5) mixed. */
  enum { W = 10, H = 6 };
  float rgba[W * H * 4];
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      float *p = rgba + 4 * (y * W + x);
      p[0] = p[1] = p[3] = 0.75f; /* other pairs' channels: ignored */
      p[2] = x < 5 ? 0.0f : 8.0f / 16;
    }
  }
  rgba[4 * (0 * W + 8) + 2] = 3.0f / 16;
  rgba[4 * (5 * W + 0) + 2] = 1.0f / 16;
  unsigned char mark[W * H];
  int box[4];
  const long refined = vsh_soft_mark_pixels(rgba + 2, 4, W, H, 8, 16, mark, box);
  /* The edge: columns 4 and 5 (every row, 12 pixels); around (8, 0):
   * columns 7-9 of rows 0-1 (6); around (0, 5): columns 0-1 of rows 4-5
   * (4). */
  CHECK(refined == 12 + 6 + 4);
  CHECK(box[0] == 0 && box[1] == 0 && box[2] == 10 && box[3] == 6);
  CHECK(mark[2 * W + 2] == VSH_SOFT_MARK_LIT);
  CHECK(mark[3 * W + 8] == VSH_SOFT_MARK_BLOCKED);
  CHECK(mark[3 * W + 4] == VSH_SOFT_MARK_REFINE && mark[3 * W + 5] == VSH_SOFT_MARK_REFINE);
  CHECK(mark[3 * W + 3] == VSH_SOFT_MARK_LIT && mark[3 * W + 6] == VSH_SOFT_MARK_BLOCKED);
  CHECK(mark[1 * W + 9] == VSH_SOFT_MARK_REFINE && mark[2 * W + 9] == VSH_SOFT_MARK_BLOCKED);
  CHECK(mark[4 * W + 1] == VSH_SOFT_MARK_REFINE && mark[3 * W + 1] == VSH_SOFT_MARK_LIT);
  /* All lit but one mixed pixel in the middle: its 3x3, and the box. */
  for (int p = 0; p < W * H; ++p) rgba[4 * p + 2] = 0.0f;
  rgba[4 * (2 * W + 6) + 2] = 2.0f / 16;
  CHECK(vsh_soft_mark_pixels(rgba + 2, 4, W, H, 8, 16, mark, box) == 9);
  CHECK(box[0] == 5 && box[1] == 1 && box[2] == 8 && box[3] == 4);
  /* Nothing to refine: an empty box. */
  rgba[4 * (2 * W + 6) + 2] = 0.0f;
  CHECK(vsh_soft_mark_pixels(rgba + 2, 4, W, H, 8, 16, mark, box) == 0);
  CHECK(box[0] == 0 && box[2] == 0 && mark[0] == VSH_SOFT_MARK_LIT);
  CHECK(vsh_soft_mark_pixels(NULL, 4, W, H, 8, 16, mark, box) == -1);
  CHECK(vsh_soft_mark_pixels(rgba, 4, W, H, 8, 4, mark, box) == -1);
}

int main(void)
{
  test_levels();
  test_order();
  test_batch_levels();
  test_missed_cap();
  test_share_state();
  test_mark_pixels();
  return vsh_check_report("soft_adaptive");
}
