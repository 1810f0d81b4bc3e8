/* test_camera.c - unit tests of vsh_camera against numbers printed by VTK
 * 9.1 (Debian 12's python3-vtk9), degenerate cameras, large offsets. */
#include "vsh_check.h"
#include "vsh_camera.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

#define VSH_TEST_PI 3.14159265358979323846

/* The reference camera of the VTK numbers below:
 *   c = vtk.vtkCamera(); c.SetPosition(1,2,10); c.SetFocalPoint(0.5,-1,0)
 *   c.SetViewUp(0,1,0.2); c.SetViewAngle(40); c.SetClippingRange(0.5,30) */
static vsh_camera ref_camera(void) {
  vsh_camera c = {{1, 2, 10}, {0.5, -1, 0}, {0, 1, 0.2}, 40};
  return c;
}

static double max_abs_diff(const double *a, const double *b, int n) {
  double m = 0;
  for (int k = 0; k < n; ++k) m = fmax(m, fabs(a[k] - b[k]));
  return m;
}

static void test_basis(void) {
  const vsh_camera c = ref_camera();
  double r[3], u[3], f[3], t[3];
  CHECK(vsh_camera_basis(&c, r, u, f) == 0);
  CHECK_NEAR(vsh_vec3_length(r), 1, 1e-15);
  CHECK_NEAR(vsh_vec3_length(u), 1, 1e-15);
  CHECK_NEAR(vsh_vec3_length(f), 1, 1e-15);
  CHECK_NEAR(vsh_vec3_dot(r, u), 0, 1e-15);
  CHECK_NEAR(vsh_vec3_dot(r, f), 0, 1e-15);
  CHECK_NEAR(vsh_vec3_dot(u, f), 0, 1e-15);
  vsh_vec3_cross(r, u, t); /* right-handed: r x u = -f (eye looks down -z) */
  CHECK(max_abs_diff(t, (double[3]){-f[0], -f[1], -f[2]}, 3) < 1e-15);
  CHECK(vsh_vec3_dot(u, c.view_up) > 0); /* up keeps the side of view_up */
  /* NULL outputs are allowed. */
  CHECK(vsh_camera_basis(&c, NULL, NULL, f) == 0);
}

static void test_basis_degenerate(void) {
  double r[3] = {9, 9, 9}, u[3], f[3];
  vsh_camera c = ref_camera();
  /* E == F */
  memcpy(c.focal_point, c.position, sizeof c.position);
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  CHECK(r[0] == 0 && u[1] == 0 && f[2] == 0);
  /* E and F one ulp apart at 1e16: rounding noise, not a direction. */
  c = ref_camera();
  c.position[0] = 1e16;
  c.focal_point[0] = 1e16 + 2; /* representable neighbour */
  c.position[1] = c.focal_point[1] = c.position[2] = c.focal_point[2] = 0;
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  /* ... while the same distance at 1e6 is fine. */
  c.position[0] = 1e6;
  c.focal_point[0] = 1e6 + 2;
  CHECK(vsh_camera_basis(&c, r, u, f) == 0);
  /* Zero view-up. */
  c = ref_camera();
  c.view_up[0] = c.view_up[1] = c.view_up[2] = 0;
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  /* View-up exactly parallel and anti-parallel to the view direction. */
  c = ref_camera();
  vsh_vec3_sub(c.focal_point, c.position, c.view_up);
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  vsh_vec3_scale(c.view_up, -3, c.view_up);
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  /* Nearly parallel (1e-13) fails, 1e-6 works. */
  vsh_camera d = {{0, 0, 0}, {0, 0, -1}, {1e-13, 0, 1}, 30};
  CHECK(vsh_camera_basis(&d, r, u, f) != 0);
  d.view_up[0] = 1e-6;
  CHECK(vsh_camera_basis(&d, r, u, f) == 0);
  CHECK_NEAR(r[1], -1, 1e-12); /* f = -z, U ~ +x -> r = f x U = -y */
  /* Non-finite anything. */
  c = ref_camera();
  c.position[2] = NAN;
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  c = ref_camera();
  c.focal_point[0] = INFINITY;
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  c = ref_camera();
  c.view_up[1] = -INFINITY;
  CHECK(vsh_camera_basis(&c, r, u, f) != 0);
  CHECK(vsh_vec3_is_finite(r) && vsh_vec3_is_finite(u) && vsh_vec3_is_finite(f));
  /* Everything that needs the basis fails too, with finite outputs. */
  double m[16], dir[3], nf[2];
  vsh_bounds b = {{-1, -1, -1}, {1, 1, 1}};
  CHECK(vsh_camera_view_matrix(&c, m) != 0 && vsh_mat4_is_finite(m) && m[0] == 1);
  CHECK(vsh_camera_view_matrix_relative(&c, m) != 0 && vsh_mat4_is_finite(m));
  CHECK(vsh_camera_pixel_ray(&c, 10, 10, 0, 0, dir) != 0 && dir[0] == 0);
  CHECK(vsh_camera_clipping_range(&c, &b, 0.001, nf) != 0);
  CHECK(nf[0] == 0.001 && nf[1] == 1);
}

