/* test_silhouette.c - unit tests of vsh_silhouette: silhouettes of boxes
 * and cylinders for known lights, the degenerate light-in-a-face's-plane
 * case, a light inside the mesh or its bounds, open and non-manifold
 * meshes; multiplicities against a brute-force count over random meshes
 * and lights; fans against ray casting (the shadow is where their winding
 * number is non-zero); silhouette length; bad input. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_silhouette.h"
#include "vsh_test_meshes.h"
#include "vsh_vec3.h"

#include <math.h>
#include <stdlib.h>

static test_mesh mesh;

static vsh_mesh_topology build(void) {
  vsh_mesh_topology t;
  CHECK(vsh_mesh_topology_build(mesh.p, mesh.nv, mesh.t, mesh.nt, 0.0, &t) == VSH_MESH_OK);
  return t;
}

static vsh_silhouette silhouette(const vsh_mesh_topology *t, const double light[4],
                                 vsh_silhouette_mode mode) {
  vsh_silhouette s;
  CHECK(vsh_silhouette_build(t, light, mode, &s) == VSH_MESH_OK);
  return s;
}

/* Every vertex has as many silhouette edges (with multiplicity) leaving it
 * as arriving: the silhouette is a cycle. Returns 1 when balanced. */
static int balanced(const vsh_mesh_topology *t, const vsh_silhouette *s) {
  long *degree = (long *)calloc(t->vertex_count + 1, sizeof(long));
  for (size_t k = 0; k < s->count; ++k) {
    degree[s->edges[k].from] += s->edges[k].multiplicity;
    degree[s->edges[k].to] -= s->edges[k].multiplicity;
  }
  int ok = 1;
  for (size_t v = 0; v < t->vertex_count; ++v) ok = ok && degree[v] == 0;
  free(degree);
  return ok;
}

/* The unit square in z = 0, facing +z. */
static void unit_quad(void) {
  mesh.nv = mesh.nt = 0;
  const uint32_t q0 = tm_vertex(&mesh, 0, 0, 0), q1 = tm_vertex(&mesh, 1, 0, 0);
  const uint32_t q2 = tm_vertex(&mesh, 1, 1, 0), q3 = tm_vertex(&mesh, 0, 1, 0);
  tm_quad(&mesh, q0, q1, q2, q3);
}

static void unit_box(void) {
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
}

static void test_box_known_lights(void) {
  unit_box();
  vsh_mesh_topology t = build();
  /* Straight down from +z: the side faces are edge-on (degenerate case,
   * they do not face it), the top square is the silhouette. */
  const double down[4] = {0, 0, 1, 0};
  vsh_silhouette s = silhouette(&t, down, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 4 && s.total_multiplicity == 4);
  for (size_t k = 0; k < s.count; ++k) {
    CHECK(t.positions[3 * s.edges[k].from + 2] == 1.0 && t.positions[3 * s.edges[k].to + 2] == 1.0);
    CHECK(s.edges[k].multiplicity == 1);
  }
  CHECK(balanced(&t, &s));
  double length = 0;
  CHECK(vsh_silhouette_length(&t, &s, down, &length) == VSH_MESH_OK);
  CHECK_NEAR(length, 4.0, 1e-15);
  vsh_silhouette_free(&s);
  CHECK(s.edges == NULL && s.count == 0);
  /* Along the diagonal: the hexagon, each edge seen at sqrt(2/3). */
  const double diagonal[4] = {1, 1, 1, 0};
  s = silhouette(&t, diagonal, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 6);
  CHECK(balanced(&t, &s));
  CHECK(vsh_silhouette_length(&t, &s, diagonal, &length) == VSH_MESH_OK);
  CHECK_NEAR(length, 6.0 * sqrt(2.0 / 3.0), 1e-14);
  vsh_silhouette_free(&s);
  /* Both sides: the same edges, twice. */
  s = silhouette(&t, diagonal, VSH_SILHOUETTE_BOTH_SIDES);
  CHECK(s.count == 6 && s.total_multiplicity == 12);
  vsh_silhouette_free(&s);
  /* A point light far up: the top square, edges across the ray. */
  const double above[4] = {0.5, 0.5, 100, 1};
  s = silhouette(&t, above, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 4);
  CHECK(vsh_silhouette_length(&t, &s, above, &length) == VSH_MESH_OK);
  CHECK_NEAR(length, 4.0, 1e-12);
  vsh_silhouette_free(&s);
  /* The same point given as (w L, w) with w = -2. */
  const double above_scaled[4] = {-1, -1, -200, -2};
  s = silhouette(&t, above_scaled, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 4);
  vsh_silhouette_free(&s);
  /* Inside the box: nothing faces it, no silhouette in either mode. */
  const double inside[4] = {0.3, 0.6, 0.5, 1};
  s = silhouette(&t, inside, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 0);
  vsh_silhouette_free(&s);
  s = silhouette(&t, inside, VSH_SILHOUETTE_BOTH_SIDES);
  CHECK(s.count == 0);
  vsh_silhouette_free(&s);
  /* In the plane of the top face, outside the box: the top is edge-on. */
  const double level[4] = {3, 0.5, 1, 1};
  s = silhouette(&t, level, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 4); /* the +x face's outline */
  CHECK(balanced(&t, &s));
  vsh_silhouette_free(&s);
  vsh_mesh_topology_free(&t);
}

