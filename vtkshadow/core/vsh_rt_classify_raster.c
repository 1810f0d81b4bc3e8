/* vsh_rt_classify_raster.c - conservative rasterization for the
 * classifier's maps (vsh_rt_classify.h): a triangle clipped to a face's
 * frustum and projected, which texels it overlaps (separating axes) or
 * covers whole, and its key range over a texel. */
#include "vsh_rt_classify.h"
#include "vsh_rt_classify_internal.h"

#include <math.h>
#include <string.h>

/* The triangle's vertices in face coordinates (x, y, z): z along the axis
 * (from the light for a perspective face). */
static void face_coordinates(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                             const double *tri, double out[3][3])
{
  for (int k = 0; k < 3; ++k) {
    vsh_rtc_face_point(map, face, tri + 3 * k, out[k]);
  }
}

/* Clip (x, y, z) polygon `in` (n vertices) to a.x + b.y + c.z >= d: at
 * most n + 1 vertices. */
static int clip(const double in[][3], int n, const double plane[4], double out[][3])
{
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const double *a = in[k], *b = in[(k + 1) % n];
    const double da = plane[0] * a[0] + plane[1] * a[1] + plane[2] * a[2] - plane[3];
    const double db = plane[0] * b[0] + plane[1] * b[1] + plane[2] * b[2] - plane[3];
    if (da >= 0) {
      memcpy(out[m++], a, sizeof(double) * 3);
    }
    if ((da >= 0) != (db >= 0)) {
      const double t = da / (da - db);
      for (int r = 0; r < 3; ++r) {
        out[m][r] = a[r] + t * (b[r] - a[r]);
      }
      ++m;
    }
  }
  return m;
}

/* A perspective face's frustum: in front of the near plane, inside its
 * four sides (the face's square grown by a texel, so texels on its border
 * keep everything that reaches them). */
static int clip_frustum(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                        const double xyz[3][3], double out[MAX_VERTICES][3])
{
  const double e = -face->u0 + face->texel;
  const double planes[5][4] = { { 0, 0, 1, map->near_z }, { -1, 0, e, 0 }, { 1, 0, e, 0 },
                                { 0, -1, e, 0 }, { 0, 1, e, 0 } };
  double a[MAX_VERTICES][3], b[MAX_VERTICES][3];
  memcpy(a, xyz, sizeof(double) * 9);
  int n = 3;
  for (int k = 0; k < 5 && n >= 3; ++k) {
    n = clip((const double(*)[3])a, n, planes[k], b);
    memcpy(a, b, sizeof(double) * 3 * (size_t)n);
  }
  memcpy(out, a, sizeof(double) * 3 * (size_t)(n > 0 ? n : 0));
  return n;
}

