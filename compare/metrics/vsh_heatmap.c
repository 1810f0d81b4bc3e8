/* vsh_heatmap.c - the signed error heat map of the HTML report. */
#include "vsh_metrics.h"
#include "vsh_metrics_size.h"

#include <math.h>
#include <stddef.h>

int vsh_error_heatmap_rgb(const float *v, const float *v_ref, const unsigned char *valid,
                          int width, int height, unsigned char *rgb) {
  if (!v || !v_ref || !valid || !rgb || !vsh_metrics_size_ok(width, height))
    return VSH_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  for (size_t i = 0; i < n; ++i) {
    unsigned char *p = rgb + 3 * i;
    if (!valid[i]) {
      p[0] = p[1] = p[2] = 128;
      continue;
    }
    double e = (double)v[i] - (double)v_ref[i];
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
  return VSH_METRICS_OK;
}
