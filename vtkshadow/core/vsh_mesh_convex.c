/* vsh_mesh_convex.c - signed volume and the convexity test of a closed
 * mesh (vsh_mesh_topology.h). */
#include "vsh_mesh_topology.h"

#include <math.h>

double vsh_mesh_signed_volume6(const vsh_mesh_topology *t) {
  if (!t || t->triangle_count == 0) return 0.0;
  const double *p = t->positions;
  const double *o = p + 3 * (size_t)t->triangles[0];
  double volume = 0.0;
  for (size_t f = 0; f < t->triangle_count; ++f) {
    const uint32_t *v = t->triangles + 3 * f;
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = p[3 * (size_t)v[0] + k] - o[k];
      b[k] = p[3 * (size_t)v[1] + k] - o[k];
      c[k] = p[3 * (size_t)v[2] + k] - o[k];
    }
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
              a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume;
}

/* The vertex of triangle v that is neither a nor b. */
static uint32_t far_vertex(const uint32_t *v, uint32_t a, uint32_t b) {
  uint32_t far = v[0];
  for (int k = 0; k < 3; ++k)
    if (v[k] != a && v[k] != b) far = v[k];
  return far;
}

/* How far (signed, along the outward normal of triangle t) the vertex `far`
 * lies in front of t's plane; 0 for a triangle without area. */
static double height_above(const double *p, const uint32_t *t, uint32_t far, double outwards) {
  double a[3], e1[3], e2[3], d[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = p[3 * (size_t)t[0] + k];
    e1[k] = p[3 * (size_t)t[1] + k] - a[k];
    e2[k] = p[3 * (size_t)t[2] + k] - a[k];
    d[k] = p[3 * (size_t)far + k] - a[k];
  }
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
  const double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(length > 0.0)) return 0.0;
  return outwards * (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / length;
}

vsh_mesh_status vsh_mesh_is_convex(const vsh_mesh_topology *t, double tolerance,
                                   int *out_convex) {
  if (out_convex) *out_convex = 0;
  if (!t || !out_convex || !(tolerance >= 0.0)) return VSH_MESH_INVALID;
  if (!t->closed) return VSH_MESH_NOT_CLOSED;
  if (t->component_count != 1) return VSH_MESH_OK; /* two bodies can shadow each other */
  /* A sphere's Euler characteristic V - E + F = 2: anything else (two
   * bodies pinched together at a vertex, a torus) is not the surface of one
   * convex body even when every edge is convex. */
  size_t used = 0;
  for (size_t v = 0; v < t->vertex_count; ++v) used += t->component[v] != VSH_MESH_NONE;
  const size_t faces = t->triangle_count - t->degenerate_count; /* three distinct vertices */
  if (used + faces != t->edge_count + 2) return VSH_MESH_OK;
  /* An inside-out mesh (negative volume) would make every edge of a convex
   * body look reflex: judge it with its faces turned over. */
  const double outwards = vsh_mesh_signed_volume6(t) < 0.0 ? -1.0 : 1.0;
  for (size_t e = 0; e < t->edge_count; ++e) {
    const vsh_mesh_edge *edge = &t->edges[e];
    /* Closed: exactly two uses, one each way. */
    const vsh_edge_use *u0 = &t->uses[edge->first_use], *u1 = u0 + 1;
    const uint32_t *left = t->triangles + 3 * (size_t)(u0->sign > 0 ? u0->face : u1->face);
    const uint32_t *right = t->triangles + 3 * (size_t)(u0->sign > 0 ? u1->face : u0->face);
    const uint32_t far = far_vertex(right, edge->a, edge->b);
    if (height_above(t->positions, left, far, outwards) > tolerance)
      return VSH_MESH_OK; /* a reflex edge: the surface folds back on itself */
  }
  *out_convex = 1;
  return VSH_MESH_OK;
}
