/* vsh_mesh_topology.c - welded vertices, the edge table with its face uses,
 * components and closedness (vsh_mesh_topology.h). Built in stages: weld,
 * compact, edges, components, classify. */
#include "vsh_mesh_topology.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *vsh_mesh_status_name(vsh_mesh_status status) {
  switch (status) {
    case VSH_MESH_OK: return "ok";
    case VSH_MESH_INVALID: return "invalid input";
    case VSH_MESH_TOO_LARGE: return "too large for 32-bit indices";
    case VSH_MESH_NO_MEMORY: return "out of memory";
    case VSH_MESH_NOT_CLOSED: return "mesh not closed";
  }
  return "unknown status";
}

void vsh_mesh_topology_free(vsh_mesh_topology *t) {
  if (!t) return;
  free(t->positions);
  free(t->vertex_of_input);
  free(t->triangles);
  free(t->edges);
  free(t->uses);
  free(t->component);
  memset(t, 0, sizeof(*t));
}

/* Stage 1-2: weld, then number the representatives 0..vertex_count-1 in
 * input order and copy their positions. */
static vsh_mesh_status weld_and_compact(const double *positions, size_t n, double tolerance,
                                        vsh_mesh_topology *t) {
  t->input_vertex_count = n;
  t->vertex_of_input = (uint32_t *)malloc((n ? n : 1) * sizeof(uint32_t));
  if (!t->vertex_of_input) return VSH_MESH_NO_MEMORY;
  size_t count = 0;
  vsh_mesh_status s = vsh_mesh_weld(positions, n, tolerance, t->vertex_of_input, &count);
  if (s != VSH_MESH_OK) return s;
  t->vertex_count = count;
  t->positions = (double *)malloc((count ? 3 * count : 1) * sizeof(double));
  if (!t->positions) return VSH_MESH_NO_MEMORY;
  /* A representative precedes every vertex welded to it, so one pass works:
   * the representative's new number is already known when a vertex needs it. */
  uint32_t next = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t r = t->vertex_of_input[i];
    if (r == i) {
      memcpy(t->positions + 3 * (size_t)next, positions + 3 * i, 3 * sizeof(double));
      t->vertex_of_input[i] = next++;
    } else {
      t->vertex_of_input[i] = t->vertex_of_input[r];
    }
  }
  return VSH_MESH_OK;
}

/* One face's directed use of an edge, before grouping. */
typedef struct directed_use {
  uint32_t a, b; /* a < b */
  uint32_t face;
  int32_t sign;
} directed_use;

static int compare_use(const void *pa, const void *pb) {
  const directed_use *x = (const directed_use *)pa, *y = (const directed_use *)pb;
  if (x->a != y->a) return x->a < y->a ? -1 : 1;
  if (x->b != y->b) return x->b < y->b ? -1 : 1;
  return (x->face > y->face) - (x->face < y->face);
}

/* Stage 3a: the welded triangles and each non-degenerate one's three
 * directed edges. *out_uses is malloc'ed (caller frees). */
static vsh_mesh_status collect_uses(const uint32_t *triangles, vsh_mesh_topology *t,
                                    directed_use **out_uses) {
  const size_t n = t->triangle_count;
  *out_uses = NULL;
  t->triangles = (uint32_t *)malloc((n ? 3 * n : 1) * sizeof(uint32_t));
  directed_use *uses = (directed_use *)malloc((n ? 3 * n : 1) * sizeof(directed_use));
  if (!t->triangles || !uses) {
    free(uses);
    return VSH_MESH_NO_MEMORY;
  }
  size_t count = 0;
  for (size_t f = 0; f < n; ++f) {
    uint32_t *v = t->triangles + 3 * f;
    for (int k = 0; k < 3; ++k) v[k] = t->vertex_of_input[triangles[3 * f + k]];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      ++t->degenerate_count;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const uint32_t from = v[k], to = v[(k + 1) % 3];
      directed_use u = {from < to ? from : to, from < to ? to : from, (uint32_t)f,
                        from < to ? 1 : -1};
      uses[count++] = u;
    }
  }
  t->use_count = count;
  qsort(uses, count, sizeof(directed_use), compare_use);
  *out_uses = uses;
  return VSH_MESH_OK;
}

