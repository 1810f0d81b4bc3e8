/* test_frustum.c - unit tests of vsh_frustum: sphere and box culling
 * against frustum planes (unnormalized, inward), checked by hand and, for
 * "not visible" answers, by sampling points of the culled shape. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_frustum.h"

#include <math.h>

/* The cube [-1, 1]^3 as six inward planes, each scaled differently so the
 * tests cannot pass only for unit normals. */
static void cube_planes(double planes[24]) {
  const double scale[6] = {1, 3, 0.5, 7, 2, 1e-3};
  for (int p = 0; p < 6; ++p) {
    const int axis = p / 2;
    const double sign = p % 2 ? -1.0 : 1.0; /* left: x >= -1, right: x <= 1 */
    for (int k = 0; k < 4; ++k) planes[4 * p + k] = 0.0;
    planes[4 * p + axis] = sign * scale[p];
    planes[4 * p + 3] = scale[p];
  }
}

static int in_cube(const double x[3]) {
  return fabs(x[0]) <= 1 && fabs(x[1]) <= 1 && fabs(x[2]) <= 1;
}

static void test_by_hand(void) {
  double planes[24];
  cube_planes(planes);
  const double centre[3] = {0, 0, 0}, right[3] = {3, 0, 0}, corner[3] = {1.6, 1.6, 0};
  CHECK(vsh_frustum_sphere_visible(planes, centre, 0.0) == 1);
  CHECK(vsh_frustum_sphere_visible(planes, right, 1.5) == 0);
  CHECK(vsh_frustum_sphere_visible(planes, right, 2.5) == 1);
  CHECK(vsh_frustum_sphere_visible(planes, right, 2.0) == 1); /* touching counts */
  /* Outside at a corner but not wholly behind one plane: conservative 1. */
  CHECK(vsh_frustum_sphere_visible(planes, corner, 0.7) == 1);
  const double far_z[3] = {0, 0, -5};
  CHECK(vsh_frustum_sphere_visible(planes, far_z, 3.9) == 0);
  vsh_bounds beyond = {{1.5, -1, -1}, {2, 1, 1}}, across = {{0.5, 0.5, 0.5}, {3, 3, 3}};
  vsh_bounds around = {{-5, -5, -5}, {5, 5, 5}};
  CHECK(vsh_frustum_box_visible(planes, &beyond) == 0);
  CHECK(vsh_frustum_box_visible(planes, &across) == 1);
  CHECK(vsh_frustum_box_visible(planes, &around) == 1);
  vsh_bounds empty;
  vsh_bounds_init_empty(&empty);
  CHECK(vsh_frustum_box_visible(planes, &empty) == 0);
}

static void test_bad_input(void) {
  double planes[24];
  cube_planes(planes);
  const double far_away[3] = {100, 0, 0}, nan_c[3] = {NAN, 0, 0};
  CHECK(vsh_frustum_sphere_visible(planes, far_away, -1.0) == 1);
  CHECK(vsh_frustum_sphere_visible(planes, nan_c, 1.0) == 1);
  CHECK(vsh_frustum_sphere_visible(NULL, far_away, 1.0) == 1);
  CHECK(vsh_frustum_sphere_visible(planes, far_away, INFINITY) == 1);
  planes[4] = planes[5] = planes[6] = 0.0; /* a zero normal */
  CHECK(vsh_frustum_sphere_visible(planes, far_away, 1.0) == 1);
  cube_planes(planes);
  vsh_bounds inf_box = {{1.5, 0, 0}, {INFINITY, 1, 1}};
  CHECK(vsh_frustum_box_visible(planes, &inf_box) == 1);
  CHECK(vsh_frustum_box_visible(NULL, &inf_box) == 1);
}

/* Culled spheres and boxes really are outside: no sampled point inside. */
static void test_random_culls_are_right(void) {
  double planes[24];
  cube_planes(planes);
  vsh_test_seed(8);
  int culled = 0, kept = 0;
  long wrong = 0;
  for (int round = 0; round < 2000; ++round) {
    const double c[3] = {vsh_test_rnd(-4, 4), vsh_test_rnd(-4, 4), vsh_test_rnd(-4, 4)};
    const double r = vsh_test_rnd(0, 2);
    if (vsh_frustum_sphere_visible(planes, c, r)) {
      ++kept;
      continue;
    }
    ++culled;
    for (int s = 0; s < 50; ++s) {
      double d[3], x[3];
      vsh_test_rnd_unit(d);
      const double t = r * cbrt(vsh_test_rnd(0, 1));
      for (int k = 0; k < 3; ++k) x[k] = c[k] + t * d[k];
      wrong += in_cube(x);
    }
    vsh_bounds box = {{c[0] - r, c[1] - r, c[2] - r}, {c[0] + r, c[1] + r, c[2] + r}};
    if (!vsh_frustum_box_visible(planes, &box))
      for (int s = 0; s < 50; ++s) {
        double x[3];
        for (int k = 0; k < 3; ++k) x[k] = vsh_test_rnd(box.min[k], box.max[k]);
        wrong += in_cube(x);
      }
  }
  CHECK(wrong == 0);
  CHECK(culled > 500 && kept > 100);
}

int main(void) {
  test_by_hand();
  test_bad_input();
  test_random_culls_are_right();
  return vsh_check_report("test_frustum");
}
