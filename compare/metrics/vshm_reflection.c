/* vshm_reflection.c - reflection_mae, the colour error over a mirror's
 * pixels (definition: vshm_metrics.h, docs/metrics.md). */
#include "vshm_metrics.h"
#include "vshm_metrics_size.h"

#include <math.h>
#include <stddef.h>

/* Clamped like a display would: an over-bright or NaN sample must not make
 * one pixel outweigh the rest (the result stays in [0,1]). */
static double channel(float x) { return !(x > 0.0f) ? 0.0 : x > 1.0f ? 1.0 : (double)x; }

int vshm_reflection_mae(const float *rgb, const float *rgb_ref, const unsigned char *mirror,
                        const unsigned char *exclude, int width, int height, double *mae,
                        long *pixels) {
  if (mae) *mae = 0.0;
  if (pixels) *pixels = 0;
  if (!rgb || !rgb_ref || !mirror || !mae || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  long count = 0;
  double sum = 0.0; /* double: a float sum of 10^7 terms loses digits */
  for (size_t i = 0; i < n; ++i) {
    if (!mirror[i] || (exclude && exclude[i])) continue;
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e += fabs(channel(rgb[3 * i + c]) - channel(rgb_ref[3 * i + c]));
    sum += e / 3.0;
    ++count;
  }
  if (pixels) *pixels = count;
  if (count == 0) return VSHM_METRICS_EMPTY;
  *mae = sum / (double)count;
  return VSHM_METRICS_OK;
}
