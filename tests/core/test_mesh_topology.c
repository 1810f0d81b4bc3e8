/* test_mesh_topology.c - unit tests of vsh_mesh_topology: welding (exact and
 * with a tolerance, against a brute-force weld on random clouds), the edge
 * table of closed, open, non-manifold, misoriented and degenerate meshes,
 * components, convexity, 1e6 offset and 1e-6 scale, and bad input. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_mesh_topology.h"
#include "vsh_test_meshes.h"

#include <math.h>
#include <stdlib.h>

static test_mesh mesh; /* large: static, not on the stack */

static vsh_mesh_topology build(double tolerance) {
  vsh_mesh_topology t;
  const vsh_mesh_status s = vsh_mesh_topology_build(mesh.p, mesh.nv, mesh.t, mesh.nt, tolerance, &t);
  CHECK(s == VSH_MESH_OK);
  return t;
}

/* The sum over edges of faces using them is 3 per non-degenerate face. */
static void check_edge_table(const vsh_mesh_topology *t) {
  size_t uses = 0;
  for (size_t e = 0; e < t->edge_count; ++e) {
    const vsh_mesh_edge *x = &t->edges[e];
    CHECK(x->a < x->b);
    if (e > 0) CHECK(t->edges[e - 1].a < x->a || (t->edges[e - 1].a == x->a && t->edges[e - 1].b < x->b));
    CHECK(x->first_use == uses);
    for (uint32_t k = 0; k < x->forward + x->backward; ++k) {
      const vsh_edge_use *u = &t->uses[x->first_use + k];
      const uint32_t *v = t->triangles + 3 * (size_t)u->face;
      int found = 0;
      for (int i = 0; i < 3; ++i) {
        const uint32_t from = v[i], to = v[(i + 1) % 3];
        if (from == x->a && to == x->b) found = u->sign == 1;
        if (from == x->b && to == x->a) found = u->sign == -1;
      }
      CHECK(found);
    }
    uses += x->forward + x->backward;
  }
  CHECK(uses == t->use_count);
  CHECK(uses == 3 * (t->triangle_count - t->degenerate_count));
}

static void test_box_welds_and_closes(void) {
  const double lo[3] = {-1, -2, -3}, hi[3] = {1, 2, 3};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.input_vertex_count == 24);
  CHECK(t.vertex_count == 8);
  CHECK(t.triangle_count == 12);
  CHECK(t.edge_count == 18); /* 12 box edges + 6 face diagonals */
  CHECK(t.closed == 1);
  CHECK(t.component_count == 1);
  CHECK(t.border_edges == 0 && t.non_manifold_edges == 0 && t.misoriented_edges == 0);
  for (size_t e = 0; e < t.edge_count; ++e) CHECK(t.edges[e].forward == 1 && t.edges[e].backward == 1);
  check_edge_table(&t);
  /* Representatives keep their input positions; every input maps onto its own. */
  for (size_t i = 0; i < 24; ++i)
    for (int k = 0; k < 3; ++k) CHECK(t.positions[3 * t.vertex_of_input[i] + k] == mesh.p[3 * i + k]);
  CHECK_NEAR(vsh_mesh_signed_volume6(&t), 6.0 * 2 * 4 * 6, 1e-12);
  int convex = 0;
  CHECK(vsh_mesh_is_convex(&t, 1e-9, &convex) == VSH_MESH_OK && convex == 1);
  vsh_mesh_topology_free(&t);
  CHECK(t.positions == NULL && t.edge_count == 0);
  vsh_mesh_topology_free(&t); /* twice is fine */
}

static void test_inside_out_box_is_convex(void) {
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  for (size_t f = 0; f < mesh.nt; ++f) {
    const uint32_t x = mesh.t[3 * f + 1];
    mesh.t[3 * f + 1] = mesh.t[3 * f + 2];
    mesh.t[3 * f + 2] = x;
  }
  vsh_mesh_topology t = build(0.0);
  CHECK(t.closed == 1);
  CHECK(vsh_mesh_signed_volume6(&t) < 0);
  int convex = 0;
  CHECK(vsh_mesh_is_convex(&t, 1e-9, &convex) == VSH_MESH_OK && convex == 1);
  vsh_mesh_topology_free(&t);
}

