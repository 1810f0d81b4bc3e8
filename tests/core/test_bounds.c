/* test_bounds.c - unit tests of vsh_bounds: empty vs zero-volume boxes,
 * non-finite points, transforms (including projective w <= 0), depth range. */
#include "vsh_check.h"
#include "vsh_bounds.h"
#include "vsh_camera.h"
#include "vsh_mat4.h"

#include <math.h>

static void test_empty(void) {
  vsh_bounds b;
  double c[3], corners[8][3], nf[2];
  vsh_bounds_init_empty(&b);
  CHECK(vsh_bounds_is_empty(&b));
  CHECK(!vsh_bounds_is_finite(&b));
  CHECK(vsh_bounds_center(&b, c) != 0 && c[0] == 0 && c[1] == 0 && c[2] == 0);
  CHECK(vsh_bounds_diagonal_length(&b) == 0);
  CHECK(vsh_bounds_corners(&b, corners) != 0 && corners[7][2] == 0);
  double id[16];
  vsh_mat4_identity(id);
  CHECK(vsh_bounds_depth_range_in_view(&b, id, nf) != 0 && nf[0] == 0 && nf[1] == 0);
  vsh_bounds t;
  CHECK(vsh_bounds_transform(&b, id, &t) == 0 && vsh_bounds_is_empty(&t));
  /* VTK's uninitialized bounds (1, -1, 1, -1, 1, -1) are empty too. */
  vsh_bounds_from_vtk(&b, (double[6]){1, -1, 1, -1, 1, -1});
  CHECK(vsh_bounds_is_empty(&b));
  /* Empty on a single axis is empty. */
  vsh_bounds_from_vtk(&b, (double[6]){0, 1, 0, 1, 1, 0});
  CHECK(vsh_bounds_is_empty(&b));
  /* NaN is empty. */
  vsh_bounds_from_vtk(&b, (double[6]){0, 1, NAN, 1, 0, 1});
  CHECK(vsh_bounds_is_empty(&b));
}

static void test_zero_volume(void) {
  vsh_bounds b;
  double c[3];
  vsh_bounds_init_empty(&b);
  const double p[3] = {1, -2, 3};
  CHECK(vsh_bounds_add_point(&b, p) == 1);
  CHECK(!vsh_bounds_is_empty(&b)); /* a point is a valid box */
  CHECK(vsh_bounds_is_finite(&b));
  CHECK(vsh_bounds_diagonal_length(&b) == 0);
  CHECK(vsh_bounds_center(&b, c) == 0 && c[0] == 1 && c[1] == -2 && c[2] == 3);
  /* A flat ground plane z = 0. */
  vsh_bounds_from_vtk(&b, (double[6]){-5, 5, -5, 5, 0, 0});
  CHECK(!vsh_bounds_is_empty(&b));
  CHECK_NEAR(vsh_bounds_diagonal_length(&b), sqrt(200.0), 1e-14);
  double corners[8][3];
  CHECK(vsh_bounds_corners(&b, corners) == 0);
  CHECK(corners[0][2] == 0 && corners[7][2] == 0);
  CHECK(corners[5][0] == 5 && corners[5][1] == -5); /* k = 5: x max, y min, z max */
}

static void test_add_merge(void) {
  vsh_bounds a, b;
  vsh_bounds_init_empty(&a);
  const double p1[3] = {1, 2, 3}, p2[3] = {-1, 5, 0}, pn[3] = {NAN, 0, 0}, pi[3] = {0, INFINITY, 0};
  vsh_bounds_add_point(&a, p1);
  vsh_bounds_add_point(&a, p2);
  CHECK(vsh_bounds_add_point(&a, pn) == 0); /* ignored */
  CHECK(vsh_bounds_add_point(&a, pi) == 0);
  CHECK(vsh_bounds_is_finite(&a));
  CHECK(a.min[0] == -1 && a.max[0] == 1 && a.min[1] == 2 && a.max[1] == 5 && a.min[2] == 0 &&
        a.max[2] == 3);
  double v[6];
  vsh_bounds_to_vtk(&a, v);
  CHECK(v[0] == -1 && v[1] == 1 && v[2] == 2 && v[3] == 5 && v[4] == 0 && v[5] == 3);

  vsh_bounds_init_empty(&b);
  vsh_bounds m = a;
  vsh_bounds_merge(&m, &b); /* merging empty changes nothing */
  CHECK(m.min[0] == a.min[0] && m.max[2] == a.max[2]);
  vsh_bounds_merge(&b, &a); /* empty + a = a */
  CHECK(b.min[1] == 2 && b.max[1] == 5);
  vsh_bounds far_box = {{10, 10, 10}, {11, 11, 11}};
  vsh_bounds_merge(&b, &far_box);
  CHECK(b.min[0] == -1 && b.max[0] == 11);
  /* Huge offsets keep exact extremes. */
  vsh_bounds h;
  vsh_bounds_init_empty(&h);
  const double q1[3] = {1e12, 1e12, 1e12}, q2[3] = {1e12 + 1, 1e12, 1e12 - 1};
  vsh_bounds_add_point(&h, q1);
  vsh_bounds_add_point(&h, q2);
  CHECK_NEAR(vsh_bounds_diagonal_length(&h), sqrt(2.0), 1e-15);
  double c[3];
  vsh_bounds_center(&h, c);
  CHECK(c[0] == 1e12 + 0.5 && c[2] == 1e12 - 0.5);
}

