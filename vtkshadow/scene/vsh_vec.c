/* vsh_vec.c - the little 3-vector maths the validator and tessellator need.
 *
 * Scene files may contain anything from 1e-300 to 1e300; the validation checks
 * (zero length, parallel vectors, singular transforms) must give the right
 * answer across that range instead of overflowing to inf or underflowing to 0,
 * so lengths are computed on vectors scaled by their largest component.
 */
#include "vsh_scene_internal.h"

#include <math.h>

static double max_abs3(const double v[3]) {
  double m = fabs(v[0]);
  if (fabs(v[1]) > m) m = fabs(v[1]);
  if (fabs(v[2]) > m) m = fabs(v[2]);
  return m;
}

double vsh__norm3(const double v[3]) {
  double m = max_abs3(v), x, y, z;
  if (m == 0.0 || !isfinite(m)) return m;
  x = v[0] / m;
  y = v[1] / m;
  z = v[2] / m;
  return m * sqrt(x * x + y * y + z * z);
}

int vsh__normalize3(const double v[3], double out[3]) {
  /* out may alias v: read everything before writing. */
  double m = max_abs3(v), s[3], n;
  if (m == 0.0 || !isfinite(m)) {
    out[0] = out[1] = out[2] = 0.0;
    return 0;
  }
  s[0] = v[0] / m;
  s[1] = v[1] / m;
  s[2] = v[2] / m;
  n = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  out[0] = s[0] / n;
  out[1] = s[1] / n;
  out[2] = s[2] / n;
  return 1;
}

void vsh__cross3(const double a[3], const double b[3], double out[3]) {
  double x = a[1] * b[2] - a[2] * b[1];
  double y = a[2] * b[0] - a[0] * b[2];
  double z = a[0] * b[1] - a[1] * b[0];
  out[0] = x;
  out[1] = y;
  out[2] = z;
}

double vsh__dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double vsh__sin_between(const double a[3], const double b[3]) {
  double ua[3], ub[3], c[3];
  if (!vsh__normalize3(a, ua) || !vsh__normalize3(b, ub)) return -1.0;
  vsh__cross3(ua, ub, c);
  return vsh__norm3(c);
}

double vsh__relative_det(const double m[16]) {
  double r[3][3];
  int i;
  /* Normalizing the rows makes the test independent of the units: a scale of
   * 1e-6 on one axis is as regular as a scale of 1. */
  for (i = 0; i < 3; ++i) {
    const double row[3] = {m[4 * i], m[4 * i + 1], m[4 * i + 2]};
    if (!vsh__normalize3(row, r[i])) return 0.0;
  }
  return r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
         r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
         r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
}

void vsh__frame_around(const double a[3], double u[3], double v[3]) {
  double e[3] = {0.0, 0.0, 0.0};
  int i, smallest = 0;
  for (i = 1; i < 3; ++i)
    if (fabs(a[i]) < fabs(a[smallest])) smallest = i;
  e[smallest] = 1.0;
  for (i = 0; i < 3; ++i) u[i] = e[i] - a[smallest] * a[i];
  vsh__normalize3(u, u);
  vsh__cross3(a, u, v);
}
