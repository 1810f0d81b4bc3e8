/* vsh_reflect.c - planar mirrors (see vsh_reflect.h). */
#include "vsh_reflect.h"

#include "vsh_mat4.h"

#include <math.h>
#include <stddef.h>

static int finite3(const double v[3]) {
  return v && isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

vsh_reflect_status vsh_reflect_plane(const double point[3], const double normal[3],
                                     const double origin[3], double out_plane[4]) {
  double n[3], rel[3], len, big;
  int i;
  if (!out_plane) return VSH_REFLECT_INVALID;
  out_plane[0] = out_plane[1] = out_plane[2] = out_plane[3] = 0.0;
  if (!finite3(point) || !finite3(normal) || (origin && !finite3(origin)))
    return VSH_REFLECT_INVALID;
  /* Scale by the largest component first: |n| of 1e-200 or 1e200 would
   * underflow or overflow when squared. */
  big = fmax(fabs(normal[0]), fmax(fabs(normal[1]), fabs(normal[2])));
  if (!(big > 0.0)) return VSH_REFLECT_DEGENERATE;
  for (i = 0; i < 3; ++i) n[i] = normal[i] / big;
  len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (i = 0; i < 3; ++i) {
    n[i] /= len;
    rel[i] = point[i] - (origin ? origin[i] : 0.0);
  }
  for (i = 0; i < 3; ++i) out_plane[i] = n[i];
  out_plane[3] = -(n[0] * rel[0] + n[1] * rel[1] + n[2] * rel[2]);
  if (!isfinite(out_plane[3])) {
    out_plane[0] = out_plane[1] = out_plane[2] = out_plane[3] = 0.0;
    return VSH_REFLECT_INVALID;
  }
  return VSH_REFLECT_OK;
}

vsh_reflect_status vsh_reflect_matrix(const double plane[4], double out[16]) {
  double len2;
  int r, c;
  if (!out) return VSH_REFLECT_INVALID;
  vsh_mat4_identity(out);
  if (!plane || !finite3(plane) || !isfinite(plane[3])) return VSH_REFLECT_INVALID;
  len2 = plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2];
  if (!(fabs(len2 - 1.0) <= 2e-9)) return VSH_REFLECT_DEGENERATE;
  for (r = 0; r < 3; ++r) {
    for (c = 0; c < 3; ++c) out[4 * r + c] = (r == c ? 1.0 : 0.0) - 2.0 * plane[r] * plane[c];
    out[4 * r + 3] = -2.0 * plane[3] * plane[r];
  }
  return VSH_REFLECT_OK;
}

double vsh_reflect_side(const double plane[4], const double point[3]) {
  return plane[0] * point[0] + plane[1] * point[1] + plane[2] * point[2] + plane[3];
}

int vsh_reflect_eye_sees(const double plane[4], const double eye[3], double scale,
                         double rel_tolerance) {
  double s;
  if (!plane || !finite3(eye) || !isfinite(plane[3]) || !finite3(plane)) return 0;
  if (!(scale >= 1e-300)) scale = 1e-300;
  s = vsh_reflect_side(plane, eye);
  return s > rel_tolerance * scale;
}

void vsh_reflect_clip_plane(const double plane[4], const double eye[3], double out[4]) {
  const double sign = vsh_reflect_side(plane, eye) > 0.0 ? -1.0 : 1.0;
  int i;
  for (i = 0; i < 4; ++i) out[i] = sign * plane[i];
}

void vsh_reflect_point(const double plane[4], const double p[3], double out[3]) {
  const double s = 2.0 * vsh_reflect_side(plane, p);
  int i;
  for (i = 0; i < 3; ++i) out[i] = p[i] - s * plane[i];
}

void vsh_reflect_direction(const double plane[4], const double v[3], double out[3]) {
  const double s = 2.0 * (plane[0] * v[0] + plane[1] * v[1] + plane[2] * v[2]);
  int i;
  for (i = 0; i < 3; ++i) out[i] = v[i] - s * plane[i];
}
