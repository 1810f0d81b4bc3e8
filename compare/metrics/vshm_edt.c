/* vshm_edt.c - see vshm_edt.h. */
#include "vshm_edt.h"

#include <math.h>
#include <stdlib.h>

/* Stands in for "no feature" inside the passes: a finite value keeps the
 * parabola intersections finite (INFINITY - INFINITY would be NaN). Any
 * real squared distance is below 2 * 32768^2, far under this, so a far
 * parabola never wins where a real one exists. */
#define FAR 1e20

/* 1D transform: d[q] = min_p (q - p)^2 + f[p]. v holds the abscissae of
 * the parabolas in the lower envelope, z the boundaries between them. */
static void edt_1d(const double *f, int n, double *d, int *v, double *z) {
  int k = 0;
  v[0] = 0;
  z[0] = -HUGE_VAL;
  z[1] = HUGE_VAL;
  for (int q = 1; q < n; ++q) {
    double s;
    for (;;) {
      int p = v[k];
      /* where the parabola from q crosses the one from p */
      s = ((f[q] + (double)q * q) - (f[p] + (double)p * p)) / (2.0 * (q - p));
      if (s > z[k]) break;
      --k; /* p is hidden below q's parabola everywhere it was lowest */
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = HUGE_VAL;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    double dq = q - v[k];
    d[q] = dq * dq + f[v[k]];
  }
}

long vshm_edt_sq(const unsigned char *feature, int width, int height, double *d2) {
  if (!feature || !d2 || width <= 0 || height <= 0) return -1;
  size_t n = (size_t)width * (size_t)height;
  long count = 0;
  for (size_t i = 0; i < n; ++i) {
    if (feature[i]) ++count;
    d2[i] = feature[i] ? 0.0 : FAR;
  }
  if (count == 0) {
    for (size_t i = 0; i < n; ++i) d2[i] = INFINITY;
    return 0;
  }
  int m = width > height ? width : height;
  double *f = malloc(sizeof(double) * (size_t)m);
  double *d = malloc(sizeof(double) * (size_t)m);
  double *z = malloc(sizeof(double) * ((size_t)m + 1));
  int *v = malloc(sizeof(int) * (size_t)m);
  if (!f || !d || !z || !v) {
    free(f);
    free(d);
    free(z);
    free(v);
    return -1;
  }
  /* Columns first, then rows: after the column pass every row holds, per
   * column, the squared vertical distance, which the row pass combines. */
  for (int x = 0; x < width; ++x) {
    for (int y = 0; y < height; ++y) f[y] = d2[(size_t)y * width + x];
    edt_1d(f, height, d, v, z);
    for (int y = 0; y < height; ++y) d2[(size_t)y * width + x] = d[y];
  }
  for (int y = 0; y < height; ++y) {
    double *row = d2 + (size_t)y * width;
    for (int x = 0; x < width; ++x) f[x] = row[x];
    edt_1d(f, width, row, v, z);
  }
  free(f);
  free(d);
  free(z);
  free(v);
  return count;
}
