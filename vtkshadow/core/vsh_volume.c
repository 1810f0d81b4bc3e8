/* vsh_volume.c - shadow volume geometry, z-pass safety, screen rectangle
 * and cost (vsh_volume.h). */
#include "vsh_volume.h"

#include "vsh_mat4.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The light with w >= 0, or 0 when it is unusable (non-finite, all zero). */
static int usable_light(const double light[4], double out[4]) {
  if (!light) return 0;
  int nonzero = 0;
  for (int k = 0; k < 4; ++k) {
    if (!isfinite(light[k])) return 0;
    nonzero |= light[k] != 0.0;
  }
  const double s = light[3] < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 4; ++k) out[k] = s * light[k];
  return nonzero;
}

/* Writes vertex v of the topology (w = 1) or its extrusion away from the
 * light (w = 0) at out[0..3]. */
static void put_vertex(const vsh_mesh_topology *t, const double l[4], uint32_t v, int infinite,
                       double *out) {
  const double *p = t->positions + 3 * (size_t)v;
  if (!infinite) {
    out[0] = p[0], out[1] = p[1], out[2] = p[2], out[3] = 1.0;
  } else if (l[3] == 0.0) {
    out[0] = -l[0], out[1] = -l[1], out[2] = -l[2], out[3] = 0.0;
  } else {
    for (int k = 0; k < 3; ++k) out[k] = p[k] - l[k] / l[3];
    out[3] = 0.0;
  }
}

static double *put_triangle(const vsh_mesh_topology *t, const double l[4], const uint32_t v[3],
                            const int inf[3], double *out) {
  for (int k = 0; k < 3; ++k) put_vertex(t, l, v[k], inf[k], out + 4 * k);
  return out + 12;
}

/* Near cap (turned to face the light) and, for a positional light, far cap
 * of face f; `flip` reverses the face's own winding. */
static double *put_caps(const vsh_mesh_topology *t, const double l[4], size_t f, int flip,
                        double *out) {
  const uint32_t *tri = t->triangles + 3 * f;
  const uint32_t near[3] = {tri[0], flip ? tri[2] : tri[1], flip ? tri[1] : tri[2]};
  const uint32_t far[3] = {near[0], near[2], near[1]};
  static const int finite[3] = {0, 0, 0}, infinite[3] = {1, 1, 1};
  out = put_triangle(t, l, near, finite, out);
  if (l[3] != 0.0) out = put_triangle(t, l, far, infinite, out);
  return out;
}

static int degenerate(const uint32_t *tri) {
  return tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
}

void vsh_volume_free(vsh_volume *v) {
  if (!v) return;
  free(v->vertices);
  memset(v, 0, sizeof(*v));
}

/* The volume with dark caps (closed meshes) or of every face turned to face
 * the light (dark_caps 0: any mesh). */
static vsh_mesh_status build(const vsh_mesh_topology *t, const double light[4], int dark_caps,
                             vsh_volume *out) {
  if (out) memset(out, 0, sizeof(*out));
  double l[4];
  if (!t || !out || !usable_light(light, l)) return VSH_MESH_INVALID;
  vsh_silhouette s;
  vsh_mesh_status status = vsh_silhouette_build(
      t, l, dark_caps ? VSH_SILHOUETTE_LIT_FACES : VSH_SILHOUETTE_BOTH_SIDES, &s);
  if (status != VSH_MESH_OK) return status;
  unsigned char *facing = (unsigned char *)malloc(t->triangle_count ? t->triangle_count : 1);
  if (!facing || vsh_silhouette_facing(t, l, facing) != VSH_MESH_OK) {
    free(facing);
    vsh_silhouette_free(&s);
    return facing ? VSH_MESH_INVALID : VSH_MESH_NO_MEMORY;
  }
  const int per_quad = l[3] != 0.0 ? 2 : 1, per_face = l[3] != 0.0 ? 2 : 1;
  size_t caps = 0;
  for (size_t f = 0; f < t->triangle_count; ++f)
    if (!degenerate(t->triangles + 3 * f) && (!dark_caps || !facing[f])) caps += per_face;
  const size_t sides = per_quad * s.total_multiplicity;
  out->vertices = (double *)malloc((sides + caps ? sides + caps : 1) * 12 * sizeof(double));
  if (!out->vertices) {
    free(facing);
    vsh_silhouette_free(&s);
    return VSH_MESH_NO_MEMORY;
  }
  double *w = out->vertices;
  for (size_t k = 0; k < s.count; ++k) {
    const vsh_silhouette_edge *e = &s.edges[k];
    for (uint32_t r = 0; r < e->multiplicity; ++r) {
      /* Quad (a, a', b', b), a' the extrusion; one triangle when a' = b'. */
      const uint32_t first[3] = {e->from, e->from, e->to}, second[3] = {e->from, e->to, e->to};
      static const int inf1[3] = {0, 1, 1}, inf2[3] = {0, 1, 0};
      if (per_quad == 2) w = put_triangle(t, l, first, inf1, w);
      w = put_triangle(t, l, second, inf2, w);
    }
  }
  for (size_t f = 0; f < t->triangle_count; ++f) {
    if (degenerate(t->triangles + 3 * f)) continue;
    if (dark_caps && facing[f]) continue;
    w = put_caps(t, l, f, !facing[f], w);
  }
  out->side_triangles = sides;
  out->cap_triangles = caps;
  out->dark_caps = dark_caps;
  out->silhouette_edges = s.count;
  out->silhouette_quads = s.total_multiplicity;
  free(facing);
  vsh_silhouette_free(&s);
  return VSH_MESH_OK;
}

