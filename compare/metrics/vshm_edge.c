/* vshm_edge.c - edge_px: symmetric mean distance between the 0.5-level
 * boundaries (cracks, see vshm_boundary.h) of v and v_ref, measured with
 * the exact distance transform on the doubled crack grid. */
#include "vshm_boundary.h"
#include "vshm_edt.h"
#include "vshm_metrics.h"
#include "vshm_metrics_size.h"

#include <math.h>
#include <stdlib.h>

/* Adds to *sum, for every counted crack of `from`, its distance in pixels
 * to the nearest crack of `to` (or `missing` when `to` has none), and the
 * number of counted cracks to *count. d2 is scratch of w2 * h2 doubles. */
static int accumulate(const unsigned char *from, const unsigned char *to, long to_count,
                      const unsigned char *exclude, int width, int w2, int h2,
                      double missing, double *d2, double *sum, long *count) {
  int have_dt = 0;
  for (int cy = 0; cy < h2; ++cy) {
    for (int cx = 0; cx < w2; ++cx) {
      size_t c = (size_t)cy * w2 + cx;
      if (!from[c]) continue;
      if (exclude) {
        long a, b;
        vshm_crack_pixels(cx, cy, width, &a, &b);
        if (exclude[a] || exclude[b]) continue;
      }
      double d = missing;
      if (to_count > 0) {
        /* The transform is only paid for when something is measured. */
        if (!have_dt) {
          if (vshm_edt_sq(to, w2, h2, d2) < 0) return VSHM_METRICS_ENOMEM;
          have_dt = 1;
        }
        d = 0.5 * sqrt(d2[c]); /* doubled grid: halve */
      }
      *sum += d;
      ++*count;
    }
  }
  return VSHM_METRICS_OK;
}

int vshm_edge_px(const float *v, const float *v_ref, const unsigned char *valid,
                 const unsigned char *exclude, int width, int height, double *edge_px) {
  if (!edge_px) return VSHM_METRICS_EINVAL;
  *edge_px = 0.0;
  if (!v || !v_ref || !valid || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;

  int w2 = 2 * width - 1, h2 = 2 * height - 1;
  size_t n2 = (size_t)w2 * (size_t)h2;
  unsigned char *ct = malloc(n2);
  unsigned char *cr = malloc(n2);
  double *d2 = malloc(n2 * sizeof *d2);
  int rc = VSHM_METRICS_ENOMEM;
  if (ct && cr && d2) {
    long nt = vshm_boundary_cracks(v, valid, width, height, ct);
    long nr = vshm_boundary_cracks(v_ref, valid, width, height, cr);
    /* The sentinel for "the other image has no boundary": no real distance
     * inside the image reaches the diagonal. */
    double missing = sqrt((double)width * width + (double)height * height);
    double sum = 0.0;
    long count = 0;
    rc = accumulate(ct, cr, nr, exclude, width, w2, h2, missing, d2, &sum, &count);
    if (rc == VSHM_METRICS_OK)
      rc = accumulate(cr, ct, nt, exclude, width, w2, h2, missing, d2, &sum, &count);
    if (rc == VSHM_METRICS_OK) *edge_px = count > 0 ? sum / (double)count : 0.0;
  }
  free(ct);
  free(cr);
  free(d2);
  return rc;
}
