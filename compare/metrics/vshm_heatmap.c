/* vshm_heatmap.c - the signed error heat maps of the HTML report (visibility
 * and the mirror region's colour). */
#include "vshm_metrics.h"
#include "vshm_metrics_size.h"

#include <math.h>
#include <stddef.h>

/* One pixel of signed error e: white at 0, blue below, red above. */
static void heat_pixel(double e, unsigned char *p) {
    if (!(e >= -1.0)) e = -1.0; /* also NaN: show it loudly */
    if (e > 1.0) e = 1.0;
    /* the two channels other than the error's colour fade to 0 */
    unsigned char fade = (unsigned char)lrint(255.0 * (1.0 - fabs(e)));
    if (e < 0) { /* too dark: blue */
      p[0] = fade;
      p[1] = fade;
      p[2] = 255;
    } else { /* too bright (or exact: fade = 255, white): red */
      p[0] = 255;
      p[1] = fade;
      p[2] = fade;
    }
}

int vshm_error_heatmap_rgb(const float *v, const float *v_ref, const unsigned char *valid,
                           int width, int height, unsigned char *rgb) {
  if (!v || !v_ref || !valid || !rgb || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  for (size_t i = 0; i < n; ++i) {
    unsigned char *p = rgb + 3 * i;
    if (!valid[i])
      p[0] = p[1] = p[2] = 128;
    else
      heat_pixel((double)v[i] - (double)v_ref[i], p);
  }
  return VSHM_METRICS_OK;
}

/* A colour channel as the reflection metric sees it: [0,1], NaN -> 0. */
static double channel(float x) { return !(x > 0.0f) ? 0.0 : x > 1.0f ? 1.0 : (double)x; }

int vshm_reflection_heatmap_rgb(const float *rgb, const float *rgb_ref,
                                const unsigned char *mirror, int width, int height,
                                unsigned char *out) {
  if (!rgb || !rgb_ref || !mirror || !out || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  for (size_t i = 0; i < n; ++i) {
    unsigned char *p = out + 3 * i;
    if (!mirror[i]) {
      p[0] = p[1] = p[2] = 128;
      continue;
    }
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e += channel(rgb[3 * i + c]) - channel(rgb_ref[3 * i + c]);
    heat_pixel(e / 3.0, p);
  }
  return VSHM_METRICS_OK;
}
