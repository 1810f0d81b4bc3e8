/* vshm_flicker.c - per-frame error state and flicker_pct (shimmering). */
#include "vshm_metrics.h"
#include "vshm_metrics_size.h"

#include <math.h>
#include <stddef.h>

long vshm_error_state(const float *v, const float *v_ref, const unsigned char *valid,
                      int width, int height, unsigned char *wrong) {
  if (!v || !v_ref || !valid || !wrong || !vshm_metrics_size_ok(width, height)) return -1;
  size_t n = (size_t)width * (size_t)height;
  long count = 0;
  for (size_t i = 0; i < n; ++i) {
    /* same test as wrong_pct, so flicker counts exactly its flips */
    wrong[i] = valid[i] && fabs((double)v[i] - (double)v_ref[i]) > 0.5;
    count += wrong[i];
  }
  return count;
}

double vshm_flicker_pct(const unsigned char *const *wrong, const unsigned char *const *valid,
                        int frames, int width, int height, int *pairs_used) {
  if (pairs_used) *pairs_used = 0;
  if (!wrong || !valid || frames < 0 || !vshm_metrics_size_ok(width, height)) return -1.0;
  for (int f = 0; f < frames; ++f)
    if (!wrong[f] || !valid[f]) return -1.0;

  size_t n = (size_t)width * (size_t)height;
  double sum_pct = 0.0;
  int pairs = 0;
  for (int f = 1; f < frames; ++f) {
    const unsigned char *w0 = wrong[f - 1], *w1 = wrong[f];
    const unsigned char *m0 = valid[f - 1], *m1 = valid[f];
    long both = 0, flips = 0;
    for (size_t i = 0; i < n; ++i) {
      if (!m0[i] || !m1[i]) continue; /* a pixel entering view is no flip */
      ++both;
      flips += (w0[i] != 0) != (w1[i] != 0);
    }
    if (both == 0) continue; /* nothing comparable: no 0% to dilute the mean */
    sum_pct += 100.0 * (double)flips / (double)both;
    ++pairs;
  }
  if (pairs_used) *pairs_used = pairs;
  return pairs > 0 ? sum_pct / pairs : 0.0;
}
