/* test_volume.c - unit tests of vsh_volume: the winding number of the built
 * volume (points at infinity brought to a large finite distance) against a
 * brute-force count of the faces between a point and the light, for closed
 * (convex, concave), open (a quad, an open cylinder) and non-manifold
 * meshes and every light kind; counts of quads and caps; z-pass safety for
 * known configurations; screen rectangles and culling; the cost estimate;
 * bad input. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_test_meshes.h"
#include "vsh_volume.h"

#include <math.h>
#include <stdlib.h>

static test_mesh mesh;
static const double PI = 3.14159265358979323846;

/* Signed solid angle of triangle (a, b, c) seen from q (Van Oosterom and
 * Strackee): the sum over a closed, outward-wound surface is 4 pi times its
 * winding number around q. */
static double solid_angle(const double q[3], const double *a, const double *b, const double *c) {
  double x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k) x[k] = a[k] - q[k], y[k] = b[k] - q[k], z[k] = c[k] - q[k];
  const double lx = vsh_vec3_length(x), ly = vsh_vec3_length(y), lz = vsh_vec3_length(z);
  double yz[3];
  vsh_vec3_cross(y, z, yz);
  const double det = vsh_vec3_dot(x, yz);
  const double den = lx * ly * lz + vsh_vec3_dot(x, y) * lz + vsh_vec3_dot(x, z) * ly +
                     vsh_vec3_dot(y, z) * lx;
  return 2.0 * atan2(det, den);
}

/* Winding number around q of a volume whose vertices are all finite
 * (finite_copy). */
static double winding(const vsh_volume *v, const double q[3]) {
  double sum = 0.0;
  const size_t n = v->side_triangles + v->cap_triangles;
  for (size_t t = 0; t < n; ++t) {
    const double *tri = v->vertices + 12 * t;
    double p[3][3];
    for (int k = 0; k < 3; ++k) {
      const double *x = tri + 4 * k;
      for (int i = 0; i < 3; ++i) p[k][i] = x[i];
    }
    sum += solid_angle(q, p[0], p[1], p[2]);
  }
  return sum / (4.0 * PI);
}

/* Every point at infinity (d, 0) brought to a finite one: L + far d for a
 * positional light (on the ray from the light through the vertex, far
 * beyond it), far d for a directional one (the one apex all sides meet). */
static void finite_copy(vsh_volume *v, const double light[4], double far) {
  const size_t n = 3 * (v->side_triangles + v->cap_triangles);
  for (size_t i = 0; i < n; ++i) {
    double *x = v->vertices + 4 * i;
    if (x[3] != 0.0) continue;
    if (light[3] != 0.0) {
      /* (p - L, 0): the finite vertex is L + far (p - L). */
      for (int k = 0; k < 3; ++k) x[k] = light[k] / light[3] + far * x[k];
    } else {
      for (int k = 0; k < 3; ++k) x[k] = far * x[k];
    }
    x[3] = 1.0;
  }
}

/* Whether segment q -> light (ray for a directional light) crosses triangle
 * f strictly inside. */
static int crosses(const vsh_mesh_topology *t, size_t f, const double q[3], const double light[4]) {
  const uint32_t *tri = t->triangles + 3 * f;
  const double *a = t->positions + 3 * tri[0], *b = t->positions + 3 * tri[1],
               *c = t->positions + 3 * tri[2];
  double d[3], e1[3], e2[3], s[3], h[3], qv[3];
  for (int k = 0; k < 3; ++k) {
    d[k] = light[3] != 0.0 ? light[k] / light[3] - q[k] : light[k];
    e1[k] = b[k] - a[k], e2[k] = c[k] - a[k], s[k] = q[k] - a[k];
  }
  vsh_vec3_cross(d, e2, h);
  const double det = vsh_vec3_dot(e1, h);
  if (fabs(det) < 1e-14) return 0;
  const double u = vsh_vec3_dot(s, h) / det;
  vsh_vec3_cross(s, e1, qv);
  const double w = vsh_vec3_dot(d, qv) / det;
  const double tt = vsh_vec3_dot(e2, qv) / det;
  const double tmax = light[3] != 0.0 ? 1.0 : INFINITY;
  return u > 0 && w > 0 && u + w < 1 && tt > 0 && tt < tmax;
}

/* The count the volume must give at q: faces crossed (open meshes, and
 * every mesh's crossings volume) or faces that do not face the light
 * crossed (closed meshes: entries). */