static void test_open_quad(void) {
  mesh.nv = mesh.nt = 0;
  const uint32_t a = tm_vertex(&mesh, 0, 0, 0), b = tm_vertex(&mesh, 1, 0, 0);
  const uint32_t c = tm_vertex(&mesh, 1, 1, 0), d = tm_vertex(&mesh, 0, 1, 0);
  tm_quad(&mesh, a, b, c, d);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.edge_count == 5);
  CHECK(t.border_edges == 4);
  CHECK(t.closed == 0);
  CHECK(t.component_count == 1);
  int convex = 1;
  CHECK(vsh_mesh_is_convex(&t, 0.0, &convex) == VSH_MESH_NOT_CLOSED && convex == 0);
  /* The diagonal a-c is shared, one face each way; the rest have one face. */
  for (size_t e = 0; e < t.edge_count; ++e) {
    const vsh_mesh_edge *x = &t.edges[e];
    if (x->a == a && x->b == c)
      CHECK(x->forward == 1 && x->backward == 1);
    else
      CHECK(x->forward + x->backward == 1);
  }
  check_edge_table(&t);
  vsh_mesh_topology_free(&t);
}

static void test_cylinders(void) {
  mesh.nv = mesh.nt = 0;
  tm_cylinder(&mesh, 1.0, 0.0, 2.0, 16, 0);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.vertex_count == 32); /* the seam column welded */
  CHECK(t.border_edges == 32); /* two rims */
  CHECK(t.closed == 0);
  CHECK(t.component_count == 1);
  check_edge_table(&t);
  vsh_mesh_topology_free(&t);
  mesh.nv = mesh.nt = 0;
  tm_cylinder(&mesh, 1.0, 0.0, 2.0, 16, 1);
  t = build(0.0);
  CHECK(t.closed == 1);
  int convex = 0;
  CHECK(vsh_mesh_is_convex(&t, 1e-12, &convex) == VSH_MESH_OK && convex == 1);
  CHECK(vsh_mesh_signed_volume6(&t) > 0);
  vsh_mesh_topology_free(&t);
  /* Without the seam weld it is open along the seam. */
  mesh.nv = mesh.nt = 0;
  tm_cylinder(&mesh, 1.0, 0.0, 2.0, 16, 0);
  mesh.p[3 * 32] += 1e-9; /* the repeated first bottom vertex, moved a hair */
  t = build(0.0);
  CHECK(t.vertex_count == 33);
  CHECK(t.border_edges == 34);
  vsh_mesh_topology_free(&t);
  t = build(1e-8); /* welds again with a tolerance */
  CHECK(t.vertex_count == 32);
  CHECK(t.border_edges == 32);
  vsh_mesh_topology_free(&t);
}

static void test_non_manifold_and_misoriented(void) {
  /* Three triangles on edge (0, 1): a fin. */
  mesh.nv = mesh.nt = 0;
  tm_vertex(&mesh, 0, 0, 0);
  tm_vertex(&mesh, 1, 0, 0);
  tm_vertex(&mesh, 0.5, 1, 0);
  tm_vertex(&mesh, 0.5, -1, 0);
  tm_vertex(&mesh, 0.5, 0, 1);
  tm_triangle(&mesh, 0, 1, 2);
  tm_triangle(&mesh, 1, 0, 3);
  tm_triangle(&mesh, 0, 1, 4);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.non_manifold_edges == 1);
  CHECK(t.border_edges == 6);
  CHECK(t.closed == 0);
  CHECK(t.edges[0].a == 0 && t.edges[0].b == 1);
  CHECK(t.edges[0].forward == 2 && t.edges[0].backward == 1);
  check_edge_table(&t);
  vsh_mesh_topology_free(&t);
  /* Two triangles on an edge running the same way: misoriented. */
  mesh.nt = 0;
  tm_triangle(&mesh, 0, 1, 2);
  tm_triangle(&mesh, 0, 1, 3);
  t = build(0.0);
  CHECK(t.misoriented_edges == 1);
  CHECK(t.edges[0].forward == 2 && t.edges[0].backward == 0);
  vsh_mesh_topology_free(&t);
  /* A box with one face flipped is not closed (misoriented edges). */
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  for (int f = 0; f < 2; ++f) {
    const uint32_t x = mesh.t[3 * f + 1];
    mesh.t[3 * f + 1] = mesh.t[3 * f + 2];
    mesh.t[3 * f + 2] = x;
  }
  t = build(0.0);
  CHECK(t.closed == 0);
  CHECK(t.misoriented_edges == 4);
  vsh_mesh_topology_free(&t);
}