static void test_transform(void) {
  vsh_bounds b = {{-1, -1, -1}, {1, 1, 1}}, t;
  /* A 45 degree rotation about z grows x, y to sqrt(2). */
  const double s = sqrt(0.5);
  const double R[16] = {s, -s, 0, 0, s, s, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK(vsh_bounds_transform(&b, R, &t) == 0);
  CHECK_NEAR(t.max[0], sqrt(2.0), 1e-15);
  CHECK_NEAR(t.min[1], -sqrt(2.0), 1e-15);
  CHECK_NEAR(t.max[2], 1, 0);
  /* Translation by 1e6, tiny scale 1e-6. */
  double T[16], S[16];
  vsh_mat4_translation((double[3]){1e6, 0, -1e6}, T);
  CHECK(vsh_bounds_transform(&b, T, &t) == 0);
  CHECK(t.min[0] == 1e6 - 1 && t.max[2] == -1e6 + 1);
  vsh_mat4_scale((double[3]){1e-6, 1e-6, 1e-6}, S);
  CHECK(vsh_bounds_transform(&b, S, &t) == 0);
  CHECK(t.min[0] == -1e-6 && t.max[1] == 1e-6);
  /* Zero-volume box stays zero-volume and non-empty. */
  vsh_bounds flat = {{-1, -1, 0}, {1, 1, 0}};
  CHECK(vsh_bounds_transform(&flat, T, &t) == 0 && !vsh_bounds_is_empty(&t));
  CHECK(t.min[2] == -1e6 && t.max[2] == -1e6);
  /* Projective with some corner at w <= 0: refused, out empty. */
  const double P[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0}; /* w = -z */
  CHECK(vsh_bounds_transform(&b, P, &t) != 0 && vsh_bounds_is_empty(&t));
  vsh_bounds front = {{-1, -1, -3}, {1, 1, -1}}; /* all w > 0 */
  CHECK(vsh_bounds_transform(&front, P, &t) == 0);
  CHECK_NEAR(t.max[0], 1, 1e-15); /* (1, y, -1) / 1 */
  CHECK_NEAR(t.min[2], -1, 1e-15);
  /* Non-finite matrix or box. */
  double Bad[16];
  vsh_mat4_identity(Bad);
  Bad[3] = NAN;
  CHECK(vsh_bounds_transform(&b, Bad, &t) != 0 && vsh_bounds_is_empty(&t));
  vsh_bounds inf_box = {{-INFINITY, 0, 0}, {1, 1, 1}};
  CHECK(vsh_bounds_transform(&inf_box, R, &t) != 0 && vsh_bounds_is_empty(&t));
  /* Aliasing in == out. */
  vsh_bounds a = b;
  CHECK(vsh_bounds_transform(&a, T, &a) == 0 && a.min[0] == 1e6 - 1);
}

static void test_depth_range(void) {
  const vsh_camera cam = {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 30};
  double V[16], nf[2];
  vsh_camera_view_matrix(&cam, V);
  vsh_bounds b = {{-1, -1, -2}, {1, 1, 3}};
  CHECK(vsh_bounds_depth_range_in_view(&b, V, nf) == 0);
  CHECK_NEAR(nf[0], 7, 1e-14);
  CHECK_NEAR(nf[1], 12, 1e-14);
  /* Behind the eye: negative depths, not clamped. */
  vsh_bounds behind = {{-1, -1, 11}, {1, 1, 20}};
  CHECK(vsh_bounds_depth_range_in_view(&behind, V, nf) == 0);
  CHECK_NEAR(nf[0], -10, 1e-14);
  CHECK_NEAR(nf[1], -1, 1e-14);
  /* Flat box facing the camera: near == far, valid. */
  vsh_bounds flat = {{-1, -1, 0}, {1, 1, 0}};
  CHECK(vsh_bounds_depth_range_in_view(&flat, V, nf) == 0);
  CHECK(nf[0] == nf[1] && fabs(nf[0] - 10) < 1e-14);
  /* Non-finite matrix. */
  V[11] = INFINITY;
  CHECK(vsh_bounds_depth_range_in_view(&b, V, nf) != 0);
  CHECK(nf[0] == 0 && nf[1] == 0);
}

int main(void) {
  test_empty();
  test_zero_volume();
  test_add_merge();
  test_transform();
  test_depth_range();
  return vsh_check_report("core.bounds");
}