static void test_open_meshes(void) {
  /* A single quad facing +z, lit from below: the lit faces have no
   * silhouette, both sides gives its border reversed. */
  unit_quad();
  vsh_mesh_topology t = build();
  const double below[4] = {0.2, 0.3, -1, 0}, above[4] = {0.2, 0.3, 1, 0};
  vsh_silhouette s = silhouette(&t, below, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 0);
  vsh_silhouette_free(&s);
  s = silhouette(&t, below, VSH_SILHOUETTE_BOTH_SIDES);
  CHECK(s.count == 4 && s.total_multiplicity == 4 && balanced(&t, &s));
  /* Reversed: the border runs clockwise seen from +z; edge (0, 1) is 1 -> 0. */
  CHECK(s.edges[0].from == 1 && s.edges[0].to == 0);
  vsh_silhouette_free(&s);
  s = silhouette(&t, above, VSH_SILHOUETTE_LIT_FACES);
  CHECK(s.count == 4 && balanced(&t, &s));
  CHECK(s.edges[0].from == 0 && s.edges[0].to == 1);
  vsh_silhouette_free(&s);
  vsh_mesh_topology_free(&t);
  /* Open cylinder lit from the side: two rims' halves and two seam lines. */
  mesh.nv = mesh.nt = 0;
  tm_cylinder(&mesh, 1.0, 0.0, 2.0, 16, 0);
  t = build();
  const double side[4] = {1, 0.1, 0, 0};
  s = silhouette(&t, side, VSH_SILHOUETTE_BOTH_SIDES);
  CHECK(balanced(&t, &s));
  /* Every rim edge is a border: each appears once (either direction). */
  size_t rim = 0;
  for (size_t k = 0; k < s.count; ++k) {
    const vsh_mesh_edge *e = &t.edges[s.edges[k].edge];
    rim += e->forward + e->backward == 1;
    CHECK(s.edges[k].multiplicity == (e->forward + e->backward == 1 ? 1u : 2u));
  }
  CHECK(rim == 32);
  vsh_silhouette_free(&s);
  vsh_mesh_topology_free(&t);
}