static void test_view_matrix_vs_vtk(void) {
  /* print(c.GetViewTransformMatrix()) of the reference camera, VTK 9.1 */
  const double vtk_view[16] = {
      0.99853198498005569,   0.010622680691277187, -0.053113403456385939, -0.48864331179875065,
      -0.025407586511490277, 0.9578660114831834,   -0.28608942411938054,  0.97056980473892884,
      0.047836487323493986,  0.2870189239409639,   0.95672974646987974,   -10.189171799904219,
      0,                     0,                    0,                     1};
  const vsh_camera c = ref_camera();
  double m[16], rel[16];
  CHECK(vsh_camera_view_matrix(&c, m) == 0);
  CHECK(max_abs_diff(m, vtk_view, 16) < 1e-14);
  /* The eye maps to the origin, the focal point to (0, 0, -distance). */
  double p[3];
  vsh_mat4_transform_point(m, c.position, p);
  CHECK(max_abs_diff(p, (double[3]){0, 0, 0}, 3) < 1e-14);
  vsh_mat4_transform_point(m, c.focal_point, p);
  CHECK_NEAR(p[0], 0, 1e-14);
  CHECK_NEAR(p[1], 0, 1e-14);
  CHECK_NEAR(p[2], -sqrt(0.25 + 9 + 100), 1e-13);
  /* The relative matrix is the same rotation without translation. */
  CHECK(vsh_camera_view_matrix_relative(&c, rel) == 0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) CHECK(rel[i * 4 + j] == m[i * 4 + j]);
  CHECK(rel[3] == 0 && rel[7] == 0 && rel[11] == 0 && rel[15] == 1);
}

static void test_view_relative_precision(void) {
  /* Camera and point at 1e6 and 1e12: rotating (X - E) gives the same eye
   * coordinates as the reference camera at the origin. */
  const vsh_camera c0 = ref_camera();
  const double X0[3] = {0.3, -0.7, 1.1};
  double m0[16], e0[3];
  vsh_camera_view_matrix(&c0, m0);
  vsh_mat4_transform_point(m0, X0, e0);
  const double offs[2] = {1e6, 1e12};
  for (int k = 0; k < 2; ++k) {
    const double o[3] = {offs[k], -2 * offs[k], offs[k]};
    vsh_camera c = c0;
    double X[3], d[3], rel[16], e[3];
    vsh_vec3_add(c0.position, o, c.position);
    vsh_vec3_add(c0.focal_point, o, c.focal_point);
    vsh_vec3_add(X0, o, X);
    CHECK(vsh_camera_view_matrix_relative(&c, rel) == 0);
    vsh_vec3_sub(X, c.position, d);
    vsh_mat4_transform_point(rel, d, e);
    /* Error is the quantization of the inputs at that offset, ~ulp(offset). */
    const double tol = 8 * offs[k] * 2.220446049250313e-16 * 10;
    CHECK(max_abs_diff(e, e0, 3) < tol);
  }
}

