/* test_penumbra.c - the penumbra metrics (vshm_penumbra.h) on images whose
 * answers are known by construction: a linear ramp penumbra compared with
 * itself, shifted, hardened, offset, leaking and over-darkened; the one
 * pixel dilation of the mask; exclusions; empty and bad inputs; and random
 * images, whose figures must stay finite and in range. */
#include "vsh_check.h"
#include "vshm_metrics.h"
#include "vshm_penumbra.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A fixed-seed generator (the metrics tests do not link the core). */
static unsigned long long rng_state = 0x9E3779B97F4A7C15ull;
static double vsh_test_rnd(double lo, double hi) {
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return lo + (hi - lo) * ((double)((rng_state * 0x2545F4914F6CDD1Dull) >> 11) /
                           9007199254740992.0);
}

#define W 64
#define H 16

static float ref[W * H], test[W * H];
static unsigned char valid[W * H];

/* A ramp from 0 at column x0 to 1 at column x0 + width (columns), shadow
 * on the left. */
static void ramp(float *img, double x0, double width) {
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      double t = (x + 0.5 - x0) / width;
      img[y * W + x] = (float)fmin(1.0, fmax(0.0, t));
    }
}

static void all_valid(void) { memset(valid, 1, sizeof valid); }

static void test_identical(void) {
  vshm_penumbra p;
  ramp(ref, 16, 20);
  memcpy(test, ref, sizeof ref);
  CHECK(vshm_penumbra_compute(test, ref, valid, NULL, W, H, &p) == VSHM_METRICS_OK);
  CHECK(p.pen_mae == 0.0 && p.pen_bias == 0.0);
  CHECK(p.leak_pct == 0.0 && p.false_shadow_pct == 0.0);
  CHECK_NEAR(p.width_ratio, 1.0, 1e-12);
  /* 16 of the 20 ramp columns are inside (0.1, 0.9): width 16 px per crack
   * row. */
  CHECK_NEAR(p.ref_width_px, 16.0, 1e-12);
  CHECK(p.contour_px[0] == 0.0 && p.contour_px[1] == 0.0 && p.contour_px[2] == 0.0);
  /* Penumbra: ramp columns 16..35 with 0.02 < v < 0.98 (columns 16..35
   * minus none: the first is 0.025, the last 0.975), plus one column on
   * each side. */
  CHECK(p.penumbra_pixels == 22 * H);
  CHECK(p.umbra_pixels == 16 * H && p.lit_pixels == (W - 36) * H);
}

static void test_shifted(void) {
  vshm_penumbra p;
  ramp(ref, 16, 20);
  ramp(test, 19, 20); /* 3 px towards the light: too dark */
  CHECK(vshm_penumbra_compute(test, ref, valid, NULL, W, H, &p) == VSHM_METRICS_OK);
  for (int k = 0; k < 3; ++k) CHECK_NEAR(p.contour_px[k], 3.0, 1e-12);
  CHECK_NEAR(p.width_ratio, 1.0, 1e-12);
  CHECK(p.pen_bias < 0.0);
  CHECK_NEAR(p.pen_bias, -p.pen_mae, 1e-12); /* darker everywhere it differs */
  /* Interior error 3/20 = 0.15 per pixel. */
  CHECK(p.pen_mae > 0.1 && p.pen_mae < 0.15);
  CHECK(p.false_shadow_pct > 0.0); /* lit columns 36..38 now below 0.9 */
}

static void test_hard(void) {
  vshm_penumbra p;
  ramp(ref, 16, 20);
  ramp(test, 26, 1e-9); /* a step where the reference crosses 0.5 */
  CHECK(vshm_penumbra_compute(test, ref, valid, NULL, W, H, &p) == VSHM_METRICS_OK);
  CHECK(p.width_px == 0.0 && p.width_ratio == 0.0);
  CHECK_NEAR(p.contour_px[1], 0.0, 1e-12);
  /* v_ref = 0.1 at column 18, 0.9 at 34; the step is at 26: 8 px each. */
  CHECK_NEAR(p.contour_px[0], 8.0, 1e-12);
  CHECK_NEAR(p.contour_px[2], 8.0, 1e-12);
  CHECK_NEAR(p.pen_bias, 0.0, 0.03); /* symmetric: too dark and too bright halves */
  CHECK(p.pen_mae > 0.2);
}

static void test_offset_leak_false(void) {
  vshm_penumbra p;
  ramp(ref, 16, 20);
  for (int i = 0; i < W * H; ++i) {
    float r = ref[i];
    if (r <= 0.02f)
      test[i] = 0.2f; /* leak */
    else if (r >= 0.98f)
      test[i] = 0.85f; /* false shadow */
    else
      test[i] = r + 0.05f;
  }
  CHECK(vshm_penumbra_compute(test, ref, valid, NULL, W, H, &p) == VSHM_METRICS_OK);
  CHECK_NEAR(p.leak_pct, 100.0, 1e-12);
  CHECK_NEAR(p.false_shadow_pct, 100.0, 1e-12);
  /* Interior pixels +0.05; the two dilated rim columns (+0.2 and -0.15). */
  CHECK_NEAR(p.pen_mae, (20 * 0.05 + 0.2 + 0.15) / 22.0, 1e-6);
  CHECK_NEAR(p.pen_bias, (20 * 0.05 + 0.2 - 0.15) / 22.0, 1e-6);
}