static void test_degenerate_triangles(void) {
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  /* A sliver whose two corners weld into one: degenerate after welding. */
  const uint32_t x = tm_vertex(&mesh, 1, 1, 1), y = tm_vertex(&mesh, 1, 1, 1);
  tm_triangle(&mesh, 0, x, y);
  tm_triangle(&mesh, 5, 5, 5);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.degenerate_count == 2);
  CHECK(t.edge_count == 18); /* degenerate faces add no edges */
  CHECK(t.closed == 1);      /* and no area: the box still bounds a solid */
  CHECK(t.component_count == 1);
  int convex = 0; /* Euler's count leaves them out too */
  CHECK(vsh_mesh_is_convex(&t, 1e-9, &convex) == VSH_MESH_OK && convex == 1);
  check_edge_table(&t);
  vsh_mesh_topology_free(&t);
  /* Only degenerate triangles: no edges, not closed, still OK. */
  mesh.nt = 0;
  tm_triangle(&mesh, 0, 0, 1);
  t = build(0.0);
  CHECK(t.edge_count == 0 && t.closed == 0 && t.degenerate_count == 1);
  vsh_mesh_topology_free(&t);
}

static void test_components_and_concave(void) {
  const double lo0[3] = {0, 0, 0}, hi0[3] = {1, 1, 1};
  const double lo1[3] = {3, 0, 0}, hi1[3] = {4, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo0, hi0);
  tm_vertex(&mesh, 9, 9, 9); /* unused: not a component */
  tm_box(&mesh, lo1, hi1);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.closed == 1);
  CHECK(t.component_count == 2);
  CHECK(t.component[t.vertex_of_input[0]] == 0);
  CHECK(t.component[t.vertex_of_input[24]] == VSH_MESH_NONE);
  CHECK(t.component[t.vertex_of_input[25]] == 1);
  int convex = 1;
  CHECK(vsh_mesh_is_convex(&t, 1e-9, &convex) == VSH_MESH_OK && convex == 0);
  vsh_mesh_topology_free(&t);
  /* Boxes sharing a corner are one component, closed (every edge has one
   * face each way) and convex along every edge, but pinched at the corner:
   * the Euler characteristic (3) says they are not one convex body. */
  const double lo2[3] = {1, 1, 1}, hi2[3] = {2, 2, 2};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo0, hi0);
  tm_box(&mesh, lo2, hi2);
  t = build(0.0);
  CHECK(t.component_count == 1);
  CHECK(t.closed == 1);
  CHECK(vsh_mesh_is_convex(&t, 1e-9, &convex) == VSH_MESH_OK && convex == 0);
  vsh_mesh_topology_free(&t);
}

static double bumpy(int ring, int segment, void *user) {
  (void)user;
  return 1.0 + 0.3 * ((ring * 7 + segment * 3) % 5 == 0);
}