/* Stage 3b: group the sorted uses into edges and count them by kind. */
static vsh_mesh_status group_edges(const directed_use *sorted, vsh_mesh_topology *t) {
  const size_t n = t->use_count;
  t->uses = (vsh_edge_use *)malloc((n ? n : 1) * sizeof(vsh_edge_use));
  t->edges = (vsh_mesh_edge *)malloc((n ? n : 1) * sizeof(vsh_mesh_edge));
  if (!t->uses || !t->edges) return VSH_MESH_NO_MEMORY;
  size_t edges = 0;
  for (size_t k = 0; k < n; ++k) {
    const directed_use *u = &sorted[k];
    if (k == 0 || u->a != sorted[k - 1].a || u->b != sorted[k - 1].b) {
      vsh_mesh_edge e = {u->a, u->b, 0, 0, (uint32_t)k};
      t->edges[edges++] = e;
    }
    vsh_mesh_edge *e = &t->edges[edges - 1];
    if (u->sign > 0)
      ++e->forward;
    else
      ++e->backward;
    t->uses[k].face = u->face;
    t->uses[k].sign = u->sign;
  }
  t->edge_count = edges;
  for (size_t e = 0; e < edges; ++e) {
    const vsh_mesh_edge *x = &t->edges[e];
    const uint32_t faces = x->forward + x->backward;
    t->border_edges += faces == 1;
    t->non_manifold_edges += faces > 2;
    t->misoriented_edges += faces == 2 && x->forward != 1;
  }
  return VSH_MESH_OK;
}

static uint32_t find_root(uint32_t *parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]]; /* path halving */
    x = parent[x];
  }
  return x;
}

/* Stage 4: connected components (union-find over every triangle, the
 * degenerate ones too: they still join their vertices). */
static vsh_mesh_status label_components(vsh_mesh_topology *t) {
  const size_t n = t->vertex_count;
  t->component = (uint32_t *)malloc((n ? n : 1) * sizeof(uint32_t));
  uint32_t *parent = (uint32_t *)malloc((n ? n : 1) * sizeof(uint32_t));
  uint32_t *label = (uint32_t *)malloc((n ? n : 1) * sizeof(uint32_t));
  if (!t->component || !parent || !label) {
    free(parent);
    free(label);
    return VSH_MESH_NO_MEMORY;
  }
  for (size_t v = 0; v < n; ++v) {
    parent[v] = (uint32_t)v;
    label[v] = VSH_MESH_NONE;
    t->component[v] = VSH_MESH_NONE;
  }
  for (size_t f = 0; f < t->triangle_count; ++f) {
    const uint32_t *v = t->triangles + 3 * f;
    const uint32_t r0 = find_root(parent, v[0]);
    parent[find_root(parent, v[1])] = r0;
    parent[find_root(parent, v[2])] = r0;
  }
  for (size_t f = 0; f < t->triangle_count; ++f)
    for (int k = 0; k < 3; ++k) t->component[t->triangles[3 * f + k]] = 0; /* used */
  t->component_count = 0;
  for (size_t v = 0; v < n; ++v) {
    if (t->component[v] == VSH_MESH_NONE) continue;
    const uint32_t root = find_root(parent, (uint32_t)v);
    if (label[root] == VSH_MESH_NONE) label[root] = (uint32_t)t->component_count++;
    t->component[v] = label[root];
  }
  free(parent);
  free(label);
  return VSH_MESH_OK;
}

static vsh_mesh_status check_input(const double *positions, size_t vertex_count,
                                   const uint32_t *triangles, size_t triangle_count,
                                   double tolerance, const vsh_mesh_topology *out) {
  if (!out || (!positions && vertex_count) || (!triangles && triangle_count) ||
      !(tolerance >= 0.0) || !isfinite(tolerance))
    return VSH_MESH_INVALID;
  if (vertex_count >= VSH_MESH_NONE || triangle_count >= VSH_MESH_NONE / 3)
    return VSH_MESH_TOO_LARGE;
  for (size_t i = 0; i < 3 * triangle_count; ++i)
    if (triangles[i] >= vertex_count) return VSH_MESH_INVALID;
  return VSH_MESH_OK;
}

vsh_mesh_status vsh_mesh_topology_build(const double *positions, size_t vertex_count,
                                        const uint32_t *triangles, size_t triangle_count,
                                        double weld_tolerance, vsh_mesh_topology *out) {
  vsh_mesh_status s =
      check_input(positions, vertex_count, triangles, triangle_count, weld_tolerance, out);
  if (out) memset(out, 0, sizeof(*out));
  if (s != VSH_MESH_OK) return s;
  directed_use *sorted = NULL;
  out->triangle_count = triangle_count;
  s = weld_and_compact(positions, vertex_count, weld_tolerance, out);
  if (s == VSH_MESH_OK) s = collect_uses(triangles, out, &sorted);
  if (s == VSH_MESH_OK) s = group_edges(sorted, out);
  free(sorted);
  if (s == VSH_MESH_OK) s = label_components(out);
  if (s != VSH_MESH_OK) {
    vsh_mesh_topology_free(out);
    return s;
  }
  /* A degenerate triangle has no area: it bounds nothing and crosses no
   * segment, so it does not change whether the others close a solid (a
   * glyph field with zero-scaled glyphs keeps their collapsed triangles). */
  out->closed = triangle_count > out->degenerate_count && out->border_edges == 0 &&
                out->non_manifold_edges == 0 && out->misoriented_edges == 0;
  return VSH_MESH_OK;
}