static void test_non_manifold_fin(void) {
  /* Three triangles on edge (0, 1), all in front of the light. */
  mesh.nv = mesh.nt = 0;
  tm_vertex(&mesh, 0, 0, 0);
  tm_vertex(&mesh, 1, 0, 0);
  tm_vertex(&mesh, 0.5, 1, 0.1);
  tm_vertex(&mesh, 0.5, -1, 0.1);
  tm_vertex(&mesh, 0.5, 0.2, 1);
  tm_triangle(&mesh, 0, 1, 2); /* faces +z */
  tm_triangle(&mesh, 1, 0, 3); /* faces +z */
  tm_triangle(&mesh, 0, 1, 4); /* faces -y mostly */
  vsh_mesh_topology t = build();
  const double up[4] = {0, 0, 1, 0};
  vsh_silhouette s = silhouette(&t, up, VSH_SILHOUETTE_LIT_FACES);
  /* Faces 0 and 1 lit (one each way on 0-1: cancels); face 2 faces -y +z:
   * normal (1,0,0)x(0.5,0.2,1) = (0,-1,0.2): lit too, adds 0->1 once. */
  CHECK(s.edges[0].from == 0 && s.edges[0].to == 1 && s.edges[0].multiplicity == 1);
  CHECK(balanced(&t, &s));
  vsh_silhouette_free(&s);
  const double y_light[4] = {0, 1, 0, 0};
  s = silhouette(&t, y_light, VSH_SILHOUETTE_BOTH_SIDES);
  CHECK(balanced(&t, &s));
  /* Normals (0,-0.1,1), (0,0.1,1), (0,-1,0.2): only face 1 faces +y. Turned
   * to the light, all three run 1 -> 0 along the fin's edge: m = 3. */
  CHECK(s.edges[0].edge == 0 && s.edges[0].from == 1 && s.edges[0].to == 0);
  CHECK(s.edges[0].multiplicity == 3);
  vsh_silhouette_free(&s);
  vsh_mesh_topology_free(&t);
}

/* ---- brute force over random meshes and lights ---------------------------- */

/* Facing computed from vertex b instead of a, with the light's ambiguity
 * reported: 1 facing, 0 not, -1 too close to call. */
static int brute_facing(const double *p, const uint32_t *v, const double l[4]) {
  const double *a = p + 3 * v[0], *b = p + 3 * v[1], *c = p + 3 * v[2];
  double cb[3], ab[3], n[3], to[3];
  vsh_vec3_sub(c, b, cb);
  vsh_vec3_sub(a, b, ab);
  vsh_vec3_cross(cb, ab, n);
  for (int k = 0; k < 3; ++k) to[k] = l[k] - l[3] * b[k];
  const double d = vsh_vec3_dot(n, to);
  const double scale = vsh_vec3_length(n) * vsh_vec3_length(to);
  if (fabs(d) <= 1e-9 * scale) return -1;
  return d > 0;
}

/* Random mesh: a soup over a few shared vertices (open, non-manifold,
 * misoriented, sometimes degenerate) or a bumpy closed sphere. */
static double random_radius(int ring, int segment, void *user) {
  (void)ring, (void)segment, (void)user;
  return vsh_test_rnd(0.6, 1.4);
}

static void random_mesh(int round) {
  mesh.nv = mesh.nt = 0;
  if (round % 2) {
    tm_sphere(&mesh, 4 + round % 5, 5 + round % 7, random_radius, NULL);
    return;
  }
  const int nv = 4 + round % 9, nt = 3 + round % 23;
  for (int i = 0; i < nv; ++i)
    tm_vertex(&mesh, vsh_test_rnd(-1, 1), vsh_test_rnd(-1, 1), vsh_test_rnd(-1, 1));
  for (int f = 0; f < nt; ++f)
    tm_triangle(&mesh, (uint32_t)vsh_test_rnd(0, nv), (uint32_t)vsh_test_rnd(0, nv),
                (uint32_t)vsh_test_rnd(0, nv));
}

/* A random light: directional, far, near, or inside the bounds. */
static void random_light(int k, double l[4]) {
  double d[3];
  vsh_test_rnd_unit(d);
  const double r = k % 4 == 0 ? 0.0 : k % 4 == 1 ? 20.0 : k % 4 == 2 ? 2.0 : 0.5;
  for (int i = 0; i < 3; ++i) l[i] = r == 0.0 ? d[i] : r * d[i] * vsh_test_rnd(0, 1);
  l[3] = r == 0.0 ? 0.0 : 1.0;
}

/* Compares the silhouette with the per-pair count of lit face uses; returns
 * the mismatching pairs, or -1 when a face is too close to call. */
