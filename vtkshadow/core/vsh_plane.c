/* vsh_plane.c - plane fitting and plane tests (vsh_plane.h). */
#include "vsh_plane.h"

#include <math.h>
#include <string.h>

/* The largest fan triangle's normal (unnormalized) from point 0; returns
 * its length (0 when every fan triangle is collinear). */
static double largest_fan_normal(const double *p, size_t count, double out[3]) {
  double best = 0.0;
  out[0] = out[1] = out[2] = 0.0;
  for (size_t i = 1; i + 1 < count; ++i) {
    const double a[3] = {p[3 * i] - p[0], p[3 * i + 1] - p[1], p[3 * i + 2] - p[2]};
    const double b[3] = {p[3 * i + 3] - p[0], p[3 * i + 4] - p[1], p[3 * i + 5] - p[2]};
    const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]};
    const double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > best) {
      best = length;
      memcpy(out, n, sizeof(n));
    }
  }
  return best;
}

vsh_plane_status vsh_plane_fit_points(const double *points, size_t count, double rel_tolerance,
                                      double out_plane[4]) {
  return vsh_plane_fit_stored_points(points, count, rel_tolerance, 0.0, out_plane);
}

vsh_plane_status vsh_plane_fit_stored_points(const double *points, size_t count,
                                             double rel_tolerance, double stored_eps,
                                             double out_plane[4]) {
  if (out_plane) memset(out_plane, 0, 4 * sizeof(double));
  if (!points || !out_plane || !(rel_tolerance >= 0.0) || !(stored_eps >= 0.0) ||
      !isfinite(rel_tolerance) || !isfinite(stored_eps))
    return VSH_PLANE_INVALID;
  for (size_t i = 0; i < 3 * count; ++i)
    if (!isfinite(points[i])) return VSH_PLANE_INVALID;
  if (count < 3) return VSH_PLANE_NO_AREA;
  double n[3];
  const double length = largest_fan_normal(points, count, n);
  if (!(length > 0.0) || !isfinite(length)) return VSH_PLANE_NO_AREA;
  const double *o = points;
  double size = 0.0, magnitude = 0.0;
  for (size_t i = 0; i < count; ++i)
    for (int a = 0; a < 3; ++a) {
      size = fmax(size, fabs(points[3 * i + a] - o[a]));
      magnitude = fmax(magnitude, fabs(points[3 * i + a]));
    }
  /* Relative to the points' size, plus what storing them rounded away. */
  const double tolerance = rel_tolerance * size + 4.0 * stored_eps * magnitude;
  for (int a = 0; a < 3; ++a) out_plane[a] = n[a] / length;
  out_plane[3] = -(out_plane[0] * o[0] + out_plane[1] * o[1] + out_plane[2] * o[2]);
  for (size_t i = 0; i < count; ++i) {
    const double *p = points + 3 * i;
    const double d = out_plane[0] * (p[0] - o[0]) + out_plane[1] * (p[1] - o[1]) +
                     out_plane[2] * (p[2] - o[2]);
    if (fabs(d) > tolerance) return VSH_PLANE_NOT_FLAT;
  }
  return VSH_PLANE_OK;
}

int vsh_plane_contains_box(const double plane[4], const vsh_bounds *box, double rel_tolerance) {
  double corners[8][3];
  if (!plane || !box || !(rel_tolerance >= 0.0) || vsh_bounds_corners(box, corners) != 0)
    return 0;
  double size = 1e-300;
  for (int a = 0; a < 3; ++a) size = fmax(size, box->max[a] - box->min[a]);
  for (int k = 0; k < 8; ++k) {
    const double *p = corners[k];
    const double d = plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
    if (!(fabs(d) <= rel_tolerance * size)) return 0;
  }
  return 1;
}

void vsh_plane_face_light(const double plane[4], const double light[4], double out[4]) {
  const double side =
      plane[0] * light[0] + plane[1] * light[1] + plane[2] * light[2] + plane[3] * light[3];
  const double s = side < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 4; ++k) out[k] = s * plane[k];
}

void vsh_plane_times_matrix(const double plane[4], const double m[16], double out[4]) {
  double r[4];
  for (int c = 0; c < 4; ++c)
    r[c] = plane[0] * m[c] + plane[1] * m[4 + c] + plane[2] * m[8 + c] + plane[3] * m[12 + c];
  memcpy(out, r, sizeof(r));
}

int vsh_planes_keep_box(const double (*planes)[4], size_t count, const vsh_bounds *box,
                        const double origin[3]) {
  double corners[8][3];
  if ((!planes && count) || !box || vsh_bounds_corners(box, corners) != 0) return 0;
  const double o[3] = {origin ? origin[0] : 0.0, origin ? origin[1] : 0.0,
                       origin ? origin[2] : 0.0};
  for (int k = 0; k < 8; ++k) {
    const double p[3] = {corners[k][0] - o[0], corners[k][1] - o[1], corners[k][2] - o[2]};
    for (size_t i = 0; i < count; ++i) {
      const double *c = planes[i];
      if (!(c[0] * p[0] + c[1] * p[1] + c[2] * p[2] + c[3] > 0.0)) return 0;
    }
  }
  return 1;
}