/* Project a triangle into a face: 0 when nothing of it is in front. */
int vsh_rtc_project(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                   const double *tri, polygon *poly)
{
  double xyz[3][3], clipped[MAX_VERTICES][3];
  face_coordinates(map, face, tri, xyz);
  int n = 3;
  if (face->perspective) {
    n = clip_frustum(map, face, (const double(*)[3])xyz, clipped);
  } else {
    memcpy(clipped, xyz, sizeof xyz);
  }
  if (n < 3) {
    return 0;
  }
  poly->count = n;
  poly->key_min = HUGE_VAL;
  poly->key_max = -HUGE_VAL;
  poly->umin = poly->vmin = HUGE_VAL;
  poly->umax = poly->vmax = -HUGE_VAL;
  double zmin = HUGE_VAL, extent = 0;
  for (int k = 0; k < n; ++k) {
    const double z = clipped[k][2];
    poly->u[k] = face->perspective ? clipped[k][0] / z : clipped[k][0];
    poly->v[k] = face->perspective ? clipped[k][1] / z : clipped[k][1];
    poly->key[k] = vsh_rt_classify_key(face, z);
    poly->key_min = fmin(poly->key_min, poly->key[k]);
    poly->key_max = fmax(poly->key_max, poly->key[k]);
    poly->umin = fmin(poly->umin, poly->u[k]);
    poly->umax = fmax(poly->umax, poly->u[k]);
    poly->vmin = fmin(poly->vmin, poly->v[k]);
    poly->vmax = fmax(poly->vmax, poly->v[k]);
    zmin = fmin(zmin, z);
    extent = fmax(extent, fabs(poly->u[k]) + fabs(poly->v[k]));
  }
  /* World margin -> (u, v): a point moved by m moves its projection by at
   * most m (1 + |u| + |v|) / z on a perspective face. */
  const double world = VSH_RT_CLASSIFY_MARGIN * map->scale;
  poly->margin = face->perspective ? world * (1.0 + extent) / zmin : world;
  poly->area2 = 0;
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    poly->area2 += poly->u[k] * poly->v[j] - poly->u[j] * poly->v[k];
  }
  /* The key plane from the 3D plane n.p = c in face coordinates. */
  double e1[3], e2[3], nrm[3];
  vsh_vec3_sub(xyz[1], xyz[0], e1);
  vsh_vec3_sub(xyz[2], xyz[0], e2);
  vsh_vec3_cross(e1, e2, nrm);
  const double len = vsh_vec3_length(nrm);
  const double c = vsh_vec3_dot(nrm, xyz[0]);
  poly->has_plane = 0;
  poly->a = poly->b = poly->c = 0;
  if (len > 0 && isfinite(len)) {
    if (!face->perspective && fabs(nrm[2]) > 1e-9 * len) {
      poly->a = -nrm[0] / nrm[2];
      poly->b = -nrm[1] / nrm[2];
      poly->c = c / nrm[2];
      poly->has_plane = 1;
    } else if (face->perspective && fabs(c) > 1e-9 * len * map->scale) {
      poly->a = -nrm[0] / c;
      poly->b = -nrm[1] / c;
      poly->c = -nrm[2] / c;
      poly->has_plane = 1;
    }
  }
  return 1;
}

/* Whether the texel [u0, u1] x [v0, v1] overlaps the polygon (separating
 * axes: the texel's two and the polygon's edge normals), the texel grown
 * by the polygon's margin. */
int vsh_rtc_overlaps(const polygon *p, double u0, double u1, double v0, double v1)
{
  const double m = p->margin;
  u0 -= m;
  u1 += m;
  v0 -= m;
  v1 += m;
  if (p->umax < u0 || p->umin > u1 || p->vmax < v0 || p->vmin > v1) {
    return 0;
  }
  if (p->area2 == 0) {
    return 1; /* edge-on: its box is the conservative answer */
  }
  const double s = p->area2 > 0 ? 1.0 : -1.0;
  for (int k = 0; k < p->count; ++k) {
    const int j = (k + 1) % p->count;
    /* Inside is s * cross(edge, point - start) >= 0; the texel is outside
     * when its corner most inside is outside. */
    const double eu = p->u[j] - p->u[k], ev = p->v[j] - p->v[k];
    const double nu = -s * ev, nv = s * eu; /* inward normal */
    const double cu = nu > 0 ? u1 : u0, cv = nv > 0 ? v1 : v0;
    if (nu * (cu - p->u[k]) + nv * (cv - p->v[k]) < 0) {
      return 0;
    }
  }
  return 1;
}

/* Whether the polygon covers the whole texel, grown by the margin. */
static int covers(const polygon *p, double u0, double u1, double v0, double v1)
{
  if (p->area2 == 0 || !isfinite(p->area2)) {
    return 0;
  }
  const double m = p->margin;
  const double cu[4] = { u0 - m, u1 + m, u0 - m, u1 + m }, cv[4] = { v0 - m, v0 - m, v1 + m, v1 + m };
  const double s = p->area2 > 0 ? 1.0 : -1.0;
  for (int k = 0; k < p->count; ++k) {
    const int j = (k + 1) % p->count;
    const double eu = p->u[j] - p->u[k], ev = p->v[j] - p->v[k];
    for (int c = 0; c < 4; ++c) {
      if (s * (eu * (cv[c] - p->v[k]) - ev * (cu[c] - p->u[k])) <= 0) {
        return 0;
      }
    }
  }
  return 1;
}

