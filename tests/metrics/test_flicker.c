/* test_flicker.c - error state and flicker_pct on a 3-frame sequence. */
#include "vsh_check.h"
#include "vshm_metrics.h"

#define W 5
#define H 4
#define N (W * H)

int main(void) {
  float ref[N], f0[N], f1[N], f2[N];
  unsigned char valid0[N], valid1[N], valid2[N];
  for (int i = 0; i < N; ++i) {
    ref[i] = 1.0f;
    f0[i] = f1[i] = f2[i] = 1.0f;
    valid0[i] = valid1[i] = valid2[i] = 1;
  }
  /* frame 0: pixels 0,1 wrong; frame 1: pixels 1,2,3 wrong; frame 2: pixel
   * 3 wrong, and pixel 0 invalid in frame 2. */
  f0[0] = f0[1] = 0.0f;
  f1[1] = f1[2] = f1[3] = 0.2f;
  f2[3] = 0.3f;
  f2[0] = 0.0f; /* wrong but invalid: not wrong, and not compared */
  valid2[0] = 0;

  unsigned char w0[N], w1[N], w2[N];
  CHECK(vshm_error_state(f0, ref, valid0, W, H, w0) == 2);
  CHECK(vshm_error_state(f1, ref, valid1, W, H, w1) == 3);
  CHECK(vshm_error_state(f2, ref, valid2, W, H, w2) == 1);
  CHECK(w2[0] == 0);

  const unsigned char *wrong[3] = {w0, w1, w2};
  const unsigned char *valid[3] = {valid0, valid1, valid2};
  int pairs = -1;
  /* pair (0,1): flips at 0, 2, 3 of 20 -> 15%; pair (1,2): pixel 0 not
   * valid in both, flips at 1, 2 of 19 -> 200/19 %. */
  double want = (15.0 + 200.0 / 19.0) / 2.0;
  CHECK_NEAR(vshm_flicker_pct(wrong, valid, 3, W, H, &pairs), want, 1e-12);
  CHECK(pairs == 2);

  /* a steady error does not flicker */
  const unsigned char *same[3] = {w1, w1, w1};
  CHECK(vshm_flicker_pct(same, valid, 3, W, H, NULL) == 0.0);
  /* one frame: no pair, 0 */
  CHECK(vshm_flicker_pct(wrong, valid, 1, W, H, &pairs) == 0.0 && pairs == 0);
  CHECK(vshm_flicker_pct(wrong, valid, 0, W, H, &pairs) == 0.0 && pairs == 0);
  /* a pair without a common valid pixel is skipped, not averaged as 0 */
  unsigned char none[N] = {0};
  const unsigned char *valid_gap[3] = {valid0, none, valid2};
  CHECK(vshm_flicker_pct(wrong, valid_gap, 3, W, H, &pairs) == 0.0 && pairs == 0);
  const unsigned char *valid_4[4] = {valid0, valid1, none, valid2};
  const unsigned char *wrong_4[4] = {w0, w1, w1, w2};
  CHECK_NEAR(vshm_flicker_pct(wrong_4, valid_4, 4, W, H, &pairs), 15.0, 1e-12);
  CHECK(pairs == 1);

  /* bad arguments */
  CHECK(vshm_flicker_pct(NULL, valid, 3, W, H, NULL) == -1.0);
  CHECK(vshm_flicker_pct(wrong, valid, -1, W, H, NULL) == -1.0);
  CHECK(vshm_flicker_pct(wrong, valid, 3, 0, H, NULL) == -1.0);
  CHECK(vshm_error_state(f0, ref, valid0, W, H, NULL) == -1);
  return vsh_check_report("metrics.flicker");
}