vsh_mesh_status vsh_volume_build(const vsh_mesh_topology *t, const double light[4],
                                 vsh_volume *out) {
  return build(t, light, t ? t->closed : 0, out);
}

vsh_mesh_status vsh_volume_build_crossings(const vsh_mesh_topology *t, const double light[4],
                                           vsh_volume *out) {
  return build(t, light, 0, out);
}

/* ---- z-pass safety: separating axes between two convex point sets ------ */

static void cross3(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

static void project(const double *pts, int n, const double axis[3], double *lo, double *hi) {
  *lo = INFINITY, *hi = -INFINITY;
  for (int i = 0; i < n; ++i) {
    const double d = pts[3 * i] * axis[0] + pts[3 * i + 1] * axis[1] + pts[3 * i + 2] * axis[2];
    if (d < *lo) *lo = d;
    if (d > *hi) *hi = d;
  }
}

static int separates(const double *a, int na, const double *b, int nb, const double axis[3]) {
  if (axis[0] == 0.0 && axis[1] == 0.0 && axis[2] == 0.0) return 0;
  double alo, ahi, blo, bhi;
  project(a, na, axis, &alo, &ahi);
  project(b, nb, axis, &blo, &bhi);
  return ahi < blo || bhi < alo;
}

/* 1 when the convex hulls of a (na points) and the box corners b (8) are
 * disjoint. Every triple's normal and every pair's cross product with a
 * box axis are tried: a superset of the face normals and edge-edge axes,
 * so the test is exact; the extra axes can only find real separations. */
static int hulls_disjoint(const double *a, int na, const double b[24]) {
  static const double axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k)
    if (separates(a, na, b, 8, axes[k])) return 1;
  for (int i = 0; i < na; ++i) {
    for (int j = i + 1; j < na; ++j) {
      const double e[3] = {a[3 * j] - a[3 * i], a[3 * j + 1] - a[3 * i + 1],
                           a[3 * j + 2] - a[3 * i + 2]};
      for (int k = 0; k < 3; ++k) {
        double n[3];
        cross3(e, axes[k], n);
        if (separates(a, na, b, 8, n)) return 1;
      }
      for (int m = j + 1; m < na; ++m) {
        const double f[3] = {a[3 * m] - a[3 * i], a[3 * m + 1] - a[3 * i + 1],
                             a[3 * m + 2] - a[3 * i + 2]};
        double n[3];
        cross3(e, f, n);
        if (separates(a, na, b, 8, n)) return 1;
      }
    }
  }
  return 0;
}

