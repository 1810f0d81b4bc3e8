/* test_reflection.c - reflection_mae and the mirror heat map: hand-computed
 * cases (clamping, NaN, exclude, empty, bad arguments), then random images
 * and masks against a brute-force sum written here independently (integer
 * sums of 8-bit levels, so exact up to the final division), and the
 * properties any mean absolute error must keep (symmetry, zero on itself,
 * bounded by [0,1]). */
#include "vsh_check.h"
#include "vshm_metrics.h"

#include <math.h>
#include <stdlib.h>

static unsigned long rng_state = 4242;
static unsigned rng(void) {
  rng_state = rng_state * 6364136223846793005UL + 1442695040888963407UL;
  return (unsigned)(rng_state >> 33);
}

static void known_values(void) {
  /* 3x1: pixel 0 off by (0.375, 0, 0) -> 0.125; pixel 1 over-bright, NaN
   * and negative (clamped: test (1, 0, 0) vs ref (0.25, 0, 0) -> 0.25);
   * pixel 2 not a mirror pixel, whatever its error. */
  float t[9] = {0.875f, 0.5f, 0.5f, 7.0f, NAN, -2.0f, 1.0f, 1.0f, 1.0f};
  float r[9] = {0.5f, 0.5f, 0.5f, 0.25f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  unsigned char m[3] = {1, 1, 0};
  double mae = -1;
  long px = -1;
  CHECK(vshm_reflection_mae(t, r, m, NULL, 3, 1, &mae, &px) == VSHM_METRICS_OK);
  CHECK(px == 2);
  CHECK_NEAR(mae, (0.125 + 0.25) / 2.0, 1e-12);
  /* exclude pixel 1: only pixel 0 */
  unsigned char ex[3] = {0, 1, 0};
  CHECK(vshm_reflection_mae(t, r, m, ex, 3, 1, &mae, &px) == VSHM_METRICS_OK);
  CHECK(px == 1);
  CHECK_NEAR(mae, 0.125, 1e-12);
  /* every mirror pixel excluded: empty, 0 */
  unsigned char all[3] = {1, 1, 1};
  CHECK(vshm_reflection_mae(t, r, m, all, 3, 1, &mae, &px) == VSHM_METRICS_EMPTY);
  CHECK(mae == 0.0 && px == 0);
  unsigned char none[3] = {0, 0, 0};
  CHECK(vshm_reflection_mae(t, r, none, NULL, 3, 1, &mae, NULL) == VSHM_METRICS_EMPTY);
  /* bad arguments */
  CHECK(vshm_reflection_mae(NULL, r, m, NULL, 3, 1, &mae, &px) == VSHM_METRICS_EINVAL);
  CHECK(mae == 0.0 && px == 0);
  CHECK(vshm_reflection_mae(t, NULL, m, NULL, 3, 1, &mae, &px) == VSHM_METRICS_EINVAL);
  CHECK(vshm_reflection_mae(t, r, NULL, NULL, 3, 1, &mae, &px) == VSHM_METRICS_EINVAL);
  CHECK(vshm_reflection_mae(t, r, m, NULL, 3, 1, NULL, &px) == VSHM_METRICS_EINVAL);
  CHECK(vshm_reflection_mae(t, r, m, NULL, 0, 1, &mae, &px) == VSHM_METRICS_EINVAL);
  CHECK(vshm_reflection_mae(t, r, m, NULL, 3, -1, &mae, &px) == VSHM_METRICS_EINVAL);
  CHECK(vshm_reflection_mae(t, r, m, NULL, 1 << 21, 1, &mae, &px) == VSHM_METRICS_EINVAL);

  /* heat map: pixel 0 too bright by 0.125 (mean of the channels): light
   * red; pixel 1 too bright by 0.25; pixel 2 grey (not a mirror pixel) */
  unsigned char rgb[9];
  CHECK(vshm_reflection_heatmap_rgb(t, r, m, 3, 1, rgb) == VSHM_METRICS_OK);
  CHECK(rgb[0] == 255 && rgb[1] == 223 && rgb[2] == 223); /* lrint(255 * 0.875) */
  CHECK(rgb[3] == 255 && rgb[4] == 191 && rgb[5] == 191); /* lrint(255 * 0.75) */
  CHECK(rgb[6] == 128 && rgb[7] == 128 && rgb[8] == 128);
  /* too dark: blue */
  CHECK(vshm_reflection_heatmap_rgb(r, t, m, 3, 1, rgb) == VSHM_METRICS_OK);
  CHECK(rgb[0] == 223 && rgb[1] == 223 && rgb[2] == 255);
  CHECK(vshm_reflection_heatmap_rgb(t, r, m, 3, 1, NULL) == VSHM_METRICS_EINVAL);
}

/* Random 8-bit images, masks and exclusions of random sizes. */
static void random_images(void) {
  for (int iter = 0; iter < 400; ++iter) {
    int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 30);
    int n = w * h;
    float *t = malloc(sizeof(float) * 3 * n), *r = malloc(sizeof(float) * 3 * n);
    unsigned char *m = malloc(n), *ex = malloc(n);
    int *ti = malloc(sizeof(int) * 3 * n), *ri = malloc(sizeof(int) * 3 * n);
    const unsigned density = rng() % 4; /* 0: few mirror pixels ... 3: most */
    for (int i = 0; i < 3 * n; ++i) {
      ti[i] = (int)(rng() % 256);
      ri[i] = (int)(rng() % 256);
      t[i] = (float)ti[i] / 255.0f;
      r[i] = (float)ri[i] / 255.0f;
    }
    long want_px = 0, sum = 0; /* sum of |levels| over channels: exact */
    for (int i = 0; i < n; ++i) {
      m[i] = (unsigned char)((rng() % 4) <= density ? 1 + rng() % 255 : 0);
      ex[i] = (unsigned char)(rng() % 8 == 0);
      if (!m[i] || ex[i]) continue;
      ++want_px;
      for (int c = 0; c < 3; ++c) sum += labs((long)ti[3 * i + c] - ri[3 * i + c]);
    }
    double mae = -1, back = -1, self = -1;
    long px = -1;
    int rc = vshm_reflection_mae(t, r, m, ex, w, h, &mae, &px);
    CHECK(px == want_px);
    if (want_px == 0) {
      CHECK(rc == VSHM_METRICS_EMPTY && mae == 0.0);
    } else {
      CHECK(rc == VSHM_METRICS_OK);
      CHECK_NEAR(mae, (double)sum / (3.0 * 255.0 * (double)want_px), 1e-6);
      CHECK(mae >= 0.0 && mae <= 1.0);
      CHECK(vshm_reflection_mae(r, t, m, ex, w, h, &back, NULL) == VSHM_METRICS_OK);
      CHECK(back == mae); /* same terms, same order */
      CHECK(vshm_reflection_mae(t, t, m, ex, w, h, &self, NULL) == VSHM_METRICS_OK);
      CHECK(self == 0.0);
    }
    free(t);
    free(r);
    free(m);
    free(ex);
    free(ti);
    free(ri);
  }
}

int main(void) {
  known_values();
  random_images();
  return vsh_check_report("metrics.reflection");
}