static long compare_brute(const vsh_mesh_topology *t, const double l[4], vsh_silhouette_mode mode,
                          const vsh_silhouette *s) {
  const size_t n = t->vertex_count;
  long *m = (long *)calloc(n * n, sizeof(long));
  for (size_t f = 0; f < t->triangle_count; ++f) {
    const uint32_t *v = t->triangles + 3 * f;
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
    const int lit = brute_facing(t->positions, v, l);
    if (lit < 0) {
      free(m);
      return -1;
    }
    const long w = lit ? 1 : mode == VSH_SILHOUETTE_BOTH_SIDES ? -1 : 0;
    for (int k = 0; k < 3; ++k) m[v[k] * n + v[(k + 1) % 3]] += w;
  }
  for (size_t k = 0; k < s->count; ++k) /* remove what the silhouette lists */
    m[s->edges[k].from * n + s->edges[k].to] -= (long)s->edges[k].multiplicity;
  long bad = 0;
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) bad += m[a * n + b] - m[b * n + a] != 0;
  free(m);
  return bad;
}

static void test_random_against_brute_force(void) {
  vsh_test_seed(4711);
  int compared = 0, skipped = 0;
  long mismatches = 0;
  for (int round = 0; round < 300; ++round) {
    random_mesh(round);
    vsh_mesh_topology t = build();
    for (int k = 0; k < 8; ++k) {
      double l[4];
      random_light(k, l);
      for (int mode = 0; mode < 2; ++mode) {
        vsh_silhouette s = silhouette(&t, l, (vsh_silhouette_mode)mode);
        const long bad = compare_brute(&t, l, (vsh_silhouette_mode)mode, &s);
        if (bad < 0) {
          ++skipped;
        } else {
          ++compared;
          mismatches += bad;
        }
        CHECK(balanced(&t, &s));
        if (t.closed && mode == 0)
          for (size_t e = 0; e < s.count; ++e) CHECK(s.edges[e].multiplicity == 1);
        vsh_silhouette_free(&s);
      }
    }
    vsh_mesh_topology_free(&t);
  }
  CHECK(mismatches == 0);
  CHECK(compared > 4500);
  CHECK(skipped < 10);
  printf("silhouettes compared with brute force: %d (%d too close to call)\n", compared, skipped);
}

/* ---- fans against ray casting ------------------------------------------- */

/* 2D orientation of (a, b, q): > 0 when q is left of a->b. */
static double orient(const double a[2], const double b[2], const double q[2]) {
  return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
}

/* +1 / -1 when q is strictly inside the counter-clockwise / clockwise
 * triangle, 0 outside; sets *close when q is within eps of an edge line. */
static int signed_cover(const double a[2], const double b[2], const double c[2], const double q[2],
                        double eps, int *close) {
  const double area = orient(a, b, c);
  if (area == 0.0) return 0;
  const double s = area > 0 ? 1.0 : -1.0;
  const double w0 = s * orient(a, b, q), w1 = s * orient(b, c, q), w2 = s * orient(c, a, q);
  const double e = eps * fabs(area);
  if ((fabs(w0) < e && w1 > -e && w2 > -e) || (fabs(w1) < e && w0 > -e && w2 > -e) ||
      (fabs(w2) < e && w0 > -e && w1 > -e))
    *close = 1;
  return (w0 > 0 && w1 > 0 && w2 > 0) ? (int)s : 0;
}

/* Directional light l: project along it onto the plane spanned by u, v
 * (u x v = towards the light), so lit faces come out counter-clockwise. */
static void project(const double p[3], const double u[3], const double v[3], double out[2]) {
  out[0] = vsh_vec3_dot(p, u);
  out[1] = vsh_vec3_dot(p, v);
}

/* For random points: the fans' winding number must equal the number of
 * faces covering the point (lit ones for LIT_FACES, all for BOTH_SIDES). */