static int all_finite(const double *v, int n) {
  for (int i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

int vsh_volume_zpass_safe(const double eye[3], const double near_corners[12],
                          const double bounds[6], const double light[4], double margin) {
  double l[4];
  if (!eye || !near_corners || !bounds || !usable_light(light, l) || !all_finite(eye, 3) ||
      !all_finite(near_corners, 12) || !all_finite(bounds, 6) || !isfinite(margin) || margin < 0)
    return 0;
  double box[24];
  for (int c = 0; c < 8; ++c)
    for (int k = 0; k < 3; ++k) {
      if (bounds[2 * k] > bounds[2 * k + 1]) return 0;
      box[3 * c + k] = (c >> k & 1) ? bounds[2 * k + 1] + margin : bounds[2 * k] - margin;
    }
  double pts[30];
  memcpy(pts, eye, 3 * sizeof(double));
  memcpy(pts + 3, near_corners, 12 * sizeof(double));
  int n = 5;
  if (l[3] != 0.0) {
    for (int k = 0; k < 3; ++k) pts[15 + k] = l[k] / l[3];
    n = 6;
  } else {
    /* Sweep far enough along the light direction to pass the whole box. */
    const double len = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    const double u[3] = {l[0] / len, l[1] / len, l[2] / len};
    double plo, phi, blo, bhi;
    project(pts, 5, u, &plo, &phi);
    project(box, 8, u, &blo, &bhi);
    double size = 0.0;
    for (int i = 0; i < 5; ++i)
      for (int k = 0; k < 3; ++k) size = fmax(size, fabs(pts[3 * i + k] - box[k]));
    const double sweep = fmax(0.0, bhi - plo) + size + 1.0;
    for (int i = 0; i < 5; ++i)
      for (int k = 0; k < 3; ++k) pts[15 + 3 * i + k] = pts[3 * i + k] + sweep * u[k];
    n = 10;
  }
  return hulls_disjoint(pts, n, box);
}

/* ---- screen rectangle and culling -------------------------------------- */

int vsh_volume_screen_rect(const double m[16], const double bounds[6], const double light[4],
                           int width, int height, int rect[4]) {
  if (!rect) return 1;
  rect[0] = 0, rect[1] = 0, rect[2] = width > 0 ? width : 0, rect[3] = height > 0 ? height : 0;
  double l[4];
  if (!m || !bounds || !usable_light(light, l) || !all_finite(m, 16) || !all_finite(bounds, 6) ||
      width <= 0 || height <= 0)
    return 1;
  double clip[16][4];
  int n = 0;
  for (int c = 0; c < 8; ++c) {
    const double p[4] = {(c & 1) ? bounds[1] : bounds[0], (c & 2) ? bounds[3] : bounds[2],
                         (c & 4) ? bounds[5] : bounds[4], 1.0};
    double x[2][4];
    memcpy(x[0], p, sizeof(p));
    for (int k = 0; k < 3; ++k) x[1][k] = l[3] != 0.0 ? p[k] - l[k] / l[3] : -l[k];
    x[1][3] = 0.0;
    for (int h = 0; h < 2; ++h, ++n)
      for (int r = 0; r < 4; ++r)
        clip[n][r] = m[4 * r] * x[h][0] + m[4 * r + 1] * x[h][1] + m[4 * r + 2] * x[h][2] +
                     m[4 * r + 3] * x[h][3];
  }
  /* Outside one clip plane (x >= -w, x <= w, y..., z...) with every point. */
  for (int plane = 0; plane < 6; ++plane) {
    const int axis = plane / 2;
    const double sign = (plane & 1) ? -1.0 : 1.0;
    int outside = 1;
    for (int i = 0; i < n && outside; ++i) outside = sign * clip[i][axis] + clip[i][3] < 0.0;
    if (outside) return 0;
  }
  /* The part of the hull in front of the eye plane (w > 0; the rest is
   * clipped) is the hull of the points with w > 0 and of where the segments
   * between points cross w = 0: there the projection goes to infinity in
   * the direction (x, y), which opens the rectangle on that side. */
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int i = 0; i < n; ++i) {
    for (int j = i; j < n; ++j) {
      const double wi = clip[i][3], wj = clip[j][3];
      if (j == i ? !(wi > 0.0) : !((wi > 0.0 && wj <= 0.0) || (wj > 0.0 && wi <= 0.0))) continue;
      if (j == i) {
        for (int k = 0; k < 2; ++k) {
          lo[k] = fmin(lo[k], clip[i][k] / wi);
          hi[k] = fmax(hi[k], clip[i][k] / wi);
        }
        continue;
      }
      const double t = wi / (wi - wj);
      for (int k = 0; k < 2; ++k) {
        const double d = clip[i][k] + t * (clip[j][k] - clip[i][k]);
        if (d > 0.0) hi[k] = INFINITY;
        if (d < 0.0) lo[k] = -INFINITY;
      }
    }
  }
  if (!(lo[0] <= hi[0])) return 0; /* nothing in front of the eye */
  const int size[2] = {width, height};
  int a[2], b[2];
  for (int k = 0; k < 2; ++k) {
    const double p0 = floor((fmax(lo[k], -2.0) + 1.0) * 0.5 * size[k]) - 1.0;
    const double p1 = ceil((fmin(hi[k], 2.0) + 1.0) * 0.5 * size[k]) + 1.0;
    a[k] = p0 < 0.0 ? 0 : (p0 > size[k] ? size[k] : (int)p0);
    b[k] = p1 < 0.0 ? 0 : (p1 > size[k] ? size[k] : (int)p1);
  }
  if (b[0] <= a[0] || b[1] <= a[1]) return 0;
  rect[0] = a[0], rect[1] = a[1], rect[2] = b[0] - a[0], rect[3] = b[1] - a[1];
  return 1;
}

double vsh_volume_cost(const vsh_volume_cost_input *in) {
  if (!in) return 0.0;
  const double fill = isfinite(in->fill_px) && in->fill_px > 0 ? in->fill_px : 0.0;
  const double layers = isfinite(in->depth_layers) && in->depth_layers > 0 ? in->depth_layers : 0.0;
  double triangles = 2.0 * (double)in->silhouette_quads;
  if (in->zfail) triangles += (double)in->cap_triangles;
  return fill * layers + VSH_VOLUME_PX_PER_TRIANGLE * triangles;
}

int vsh_volume_near_corners(const double clip_from_eye[16], double out[12])
{
  static const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  double inverse[16];
  int c, k;
  memset(out, 0, 12 * sizeof(double));
  if (!vsh_mat4_inverse(clip_from_eye, inverse))
    return 0;
  for (c = 0; c < 4; ++c) {
    const double ndc[4] = {corners[c][0], corners[c][1], -1.0, 1.0};
    double p[4];
    vsh_mat4_transform_point4(inverse, ndc, p);
    for (k = 0; k < 3; ++k)
      out[3 * c + k] = p[3] != 0.0 ? p[k] / p[3] : 0.0;
  }
  return 1;
}
