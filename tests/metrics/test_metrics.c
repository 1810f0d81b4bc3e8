/* test_metrics.c - the per-pixel metrics on small synthetic images. */
#include "vsh_check.h"
#include "vshm_metrics.h"

#include <stdlib.h>

#define W 10
#define H 10
#define N (W * H)

static float v[N], r[N];
static unsigned char valid[N], ex[N];

static void fill(float *a, float x) {
  for (int i = 0; i < N; ++i) a[i] = x;
}

/* The errors of one image against another, every pixel valid. */
static void test_errors(void) {
  vshm_metrics m;

  /* identical images: every error 0, no boundary */
  fill(v, 1.0f);
  fill(r, 1.0f);
  for (int i = 0; i < N; ++i) valid[i] = 1;
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.valid_pixels == N && m.compared_pixels == N);
  CHECK(m.vis_mae == 0.0 && m.wrong_pct == 0.0 && m.edge_px == 0.0);
  CHECK(m.false_shadow_pct == 0.0 && m.false_light_pct == 0.0);

  /* reference lit; test: 10 pixels at 0 (false shadow, wrong), 10 at 0.6
   * (0.4 off: not wrong), 10 at 0.45 (0.55 off: wrong, v < 0.5 so false
   * shadow), rest exact. */
  for (int i = 0; i < 10; ++i) v[i] = 0.0f;
  for (int i = 10; i < 20; ++i) v[i] = 0.6f;
  for (int i = 20; i < 30; ++i) v[i] = 0.45f;
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK_NEAR(m.vis_mae, (10 * 1.0 + 10 * 0.4 + 10 * 0.55) / N, 1e-6);
  CHECK_NEAR(m.wrong_pct, 20.0, 1e-12);
  CHECK_NEAR(m.false_shadow_pct, 20.0, 1e-12);
  CHECK(m.false_light_pct == 0.0);

  /* reference dark (0.05), test 0.7 in 5 pixels: false light and wrong;
   * 0.5 exactly is neither (the tests are strict: > 0.5). */
  fill(r, 0.05f);
  fill(v, 0.05f);
  for (int i = 0; i < 5; ++i) v[i] = 0.7f;
  v[5] = 0.5f;
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK_NEAR(m.false_light_pct, 5.0, 1e-12);
  CHECK_NEAR(m.wrong_pct, 5.0, 1e-12);
  CHECK(m.false_shadow_pct == 0.0);

  /* penumbra reference (0.5) is neither false shadow nor false light */
  fill(r, 0.5f);
  fill(v, 0.0f);
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.false_shadow_pct == 0.0 && m.false_light_pct == 0.0 && m.wrong_pct == 0.0);
  CHECK_NEAR(m.vis_mae, 0.5, 1e-12);
}

/* Which pixels are compared: invalid ones never, excluded ones not. */
static void test_valid_and_excluded(void) {
  vshm_metrics m;

  /* invalid pixels never count, whatever they hold */
  for (int i = 0; i < N; ++i) valid[i] = 1;
  fill(r, 1.0f);
  fill(v, 1.0f);
  for (int i = 0; i < 40; ++i) {
    valid[i] = 0;
    v[i] = 0.0f;
  }
  v[50] = 0.0f; /* one valid wrong pixel of 60 */
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.valid_pixels == 60 && m.compared_pixels == 60);
  CHECK_NEAR(m.wrong_pct, 100.0 / 60.0, 1e-12);
  CHECK_NEAR(m.vis_mae, 1.0 / 60.0, 1e-12);

  /* exclude: leaving out the wrong pixel and 19 others */
  for (int i = 0; i < N; ++i) ex[i] = (i >= 45 && i < 65);
  CHECK(vshm_metrics_compute(v, r, valid, ex, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.valid_pixels == 60 && m.compared_pixels == 40);
  CHECK(m.wrong_pct == 0.0 && m.vis_mae == 0.0 && m.false_shadow_pct == 0.0);
  /* ... and excluding an invalid pixel changes nothing */
  ex[0] = 1;
  CHECK(vshm_metrics_compute(v, r, valid, ex, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.compared_pixels == 40);

  /* all invalid: distinct code, all zero, no division by zero */
  for (int i = 0; i < N; ++i) valid[i] = 0;
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_EMPTY);
  CHECK(m.valid_pixels == 0 && m.compared_pixels == 0);
  CHECK(m.vis_mae == 0.0 && m.wrong_pct == 0.0 && m.edge_px == 0.0);
  CHECK(m.false_shadow_pct == 0.0 && m.false_light_pct == 0.0);
  CHECK(m.ref_shadow_pixels == 0 && m.wrong_of_shadow_pct == 0.0 &&
        m.wrong_of_test_shadow_pct == 0.0);

  /* all valid but all excluded: EMPTY too, valid_pixels still reported */
  for (int i = 0; i < N; ++i) valid[i] = ex[i] = 1;
  CHECK(vshm_metrics_compute(v, r, valid, ex, W, H, &m) == VSHM_METRICS_EMPTY);
  CHECK(m.valid_pixels == N && m.compared_pixels == 0 && m.wrong_pct == 0.0);
}