static void test_projection_vs_vtk(void) {
  /* c.GetProjectionTransformMatrix(1.5, -1, 1) of the reference camera. */
  const double vtk_proj[16] = {1.8316516129697482, 0, 0, 0, 0, 2.7474774194546225, 0, 0, 0, 0,
                               -1.0338983050847457, -1.0169491525423728, 0, 0, -1, 0};
  double m[16];
  CHECK(vsh_camera_projection_matrix(40, 1.5, 0.5, 30, m) == 0);
  CHECK(max_abs_diff(m, vtk_proj, 16) < 1e-15);
  /* c = vtk.vtkCamera(); c.SetViewAngle(30); c.SetClippingRange(0.01, 1000);
   * c.GetProjectionTransformMatrix(0.75, -1, 1) */
  const double vtk_proj2[16] = {4.9760677434251699, 0, 0, 0, 0, 3.7320508075688776, 0, 0, 0, 0,
                                -1.0000200002000019, -0.020000200002000021, 0, 0, -1, 0};
  CHECK(vsh_camera_projection_matrix(30, 0.75, 0.01, 1000, m) == 0);
  CHECK(max_abs_diff(m, vtk_proj2, 16) < 1e-15);
  /* By hand: near maps to NDC z = -1, far to +1, and the half angle to y = 1. */
  double p[3];
  const double at_near[3] = {0, 0.01 * tan(15 * VSH_TEST_PI / 180), -0.01};
  CHECK(vsh_mat4_transform_point(m, at_near, p) > 0);
  CHECK_NEAR(p[2], -1, 1e-12);
  CHECK_NEAR(p[1], 1, 1e-12);
  const double at_far[3] = {1000 * tan(15 * VSH_TEST_PI / 180) * 0.75, 0, -1000};
  vsh_mat4_transform_point(m, at_far, p);
  CHECK_NEAR(p[2], 1, 1e-12);
  CHECK_NEAR(p[0], 1, 1e-12);
}

static void test_projection_invalid(void) {
  double m[16];
  const double bad[][4] = {{0, 1, 1, 2},   {180, 1, 1, 2}, {-10, 1, 1, 2},  {NAN, 1, 1, 2},
                           {40, 0, 1, 2},  {40, -1, 1, 2}, {40, INFINITY, 1, 2},
                           {40, 1, 0, 2},  {40, 1, -1, 2}, {40, 1, 2, 2},   {40, 1, 3, 2},
                           {40, 1, 1, INFINITY}, {40, 1, NAN, 2}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    m[0] = 7;
    CHECK(vsh_camera_projection_matrix(bad[k][0], bad[k][1], bad[k][2], bad[k][3], m) != 0);
    CHECK(vsh_mat4_is_finite(m) && m[0] == 1 && m[14] == 0); /* identity */
  }
}