static void test_sphere_convexity(void) {
  mesh.nv = mesh.nt = 0;
  tm_sphere(&mesh, 12, 24, NULL, NULL);
  vsh_mesh_topology t = build(0.0);
  CHECK(t.closed == 1);
  CHECK(t.vertex_count == 11 * 24 + 2); /* seams and poles welded */
  int convex = 0;
  CHECK(vsh_mesh_is_convex(&t, 1e-12, &convex) == VSH_MESH_OK && convex == 1);
  vsh_mesh_topology_free(&t);
  mesh.nv = mesh.nt = 0;
  tm_sphere(&mesh, 12, 24, bumpy, NULL);
  t = build(0.0);
  CHECK(t.closed == 1);
  CHECK(vsh_mesh_is_convex(&t, 1e-12, &convex) == VSH_MESH_OK && convex == 0);
  vsh_mesh_topology_free(&t);
}

/* The same closed meshes far from the origin and tiny give the same
 * topology; welding with a tolerance relative to their size too. */
static void test_offset_and_scale(void) {
  const double offsets[3][3] = {{0, 0, 0}, {1e6, -1e6, 1e6}, {0.5, 0.25, -0.125}};
  const double scales[3] = {1.0, 1.0, 1e-6};
  for (int c = 0; c < 3; ++c) {
    mesh.nv = mesh.nt = 0;
    tm_sphere(&mesh, 10, 20, NULL, NULL);
    tm_transform(&mesh, 0, scales[c], offsets[c]);
    vsh_mesh_topology t = build(0.0);
    CHECK(t.closed == 1);
    CHECK(t.vertex_count == 9 * 20 + 2); /* 9 rings of 20 + 2 poles */
    int convex = 0;
    /* Rounding of positions near 1e6 is 1e-10: the tolerance has to allow it. */
    CHECK(vsh_mesh_is_convex(&t, 1e-9 * scales[c], &convex) == VSH_MESH_OK && convex == 1);
    const size_t edges = t.edge_count;
    vsh_mesh_topology_free(&t);
    /* Jitter every vertex by 1e-4 of the size: exact welding fails, a
     * tolerance of 1e-3 of the size welds it back. */
    vsh_test_seed(77 + c);
    for (size_t i = 0; i < 3 * mesh.nv; ++i) mesh.p[i] += vsh_test_rnd(-1e-4, 1e-4) * scales[c];
    t = build(0.0);
    CHECK(t.closed == 0);
    vsh_mesh_topology_free(&t);
    t = build(1e-3 * scales[c]);
    CHECK(t.closed == 1);
    CHECK(t.edge_count == edges);
    vsh_mesh_topology_free(&t);
  }
}

/* Brute force: vertex j joins the smallest earlier representative within
 * the tolerance. */
static void brute_weld(const double *p, size_t n, double tol, uint32_t *map) {
  for (size_t j = 0; j < n; ++j) {
    map[j] = (uint32_t)j;
    for (size_t i = 0; i < j; ++i) {
      const double d[3] = {p[3 * i] - p[3 * j], p[3 * i + 1] - p[3 * j + 1], p[3 * i + 2] - p[3 * j + 2]};
      if (map[i] == i && d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= tol * tol) {
        map[j] = (uint32_t)i;
        break;
      }
    }
  }
}

static void test_weld_random(void) {
  static double p[3 * 600];
  static uint32_t fast[600], slow[600];
  vsh_test_seed(2024);
  int welded_some = 0;
  for (int round = 0; round < 40; ++round) {
    const size_t n = 50 + (size_t)vsh_test_rnd(0, 500);
    const double scale = round % 3 == 0 ? 1e-6 : round % 3 == 1 ? 1.0 : 1e3;
    const double offset = round % 2 ? 1e6 * scale : 0.0;
    /* Clusters: many points near a few centres, some exact copies. */
    for (size_t i = 0; i < n; ++i) {
      if (i > 0 && vsh_test_rnd(0, 1) < 0.2) {
        const size_t j = (size_t)vsh_test_rnd(0, (double)i);
        for (int k = 0; k < 3; ++k) p[3 * i + k] = p[3 * j + k];
        continue;
      }
      for (int k = 0; k < 3; ++k)
        p[3 * i + k] = offset + scale * (floor(vsh_test_rnd(0, 4)) + vsh_test_rnd(-0.05, 0.05));
    }
    const double tol = round % 4 == 0 ? 0.0 : scale * vsh_test_rnd(0.001, 0.08);
    size_t reps = 0;
    CHECK(vsh_mesh_weld(p, n, tol, fast, &reps) == VSH_MESH_OK);
    brute_weld(p, n, tol, slow);
    size_t mismatches = 0, brute_reps = 0;
    for (size_t i = 0; i < n; ++i) {
      mismatches += fast[i] != slow[i];
      brute_reps += slow[i] == i;
    }
    CHECK(mismatches == 0);
    CHECK(reps == brute_reps);
    welded_some += reps < n;
  }
  CHECK(welded_some == 40);
}

