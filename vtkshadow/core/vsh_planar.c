/* vsh_planar.c - see vsh_planar.h. */
#include "vsh_planar.h"

#include "vsh_vec3.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* Dot product of n-vectors evaluated as if in twice the working precision
 * (Ogita, Rump & Oishi's Dot2: error-free products via fma, error-free sums).
 * Used where large terms cancel: N.L + d, d + N.origin at 1e6 offsets. */
static double dot_compensated(const double *x, const double *y, int n) {
  double p = x[0] * y[0];
  double s = fma(x[0], y[0], -p);
  for (int i = 1; i < n; ++i) {
    const double h = x[i] * y[i];
    const double r = fma(x[i], y[i], -h);
    const double t = p + h;
    const double z = t - p;
    const double q = (p - (t - z)) + (h - z);
    p = t;
    s += q + r;
  }
  return p + s;
}

static int finite4(const double v[4]) {
  return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]) && isfinite(v[3]);
}

int vsh_planar_normalize_plane(const double plane[4], double out[4]) {
  double n[3];
  const double len = finite4(plane) ? vsh_vec3_normalize(plane, n) : 0.0;
  const double d = len > 0.0 ? plane[3] / len : 0.0;
  if (!(len > 0.0) || !isfinite(d)) {
    memset(out, 0, 4 * sizeof(double));
    return VSH_PLANAR_INVALID;
  }
  out[0] = n[0];
  out[1] = n[1];
  out[2] = n[2];
  out[3] = d;
  return VSH_PLANAR_OK;
}

/* Normalized light: point (L, 1) or directional (unit -D, 0). */
static int normalize_light(const double light[4], double out[4]) {
  memset(out, 0, 4 * sizeof(double));
  if (!finite4(light)) return VSH_PLANAR_INVALID;
  if (light[3] != 0.0) {
    for (int k = 0; k < 3; ++k) out[k] = light[k] / light[3];
    out[3] = 1.0;
    if (!vsh_vec3_is_finite(out)) {
      memset(out, 0, 4 * sizeof(double));
      return VSH_PLANAR_INVALID;
    }
    return VSH_PLANAR_OK;
  }
  if (vsh_vec3_normalize(light, out) == 0.0) return VSH_PLANAR_INVALID;
  out[3] = 0.0;
  return VSH_PLANAR_OK;
}

/* Normalizes plane and light, optionally re-expresses both relative to
 * origin, and computes pi.l with its NO_SHADOW test. Everything that builds
 * M or its clip planes goes through here, so they always agree. */
static int prepare(const double plane[4], const double light[4], const double *origin,
                   double pi[4], double l[4], double *pl) {
  *pl = 0.0;
  int st = vsh_planar_normalize_plane(plane, pi);
  if (st == VSH_PLANAR_OK) st = normalize_light(light, l);
  if (st == VSH_PLANAR_OK && origin) {
    if (!vsh_vec3_is_finite(origin)) {
      st = VSH_PLANAR_INVALID;
    } else {
      /* pi' = (N, d + N.origin): X on the plane <=> X - origin on pi'. */
      const double x[4] = {pi[0], pi[1], pi[2], pi[3]};
      const double y[4] = {origin[0], origin[1], origin[2], 1.0};
      pi[3] = dot_compensated(x, y, 4);
      if (l[3] != 0.0) vsh_vec3_sub(l, origin, l); /* directions do not move */
      if (!isfinite(pi[3]) || !vsh_vec3_is_finite(l)) st = VSH_PLANAR_INVALID;
    }
  }
  if (st != VSH_PLANAR_OK) return st;

  *pl = dot_compensated(pi, l, 4);
  /* Scale-aware "zero": rounding of the inputs is relative to the size of
   * the terms, not to 1. Each term is <= DBL_MAX (|N| <= 1, |l_w| <= 1), and
   * the sum is taken in eighths (exact) so that it cannot overflow either:
   * threshold = 8 eps sum|terms| = 64 eps sum|terms|/8. */
  const double mag8 = 0.125 * fabs(pi[0] * l[0]) + 0.125 * fabs(pi[1] * l[1]) +
                      0.125 * fabs(pi[2] * l[2]) + 0.125 * fabs(pi[3] * l[3]);
  if (!isfinite(*pl) || !isfinite(mag8)) return VSH_PLANAR_INVALID;
  if (!(*pl > 64.0 * DBL_EPSILON * mag8)) return VSH_PLANAR_NO_SHADOW;
  return VSH_PLANAR_OK;
}

static int build_matrix(int st, const double pi[4], const double l[4], double pl, double out[16]) {
  double m[16];
  if (st == VSH_PLANAR_OK) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) m[i * 4 + j] = (i == j ? pl : 0.0) - l[i] * pi[j];
    for (int k = 0; k < 16 && st == VSH_PLANAR_OK; ++k)
      if (!isfinite(m[k])) st = VSH_PLANAR_INVALID;
  }
  if (st != VSH_PLANAR_OK) memset(m, 0, sizeof m);
  memcpy(out, m, sizeof m);
  return st;
}

int vsh_planar_shadow_matrix(const double plane[4], const double light[4], double out[16]) {
  double pi[4], l[4], pl;
  const int st = prepare(plane, light, NULL, pi, l, &pl);
  return build_matrix(st, pi, l, pl, out);
}