static long check_fans(const vsh_mesh_topology *t, const double l[4], vsh_silhouette_mode mode,
                       int *checked) {
  double dir[3], u[3], v[3], tmp[3] = {0.3, -0.7, 0.2};
  vsh_vec3_normalize(l, dir);
  vsh_vec3_cross(dir, tmp, u);
  vsh_vec3_normalize(u, u);
  vsh_vec3_cross(dir, u, v); /* u x v = dir */
  vsh_silhouette s = silhouette(t, l, mode);
  uint32_t *fans = (uint32_t *)malloc((3 * s.total_multiplicity + 1) * sizeof(uint32_t));
  CHECK(vsh_silhouette_fans(t, &s, fans) == VSH_MESH_OK);
  unsigned char *facing = (unsigned char *)malloc(t->triangle_count + 1);
  CHECK(vsh_silhouette_facing(t, l, facing) == VSH_MESH_OK);
  long bad = 0;
  for (int q = 0; q < 200; ++q) {
    const double point[2] = {vsh_test_rnd(-1.5, 1.5), vsh_test_rnd(-1.5, 1.5)};
    int close = 0, winding = 0, covered = 0;
    for (size_t f = 0; f < s.total_multiplicity; ++f) {
      double a[2], b[2], c[2];
      project(t->positions + 3 * fans[3 * f], u, v, a);
      project(t->positions + 3 * fans[3 * f + 1], u, v, b);
      project(t->positions + 3 * fans[3 * f + 2], u, v, c);
      winding += signed_cover(a, b, c, point, 1e-9, &close);
    }
    for (size_t f = 0; f < t->triangle_count; ++f) {
      const uint32_t *x = t->triangles + 3 * f;
      double a[2], b[2], c[2];
      project(t->positions + 3 * x[0], u, v, a);
      project(t->positions + 3 * x[1], u, v, b);
      project(t->positions + 3 * x[2], u, v, c);
      const int cover = signed_cover(a, b, c, point, 1e-9, &close);
      covered += facing[f] ? cover : mode == VSH_SILHOUETTE_BOTH_SIDES ? -cover : 0;
    }
    if (close) continue;
    ++*checked;
    bad += winding != covered;
  }
  free(facing);
  free(fans);
  vsh_silhouette_free(&s);
  return bad;
}

static void test_fans_winding(void) {
  vsh_test_seed(99);
  int checked = 0, shadowed = 0;
  long bad = 0;
  for (int round = 0; round < 120; ++round) {
    random_mesh(round);
    vsh_mesh_topology t = build();
    double l[4];
    random_light(0, l);
    bad += check_fans(&t, l, VSH_SILHOUETTE_LIT_FACES, &checked);
    bad += check_fans(&t, l, VSH_SILHOUETTE_BOTH_SIDES, &checked);
    shadowed += t.component_count > 0;
    vsh_mesh_topology_free(&t);
  }
  CHECK(bad == 0);
  CHECK(checked > 40000);
  CHECK(shadowed == 120);
  printf("fan winding numbers checked at %d points\n", checked);
}

/* Two boxes: one fan centre each, in its own component. */
static void test_fan_centres_per_component(void) {
  const double lo0[3] = {0, 0, 0}, hi0[3] = {1, 1, 1}, lo1[3] = {5, 0, 0}, hi1[3] = {6, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo0, hi0);
  tm_box(&mesh, lo1, hi1);
  vsh_mesh_topology t = build();
  const double l[4] = {0.2, 0.3, 1, 0};
  vsh_silhouette s = silhouette(&t, l, VSH_SILHOUETTE_LIT_FACES);
  uint32_t fans[3 * 64];
  CHECK(s.total_multiplicity == 12);
  CHECK(vsh_silhouette_fans(&t, &s, fans) == VSH_MESH_OK);
  for (size_t f = 0; f < s.total_multiplicity; ++f) {
    CHECK(t.component[fans[3 * f]] == t.component[fans[3 * f + 1]]);
    CHECK(t.component[fans[3 * f]] == t.component[fans[3 * f + 2]]);
  }
  vsh_silhouette_free(&s);
  vsh_mesh_topology_free(&t);
}

/* 1e6 offset and 1e-6 scale: the same silhouette as at the origin, when the
 * light moves with the mesh. */