static long expected(const vsh_mesh_topology *t, const double q[3], const double light[4],
                     int crossings) {
  long n = 0;
  for (size_t f = 0; f < t->triangle_count; ++f) {
    if (!crosses(t, f, q, light)) continue;
    if (crossings || !t->closed ||
        !vsh_triangle_faces_light(t->positions, t->triangles + 3 * f, light))
      ++n;
  }
  return n;
}

/* Random points around the mesh: the volume's winding number equals the
 * brute-force count wherever it is clearly an integer (points within
 * rounding of a face are skipped). Returns how many points were compared. */
static int check_counts(const char *name, const double light[4], double spread,
                        int crossings) {
  vsh_mesh_topology t;
  CHECK(vsh_mesh_topology_build(mesh.p, mesh.nv, mesh.t, mesh.nt, 0.0, &t) == VSH_MESH_OK);
  vsh_volume v;
  CHECK((crossings ? vsh_volume_build_crossings(&t, light, &v) : vsh_volume_build(&t, light, &v)) ==
        VSH_MESH_OK);
  CHECK(!crossings || v.dark_caps == 0);
  const double far = 1e4;
  finite_copy(&v, light, far);
  int compared = 0, wrong = 0, shadowed = 0;
  for (int i = 0; i < 400; ++i) {
    const double q[3] = {vsh_test_rnd(-spread, spread), vsh_test_rnd(-spread, spread),
                         vsh_test_rnd(-spread, spread)};
    const double w = winding(&v, q);
    if (fabs(w - round(w)) > 1e-3) continue; /* on a face: not meaningful */
    const long e = expected(&t, q, light, crossings);
    ++compared;
    shadowed += e != 0;
    if ((long)round(w) != e) {
      if (wrong++ < 3)
        fprintf(stderr, "%s: at (%g %g %g) winding %g, expected %ld\n", name, q[0], q[1], q[2],
                w, e);
    }
  }
  CHECK(wrong == 0);
  CHECK(compared > 300);
  CHECK(shadowed > 10);
  vsh_volume_free(&v);
  vsh_mesh_topology_free(&t);
  return compared;
}

static double bumpy(int ring, int segment, void *user) {
  (void)user;
  return 0.6 + 0.35 * fabs(sin(1.7 * ring + 2.3 * segment));
}

static void counts_for_all_lights(const char *name, double spread) {
  const double lights[3][4] = {{0.3, 0.4, 1.0, 0.0}, {0.5, -0.7, 3.0, 1.0}, {-6, 2, 3, 2}};
  for (int k = 0; k < 3; ++k) {
    check_counts(name, lights[k], spread, 0);
    check_counts(name, lights[k], spread, 1); /* every crossing (translucent casters) */
  }
}

static void test_counts(void) {
  const double lo[3] = {-0.5, -0.4, -0.3}, hi[3] = {0.5, 0.4, 0.3};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  counts_for_all_lights("box", 1.5);

  /* A box among glyphs scaled to nothing (vtkGlyph3D keeps their collapsed
   * triangles): still closed, with dark caps, and counted as the box. */
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  const double at[3] = {0.7, 0.6, 0.5};
  tm_box(&mesh, at, at);
  vsh_mesh_topology collapsed;
  CHECK(vsh_mesh_topology_build(mesh.p, mesh.nv, mesh.t, mesh.nt, 0.0, &collapsed) ==
        VSH_MESH_OK);
  CHECK(collapsed.closed == 1 && collapsed.degenerate_count == 12);
  vsh_mesh_topology_free(&collapsed);
  counts_for_all_lights("box with a collapsed box", 1.5);

  mesh.nv = mesh.nt = 0;
  tm_sphere(&mesh, 9, 14, bumpy, NULL); /* closed and concave: shadows itself */
  counts_for_all_lights("bumpy sphere", 1.5);

  mesh.nv = mesh.nt = 0;
  tm_cylinder(&mesh, 0.5, -0.6, 0.6, 12, 0); /* open */
  counts_for_all_lights("open cylinder", 1.5);

  mesh.nv = mesh.nt = 0; /* a single quad */
  tm_quad(&mesh, tm_vertex(&mesh, -0.5, -0.5, 0), tm_vertex(&mesh, 0.5, -0.5, 0),
          tm_vertex(&mesh, 0.5, 0.5, 0), tm_vertex(&mesh, -0.5, 0.5, 0));
  counts_for_all_lights("quad", 1.2);

  mesh.nv = mesh.nt = 0; /* three fins on one edge: non-manifold */
  const uint32_t a = tm_vertex(&mesh, 0, 0, -0.5), b = tm_vertex(&mesh, 0, 0, 0.5);
  for (int k = 0; k < 3; ++k) {
    const double ang = 2.0 * PI * k / 3.0 + 0.2;
    const uint32_t c = tm_vertex(&mesh, 0.7 * cos(ang), 0.7 * sin(ang), 0.5);
    const uint32_t d = tm_vertex(&mesh, 0.7 * cos(ang), 0.7 * sin(ang), -0.5);
    tm_quad(&mesh, a, d, c, b);
  }
  counts_for_all_lights("fins", 1.2);
}

