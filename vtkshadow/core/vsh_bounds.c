/* vsh_bounds.c - see vsh_bounds.h. */
#include "vsh_bounds.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

void vsh_bounds_init_empty(vsh_bounds *b) {
  for (int i = 0; i < 3; ++i) {
    b->min[i] = INFINITY;
    b->max[i] = -INFINITY;
  }
}

void vsh_bounds_from_vtk(vsh_bounds *b, const double vtk_bounds[6]) {
  for (int i = 0; i < 3; ++i) {
    b->min[i] = vtk_bounds[2 * i];
    b->max[i] = vtk_bounds[2 * i + 1];
  }
}

void vsh_bounds_to_vtk(const vsh_bounds *b, double vtk_bounds[6]) {
  for (int i = 0; i < 3; ++i) {
    vtk_bounds[2 * i] = b->min[i];
    vtk_bounds[2 * i + 1] = b->max[i];
  }
}

int vsh_bounds_add_point(vsh_bounds *b, const double p[3]) {
  if (!vsh_vec3_is_finite(p)) return 0;
  for (int i = 0; i < 3; ++i) {
    if (p[i] < b->min[i]) b->min[i] = p[i];
    if (p[i] > b->max[i]) b->max[i] = p[i];
  }
  return 1;
}

void vsh_bounds_merge(vsh_bounds *into, const vsh_bounds *other) {
  if (vsh_bounds_is_empty(other)) return;
  for (int i = 0; i < 3; ++i) {
    if (other->min[i] < into->min[i]) into->min[i] = other->min[i];
    if (other->max[i] > into->max[i]) into->max[i] = other->max[i];
  }
}

int vsh_bounds_is_empty(const vsh_bounds *b) {
  for (int i = 0; i < 3; ++i)
    if (!(b->min[i] <= b->max[i])) return 1; /* also catches NaN */
  return 0;
}

int vsh_bounds_is_finite(const vsh_bounds *b) {
  return vsh_vec3_is_finite(b->min) && vsh_vec3_is_finite(b->max);
}

/* Usable = non-empty and finite: what every derived quantity needs. */
static int usable(const vsh_bounds *b) {
  return !vsh_bounds_is_empty(b) && vsh_bounds_is_finite(b);
}

int vsh_bounds_center(const vsh_bounds *b, double out[3]) {
  if (!usable(b)) {
    out[0] = out[1] = out[2] = 0.0;
    return 1;
  }
  /* min + half the extent: exact for a point box, and no overflow of
   * min + max near DBL_MAX. */
  for (int i = 0; i < 3; ++i) out[i] = b->min[i] + 0.5 * (b->max[i] - b->min[i]);
  return 0;
}

double vsh_bounds_diagonal_length(const vsh_bounds *b) {
  if (!usable(b)) return 0.0;
  double d[3];
  vsh_vec3_sub(b->max, b->min, d);
  return vsh_vec3_length(d);
}

int vsh_bounds_corners(const vsh_bounds *b, double out[8][3]) {
  if (vsh_bounds_is_empty(b)) {
    memset(out, 0, 8 * sizeof out[0]);
    return 1;
  }
  for (int k = 0; k < 8; ++k) {
    out[k][0] = (k & 1) ? b->max[0] : b->min[0];
    out[k][1] = (k & 2) ? b->max[1] : b->min[1];
    out[k][2] = (k & 4) ? b->max[2] : b->min[2];
  }
  return 0;
}

int vsh_bounds_transform(const vsh_bounds *b, const double m[16], vsh_bounds *out) {
  vsh_bounds r;
  vsh_bounds_init_empty(&r);
  if (vsh_bounds_is_empty(b)) {
    *out = r;
    return 0;
  }
  if (!vsh_bounds_is_finite(b) || !vsh_mat4_is_finite(m)) {
    *out = r;
    return 1;
  }
  double c[8][3];
  vsh_bounds_corners(b, c);
  for (int k = 0; k < 8; ++k) {
    double p[3];
    const double w = vsh_mat4_transform_point(m, c[k], p);
    if (!(w > 0.0) || !vsh_bounds_add_point(&r, p)) {
      vsh_bounds_init_empty(out);
      return 1;
    }
  }
  *out = r;
  return 0;
}

int vsh_bounds_depth_range_in_view(const vsh_bounds *b, const double view_matrix[16],
                                   double out_near_far[2]) {
  out_near_far[0] = out_near_far[1] = 0.0;
  if (!usable(b) || !vsh_mat4_is_finite(view_matrix)) return 1;
  double c[8][3];
  vsh_bounds_corners(b, c);
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    /* Only the z row matters; the view matrix is affine (w = 1). */
    const double *r = view_matrix + 8;
    const double depth = -(r[0] * c[k][0] + r[1] * c[k][1] + r[2] * c[k][2] + r[3]);
    if (depth < lo) lo = depth;
    if (depth > hi) hi = depth;
  }
  if (!isfinite(lo) || !isfinite(hi)) return 1;
  out_near_far[0] = lo;
  out_near_far[1] = hi;
  return 0;
}
