/* test_plane.c - unit tests of vsh_plane: fitting the plane of a receiver's
 * points (flat, not flat, collinear, 1e6 offset, 1e-6 scale), a box lying
 * in a plane, turning a plane to a light, a plane through a matrix, and
 * whether clip planes keep a whole box. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_plane.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <float.h>
#include <math.h>
#include <string.h>

static double eval(const double plane[4], const double p[3]) {
  return plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
}

/* n random points on a random plane around `centre`, spread `size`. */
static void random_flat_points(double *p, int n, const double centre[3], double size,
                               double normal[3]) {
  double u[3], v[3], tmp[3];
  vsh_test_rnd_unit(normal);
  vsh_test_rnd_unit(tmp);
  vsh_vec3_cross(normal, tmp, u);
  vsh_vec3_normalize(u, u);
  vsh_vec3_cross(normal, u, v);
  for (int i = 0; i < n; ++i) {
    const double a = vsh_test_rnd(-size, size), b = vsh_test_rnd(-size, size);
    for (int k = 0; k < 3; ++k) p[3 * i + k] = centre[k] + a * u[k] + b * v[k];
  }
}

static void test_fit_random(void) {
  static double p[3 * 64];
  vsh_test_seed(31);
  int ok = 0, rejected = 0;
  for (int round = 0; round < 200; ++round) {
    const double size = round % 3 == 0 ? 1e-6 : round % 3 == 1 ? 1.0 : 1e3;
    /* Far from the origin only what double can resolve: a 1e-6
     * receiver 1e6 away has coordinates rounded by 1e-10, 1e-4 of its size. */
    const double far = size < 1.0 ? 0.0 : 1e6;
    const double centre[3] = {round % 2 ? far : 0.0, round % 4 < 2 ? -far : 0.5, 3.0};
    double n[3], plane[4];
    const int count = 4 + round % 60; /* three points are always flat */
    random_flat_points(p, count, centre, size, n);
    CHECK(vsh_plane_fit_points(p, (size_t)count, 1e-6, plane) == VSH_PLANE_OK);
    /* The plane's normal is +-n, and every point is on it. */
    CHECK_NEAR(fabs(vsh_vec3_dot(plane, n)), 1.0, 1e-9);
    for (int i = 0; i < count; ++i) CHECK(fabs(eval(plane, p + 3 * i)) <= 1e-6 * size);
    ok += 1;
    /* Lift one point by 1e-3 of the size: not flat any more. */
    const int lifted = count - 1;
    for (int k = 0; k < 3; ++k) p[3 * lifted + k] += 1e-3 * size * n[k];
    rejected += vsh_plane_fit_points(p, (size_t)count, 1e-6, plane) == VSH_PLANE_NOT_FLAT;
  }
  CHECK(ok == 200);
  CHECK(rejected == 200);
}

static void test_fit_degenerate(void) {
  double plane[4] = {9, 9, 9, 9};
  const double two[6] = {0, 0, 0, 1, 0, 0};
  CHECK(vsh_plane_fit_points(two, 2, 1e-6, plane) == VSH_PLANE_NO_AREA);
  CHECK(plane[0] == 0 && plane[3] == 0);
  const double line[12] = {0, 0, 0, 1, 1, 1, 2, 2, 2, -3, -3, -3};
  CHECK(vsh_plane_fit_points(line, 4, 1e-6, plane) == VSH_PLANE_NO_AREA);
  /* Collinear leading points, then one off the line: still a plane. */
  const double lead[15] = {0, 0, 5, 1, 0, 5, 2, 0, 5, 3, 0, 5, 3, 2, 5};
  CHECK(vsh_plane_fit_points(lead, 5, 1e-6, plane) == VSH_PLANE_OK);
  CHECK(fabs(plane[2]) == 1.0 && plane[3] == -5.0 * plane[2]);
  const double bad[9] = {0, 0, 0, 1, NAN, 0, 0, 1, 0};
  CHECK(vsh_plane_fit_points(bad, 3, 1e-6, plane) == VSH_PLANE_INVALID);
  CHECK(vsh_plane_fit_points(lead, 5, -1.0, plane) == VSH_PLANE_INVALID);
  CHECK(vsh_plane_fit_points(NULL, 5, 1e-6, plane) == VSH_PLANE_INVALID);
}

/* Receiver detection's flatness test (vsh_plane_fit_stored_points): points
 * that went through float storage, far from the origin and tiny. */
