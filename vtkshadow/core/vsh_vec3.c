/* vsh_vec3.c - see vsh_vec3.h. */
#include "vsh_vec3.h"

#include <math.h>

double vsh_vec3_dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void vsh_vec3_cross(const double a[3], const double b[3], double out[3]) {
  const double x = a[1] * b[2] - a[2] * b[1];
  const double y = a[2] * b[0] - a[0] * b[2];
  const double z = a[0] * b[1] - a[1] * b[0];
  out[0] = x;
  out[1] = y;
  out[2] = z;
}

/* Largest absolute component; the scale used to keep squares in range. */
static double max_abs(const double v[3]) {
  double m = fabs(v[0]);
  if (fabs(v[1]) > m) m = fabs(v[1]);
  if (fabs(v[2]) > m) m = fabs(v[2]);
  return m;
}

/* Below this largest component and above its inverse, the plain sum of
 * squares neither overflows nor loses the vector to underflow (the largest
 * square stays above DBL_MIN), so it needs no scaling: the tracer's per-pixel
 * rays take this path, scaling costs three divisions more. */
static const double UnscaledLimit = 1e150;

/* Whether v is finite (a NaN component fails the sum) and in that range. */
static int unscaled(const double v[3]) {
  const double m = max_abs(v);
  return m < UnscaledLimit && m > 1.0 / UnscaledLimit && isfinite(v[0] + v[1] + v[2]);
}

double vsh_vec3_length(const double v[3]) {
  if (unscaled(v)) {
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  if (!vsh_vec3_is_finite(v)) return fabs(v[0]) + fabs(v[1]) + fabs(v[2]);
  const double m = max_abs(v);
  if (m == 0.0) return 0.0;
  const double x = v[0] / m, y = v[1] / m, z = v[2] / m;
  return m * sqrt(x * x + y * y + z * z);
}

double vsh_vec3_normalize(const double v[3], double out[3]) {
  if (unscaled(v)) {
    const double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    out[0] = v[0] / len;
    out[1] = v[1] / len;
    out[2] = v[2] / len;
    return len;
  }
  if (!vsh_vec3_is_finite(v)) {
    out[0] = out[1] = out[2] = 0.0;
    return 0.0;
  }
  const double len = vsh_vec3_length(v);
  if (!(len > 0.0)) {
    out[0] = out[1] = out[2] = 0.0;
    return 0.0;
  }
  /* Divide by the scaled length rather than len itself, so that denormal
   * inputs (len itself denormal, 1/len overflowing) still normalize. */
  const double m = max_abs(v);
  const double x = v[0] / m, y = v[1] / m, z = v[2] / m;
  const double s = sqrt(x * x + y * y + z * z);
  out[0] = x / s;
  out[1] = y / s;
  out[2] = z / s;
  return len;
}

void vsh_vec3_sub(const double a[3], const double b[3], double out[3]) {
  out[0] = a[0] - b[0];
  out[1] = a[1] - b[1];
  out[2] = a[2] - b[2];
}

void vsh_vec3_add(const double a[3], const double b[3], double out[3]) {
  out[0] = a[0] + b[0];
  out[1] = a[1] + b[1];
  out[2] = a[2] + b[2];
}

void vsh_vec3_scale(const double v[3], double s, double out[3]) {
  out[0] = v[0] * s;
  out[1] = v[1] * s;
  out[2] = v[2] * s;
}

void vsh_vec3_lerp(const double a[3], const double b[3], double t, double out[3]) {
  const double u = 1.0 - t;
  out[0] = u * a[0] + t * b[0];
  out[1] = u * a[1] + t * b[1];
  out[2] = u * a[2] + t * b[2];
}

int vsh_vec3_parallel(const double a[3], const double b[3], double rel_tol) {
  double na[3], nb[3], c[3];
  if (!vsh_vec3_is_finite(a) || !vsh_vec3_is_finite(b)) return 1;
  if (vsh_vec3_normalize(a, na) == 0.0 || vsh_vec3_normalize(b, nb) == 0.0) return 1;
  vsh_vec3_cross(na, nb, c);
  return vsh_vec3_length(c) <= rel_tol;
}

int vsh_vec3_is_finite(const double v[3]) {
  return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}
