/* vshm_metrics.c - the per-pixel metrics; edge_px is in vshm_edge.c. */
#include "vshm_metrics.h"

#include "vshm_boundary.h"
#include "vshm_metrics_size.h"

#include <math.h>
#include <string.h>

int vshm_metrics_compute(const float *v, const float *v_ref, const unsigned char *valid,
                         const unsigned char *exclude, int width, int height,
                         vshm_metrics *out) {
  if (!out) return VSHM_METRICS_EINVAL;
  memset(out, 0, sizeof *out);
  if (!v || !v_ref || !valid || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;

  size_t n = (size_t)width * (size_t)height;
  long n_valid = 0, n_cmp = 0, n_wrong = 0, n_fshadow = 0, n_flight = 0;
  long n_ref_shadow = 0, n_test_shadow = 0;
  double sum_abs = 0.0; /* double: a float sum of 10^7 terms loses digits */
  for (size_t i = 0; i < n; ++i) {
    if (!valid[i]) continue;
    ++n_valid;
    if (exclude && exclude[i]) continue;
    ++n_cmp;
    double t = v[i], r = v_ref[i];
    double e = fabs(t - r);
    sum_abs += e;
    if (e > 0.5) ++n_wrong;
    if (r > 0.9 && t < 0.5) ++n_fshadow;
    if (r < 0.1 && t > 0.5) ++n_flight;
    n_ref_shadow += !vshm_is_lit(v_ref[i]);
    n_test_shadow += !vshm_is_lit(v[i]);
  }
  out->valid_pixels = n_valid;
  if (n_cmp == 0) return VSHM_METRICS_EMPTY;

  double edge = 0.0;
  int rc = vshm_edge_px(v, v_ref, valid, exclude, width, height, &edge);
  if (rc != VSHM_METRICS_OK) {
    memset(out, 0, sizeof *out);
    return rc;
  }
  out->compared_pixels = n_cmp;
  out->vis_mae = sum_abs / (double)n_cmp;
  out->wrong_pct = 100.0 * (double)n_wrong / (double)n_cmp;
  out->false_shadow_pct = 100.0 * (double)n_fshadow / (double)n_cmp;
  out->false_light_pct = 100.0 * (double)n_flight / (double)n_cmp;
  out->edge_px = edge;
  out->ref_shadow_pixels = n_ref_shadow;
  out->test_shadow_pixels = n_test_shadow;
  out->wrong_of_shadow_pct = 100.0 * (double)n_wrong / (double)(n_ref_shadow > 0 ? n_ref_shadow : 1);
  out->wrong_of_test_shadow_pct =
      100.0 * (double)n_wrong / (double)(n_test_shadow > 0 ? n_test_shadow : 1);
  return VSHM_METRICS_OK;
}