static void test_mask_and_exclude(void) {
  unsigned char mask[W * H], excl[W * H];
  vshm_penumbra p;
  long count = 0;
  for (int i = 0; i < W * H; ++i) ref[i] = 1.0f;
  ref[5 * W + 10] = 0.5f;
  CHECK(vshm_penumbra_mask(ref, valid, W, H, mask) == VSHM_METRICS_OK);
  for (int i = 0; i < W * H; ++i) count += mask[i];
  CHECK(count == 9);
  /* Invalid pixels never join the mask. */
  valid[4 * W + 10] = 0;
  vshm_penumbra_mask(ref, valid, W, H, mask);
  CHECK(mask[4 * W + 10] == 0 && mask[6 * W + 10] == 1);
  all_valid();
  /* Excluding the penumbra leaves nothing to measure: EMPTY, zeros. */
  memcpy(test, ref, sizeof ref);
  memset(excl, 0, sizeof excl);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) excl[(5 + dy) * W + 10 + dx] = 1;
  CHECK(vshm_penumbra_compute(test, ref, valid, excl, W, H, &p) == VSHM_METRICS_EMPTY);
  CHECK(p.penumbra_pixels == 0 && p.pen_mae == 0.0 && p.lit_pixels == W * H - 9);
}

static void test_bad_and_empty(void) {
  vshm_penumbra p;
  unsigned char none[W * H], rgb[3 * W * H];
  memset(none, 0, sizeof none);
  CHECK(vshm_penumbra_compute(NULL, ref, valid, NULL, W, H, &p) == VSHM_METRICS_EINVAL);
  CHECK(vshm_penumbra_compute(test, ref, valid, NULL, 0, H, &p) == VSHM_METRICS_EINVAL);
  CHECK(vshm_penumbra_compute(test, ref, valid, NULL, W, H, NULL) == VSHM_METRICS_EINVAL);
  CHECK(vshm_penumbra_mask(ref, NULL, W, H, none) == VSHM_METRICS_EINVAL);
  CHECK(vshm_penumbra_heatmap_rgb(test, ref, valid, -1, H, rgb) == VSHM_METRICS_EINVAL);
  CHECK(vshm_penumbra_compute(test, ref, none, NULL, W, H, &p) == VSHM_METRICS_EMPTY);
  CHECK(p.width_ratio == 0.0 && p.leak_pct == 0.0 && p.contour_px[1] == 0.0);
}

static void test_heatmap(void) {
  unsigned char rgb[3 * W * H];
  ramp(ref, 16, 20);
  memcpy(test, ref, sizeof ref);
  test[8 * W + 25] -= 0.25f; /* saturated blue */
  test[8 * W + 27] += 0.125f; /* half red */
  valid[0] = 0;
  CHECK(vshm_penumbra_heatmap_rgb(test, ref, valid, W, H, rgb) == VSHM_METRICS_OK);
  CHECK(rgb[0] == 128 && rgb[1] == 128 && rgb[2] == 128);
  {
    const unsigned char *b = rgb + 3 * (8 * W + 25), *r = rgb + 3 * (8 * W + 27);
    const unsigned char *ok = rgb + 3 * (8 * W + 26), *lit = rgb + 3 * (8 * W + 60);
    CHECK(b[0] == 0 && b[1] == 0 && b[2] == 255);
    CHECK(r[0] == 255 && r[1] >= 127 && r[1] <= 128 && r[2] == r[1]);
    CHECK(ok[0] == 255 && ok[1] == 255 && ok[2] == 255);
    CHECK(lit[0] == 96 && lit[1] == 96); /* outside: the reference in dark grey */
  }
  all_valid();
}

/* Random images: every figure finite and in its range. */
static void test_random(void) {
  for (int it = 0; it < 300; ++it) {
    vshm_penumbra p;
    int rc;
    for (int i = 0; i < W * H; ++i) {
      double s = vsh_test_rnd(0, 1);
      ref[i] = (float)(s < 0.3 ? 0.0 : s > 0.7 ? 1.0 : vsh_test_rnd(0, 1));
      test[i] = (float)vsh_test_rnd(0, 1);
      valid[i] = vsh_test_rnd(0, 1) < 0.9;
    }
    rc = vshm_penumbra_compute(test, ref, valid, NULL, W, H, &p);
    CHECK(rc == VSHM_METRICS_OK || rc == VSHM_METRICS_EMPTY);
    CHECK(p.pen_mae >= 0.0 && p.pen_mae <= 1.0 && fabs(p.pen_bias) <= p.pen_mae + 1e-12);
    CHECK(p.leak_pct >= 0.0 && p.leak_pct <= 100.0);
    CHECK(p.false_shadow_pct >= 0.0 && p.false_shadow_pct <= 100.0);
    CHECK(isfinite(p.width_ratio) && p.width_ratio >= 0.0);
    for (int k = 0; k < 3; ++k)
      CHECK(isfinite(p.contour_px[k]) && p.contour_px[k] >= 0.0 &&
            p.contour_px[k] <= sqrt((double)W * W + H * H) + 1e-9);
  }
  all_valid();
}

int main(void) {
  all_valid();
  test_identical();
  test_shifted();
  test_hard();
  test_offset_leak_false();
  test_mask_and_exclude();
  test_bad_and_empty();
  test_heatmap();
  test_random();
  return vsh_check_report("metrics.penumbra");
}
