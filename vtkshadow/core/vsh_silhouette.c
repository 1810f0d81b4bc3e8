/* vsh_silhouette.c - silhouette edges with multiplicity, their length as the
 * light sees it, and fans per component (vsh_silhouette.h). */
#include "vsh_silhouette.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The light with w >= 0 ((w L, w) and (-w L, -w) are the same point), or
 * 0 when it is unusable (non-finite or all zero). */
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

/* Triangle v's first vertex `a` and its (unnormalized) normal
 * (b - a) x (c - a). */
static void face_plane(const double *p, const uint32_t v[3], double a[3], double n[3]) {
  double e1[3], e2[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = p[3 * (size_t)v[0] + k];
    e1[k] = p[3 * (size_t)v[1] + k] - a[k];
    e2[k] = p[3 * (size_t)v[2] + k] - a[k];
  }
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

int vsh_triangle_faces_light(const double *p, const uint32_t v[3], const double light[4]) {
  double a[3], n[3];
  face_plane(p, v, a, n);
  const double to[3] = {light[0] - light[3] * a[0], light[1] - light[3] * a[1],
                        light[2] - light[3] * a[2]};
  return (n[0] * to[0] + n[1] * to[1] + n[2] * to[2]) > 0.0;
}

vsh_mesh_status vsh_silhouette_facing(const vsh_mesh_topology *t, const double light[4],
                                      unsigned char *out_facing) {
  double l[4];
  if (!t || (!out_facing && t->triangle_count) || !usable_light(light, l))
    return VSH_MESH_INVALID;
  for (size_t f = 0; f < t->triangle_count; ++f)
    out_facing[f] = (unsigned char)vsh_triangle_faces_light(t->positions, t->triangles + 3 * f, l);
  return VSH_MESH_OK;
}

/* The edge's coefficient in the silhouette cycle (vsh_silhouette.h). */
static long edge_multiplicity(const vsh_mesh_topology *t, const vsh_mesh_edge *e,
                              const unsigned char *facing, vsh_silhouette_mode mode) {
  long m = 0;
  const vsh_edge_use *u = t->uses + e->first_use;
  for (uint32_t k = 0; k < e->forward + e->backward; ++k) {
    if (facing[u[k].face])
      m += u[k].sign;
    else if (mode == VSH_SILHOUETTE_BOTH_SIDES)
      m -= u[k].sign;
  }
  return m;
}

void vsh_silhouette_free(vsh_silhouette *s) {
  if (!s) return;
  free(s->edges);
  memset(s, 0, sizeof(*s));
}

vsh_mesh_status vsh_silhouette_build(const vsh_mesh_topology *t, const double light[4],
                                     vsh_silhouette_mode mode, vsh_silhouette *out) {
  if (out) memset(out, 0, sizeof(*out));
  if (!t || !out || (mode != VSH_SILHOUETTE_LIT_FACES && mode != VSH_SILHOUETTE_BOTH_SIDES))
    return VSH_MESH_INVALID;
  const size_t nt = t->triangle_count, ne = t->edge_count;
  unsigned char *facing = (unsigned char *)malloc(nt ? nt : 1);
  out->edges = (vsh_silhouette_edge *)malloc((ne ? ne : 1) * sizeof(vsh_silhouette_edge));
  if (!facing || !out->edges) {
    free(facing);
    vsh_silhouette_free(out);
    return VSH_MESH_NO_MEMORY;
  }
  const vsh_mesh_status s = vsh_silhouette_facing(t, light, facing);
  if (s != VSH_MESH_OK) {
    free(facing);
    vsh_silhouette_free(out);
    return s;
  }
  for (size_t e = 0; e < ne; ++e) {
    const vsh_mesh_edge *edge = &t->edges[e];
    const long m = edge_multiplicity(t, edge, facing, mode);
    if (m == 0) continue;
    vsh_silhouette_edge *x = &out->edges[out->count++];
    x->from = m > 0 ? edge->a : edge->b;
    x->to = m > 0 ? edge->b : edge->a;
    x->multiplicity = (uint32_t)(m > 0 ? m : -m);
    x->edge = (uint32_t)e;
    out->total_multiplicity += x->multiplicity;
  }
  free(facing);
  return VSH_MESH_OK;
}

vsh_mesh_status vsh_silhouette_length(const vsh_mesh_topology *t, const vsh_silhouette *s,
                                      const double light[4], double *out_length) {
  double l[4];
  if (out_length) *out_length = 0.0;
  if (!t || !s || !out_length || !usable_light(light, l)) return VSH_MESH_INVALID;
  double length = 0.0;
  for (size_t k = 0; k < s->count; ++k) {
    const vsh_mesh_edge *edge = &t->edges[s->edges[k].edge];
    const double *a = t->positions + 3 * (size_t)edge->a;
    const double *b = t->positions + 3 * (size_t)edge->b;
    double d[3], u[3];
    for (int i = 0; i < 3; ++i) {
      d[i] = b[i] - a[i];
      u[i] = l[i] - l[3] * 0.5 * (a[i] + b[i]); /* towards the light from the middle */
    }
    const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    const double along = uu > 0.0 ? (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / uu : 0.0;
    for (int i = 0; i < 3; ++i) d[i] -= along * u[i];
    length += s->edges[k].multiplicity * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
  *out_length = length;
  return VSH_MESH_OK;
}

vsh_mesh_status vsh_silhouette_fans(const vsh_mesh_topology *t, const vsh_silhouette *s,
                                    uint32_t *out_triangles) {
  if (!t || !s || (!out_triangles && s->total_multiplicity)) return VSH_MESH_INVALID;
  uint32_t *centre_of =
      (uint32_t *)malloc((t->component_count ? t->component_count : 1) * sizeof(uint32_t));
  if (!centre_of) return VSH_MESH_NO_MEMORY;
  for (size_t c = 0; c < t->component_count; ++c) centre_of[c] = VSH_MESH_NONE;
  size_t out = 0;
  for (size_t k = 0; k < s->count; ++k) {
    const vsh_silhouette_edge *e = &s->edges[k];
    uint32_t *centre = &centre_of[t->component[e->from]];
    if (*centre == VSH_MESH_NONE) *centre = e->from;
    for (uint32_t r = 0; r < e->multiplicity; ++r, out += 3) {
      out_triangles[out] = *centre;
      out_triangles[out + 1] = e->from;
      out_triangles[out + 2] = e->to;
    }
  }
  free(centre_of);
  return VSH_MESH_OK;
}

int vsh_silhouette_seen_unlit(const vsh_mesh_topology *t, const double light[4],
                              const double eye[4]) {
  double l[4], e[4];
  if (!t || !usable_light(light, l) || !usable_light(eye, e)) return 1;
  const double *p = t->positions;
  for (size_t f = 0; f < t->triangle_count; ++f) {
    const uint32_t *v = t->triangles + 3 * f;
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
    double a[3], n[3];
    face_plane(p, v, a, n);
    double to_light = 0.0, to_eye = 0.0;
    for (int k = 0; k < 3; ++k) {
      to_light += n[k] * (l[k] - l[3] * a[k]);
      to_eye += n[k] * (e[k] - e[3] * a[k]);
    }
    if ((to_light > 0.0 && to_eye < 0.0) || (to_light < 0.0 && to_eye > 0.0)) return 1;
  }
  return 0;
}