static void test_offset_and_scale(void) {
  const double offsets[2][3] = {{1e6, 1e6, -1e6}, {1e-6, 0, 0}};
  const double scales[2] = {1.0, 1e-6};
  const double l0[4] = {0.3, -0.2, 3.0, 1};
  mesh.nv = mesh.nt = 0;
  tm_sphere(&mesh, 16, 32, NULL, NULL);
  vsh_mesh_topology ref = build();
  vsh_silhouette s0 = silhouette(&ref, l0, VSH_SILHOUETTE_LIT_FACES);
  for (int c = 0; c < 2; ++c) {
    mesh.nv = mesh.nt = 0;
    tm_sphere(&mesh, 16, 32, NULL, NULL);
    tm_transform(&mesh, 0, scales[c], offsets[c]);
    vsh_mesh_topology t = build();
    double l[4] = {0, 0, 0, 1};
    for (int k = 0; k < 3; ++k) l[k] = l0[k] * scales[c] + offsets[c][k];
    vsh_silhouette s = silhouette(&t, l, VSH_SILHOUETTE_LIT_FACES);
    CHECK(s.count == s0.count);
    size_t same = 0;
    for (size_t k = 0; k < s.count && k < s0.count; ++k)
      same += s.edges[k].from == s0.edges[k].from && s.edges[k].to == s0.edges[k].to;
    CHECK(same == s0.count);
    double len = 0, len0 = 0;
    CHECK(vsh_silhouette_length(&t, &s, l, &len) == VSH_MESH_OK);
    CHECK(vsh_silhouette_length(&ref, &s0, l0, &len0) == VSH_MESH_OK);
    CHECK_NEAR(len / scales[c], len0, 1e-6 * len0);
    vsh_silhouette_free(&s);
    vsh_mesh_topology_free(&t);
  }
  vsh_silhouette_free(&s0);
  vsh_mesh_topology_free(&ref);
}

static void test_bad_input(void) {
  unit_box();
  vsh_mesh_topology t = build();
  vsh_silhouette s;
  const double zero[4] = {0, 0, 0, 0}, nan_light[4] = {NAN, 0, 1, 0}, ok[4] = {0, 0, 1, 0};
  CHECK(vsh_silhouette_build(&t, zero, VSH_SILHOUETTE_LIT_FACES, &s) == VSH_MESH_INVALID);
  CHECK(s.edges == NULL && s.count == 0);
  CHECK(vsh_silhouette_build(&t, nan_light, VSH_SILHOUETTE_LIT_FACES, &s) == VSH_MESH_INVALID);
  CHECK(vsh_silhouette_build(&t, NULL, VSH_SILHOUETTE_LIT_FACES, &s) == VSH_MESH_INVALID);
  CHECK(vsh_silhouette_build(NULL, ok, VSH_SILHOUETTE_LIT_FACES, &s) == VSH_MESH_INVALID);
  CHECK(vsh_silhouette_build(&t, ok, (vsh_silhouette_mode)7, &s) == VSH_MESH_INVALID);
  CHECK(vsh_silhouette_build(&t, ok, VSH_SILHOUETTE_LIT_FACES, NULL) == VSH_MESH_INVALID);
  unsigned char facing[12];
  CHECK(vsh_silhouette_facing(&t, zero, facing) == VSH_MESH_INVALID);
  double length = 1;
  CHECK(vsh_silhouette_build(&t, ok, VSH_SILHOUETTE_LIT_FACES, &s) == VSH_MESH_OK);
  CHECK(vsh_silhouette_length(&t, &s, zero, &length) == VSH_MESH_INVALID && length == 0);
  CHECK(vsh_silhouette_fans(&t, &s, NULL) == VSH_MESH_INVALID);
  vsh_silhouette_free(&s);
  vsh_silhouette_free(NULL);
  vsh_mesh_topology_free(&t);
  /* An empty topology: an empty silhouette. */
  CHECK(vsh_mesh_topology_build(NULL, 0, NULL, 0, 0.0, &t) == VSH_MESH_OK);
  CHECK(vsh_silhouette_build(&t, ok, VSH_SILHOUETTE_BOTH_SIDES, &s) == VSH_MESH_OK);
  CHECK(s.count == 0 && s.total_multiplicity == 0);
  CHECK(vsh_silhouette_fans(&t, &s, NULL) == VSH_MESH_OK);
  vsh_silhouette_free(&s);
  vsh_mesh_topology_free(&t);
}