static void test_pixel_ray(void) {
  /* The ray through a pixel centre must land, through VTK's own view and
   * projection matrices (numbers above, aspect 1.5 = 300 x 200), on that
   * pixel's NDC centre: x = 2(i + 0.5)/W - 1, y = 1 - 2(j + 0.5)/H. */
  const double vtk_view[16] = {
      0.99853198498005569,   0.010622680691277187, -0.053113403456385939, -0.48864331179875065,
      -0.025407586511490277, 0.9578660114831834,   -0.28608942411938054,  0.97056980473892884,
      0.047836487323493986,  0.2870189239409639,   0.95672974646987974,   -10.189171799904219,
      0,                     0,                    0,                     1};
  const double vtk_proj[16] = {1.8316516129697482, 0, 0, 0, 0, 2.7474774194546225, 0, 0, 0, 0,
                               -1.0338983050847457, -1.0169491525423728, 0, 0, -1, 0};
  double vp[16];
  vsh_mat4_multiply(vtk_proj, vtk_view, vp);
  const vsh_camera c = ref_camera();
  const int W = 300, H = 200;
  const double pix[][2] = {{0, 0}, {299, 199}, {149.5, 99.5}, {10, 150}, {250, 3}};
  for (size_t k = 0; k < sizeof pix / sizeof pix[0]; ++k) {
    double dir[3], X[3], ndc[3], f[3];
    CHECK(vsh_camera_pixel_ray(&c, W, H, pix[k][0], pix[k][1], dir) == 0);
    vsh_camera_basis(&c, NULL, NULL, f);
    CHECK_NEAR(vsh_vec3_dot(dir, f), 1, 1e-15); /* not normalized: unit depth */
    for (int a = 0; a < 3; ++a) X[a] = c.position[a] + 5 * dir[a]; /* depth 5 */
    CHECK(vsh_mat4_transform_point(vp, X, ndc) > 0);
    CHECK_NEAR(ndc[0], 2 * (pix[k][0] + 0.5) / W - 1, 1e-13);
    CHECK_NEAR(ndc[1], 1 - 2 * (pix[k][1] + 0.5) / H, 1e-13);
  }
  /* The centre of the image (i = W/2 - 0.5) is the view direction. */
  double dir[3], f[3];
  vsh_camera_pixel_ray(&c, W, H, 149.5, 99.5, dir);
  vsh_camera_basis(&c, NULL, NULL, f);
  CHECK(max_abs_diff(dir, f, 3) < 1e-15);
  /* Invalid: sizes, angles, NaN pixel. */
  CHECK(vsh_camera_pixel_ray(&c, 0, H, 0, 0, dir) != 0);
  CHECK(vsh_camera_pixel_ray(&c, W, -1, 0, 0, dir) != 0);
  CHECK(vsh_camera_pixel_ray(&c, W, H, NAN, 0, dir) != 0);
  CHECK(dir[0] == 0 && dir[1] == 0 && dir[2] == 0);
  vsh_camera bad = c;
  bad.view_angle = 180;
  CHECK(vsh_camera_pixel_ray(&bad, W, H, 0, 0, dir) != 0);
  bad.view_angle = 0;
  CHECK(vsh_camera_pixel_ray(&bad, W, H, 0, 0, dir) != 0);
}

/* Numbers from VTK 9.1:
 *   r = vtk.vtkRenderer(); c = r.GetActiveCamera(); (camera set as named)
 *   r.SetNearClippingPlaneTolerance(tol); r.ResetCameraClippingRange(*bounds)
 *   c.GetClippingRange() */
static void check_range(const vsh_camera *c, const double vb[6], double tol, double n, double f,
                        double eps) {
  vsh_bounds b;
  double nf[2];
  vsh_bounds_from_vtk(&b, vb);
  CHECK(vsh_camera_clipping_range(c, &b, tol, nf) == 0);
  CHECK_NEAR(nf[0], n, eps);
  CHECK_NEAR(nf[1], f, eps);
}

static void test_clipping_range_vs_vtk(void) {
  const vsh_camera c = ref_camera();
  check_range(&c, (double[6]){-1, 2, -3, 0.5, -2, 1}, 0.001, 6.8941945530619542,
              16.200304796974471, 1e-13);
  /* Flat box (z = 0 plane). */
  check_range(&c, (double[6]){-1, 2, -3, 0.5, 0, 0}, 0.001, 9.2764516217719546,
              12.119852428280435, 1e-13);
  /* A single point: the minimum-gap rule. */
  check_range(&c, (double[6]){0, 0, 0, 0, 0, 0}, 0.001, 9.3492775877542247, 11.271002466273707,
              1e-13);
  const vsh_camera c2 = {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30};
  /* A flat square facing the camera. */
  check_range(&c2, (double[6]){-1, 1, -1, 1, 0, 0}, 0.001, 4.6833905535310345,
              5.4106063635199799, 1e-13);
  /* Straddling the eye: near clamps to ratio * far. */
  check_range(&c2, (double[6]){-1, 1, -1, 1, -10, 10}, 0.001, 0.0264, 26.4, 1e-13);
  check_range(&c2, (double[6]){-1, 1, -1, 1, -10, 10}, 0.01, 0.264, 26.4, 1e-13);
  /* The reference scene moved by (1e6, 2e6, 0). VTK itself gives
   * 6.8941945531661624, 16.200304796957646 here (1e-11 off, it does not
   * subtract the eye first); we must match the at-origin numbers better. */
  const vsh_camera c3 = {{1e6 + 1, 2e6 + 2, 10}, {1e6 + 0.5, 2e6 - 1, 0}, {0, 1, 0.2}, 40};
  check_range(&c3, (double[6]){1e6 - 1, 1e6 + 2, 2e6 - 3, 2e6 + 0.5, -2, 1}, 0.001,
              6.8941945530619542, 16.200304796974471, 1e-12);
  /* And at 1e12 (inputs exactly representable, offset only). */
  const vsh_camera c4 = {{1e12 + 1, 2e12 + 2, 10}, {1e12 + 0.5, 2e12 - 1, 0}, {0, 1, 0.2}, 40};
  check_range(&c4, (double[6]){1e12 - 1, 1e12 + 2, 2e12 - 3, 2e12 + 0.5, -2, 1}, 0.001,
              6.8941945530619542, 16.200304796974471, 1e-12);
}

