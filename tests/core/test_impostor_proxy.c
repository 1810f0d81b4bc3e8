/* test_impostor_proxy.c - unit tests of vsh_impostor_proxy: the sphere and
 * tube proxies are closed and wound outwards (vsh_mesh_topology, positive
 * volume), the sphere's area is the true sphere's (Cauchy: equal mean
 * silhouette area), its vertices and faces lie within the documented radii,
 * the tube's mean width is the circle's, a polyline's tubes with their
 * joint spheres weld into a closed mesh, and a segment of no length makes
 * nothing. */
#include "vsh_check.h"
#include "vsh_impostor_proxy.h"
#include "vsh_mesh_topology.h"

#include <math.h>

#define PI 3.14159265358979323846

/* Signed volume and area of a triangle mesh. */
static void volume_area(const double *p, const uint32_t *t, size_t triangles, double *volume,
                        double *area) {
  *volume = 0.0;
  *area = 0.0;
  for (size_t i = 0; i < triangles; ++i) {
    const double *a = p + 3 * t[3 * i], *b = p + 3 * t[3 * i + 1], *c = p + 3 * t[3 * i + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    *area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    *volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
  }
}

static int closed(const double *p, size_t vertices, const uint32_t *t, size_t triangles) {
  vsh_mesh_topology topology;
  const int ok = vsh_mesh_topology_build(p, vertices, t, triangles, 0.0, &topology) == VSH_MESH_OK &&
                 topology.closed;
  vsh_mesh_topology_free(&topology);
  return ok;
}

static void test_sphere(const vsh_proxy_shapes *shapes) {
  double p[3 * VSH_PROXY_SPHERE_VERTICES];
  uint32_t t[3 * VSH_PROXY_SPHERE_TRIANGLES];
  const double centre[3] = {10.0, -2.0, 3.0}, r = 0.5;
  vsh_proxy_sphere(shapes, centre, r, p, t, 0);
  CHECK(closed(p, VSH_PROXY_SPHERE_VERTICES, t, VSH_PROXY_SPHERE_TRIANGLES));
  double volume, area;
  volume_area(p, t, VSH_PROXY_SPHERE_TRIANGLES, &volume, &area);
  CHECK(volume > 0.0); /* wound outwards */
  /* Cauchy: mean projected area = area / 4 = the disc's pi r^2. */
  CHECK_NEAR(area / 4.0, PI * r * r, 1e-12);
  CHECK_NEAR(shapes->sphere_scale, 1.0378754112585393, 1e-12);
  for (int i = 0; i < VSH_PROXY_SPHERE_VERTICES; ++i) {
    const double d = sqrt(pow(p[3 * i] - centre[0], 2) + pow(p[3 * i + 1] - centre[1], 2) +
                          pow(p[3 * i + 2] - centre[2], 2));
    CHECK_NEAR(d, shapes->sphere_scale * r, 1e-12);
  }
  /* Faces at least 0.9695 radii from the centre (the inscribed sphere). */
  for (int i = 0; i < VSH_PROXY_SPHERE_TRIANGLES; ++i) {
    const double *a = p + 3 * t[3 * i];
    const double *b = p + 3 * t[3 * i + 1], *c = p + 3 * t[3 * i + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double dist = ((a[0] - centre[0]) * n[0] + (a[1] - centre[1]) * n[1] +
                         (a[2] - centre[2]) * n[2]) / len;
    CHECK(dist > 0.9695 * r && dist < 1.0379 * r);
  }
}

static void test_tube(const vsh_proxy_shapes *shapes) {
  double p[3 * VSH_PROXY_TUBE_VERTICES];
  uint32_t t[3 * VSH_PROXY_TUBE_TRIANGLES];
  const double a[3] = {0, 0, 0}, b[3] = {0.3, 2.0, -0.4};
  CHECK(vsh_proxy_tube(shapes, a, 0.2, b, 0.3, 1, p, t, 0) == 1);
  CHECK(closed(p, VSH_PROXY_TUBE_VERTICES, t, VSH_PROXY_TUBE_TRIANGLES));
  double volume, area;
  volume_area(p, t, VSH_PROXY_TUBE_TRIANGLES, &volume, &area);
  CHECK(volume > 0.0);
  /* The polygon's perimeter / pi (its mean width) is the circle's 2r. */
  const double n = VSH_PROXY_TUBE_SIDES;
  CHECK_NEAR(2.0 * n * shapes->tube_scale * sin(PI / n) / PI, 2.0, 1e-12);
  /* Every ring vertex at tube_scale radii from its end. */
  for (int i = 0; i < VSH_PROXY_TUBE_SIDES; ++i) {
    const double *q = p + 3 * i, *s = p + 3 * (VSH_PROXY_TUBE_SIDES + i);
    CHECK_NEAR(sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), 0.2 * shapes->tube_scale, 1e-12);
    CHECK_NEAR(sqrt(pow(s[0] - b[0], 2) + pow(s[1] - b[1], 2) + pow(s[2] - b[2], 2)),
               0.3 * shapes->tube_scale, 1e-12);
  }
  /* No length, or not finite: nothing. */
  CHECK(vsh_proxy_tube(shapes, a, 0.2, a, 0.2, 0, p, t, 0) == 0);
  const double bad[3] = {NAN, 0, 0};
  CHECK(vsh_proxy_tube(shapes, a, 0.2, bad, 0.2, 0, p, t, 0) == 0);
}

/* Three collinear segments with a sphere at each of the four vertices:
 * with alternating turns no two rings coincide, so the exact weld leaves
 * every component closed. */
static void test_polyline(const vsh_proxy_shapes *shapes) {
  enum { V = 4 * VSH_PROXY_SPHERE_VERTICES + 3 * VSH_PROXY_TUBE_VERTICES };
  enum { T = 4 * VSH_PROXY_SPHERE_TRIANGLES + 3 * VSH_PROXY_TUBE_TRIANGLES };
  static double p[3 * V];
  static uint32_t t[3 * T];
  const double points[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  uint32_t base = 0, tri = 0;
  for (int i = 0; i < 4; ++i) {
    vsh_proxy_sphere(shapes, points[i], 0.25, p + 3 * base, t + 3 * tri, base);
    base += VSH_PROXY_SPHERE_VERTICES;
    tri += VSH_PROXY_SPHERE_TRIANGLES;
  }
  for (int i = 0; i < 3; ++i) {
    CHECK(vsh_proxy_tube(shapes, points[i], 0.25, points[i + 1], 0.25, i, p + 3 * base,
                         t + 3 * tri, base) == 1);
    base += VSH_PROXY_TUBE_VERTICES;
    tri += VSH_PROXY_TUBE_TRIANGLES;
  }
  CHECK(closed(p, V, t, T));
  /* Without the turn, two collinear rings coincide: not closed. */
  vsh_proxy_tube(shapes, points[1], 0.25, points[2], 0.25, 0, p + 3 * (base - 2 * VSH_PROXY_TUBE_VERTICES),
                 t + 3 * (tri - 2 * VSH_PROXY_TUBE_TRIANGLES), base - 2 * VSH_PROXY_TUBE_VERTICES);
  CHECK(!closed(p, V, t, T));
}

/* x / w and y / w of eye point e under the perspective `projection`. */
static void screen(const double projection[16], const double e[3], double out[2]) {
  const double w = -e[2];
  out[0] = projection[0] * e[0] / w;
  out[1] = projection[5] * e[1] / w;
}

/* Flat squares and bands: with the identity view (eye at the origin looking
 * down -z) a square lies in its plane z = const, its sides along x and y,
 * counter-clockwise from the camera; a band's ends stay on their depth
 * planes and reach across the segment's screen direction, whatever its
 * slant in depth; a segment seen end-on, a zero width or NaN give none. */
static void test_flat(void) {
  const double view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const double projection[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, -1.1, -2.1, 0, 0, -1, 0};
  const double centre[3] = {1, 2, -5};
  double q[12];
  CHECK(vsh_flat_square(view, centre, 0.5, q) == 1);
  const double square[12] = {0.5, 1.5, -5, 1.5, 1.5, -5, 1.5, 2.5, -5, 0.5, 2.5, -5};
  for (int i = 0; i < 12; ++i) {
    CHECK(fabs(q[i] - square[i]) < 1e-12);
  }
  CHECK(vsh_flat_square(view, centre, 0.0, q) == 0);
  CHECK(vsh_flat_square(view, centre, NAN, q) == 0);
  const double a[3] = {-1, 0.5, -3}, b[3] = {2, 1, -8};
  CHECK(vsh_flat_band(projection, view, a, 0.1, b, 0.3, q) == 1);
  double sa[2], sb[2], s0[2], s3[2], s1[2], s2[2];
  screen(projection, a, sa);
  screen(projection, b, sb);
  screen(projection, q, s0);
  screen(projection, q + 3, s1);
  screen(projection, q + 6, s2);
  screen(projection, q + 9, s3);
  const double dir[2] = {sb[0] - sa[0], sb[1] - sa[1]};
  /* Across at both ends, the given half-widths in eye units, each end on
   * its own depth plane, and counter-clockwise on screen. */
  CHECK(fabs((s3[0] - s0[0]) * dir[0] + (s3[1] - s0[1]) * dir[1]) < 1e-12);
  CHECK(fabs((s2[0] - s1[0]) * dir[0] + (s2[1] - s1[1]) * dir[1]) < 1e-12);
  CHECK(fabs(hypot(q[9] - q[0], q[10] - q[1]) - 0.2) < 1e-12 && q[2] == -3 && q[11] == -3);
  CHECK(fabs(hypot(q[6] - q[3], q[7] - q[4]) - 0.6) < 1e-12 && q[5] == -8 && q[8] == -8);
  CHECK(dir[0] * (s3[1] - s0[1]) - dir[1] * (s3[0] - s0[0]) > 0);
  const double near_end[3] = {0, 0, -2}, far_end[3] = {0, 0, -6};
  CHECK(vsh_flat_band(projection, view, near_end, 0.1, far_end, 0.1, q) == 0);
  CHECK(vsh_flat_band(projection, view, a, 0.0, b, 0.1, q) == 0);
  CHECK(vsh_flat_band(projection, view, a, 0.1, centre, NAN, q) == 0);
}

int main(void) {
  vsh_proxy_shapes shapes;
  vsh_proxy_shapes_init(&shapes);
  test_sphere(&shapes);
  test_tube(&shapes);
  test_polyline(&shapes);
  test_flat();
  return vsh_check_report("impostor_proxy");
}