int vsh_planar_shadow_matrix_relative(const double plane[4], const double light[4],
                                      const double origin[3], double out[16]) {
  double pi[4], l[4], pl;
  const int st = prepare(plane, light, origin, pi, l, &pl);
  return build_matrix(st, pi, l, pl, out);
}

int vsh_planar_plane_from_points(const double origin[3], const double point1[3],
                                 const double point2[3], double out_plane[4]) {
  double a[3], b[3], c[3], n[3];
  memset(out_plane, 0, 4 * sizeof(double));
  if (!vsh_vec3_is_finite(origin) || !vsh_vec3_is_finite(point1) || !vsh_vec3_is_finite(point2))
    return VSH_PLANAR_INVALID;
  vsh_vec3_sub(point1, origin, a);
  vsh_vec3_sub(point2, origin, b);
  if (vsh_vec3_parallel(a, b, VSH_PLANAR_COLLINEAR_TOL)) return VSH_PLANAR_INVALID;
  vsh_vec3_cross(a, b, c);
  if (vsh_vec3_normalize(c, n) == 0.0) return VSH_PLANAR_INVALID;
  const double d = -vsh_vec3_dot(n, origin);
  if (!isfinite(d)) return VSH_PLANAR_INVALID;
  out_plane[0] = n[0];
  out_plane[1] = n[1];
  out_plane[2] = n[2];
  out_plane[3] = d;
  return VSH_PLANAR_OK;
}

static int build_clip_planes(int st, const double pi[4], const double l[4], double pl,
                             double out_clip[2][4]) {
  if (st != VSH_PLANAR_OK) {
    for (int k = 0; k < 2; ++k) {
      out_clip[k][0] = out_clip[k][1] = out_clip[k][2] = 0.0;
      out_clip[k][3] = -1.0;
    }
    return st;
  }
  memcpy(out_clip[0], pi, 4 * sizeof(double));
  if (l[3] == 0.0) {
    out_clip[1][0] = out_clip[1][1] = out_clip[1][2] = 0.0;
    out_clip[1][3] = 1.0;
  } else {
    /* Row 3 of M with l_w = 1: pl e_3 - pi = (-N, pl - d) = (-N, N.L). */
    out_clip[1][0] = -pi[0];
    out_clip[1][1] = -pi[1];
    out_clip[1][2] = -pi[2];
    out_clip[1][3] = pl - pi[3];
  }
  return st;
}

int vsh_planar_caster_clip_planes(const double plane[4], const double light[4],
                                  double out_clip[2][4]) {
  double pi[4], l[4], pl;
  const int st = prepare(plane, light, NULL, pi, l, &pl);
  return build_clip_planes(st, pi, l, pl, out_clip);
}

int vsh_planar_caster_clip_planes_relative(const double plane[4], const double light[4],
                                           const double origin[3], double out_clip[2][4]) {
  double pi[4], l[4], pl;
  const int st = prepare(plane, light, origin, pi, l, &pl);
  return build_clip_planes(st, pi, l, pl, out_clip);
}

int vsh_planar_project_point(const double M[16], const double P[3], double out[3]) {
  double r[4];
  const double p4[4] = {P[0], P[1], P[2], 1.0};
  for (int i = 0; i < 4; ++i) r[i] = dot_compensated(M + 4 * i, p4, 4);
  const double w = r[3];
  if (w > 0.0 && isfinite(w)) {
    const double x = r[0] / w, y = r[1] / w, z = r[2] / w;
    if (isfinite(x) && isfinite(y) && isfinite(z)) {
      out[0] = x;
      out[1] = y;
      out[2] = z;
      return 1;
    }
  }
  const double keep[3] = {P[0], P[1], P[2]};
  memcpy(out, keep, sizeof keep);
  return 0;
}

int vsh_planar_project_point_clipped(const double plane[4], const double light[4],
                                     const double P[3], double out[3]) {
  double pi[4], l[4], pl, m[16], clip[2][4];
  const int st = prepare(plane, light, NULL, pi, l, &pl);
  build_matrix(st, pi, l, pl, m);
  build_clip_planes(st, pi, l, pl, clip);
  const double p4[4] = {P[0], P[1], P[2], 1.0};
  if (st != VSH_PLANAR_OK || !vsh_vec3_is_finite(P) || dot_compensated(clip[0], p4, 4) < 0.0 ||
      !(dot_compensated(clip[1], p4, 4) > 0.0)) {
    const double keep[3] = {P[0], P[1], P[2]};
    memcpy(out, keep, sizeof keep);
    return 0;
  }
  return vsh_planar_project_point(m, P, out);
}

int vsh_planar_plane_offset(const double plane[4], double distance, double out_plane[4]) {
  double pi[4];
  if (!isfinite(distance) || vsh_planar_normalize_plane(plane, pi) != VSH_PLANAR_OK) {
    memset(out_plane, 0, 4 * sizeof(double));
    return VSH_PLANAR_INVALID;
  }
  pi[3] -= distance;
  if (!isfinite(pi[3])) {
    memset(out_plane, 0, 4 * sizeof(double));
    return VSH_PLANAR_INVALID;
  }
  memcpy(out_plane, pi, sizeof pi);
  return VSH_PLANAR_OK;
}