static void test_clipping_range_degenerate(void) {
  const vsh_camera c = ref_camera();
  double nf[2];
  vsh_bounds b;
  vsh_bounds_init_empty(&b);
  CHECK(vsh_camera_clipping_range(&c, &b, 0.001, nf) != 0);
  CHECK(nf[0] == 0.001 && nf[1] == 1);
  /* Entirely behind the eye. */
  const vsh_camera c2 = {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30};
  vsh_bounds_from_vtk(&b, (double[6]){-1, 1, -1, 1, 20, 30});
  CHECK(vsh_camera_clipping_range(&c2, &b, 0.01, nf) != 0);
  CHECK(nf[0] == 0.01 && nf[1] == 1);
  /* Bad ratio, bad angle, non-finite bounds. */
  vsh_bounds_from_vtk(&b, (double[6]){-1, 1, -1, 1, -1, 1});
  CHECK(vsh_camera_clipping_range(&c2, &b, 0, nf) != 0);
  CHECK(nf[0] == 0.001 && nf[1] == 1);
  CHECK(vsh_camera_clipping_range(&c2, &b, 1, nf) != 0);
  CHECK(vsh_camera_clipping_range(&c2, &b, NAN, nf) != 0);
  vsh_camera c3 = c2;
  c3.view_angle = NAN;
  CHECK(vsh_camera_clipping_range(&c3, &b, 0.001, nf) != 0);
  b.max[0] = INFINITY;
  CHECK(vsh_camera_clipping_range(&c2, &b, 0.001, nf) != 0);
  CHECK(isfinite(nf[0]) && isfinite(nf[1]));
  /* A point box at the eye itself: far = 0 after the gap rule -> failure. */
  vsh_bounds_from_vtk(&b, (double[6]){0, 0, 0, 0, 5, 5});
  CHECK(vsh_camera_clipping_range(&c2, &b, 0.001, nf) != 0);
  /* A tiny scene (1e-6) gets a tiny, valid range. */
  vsh_camera c4 = {{0, 0, 5e-6}, {0, 0, 0}, {0, 1, 0}, 30};
  vsh_bounds_from_vtk(&b, (double[6]){-1e-6, 1e-6, -1e-6, 1e-6, -1e-6, 1e-6});
  CHECK(vsh_camera_clipping_range(&c4, &b, 0.001, nf) == 0);
  CHECK(nf[0] > 0 && nf[0] < 4e-6 && nf[1] > 6e-6 && nf[1] < 1e-5);
}

int main(void) {
  test_basis();
  test_basis_degenerate();
  test_view_matrix_vs_vtk();
  test_view_relative_precision();
  test_projection_vs_vtk();
  test_projection_invalid();
  test_pixel_ray();
  test_clipping_range_vs_vtk();
  test_clipping_range_degenerate();
  return vsh_check_report("core.camera");
}