static void test_fit_stored(void) {
  double plane[4] = {9, 9, 9, 9};
  const double one[3] = {1e6, 2, 3};
  CHECK(vsh_plane_fit_stored_points(one, 1, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_NO_AREA);
  CHECK(plane[0] == 0 && plane[1] == 0 && plane[2] == 0 && plane[3] == 0);
  const double same[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1};
  CHECK(vsh_plane_fit_stored_points(same, 3, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_NO_AREA);
  const double line[12] = {1e6, 0, 0, 1e6 + 1, 1, 1, 1e6 + 2, 2, 2, 1e6 - 3, -3, -3};
  CHECK(vsh_plane_fit_stored_points(line, 4, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_NO_AREA);
  CHECK(vsh_plane_fit_stored_points(line, 4, 1e-6, -1.0, plane) == VSH_PLANE_INVALID);
  CHECK(vsh_plane_fit_stored_points(line, 4, 1e-6, NAN, plane) == VSH_PLANE_INVALID);
  CHECK(vsh_plane_fit_stored_points(line, 4, INFINITY, 0.0, plane) == VSH_PLANE_INVALID);
  /* A tilted 10-unit floor 1e6 from the origin, its points rounded to float
   * as a VTK float array stores them: flat once the rounding is allowed
   * for, not flat at 1e-6 of its size without; a 1-unit bump is not flat
   * either way. */
  static double p[3 * 100];
  vsh_test_seed(77);
  double n[3];
  const double far[3] = {1e6, -1e6, 5e5};
  random_flat_points(p, 100, far, 10.0, n);
  for (int i = 0; i < 300; ++i) p[i] = (double)(float)p[i];
  CHECK(vsh_plane_fit_stored_points(p, 100, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_OK);
  CHECK_NEAR(fabs(vsh_vec3_dot(plane, n)), 1.0, 1e-2);
  CHECK(vsh_plane_fit_stored_points(p, 100, 1e-6, 0.0, plane) == VSH_PLANE_NOT_FLAT);
  for (int k = 0; k < 3; ++k) p[3 * 50 + k] += 1.0 * n[k];
  CHECK(vsh_plane_fit_stored_points(p, 100, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_NOT_FLAT);
  /* A 1e-6 slice at the origin: flat at any storage, and its 1e-9 bump
   * (1e-3 of its size) is seen because the tolerance scales with it. */
  const double origin[3] = {0, 0, 0};
  random_flat_points(p, 40, origin, 1e-6, n);
  CHECK(vsh_plane_fit_stored_points(p, 40, 1e-6, 0.0, plane) == VSH_PLANE_OK);
  for (int i = 0; i < 120; ++i) p[i] = (double)(float)p[i];
  CHECK(vsh_plane_fit_stored_points(p, 40, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_OK);
  for (int k = 0; k < 3; ++k) p[3 * 20 + k] += 1e-9 * n[k];
  CHECK(vsh_plane_fit_stored_points(p, 40, 1e-6, FLT_EPSILON, plane) == VSH_PLANE_NOT_FLAT);
  /* The same call as vsh_plane_fit_points when nothing was rounded. */
  const double lead[15] = {0, 0, 5, 1, 0, 5, 2, 0, 5, 3, 0, 5, 3, 2, 5};
  double a[4], b[4];
  CHECK(vsh_plane_fit_stored_points(lead, 5, 1e-6, 0.0, a) == VSH_PLANE_OK);
  CHECK(vsh_plane_fit_points(lead, 5, 1e-6, b) == VSH_PLANE_OK);
  CHECK(memcmp(a, b, sizeof(a)) == 0);
}

static void test_contains_box(void) {
  const double ground[4] = {0, 0, 1, -2};
  vsh_bounds flat = {{-1e6, -3, 2}, {1e6, 3, 2}}, thick = {{0, 0, 2}, {1, 1, 2.1}};
  CHECK(vsh_plane_contains_box(ground, &flat, 1e-6) == 1);
  CHECK(vsh_plane_contains_box(ground, &thick, 1e-6) == 0);
  vsh_bounds nearly = {{0, 0, 2}, {1, 1, 2 + 1e-7}}; /* within 1e-6 of size 1 */
  CHECK(vsh_plane_contains_box(ground, &nearly, 1e-6) == 1);
  vsh_bounds point = {{5, 5, 2}, {5, 5, 2}}, off = {{5, 5, 2.5}, {5, 5, 2.5}};
  CHECK(vsh_plane_contains_box(ground, &point, 1e-6) == 1);
  CHECK(vsh_plane_contains_box(ground, &off, 1e-6) == 0);
  vsh_bounds empty;
  vsh_bounds_init_empty(&empty);
  CHECK(vsh_plane_contains_box(ground, &empty, 1e-6) == 0);
  CHECK(vsh_plane_contains_box(NULL, &flat, 1e-6) == 0);
}

static void test_face_light(void) {
  const double plane[4] = {0, 0, 2, -4}; /* z = 2, not unit */
  double out[4];
  const double below[4] = {0, 0, -5, 1}, above[4] = {1, 1, 7, 1};
  vsh_plane_face_light(plane, below, out);
  CHECK(out[0] == 0 && out[2] == -2 && out[3] == 4);
  vsh_plane_face_light(plane, above, out);
  CHECK(memcmp(out, plane, sizeof(out)) == 0);
  const double sun_below[4] = {0, 0.3, -1, 0};
  vsh_plane_face_light(plane, sun_below, out);
  CHECK(out[2] == -2);
  CHECK(eval(out, below) > 0); /* the light's side is now positive */
  /* A light in the plane leaves it as it is. */
  const double on[4] = {3, 3, 2, 1};
  vsh_plane_face_light(plane, on, out);
  CHECK(memcmp(out, plane, sizeof(out)) == 0);
}

static void test_times_matrix(void) {
  vsh_test_seed(5);
  for (int round = 0; round < 100; ++round) {
    double m[16], plane[4], out[4], x[3], y[4];
    for (int k = 0; k < 16; ++k) m[k] = vsh_test_rnd(-2, 2);
    for (int k = 0; k < 4; ++k) plane[k] = vsh_test_rnd(-1, 1);
    for (int k = 0; k < 3; ++k) x[k] = vsh_test_rnd(-10, 10);
    vsh_plane_times_matrix(plane, m, out);
    /* plane . (m (x, 1)) == out . (x, 1) */
    for (int r = 0; r < 4; ++r) y[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
    const double lhs = plane[0] * y[0] + plane[1] * y[1] + plane[2] * y[2] + plane[3] * y[3];
    CHECK_NEAR(eval(out, x), lhs, 1e-11 * (1 + fabs(lhs)) * 100);
    /* In place. */
    double same[4];
    memcpy(same, plane, sizeof(same));
    vsh_plane_times_matrix(same, m, same);
    CHECK(memcmp(same, out, sizeof(out)) == 0);
  }
}

static void test_keep_box(void) {
  const double planes[2][4] = {{0, 0, 1, 0}, {0, 0, -1, 10}}; /* 0 < z < 10 */
  vsh_bounds inside = {{-5, -5, 1}, {5, 5, 9}}, touching = {{0, 0, 0}, {1, 1, 1}};
  vsh_bounds across = {{0, 0, 5}, {1, 1, 12}};
  CHECK(vsh_planes_keep_box(planes, 2, &inside, NULL) == 1);
  CHECK(vsh_planes_keep_box(planes, 2, &touching, NULL) == 0); /* z = 0 is not kept strictly */
  CHECK(vsh_planes_keep_box(planes, 2, &across, NULL) == 0);
  CHECK(vsh_planes_keep_box(planes, 1, &across, NULL) == 1);
  CHECK(vsh_planes_keep_box(planes, 0, &across, NULL) == 1);
  /* The same planes given relative to an origin 1e6 away. */
  const double origin[3] = {1e6, -1e6, 1e6};
  const double rel[2][4] = {{0, 0, 1, 1e6}, {0, 0, -1, 10 - 1e6}};
  vsh_bounds far_inside = {{1e6 - 5, -1e6 - 5, 1}, {1e6 + 5, -1e6 + 5, 9}};
  vsh_bounds far_across = {{1e6, -1e6, 5}, {1e6 + 1, -1e6 + 1, 12}};
  CHECK(vsh_planes_keep_box(rel, 2, &far_inside, origin) == 1);
  CHECK(vsh_planes_keep_box(rel, 2, &far_across, origin) == 0);
  vsh_bounds empty;
  vsh_bounds_init_empty(&empty);
  CHECK(vsh_planes_keep_box(planes, 2, &empty, NULL) == 0);
  CHECK(vsh_planes_keep_box(NULL, 2, &inside, NULL) == 0);
}

int main(void) {
  test_fit_random();
  test_fit_degenerate();
  test_fit_stored();
  test_contains_box();
  test_face_light();
  test_times_matrix();
  test_keep_box();
  return vsh_check_report("test_plane");
}