static void test_structure(void) {
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  mesh.nv = mesh.nt = 0;
  tm_box(&mesh, lo, hi);
  vsh_mesh_topology t;
  CHECK(vsh_mesh_topology_build(mesh.p, mesh.nv, mesh.t, mesh.nt, 0.0, &t) == VSH_MESH_OK);
  vsh_volume v;
  /* Light straight above a unit box: 4 silhouette edges, the 10 triangles
   * that do not face up as near caps, and as far caps for a point light. */
  const double point[4] = {0.5, 0.5, 5.0, 1.0}, sun[4] = {0.1, 0.2, 1.0, 0.0};
  CHECK(vsh_volume_build(&t, point, &v) == VSH_MESH_OK);
  CHECK(v.dark_caps == 1);
  CHECK(v.silhouette_edges == 4 && v.silhouette_quads == 4);
  CHECK(v.side_triangles == 8);
  CHECK(v.cap_triangles == 20);
  vsh_volume_free(&v);
  CHECK(v.vertices == NULL && v.side_triangles == 0);
  /* A directional light: sides are triangles to the one vanishing point and
   * there is no far cap. Light from +x+y+z: 3 faces lit, 6 silhouette edges. */
  const double diag[4] = {1, 1.5, 2, 0};
  CHECK(vsh_volume_build(&t, diag, &v) == VSH_MESH_OK);
  CHECK(v.silhouette_quads == 6 && v.side_triangles == 6 && v.cap_triangles == 6);
  for (size_t i = 0; i < 3 * v.side_triangles; ++i)
    if (v.vertices[4 * i + 3] == 0.0)
      CHECK(v.vertices[4 * i] == -1 && v.vertices[4 * i + 1] == -1.5 && v.vertices[4 * i + 2] == -2);
  vsh_volume_free(&v);
  (void)sun;
  /* Light inside a closed box: nothing faces it, every face is a dark cap,
   * no silhouette; everything outside is shadowed. */
  const double inside[4] = {0.5, 0.5, 0.5, 1.0};
  CHECK(vsh_volume_build(&t, inside, &v) == VSH_MESH_OK);
  CHECK(v.silhouette_quads == 0 && v.cap_triangles == 24);
  vsh_volume_free(&v);
  vsh_mesh_topology_free(&t);

  /* Bad input. */
  const double zero[4] = {0, 0, 0, 0}, nan4[4] = {NAN, 0, 1, 0};
  CHECK(vsh_volume_build(NULL, point, &v) == VSH_MESH_INVALID && v.vertices == NULL);
  CHECK(vsh_mesh_topology_build(mesh.p, mesh.nv, mesh.t, mesh.nt, 0.0, &t) == VSH_MESH_OK);
  CHECK(vsh_volume_build(&t, zero, &v) == VSH_MESH_INVALID && v.vertices == NULL);
  CHECK(vsh_volume_build(&t, nan4, &v) == VSH_MESH_INVALID);
  CHECK(vsh_volume_build(&t, point, NULL) == VSH_MESH_INVALID);
  vsh_mesh_topology_free(&t);
  vsh_volume_free(NULL);
  /* An empty mesh casts nothing. */
  CHECK(vsh_mesh_topology_build(mesh.p, 0, mesh.t, 0, 0.0, &t) == VSH_MESH_OK);
  CHECK(vsh_volume_build(&t, point, &v) == VSH_MESH_OK);
  CHECK(v.side_triangles == 0 && v.cap_triangles == 0);
  vsh_volume_free(&v);
  vsh_mesh_topology_free(&t);
}

/* A camera at `eye` looking along -z with a near plane `near` away and
 * half-size h: the near rectangle's corners. */
static void near_rect(const double eye[3], double near, double h, double out[12]) {
  const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    out[3 * k] = eye[0] + h * c[k][0];
    out[3 * k + 1] = eye[1] + h * c[k][1];
    out[3 * k + 2] = eye[2] - near;
  }
}

