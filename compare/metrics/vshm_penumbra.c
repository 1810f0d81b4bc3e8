/* vshm_penumbra.c - penumbra metrics: error and bias inside the reference's
 * penumbra, leaks into its umbra, false shadow on its lit area, penumbra
 * width, and contour distances at three levels (vshm_penumbra.h). */
#include "vshm_penumbra.h"

#include "vshm_metrics.h"
#include "vshm_metrics_size.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int in_penumbra(float r) { return r > VSHM_PENUMBRA_LO && r < VSHM_PENUMBRA_HI; }

int vshm_penumbra_mask(const float *v_ref, const unsigned char *valid, int width, int height,
                       unsigned char *mask) {
  if (!v_ref || !valid || !mask || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;
  memset(mask, 0, (size_t)width * (size_t)height);
  /* Dilation by one pixel: a valid pixel joins when any pixel of its 3 x 3
   * neighbourhood is a valid penumbra pixel. The dilation covers the pixel
   * footprints a rasterizer and a ray tracer disagree on at the rim. */
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      size_t i = (size_t)y * width + x;
      if (!valid[i]) continue;
      for (int dy = -1; dy <= 1 && !mask[i]; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int xx = x + dx, yy = y + dy;
          size_t j;
          if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
          j = (size_t)yy * width + xx;
          if (valid[j] && in_penumbra(v_ref[j])) {
            mask[i] = 1;
            break;
          }
        }
    }
  return VSHM_METRICS_OK;
}

/* Pixels with 0.1 < v < 0.9 over cracks of the 0.5 contour, both counted
 * where nothing is excluded. A crack is one pixel long, so a straight
 * penumbra k pixels wide measures k; a curved or diagonal contour counts
 * more cracks than its length (up to sqrt 2 on a diagonal), the same way
 * for v and v_ref, so the ratio is the figure to read. */
static double width_of(const float *v, const unsigned char *valid, const unsigned char *exclude,
                       int width, int height) {
  long area = 0, cracks = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      size_t i = (size_t)y * width + x;
      if (!valid[i] || (exclude && exclude[i])) continue;
      area += v[i] > 0.1f && v[i] < 0.9f;
      if (x + 1 < width && valid[i + 1] && !(exclude && exclude[i + 1]))
        cracks += (v[i] >= 0.5f) != (v[i + 1] >= 0.5f);
      if (y + 1 < height && valid[i + width] && !(exclude && exclude[i + width]))
        cracks += (v[i] >= 0.5f) != (v[i + width] >= 0.5f);
    }
  return cracks > 0 ? (double)area / (double)cracks : 0.0;
}

/* Contour distance at `level`: both images thresholded there (1 at or
 * above, 0 below), then edge_px, whose contour is at 0.5. */
static int contour_at(const float *v, const float *v_ref, const unsigned char *valid,
                      const unsigned char *exclude, int width, int height, float level,
                      float *a, float *b, double *out) {
  size_t n = (size_t)width * (size_t)height;
  for (size_t i = 0; i < n; ++i) {
    a[i] = v[i] >= level ? 1.0f : 0.0f;
    b[i] = v_ref[i] >= level ? 1.0f : 0.0f;
  }
  return vshm_edge_px(a, b, valid, exclude, width, height, out);
}

int vshm_penumbra_compute(const float *v, const float *v_ref, const unsigned char *valid,
                          const unsigned char *exclude, int width, int height,
                          vshm_penumbra *out) {
  static const float levels[3] = {0.1f, 0.5f, 0.9f};
  if (!out) return VSHM_METRICS_EINVAL;
  memset(out, 0, sizeof *out);
  if (!v || !v_ref || !valid || !vshm_metrics_size_ok(width, height)) return VSHM_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  unsigned char *mask = malloc(n);
  float *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
  int rc = VSHM_METRICS_ENOMEM;
  if (mask && a && b && vshm_penumbra_mask(v_ref, valid, width, height, mask) == VSHM_METRICS_OK) {
    double sum_abs = 0.0, sum = 0.0;
    long leaks = 0, false_shadow = 0;
    for (size_t i = 0; i < n; ++i) {
      if (!valid[i] || (exclude && exclude[i])) continue;
      double e = (double)v[i] - (double)v_ref[i];
      if (mask[i]) {
        ++out->penumbra_pixels;
        sum_abs += fabs(e);
        sum += e;
      }
      if (v_ref[i] <= VSHM_PENUMBRA_LO) {
        ++out->umbra_pixels;
        leaks += v[i] > 0.1f;
      } else if (v_ref[i] >= VSHM_PENUMBRA_HI) {
        ++out->lit_pixels;
        false_shadow += v[i] < 0.9f;
      }
    }
    if (out->penumbra_pixels > 0) {
      out->pen_mae = sum_abs / (double)out->penumbra_pixels;
      out->pen_bias = sum / (double)out->penumbra_pixels;
    }
    out->leak_pct = 100.0 * (double)leaks / (double)(out->umbra_pixels > 0 ? out->umbra_pixels : 1);
    out->false_shadow_pct =
        100.0 * (double)false_shadow / (double)(out->lit_pixels > 0 ? out->lit_pixels : 1);
    out->width_px = width_of(v, valid, exclude, width, height);
    out->ref_width_px = width_of(v_ref, valid, exclude, width, height);
    out->width_ratio = out->ref_width_px > 0.0 ? out->width_px / out->ref_width_px : 0.0;
    rc = VSHM_METRICS_OK;
    for (int k = 0; k < 3 && rc == VSHM_METRICS_OK; ++k)
      rc = contour_at(v, v_ref, valid, exclude, width, height, levels[k], a, b,
                      &out->contour_px[k]);
    if (rc == VSHM_METRICS_OK && out->penumbra_pixels == 0) rc = VSHM_METRICS_EMPTY;
  }
  if (rc < 0) memset(out, 0, sizeof *out);
  free(mask);
  free(a);
  free(b);
  return rc;
}

int vshm_penumbra_heatmap_rgb(const float *v, const float *v_ref, const unsigned char *valid,
                              int width, int height, unsigned char *rgb) {
  if (!v || !v_ref || !valid || !rgb || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  unsigned char *mask = malloc(n);
  if (!mask) return VSHM_METRICS_ENOMEM;
  vshm_penumbra_mask(v_ref, valid, width, height, mask);
  for (size_t i = 0; i < n; ++i) {
    unsigned char *p = rgb + 3 * i;
    if (!valid[i]) {
      p[0] = p[1] = p[2] = 128;
    } else if (!mask[i]) {
      double g = 96.0 * fmin(1.0, fmax(0.0, (double)v_ref[i]));
      p[0] = p[1] = p[2] = (unsigned char)lrint(g);
    } else {
      double e = fmax(-1.0, fmin(1.0, ((double)v[i] - (double)v_ref[i]) / 0.25));
      unsigned char fade = (unsigned char)lrint(255.0 * (1.0 - fabs(e)));
      p[0] = e < 0 ? fade : 255;
      p[1] = fade;
      p[2] = e > 0 ? fade : 255;
    }
  }
  free(mask);
  return VSHM_METRICS_OK;
}