/* wrong_of_shadow_pct and wrong_of_test_shadow_pct. */
static void test_shadow_relative(void) {
  vshm_metrics m;

  /* Errors relative to the shadow. Reference shadowed in rows 0-2 (30
   * pixels); the test keeps row 0 only and adds 4 false shadow pixels in
   * row 9: test shadow 10 + 4 = 14 pixels, wrong 20 (rows 1-2 lost) + 4 =
   * 24. Of the reference's shadow: 100 * 24 / 30 = 80; of the test's:
   * 100 * 24 / 14. */
  for (int i = 0; i < N; ++i) {
    valid[i] = 1;
    r[i] = i < 30 ? 0.0f : 1.0f;
    v[i] = i < 10 || (i >= 90 && i < 94) ? 0.0f : 1.0f;
  }
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.ref_shadow_pixels == 30 && m.test_shadow_pixels == 14);
  CHECK_NEAR(m.wrong_pct, 24.0, 1e-12);
  CHECK_NEAR(m.wrong_of_shadow_pct, 80.0, 1e-12);
  CHECK_NEAR(m.wrong_of_test_shadow_pct, 2400.0 / 14.0, 1e-9);
  /* counted over compared pixels only: excluding row 2 (10 lost pixels)
   * leaves reference shadow 20, wrong 14, test shadow still 14 */
  for (int i = 0; i < N; ++i) ex[i] = (i >= 20 && i < 30);
  CHECK(vshm_metrics_compute(v, r, valid, ex, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.ref_shadow_pixels == 20 && m.test_shadow_pixels == 14);
  CHECK_NEAR(m.wrong_of_shadow_pct, 70.0, 1e-12);
  CHECK_NEAR(m.wrong_of_test_shadow_pct, 100.0, 1e-12);

  /* a small shadow lost entirely: 3 of 100 pixels, wrong_pct only 3 but
   * 100 % of the shadow; the test has no shadow, which counts as one
   * pixel: 100 * 3 / 1 = 300 */
  for (int i = 0; i < N; ++i) {
    r[i] = i < 3 ? 0.0f : 1.0f;
    v[i] = 1.0f;
  }
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.ref_shadow_pixels == 3 && m.test_shadow_pixels == 0);
  CHECK_NEAR(m.wrong_pct, 3.0, 1e-12);
  CHECK_NEAR(m.wrong_of_shadow_pct, 100.0, 1e-12);
  CHECK_NEAR(m.wrong_of_test_shadow_pct, 300.0, 1e-12);
  /* ... the reverse: a false shadow of 2 pixels where the reference has
   * none: 200 of the (one-pixel) reference shadow, 100 of the test's */
  for (int i = 0; i < N; ++i) {
    r[i] = 1.0f;
    v[i] = i < 2 ? 0.2f : 1.0f;
  }
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.ref_shadow_pixels == 0 && m.test_shadow_pixels == 2);
  CHECK_NEAR(m.wrong_of_shadow_pct, 200.0, 1e-12);
  CHECK_NEAR(m.wrong_of_test_shadow_pct, 100.0, 1e-12);
  /* no shadow on either side and nothing wrong: exactly 0, not 0/0 */
  fill(v, 1.0f);
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.ref_shadow_pixels == 0 && m.test_shadow_pixels == 0);
  CHECK(m.wrong_of_shadow_pct == 0.0 && m.wrong_of_test_shadow_pct == 0.0);
  /* v = 0.5 is lit (the thresholded state), 0.49 is shadowed */
  fill(r, 0.5f);
  fill(v, 0.49f);
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
  CHECK(m.ref_shadow_pixels == 0 && m.test_shadow_pixels == N);
  CHECK(m.wrong_of_shadow_pct == 0.0 && m.wrong_of_test_shadow_pct == 0.0);
}

static void test_bad_arguments(void) {
  vshm_metrics m;

  for (int i = 0; i < N; ++i) valid[i] = 1;
  CHECK(vshm_metrics_compute(NULL, r, valid, NULL, W, H, &m) == VSHM_METRICS_EINVAL);
  CHECK(vshm_metrics_compute(v, r, NULL, NULL, W, H, &m) == VSHM_METRICS_EINVAL);
  CHECK(vshm_metrics_compute(v, r, valid, NULL, 0, H, &m) == VSHM_METRICS_EINVAL);
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, -1, &m) == VSHM_METRICS_EINVAL);
  CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, NULL) == VSHM_METRICS_EINVAL);
}

int main(void) {
  test_errors();
  test_valid_and_excluded();
  test_shadow_relative();
  test_bad_arguments();
  return vsh_check_report("metrics.pixel");
}