static void test_zpass(void) {
  const double box[6] = {-1, 1, -1, 1, 0, 2}; /* a caster standing on z = 0 */
  const double sun[4] = {0, 0, 1, 0}, lamp[4] = {0, 0, 10, 1};
  double rect[12];
  /* Camera high above the caster, looking down: outside every shadow. */
  double eye[3] = {5, 0, 8};
  near_rect(eye, 0.1, 0.05, rect);
  CHECK(vsh_volume_zpass_safe(eye, rect, box, sun, 1e-6) == 1);
  CHECK(vsh_volume_zpass_safe(eye, rect, box, lamp, 1e-6) == 1);
  /* Camera below the caster, in its shadow. */
  const double under[3] = {0, 0, -3};
  near_rect(under, 0.1, 0.05, rect);
  CHECK(vsh_volume_zpass_safe(under, rect, box, sun, 1e-6) == 0);
  CHECK(vsh_volume_zpass_safe(under, rect, box, lamp, 1e-6) == 0);
  /* Eye just outside the shadow, near plane reaching into it. */
  const double edge[3] = {1.05, 0, -3};
  near_rect(edge, 0.1, 0.02, rect);
  CHECK(vsh_volume_zpass_safe(edge, rect, box, sun, 0.0) == 1);
  near_rect(edge, 0.1, 0.2, rect);
  CHECK(vsh_volume_zpass_safe(edge, rect, box, sun, 0.0) == 0);
  /* The margin makes a near miss unsafe. */
  near_rect(edge, 0.1, 0.02, rect);
  CHECK(vsh_volume_zpass_safe(edge, rect, box, sun, 0.1) == 0);
  /* Light inside the caster's box: everything may be in shadow. */
  const double inside[4] = {0, 0, 1, 1};
  near_rect(eye, 0.1, 0.05, rect);
  CHECK(vsh_volume_zpass_safe(eye, rect, box, inside, 0.0) == 0);
  /* Camera between the light and the caster (above it, under the lamp):
   * the segment to the light does not meet the box. */
  const double above[3] = {0, 0, 5};
  near_rect(above, 0.1, 0.05, rect);
  CHECK(vsh_volume_zpass_safe(above, rect, box, lamp, 0.0) == 1);
  CHECK(vsh_volume_zpass_safe(above, rect, box, sun, 0.0) == 1);
  /* 1e6 offsets and 1e-6 scales give the same answers. */
  for (int s = 0; s < 2; ++s) {
    const double scale = s ? 1e-6 : 1.0, offset = s ? 0.0 : 1e6;
    double b2[6], u2[3], e2[3], l2[4] = {offset, offset, 10 * scale + offset, 1};
    for (int k = 0; k < 6; ++k) b2[k] = box[k] * scale + offset;
    for (int k = 0; k < 3; ++k) u2[k] = under[k] * scale + offset, e2[k] = eye[k] * scale + offset;
    near_rect(u2, 0.1 * scale, 0.05 * scale, rect);
    CHECK(vsh_volume_zpass_safe(u2, rect, b2, l2, 0.0) == 0);
    near_rect(e2, 0.1 * scale, 0.05 * scale, rect);
    CHECK(vsh_volume_zpass_safe(e2, rect, b2, l2, 0.0) == 1);
  }
  /* Bad input is never "safe". */
  const double bad_box[6] = {1, -1, 0, 1, 0, 1}, zero[4] = {0, 0, 0, 0};
  CHECK(vsh_volume_zpass_safe(eye, rect, bad_box, sun, 0.0) == 0);
  CHECK(vsh_volume_zpass_safe(eye, rect, box, zero, 0.0) == 0);
  CHECK(vsh_volume_zpass_safe(eye, rect, box, sun, -1.0) == 0);
  CHECK(vsh_volume_zpass_safe(NULL, rect, box, sun, 0.0) == 0);
  const double nan_eye[3] = {NAN, 0, 0};
  CHECK(vsh_volume_zpass_safe(nan_eye, rect, box, sun, 0.0) == 0);
}

/* Clip-from-world of a camera at the origin looking along -z, 90 degree
 * field of view, near 1, far 100 (OpenGL convention, row-major). */
static void projection(double m[16]) {
  const double n = 1, f = 100;
  for (int i = 0; i < 16; ++i) m[i] = 0;
  m[0] = 1, m[5] = 1, m[10] = -(f + n) / (f - n), m[11] = -2 * f * n / (f - n), m[14] = -1;
}

