/* vsh_mesh.c - allocation, affine transformation and release of vsh_mesh.
 *
 * Normals go through the inverse-transpose of the linear part L so they stay
 * perpendicular to the surface under non-uniform scale and shear. Only their
 * direction matters (they are renormalized), which allows a computation that
 * cannot overflow or underflow even for scales like 1e-200 on one axis and
 * 1e200 on another (found by the mutation fuzzer):
 *   L = D R with D = diag(d_i), d_i = max |row i|, so R has entries <= 1;
 *   L^-T = D^-1 R^-T = D^-1 cof(R) / det(R);
 *   n' ~ sign(det R) * (w_i / d_i) with w = cof(R) n,
 * where w_i / d_i is evaluated as mantissas and exponents separately and all
 * components are rescaled by the largest exponent before normalizing.
 */
#include "vsh_scene_internal.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int vsh__mesh_alloc(vsh_mesh *mesh, size_t point_count, size_t triangle_count) {
  memset(mesh, 0, sizeof *mesh);
  if (point_count > (size_t)UINT32_MAX || point_count > SIZE_MAX / (3 * sizeof(double)) ||
      triangle_count > SIZE_MAX / (3 * sizeof(uint32_t)))
    return -1;
  mesh->points = (double *)calloc(point_count * 3, sizeof(double));
  mesh->normals = (double *)calloc(point_count * 3, sizeof(double));
  mesh->triangles = (uint32_t *)calloc(triangle_count * 3, sizeof(uint32_t));
  if (!mesh->points || !mesh->normals || !mesh->triangles) {
    vsh_mesh_free(mesh);
    return -1;
  }
  mesh->point_count = point_count;
  mesh->triangle_count = triangle_count;
  return 0;
}

void vsh_mesh_transform(vsh_mesh *mesh, const double t[16]) {
  double l[3][3], c[3][3], d[3], det;
  size_t i;
  int r, k;
  if (!mesh || !t) return;

  for (i = 0; i < mesh->point_count; ++i) {
    double *p = mesh->points + 3 * i;
    double x = p[0], y = p[1], z = p[2];
    p[0] = t[0] * x + t[1] * y + t[2] * z + t[3];
    p[1] = t[4] * x + t[5] * y + t[6] * z + t[7];
    p[2] = t[8] * x + t[9] * y + t[10] * z + t[11];
  }

  for (r = 0; r < 3; ++r) {
    d[r] = 0.0;
    for (k = 0; k < 3; ++k)
      if (fabs(t[4 * r + k]) > d[r]) d[r] = fabs(t[4 * r + k]);
    if (!(d[r] > 0.0) || !isfinite(d[r])) return; /* singular: nothing sensible to do */
    for (k = 0; k < 3; ++k) l[r][k] = t[4 * r + k] / d[r];
  }
  c[0][0] = l[1][1] * l[2][2] - l[1][2] * l[2][1];
  c[0][1] = l[1][2] * l[2][0] - l[1][0] * l[2][2];
  c[0][2] = l[1][0] * l[2][1] - l[1][1] * l[2][0];
  c[1][0] = l[0][2] * l[2][1] - l[0][1] * l[2][2];
  c[1][1] = l[0][0] * l[2][2] - l[0][2] * l[2][0];
  c[1][2] = l[0][1] * l[2][0] - l[0][0] * l[2][1];
  c[2][0] = l[0][1] * l[1][2] - l[0][2] * l[1][1];
  c[2][1] = l[0][2] * l[1][0] - l[0][0] * l[1][2];
  c[2][2] = l[0][0] * l[1][1] - l[0][1] * l[1][0];
  det = l[0][0] * c[0][0] + l[0][1] * c[0][1] + l[0][2] * c[0][2];

  for (i = 0; i < mesh->point_count; ++i) {
    double *n = mesh->normals + 3 * i, w[3], m[3];
    int e[3] = {0, 0, 0}, top = INT_MIN;
    for (r = 0; r < 3; ++r) {
      w[r] = c[r][0] * n[0] + c[r][1] * n[1] + c[r][2] * n[2];
      /* cofactor = det * inverse-transpose: undo det's sign so normals keep
       * pointing outward under a mirroring transform. */
      if (det < 0.0) w[r] = -w[r];
      if (w[r] != 0.0) {
        e[r] = ilogb(w[r]) - ilogb(d[r]);
        if (e[r] > top) top = e[r];
      }
    }
    for (r = 0; r < 3; ++r) {
      /* (w/d) = (mantissa(w)/mantissa(d)) * 2^(e - top), up to the common 2^top. */
      m[r] = w[r] == 0.0 ? 0.0
                         : scalbn(scalbn(w[r], -ilogb(w[r])) / scalbn(d[r], -ilogb(d[r])),
                                  e[r] - top);
    }
    if (!vsh__normalize3(m, n)) {
      n[0] = m[0]; /* degenerate: leave the (zero) result rather than invent one */
      n[1] = m[1];
      n[2] = m[2];
    }
  }

  /* A mirror reverses the winding; swap two corners so triangles stay
   * counter-clockwise seen from outside (the side the normals point to). */
  if (det < 0.0) {
    for (i = 0; i < mesh->triangle_count; ++i) {
      uint32_t *tri = mesh->triangles + 3 * i, tmp = tri[1];
      tri[1] = tri[2];
      tri[2] = tmp;
    }
  }
}

void vsh_mesh_free(vsh_mesh *mesh) {
  if (!mesh) return;
  free(mesh->points);
  free(mesh->normals);
  free(mesh->triangles);
  memset(mesh, 0, sizeof *mesh);
}