static void test_bad_input(void) {
  vsh_mesh_topology t;
  const double p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint32_t tri[3] = {0, 1, 2}, bad[3] = {0, 1, 3};
  CHECK(vsh_mesh_topology_build(p, 3, tri, 1, 0.0, &t) == VSH_MESH_OK);
  CHECK(t.closed == 0 && t.border_edges == 3);
  vsh_mesh_topology_free(&t);
  CHECK(vsh_mesh_topology_build(p, 3, bad, 1, 0.0, &t) == VSH_MESH_INVALID);
  CHECK(t.edges == NULL && t.positions == NULL);
  CHECK(vsh_mesh_topology_build(p, 3, tri, 1, -1.0, &t) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_topology_build(p, 3, tri, 1, NAN, &t) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_topology_build(p, 3, tri, 1, INFINITY, &t) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_topology_build(NULL, 3, tri, 1, 0.0, &t) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_topology_build(p, 3, NULL, 1, 0.0, &t) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_topology_build(p, 3, tri, 1, 0.0, NULL) == VSH_MESH_INVALID);
  const double nan_p[9] = {0, 0, 0, 1, NAN, 0, 0, 1, 0};
  CHECK(vsh_mesh_topology_build(nan_p, 3, tri, 1, 0.0, &t) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_topology_build(p, 3, tri, (size_t)1 << 31, 0.0, &t) == VSH_MESH_TOO_LARGE);
  /* Empty: OK, nothing closed. */
  CHECK(vsh_mesh_topology_build(NULL, 0, NULL, 0, 0.0, &t) == VSH_MESH_OK);
  CHECK(t.closed == 0 && t.edge_count == 0 && t.vertex_count == 0);
  CHECK(vsh_mesh_signed_volume6(&t) == 0.0);
  vsh_mesh_topology_free(&t);
  int convex = 1;
  CHECK(vsh_mesh_is_convex(NULL, 0.0, &convex) == VSH_MESH_INVALID && convex == 0);
  uint32_t map[3];
  CHECK(vsh_mesh_weld(p, 3, -1.0, map, NULL) == VSH_MESH_INVALID);
  CHECK(vsh_mesh_weld(p, 3, 0.0, map, NULL) == VSH_MESH_OK);
  CHECK(map[0] == 0 && map[1] == 1 && map[2] == 2);
  /* -0 and +0 are the same position. */
  const double signed_zero[6] = {0.0, -0.0, 0.0, -0.0, 0.0, -0.0};
  CHECK(vsh_mesh_weld(signed_zero, 2, 0.0, map, NULL) == VSH_MESH_OK && map[1] == 0);
  CHECK_STR_CONTAINS(vsh_mesh_status_name(VSH_MESH_NOT_CLOSED), "closed");
  CHECK_STR_CONTAINS(vsh_mesh_status_name((vsh_mesh_status)99), "unknown");
}

int main(void) {
  test_box_welds_and_closes();
  test_inside_out_box_is_convex();
  test_open_quad();
  test_cylinders();
  test_non_manifold_and_misoriented();
  test_degenerate_triangles();
  test_components_and_concave();
  test_sphere_convexity();
  test_offset_and_scale();
  test_weld_random();
  test_bad_input();
  return vsh_check_report("test_mesh_topology");
}