static void test_rect(void) {
  double m[16];
  projection(m);
  int r[4];
  /* A small box straight ahead lit from behind the camera: its shadow goes
   * away from the camera and converges; the rectangle is around the centre. */
  const double box[6] = {-0.5, 0.5, -0.5, 0.5, -10.5, -9.5};
  const double behind[4] = {0, 0, 1, 0}; /* towards the light: +z, light travels -z */
  CHECK(vsh_volume_screen_rect(m, box, behind, 200, 100, r) == 1);
  CHECK(r[0] > 80 && r[0] + r[2] < 120 && r[1] > 30 && r[1] + r[3] < 70);
  /* Same box, light from the left (+x towards the light): the shadow
   * extends to the right edge of the view. */
  const double left[4] = {-1, 0, 0, 0};
  CHECK(vsh_volume_screen_rect(m, box, left, 200, 100, r) == 1);
  CHECK(r[0] > 80 && r[0] + r[2] == 200);
  /* A box behind the camera lit from in front of it (towards the light:
   * -z): its shadow goes backwards too: culled. */
  const double back[6] = {-0.5, 0.5, -0.5, 0.5, 5, 6};
  const double ahead[4] = {0, 0, -1, 0};
  CHECK(vsh_volume_screen_rect(m, back, ahead, 200, 100, r) == 0);
  /* The same box lit from behind: its shadow comes through the view. */
  CHECK(vsh_volume_screen_rect(m, back, behind, 200, 100, r) == 1);
  CHECK(r[2] == 200 && r[3] == 100);
  /* A box far to the right with its shadow going further right: culled. */
  const double side[6] = {50, 60, -1, 1, -11, -9};
  CHECK(vsh_volume_screen_rect(m, side, left, 200, 100, r) == 0);
  /* Point light between camera and box: extrusions diverge but stay ahead. */
  const double lamp[4] = {0, 0, -5, 1};
  CHECK(vsh_volume_screen_rect(m, box, lamp, 200, 100, r) == 1);
  CHECK(r[2] < 200 && r[3] < 100);
  /* Bad input: drawn, whole viewport. */
  const double nan_box[6] = {NAN, 0, 0, 1, 0, 1};
  CHECK(vsh_volume_screen_rect(m, nan_box, lamp, 200, 100, r) == 1);
  CHECK(r[0] == 0 && r[1] == 0 && r[2] == 200 && r[3] == 100);
}

static void test_cost(void) {
  vsh_volume_cost_input in = {100, 50, 1, 1000.0, 2.0};
  CHECK_NEAR(vsh_volume_cost(&in), 2000.0 + VSH_VOLUME_PX_PER_TRIANGLE * 250.0, 1e-9);
  in.zfail = 0;
  CHECK_NEAR(vsh_volume_cost(&in), 2000.0 + VSH_VOLUME_PX_PER_TRIANGLE * 200.0, 1e-9);
  in.fill_px = NAN;
  CHECK_NEAR(vsh_volume_cost(&in), VSH_VOLUME_PX_PER_TRIANGLE * 200.0, 1e-9);
  CHECK(vsh_volume_cost(NULL) == 0.0);
}

/* The near-plane rectangle of a perspective matrix (gluPerspective-like,
 * row-major, camera at the origin looking down -z): its corners at z = -n,
 * half-sizes n tan(fov/2) x aspect and n tan(fov/2); a singular matrix
 * gives 0 and zeros. */
static void test_near_corners(void) {
  const double n = 0.25, f = 40.0, t = tan(0.5 * 30.0 * 3.14159265358979323846 / 180.0);
  const double aspect = 4.0 / 3.0;
  const double m[16] = {1.0 / (aspect * t), 0, 0, 0, 0, 1.0 / t, 0, 0,
                        0, 0, -(f + n) / (f - n), -2.0 * f * n / (f - n), 0, 0, -1, 0};
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  double c[12], zero[16] = {0}, z[12];
  int k;
  CHECK(vsh_volume_near_corners(m, c) == 1);
  for (k = 0; k < 4; ++k) {
    CHECK_NEAR(c[3 * k + 0], sx[k] * n * t * aspect, 1e-12);
    CHECK_NEAR(c[3 * k + 1], sy[k] * n * t, 1e-12);
    CHECK_NEAR(c[3 * k + 2], -n, 1e-12);
  }
  for (k = 0; k < 12; ++k)
    z[k] = 1.0;
  CHECK(vsh_volume_near_corners(zero, z) == 0);
  for (k = 0; k < 12; ++k)
    CHECK(z[k] == 0.0);
}

int main(void) {
  vsh_test_seed(12);
  test_near_corners();
  test_counts();
  test_structure();
  test_zpass();
  test_rect();
  test_cost();
  return vsh_check_report("test_volume");
}