/* The polygon's key range over the texel: its plane at the texel's corners,
 * clamped by its vertices' keys (both bound it there). */
void vsh_rtc_key_range(const polygon *p, double u0, double u1, double v0, double v1, double *lo,
                       double *hi)
{
  *lo = p->key_min;
  *hi = p->key_max;
  if (!p->has_plane) {
    return;
  }
  const double m = p->margin;
  const double k00 = p->a * (u0 - m) + p->b * (v0 - m) + p->c;
  const double k10 = p->a * (u1 + m) + p->b * (v0 - m) + p->c;
  const double k01 = p->a * (u0 - m) + p->b * (v1 + m) + p->c;
  const double k11 = p->a * (u1 + m) + p->b * (v1 + m) + p->c;
  const double pmin = fmin(fmin(k00, k10), fmin(k01, k11));
  const double pmax = fmax(fmax(k00, k10), fmax(k01, k11));
  if (isfinite(pmin) && isfinite(pmax)) {
    *lo = fmax(*lo, pmin);
    *hi = fmin(*hi, pmax);
    if (*lo > *hi) { /* rounding at a vertex: keep the vertex range */
      *lo = p->key_min;
      *hi = p->key_max;
    }
  }
}

float vsh_rtc_round_down(double x)
{
  float f = (float)x;
  return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

float vsh_rtc_round_up(double x)
{
  float f = (float)x;
  return (double)f < x ? nextafterf(f, INFINITY) : f;
}

/* The texel range a (u, v) box grown by m covers, clamped to the face;
 * 0 when it misses the face. */
int vsh_rtc_texel_range(const vsh_rt_classify_face *face, double umin, double umax, double vmin,
                       double vmax, double m, int range[4])
{
  const double size = face->texel;
  range[0] = (int)floor((umin - m - face->u0) / size);
  range[1] = (int)floor((umax + m - face->u0) / size);
  range[2] = (int)floor((vmin - m - face->v0) / size);
  range[3] = (int)floor((vmax + m - face->v0) / size);
  range[0] = range[0] < 0 ? 0 : range[0];
  range[2] = range[2] < 0 ? 0 : range[2];
  range[1] = range[1] >= face->n ? face->n - 1 : range[1];
  range[3] = range[3] >= face->n ? face->n - 1 : range[3];
  return range[0] <= range[1] && range[2] <= range[3];
}

/* Remember texel x in the scratch (once) with mark bits `bits`. */
static void touch(vsh_rtc_scratch *scratch, size_t x, unsigned char bits)
{
  if (!scratch->mark[x]) {
    scratch->touched[scratch->count++] = x;
    scratch->hi[x] = -INFINITY;
  }
  scratch->mark[x] |= bits;
}

double vsh_rtc_margin(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face, size_t t)
{
  polygon p;
  return vsh_rtc_project(map, face, map->triangles + 9 * t, &p) ? p.margin : 0.0;
}

void vsh_rtc_rasterize(vsh_rt_classify_map *map, vsh_rt_classify_face *face, size_t t, int pass,
                       vsh_rtc_scratch *scratch)
{
  polygon p;
  const double *tri = map->triangles + 9 * t;
  int range[4];
  if (!vsh_rtc_project(map, face, tri, &p) ||
      !vsh_rtc_texel_range(face, p.umin, p.umax, p.vmin, p.vmax, p.margin, range)) {
    return;
  }
  const int flags = map->flags[t], group = map->group[t];
  const int opaque = (flags & VSH_RT_CLASSIFY_CASTS) != 0;
  const int casts = opaque || (flags & VSH_RT_CLASSIFY_TRANSLUCENT) != 0;
  const double size = face->texel;
  for (int j = range[2]; j <= range[3]; ++j) {
    const double v0 = face->v0 + j * size, v1 = v0 + size;
    for (int i = range[0]; i <= range[1]; ++i) {
      const double u0 = face->u0 + i * size, u1 = u0 + size;
      if (!vsh_rtc_overlaps(&p, u0, u1, v0, v1)) {
        continue;
      }
      const size_t x = vsh_rtc_texel_index(face, i, j);
      double lo, hi;
      vsh_rtc_key_range(&p, u0, u1, v0, v1, &lo, &hi);
      if (pass == 1) {
        /* rest: everything but the full triangle's plane (opaque casters
         * in it cannot stop a ray leaving it). */
        if (!(opaque && group == face->texels[x].full)) {
          face->texels[x].rest = fminf(face->texels[x].rest, vsh_rtc_round_down(lo));
        }
        continue;
      }
      if (casts) {
        face->texels[x].near_key = fminf(face->texels[x].near_key, vsh_rtc_round_down(lo));
      }
      if (!opaque) {
        continue;
      }
      if (covers(&p, u0, u1, v0, v1) && vsh_rtc_round_up(hi) < face->texels[x].full_far) {
        face->texels[x].full_far = vsh_rtc_round_up(hi);
        face->texels[x].full = group;
      }
      if (scratch) {
        touch(scratch, x, 1);
        scratch->hi[x] = fmaxf(scratch->hi[x], vsh_rtc_round_up(hi));
      }
    }
  }
}

int vsh_rtc_project_segment(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                            const double a[3], const double b[3], polygon *p, int ends[2])
{
  /* The segment as a two-vertex polygon through the same clip and
   * projection as the triangles. */
  const double seg[9] = { a[0], a[1], a[2], b[0], b[1], b[2], b[0], b[1], b[2] };
  if (!vsh_rtc_project(map, face, seg, p)) {
    return 0;
  }
  /* The clipped segment's ends: its polygon's two vertices farthest apart. */
  double far2 = -1;
  ends[0] = ends[1] = 0;
  for (int k = 0; k < p->count; ++k) {
    for (int l = k + 1; l < p->count; ++l) {
      const double du = p->u[l] - p->u[k], dv = p->v[l] - p->v[k];
      if (du * du + dv * dv > far2) {
        far2 = du * du + dv * dv, ends[0] = k, ends[1] = l;
      }
    }
  }
  return 1;
}

void vsh_rtc_mark_segment(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                          const double a[3], const double b[3], double margin,
                          unsigned char bits, vsh_rtc_scratch *scratch)
{
  polygon p;
  int range[4], ends[2];
  if (!vsh_rtc_project_segment(map, face, a, b, &p, ends)) {
    return;
  }
  p.margin = fmax(p.margin, margin);
  if (!vsh_rtc_texel_range(face, p.umin, p.umax, p.vmin, p.vmax, p.margin, range)) {
    return;
  }
  /* The segment's line: through its ends. */
  const int e0 = ends[0], e1 = ends[1];
  const double du = p.u[e1] - p.u[e0], dv = p.v[e1] - p.v[e0], size = face->texel;
  for (int j = range[2]; j <= range[3]; ++j) {
    const double v0 = face->v0 + j * size - p.margin, v1 = v0 + size + 2 * p.margin;
    for (int i = range[0]; i <= range[1]; ++i) {
      const double u0 = face->u0 + i * size - p.margin, u1 = u0 + size + 2 * p.margin;
      /* The texel's corners on both sides of the line (or on it). */
      const double c[4] = { du * (v0 - p.v[e0]) - dv * (u0 - p.u[e0]),
                            du * (v0 - p.v[e0]) - dv * (u1 - p.u[e0]),
                            du * (v1 - p.v[e0]) - dv * (u0 - p.u[e0]),
                            du * (v1 - p.v[e0]) - dv * (u1 - p.u[e0]) };
      const double lo = fmin(fmin(c[0], c[1]), fmin(c[2], c[3]));
      const double hi = fmax(fmax(c[0], c[1]), fmax(c[2], c[3]));
      if (lo <= 0 && hi >= 0) {
        touch(scratch, vsh_rtc_texel_index(face, i, j), bits);
      }
    }
  }
}