static void test_seen_unlit(void) {
  /* A floor quad facing +z: lit from above and seen from above, or both
   * from below, every face is seen from its lit side; a camera below a
   * light above (or the other way) sees its unlit side. */
  unit_quad();
  vsh_mesh_topology t = build();
  const double sun[4] = {0.2, 0.3, 1, 0}, lamp[4] = {0.5, 0.5, 2, 1}, under[4] = {0, 0, -1, 0};
  const double above[4] = {3, -2, 5, 1}, below[4] = {0.5, 0.5, -4, 1};
  const double parallel_above[4] = {0, 0, 1, 0}, parallel_below[4] = {0, 0, -1, 0};
  CHECK(vsh_silhouette_seen_unlit(&t, sun, above) == 0);
  CHECK(vsh_silhouette_seen_unlit(&t, lamp, above) == 0);
  CHECK(vsh_silhouette_seen_unlit(&t, sun, parallel_above) == 0);
  CHECK(vsh_silhouette_seen_unlit(&t, under, below) == 0);
  CHECK(vsh_silhouette_seen_unlit(&t, sun, below) == 1);
  CHECK(vsh_silhouette_seen_unlit(&t, lamp, parallel_below) == 1);
  CHECK(vsh_silhouette_seen_unlit(&t, under, above) == 1);
  /* Homogeneous scale and sign do not matter. */
  const double lamp_scaled[4] = {-1, -1, -4, -2}, above_scaled[4] = {6, -4, 10, 2};
  CHECK(vsh_silhouette_seen_unlit(&t, lamp_scaled, above_scaled) == 0);
  /* Eye or light in the plane (edge-on): no side is seen. */
  const double level[4] = {5, 5, 0, 1};
  CHECK(vsh_silhouette_seen_unlit(&t, sun, level) == 0);
  CHECK(vsh_silhouette_seen_unlit(&t, level, below) == 0);
  /* Unknown answers are the safe one. */
  const double zero[4] = {0, 0, 0, 0}, bad[4] = {NAN, 0, 1, 0};
  CHECK(vsh_silhouette_seen_unlit(NULL, sun, above) == 1);
  CHECK(vsh_silhouette_seen_unlit(&t, zero, above) == 1);
  CHECK(vsh_silhouette_seen_unlit(&t, sun, bad) == 1);
  vsh_mesh_topology_free(&t);
  /* An open cylinder (a pipe) lit from the side and seen from the side:
   * the camera sees the inside of the far wall, turned away from the light
   * where the light is on the camera's side. */
  mesh.nv = mesh.nt = 0;
  tm_cylinder(&mesh, 1.0, 0.0, 2.0, 16, 0);
  t = build();
  const double side[4] = {1, 0.1, 0, 0}, eye_side[4] = {6, 0.5, 1, 1};
  const double eye_axis[4] = {0, 0, 8, 1};
  CHECK(vsh_silhouette_seen_unlit(&t, side, eye_side) == 1);
  CHECK(vsh_silhouette_seen_unlit(&t, side, eye_axis) == 1);
  vsh_mesh_topology_free(&t);
  /* Any mesh is answered: a closed box seen from where the light is shows
   * only lit faces. */
  unit_box();
  t = build();
  const double corner[4] = {3, 3, 3, 1};
  CHECK(vsh_silhouette_seen_unlit(&t, corner, corner) == 0);
  vsh_mesh_topology_free(&t);
}

int main(void) {
  test_box_known_lights();
  test_open_meshes();
  test_seen_unlit();
  test_non_manifold_fin();
  test_random_against_brute_force();
  test_fans_winding();
  test_fan_centres_per_component();
  test_offset_and_scale();
  test_bad_input();
  return vsh_check_report("test_silhouette");
}
