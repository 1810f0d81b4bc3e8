/* test_reflect.c - unit tests of vsh_reflect: the reflection matrix
 * (involution, determinant -1, fixed plane, distances kept), degenerate and
 * invalid planes, the camera-side test (below, in the plane, grazing), the
 * clip plane, and mirrors 1e6 from the origin handled relative to the eye. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_reflect.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <float.h>
#include <math.h>

static double dist(const double a[3], const double b[3]) {
  const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* The floor z = 0: the matrix is diag(1, 1, -1, 1). */
static void test_floor(void) {
  const double p[3] = {0, 0, 0}, n[3] = {0, 0, 7}, x[3] = {1, 2, 3};
  double plane[4], m[16], y[3];
  CHECK(vsh_reflect_plane(p, n, NULL, plane) == VSH_REFLECT_OK);
  CHECK(plane[0] == 0 && plane[1] == 0 && plane[2] == 1 && plane[3] == 0);
  CHECK(vsh_reflect_matrix(plane, m) == VSH_REFLECT_OK);
  for (int i = 0; i < 16; ++i) CHECK(m[i] == (i == 0 || i == 5 || i == 15 ? 1.0 : i == 10 ? -1.0 : 0.0));
  vsh_mat4_transform_point(m, x, y);
  CHECK(y[0] == 1 && y[1] == 2 && y[2] == -3);
  vsh_reflect_point(plane, x, y);
  CHECK(y[0] == 1 && y[1] == 2 && y[2] == -3);
  vsh_reflect_direction(plane, x, y);
  CHECK(y[0] == 1 && y[1] == 2 && y[2] == -3);
}

/* Random planes: R R = I, det R = -1, plane points fixed, distances to the
 * plane negated, distances between points kept, matrix = point function. */
static void test_random_planes(void) {
  vsh_test_seed(17);
  for (int round = 0; round < 500; ++round) {
    double p[3], n[3], plane[4], m[16], mm[16], a[3], b[3], ra[3], rb[3], q[3];
    for (int k = 0; k < 3; ++k) p[k] = vsh_test_rnd(-10, 10);
    vsh_test_rnd_unit(n);
    vsh_vec3_scale(n, vsh_test_rnd(1e-3, 1e3), n);
    CHECK(vsh_reflect_plane(p, n, NULL, plane) == VSH_REFLECT_OK);
    CHECK(vsh_reflect_matrix(plane, m) == VSH_REFLECT_OK);
    vsh_mat4_multiply(m, m, mm);
    for (int i = 0; i < 16; ++i) CHECK_NEAR(mm[i], i % 5 == 0 ? 1.0 : 0.0, 1e-13);
    CHECK_NEAR(vsh_mat4_determinant(m), -1.0, 1e-13);
    vsh_mat4_transform_point(m, p, q);
    CHECK(dist(p, q) < 1e-13 * 20);
    for (int k = 0; k < 3; ++k) {
      a[k] = vsh_test_rnd(-10, 10);
      b[k] = vsh_test_rnd(-10, 10);
    }
    vsh_mat4_transform_point(m, a, ra);
    vsh_reflect_point(plane, b, rb);
    CHECK_NEAR(vsh_reflect_side(plane, ra), -vsh_reflect_side(plane, a), 1e-12);
    CHECK_NEAR(dist(ra, rb), dist(a, b), 1e-12);
    vsh_reflect_point(plane, a, q);
    CHECK(dist(q, ra) < 1e-12);
  }
}

static void test_degenerate(void) {
  const double p[3] = {1, 2, 3}, zero[3] = {0, 0, 0}, tiny[3] = {0, 0, 1e-310};
  const double huge[3] = {1e300, 1e300, 0}, nan3[3] = {NAN, 0, 1}, inf3[3] = {0, INFINITY, 0};
  double plane[4] = {9, 9, 9, 9}, m[16];
  CHECK(vsh_reflect_plane(p, zero, NULL, plane) == VSH_REFLECT_DEGENERATE);
  CHECK(plane[0] == 0 && plane[1] == 0 && plane[2] == 0 && plane[3] == 0);
  /* A denormal normal still has a direction; scaled before squaring. */
  CHECK(vsh_reflect_plane(p, tiny, NULL, plane) == VSH_REFLECT_OK);
  CHECK(plane[2] == 1 && plane[3] == -3);
  CHECK(vsh_reflect_plane(p, huge, NULL, plane) == VSH_REFLECT_OK);
  CHECK_NEAR(plane[0], sqrt(0.5), 1e-15);
  CHECK(vsh_reflect_plane(p, nan3, NULL, plane) == VSH_REFLECT_INVALID);
  CHECK(vsh_reflect_plane(inf3, p, NULL, plane) == VSH_REFLECT_INVALID);
  CHECK(vsh_reflect_plane(p, p, inf3, plane) == VSH_REFLECT_INVALID);
  CHECK(vsh_reflect_plane(NULL, p, NULL, plane) == VSH_REFLECT_INVALID);
  CHECK(vsh_reflect_plane(p, p, NULL, NULL) == VSH_REFLECT_INVALID);
  {
    const double notunit[4] = {0, 0, 2, 0}, nanplane[4] = {0, 0, 1, NAN};
    CHECK(vsh_reflect_matrix(notunit, m) == VSH_REFLECT_DEGENERATE);
    for (int i = 0; i < 16; ++i) CHECK(m[i] == (i % 5 == 0 ? 1.0 : 0.0));
    CHECK(vsh_reflect_matrix(nanplane, m) == VSH_REFLECT_INVALID);
    CHECK(vsh_reflect_matrix(NULL, m) == VSH_REFLECT_INVALID);
    CHECK(vsh_reflect_matrix(nanplane, NULL) == VSH_REFLECT_INVALID);
  }
}

/* Which side the eye is on: above sees, below and in the plane do not;
 * grazing (just above at a large distance) still sees; the tolerance is
 * relative to the mirror's size. */
static void test_eye_side(void) {
  const double p[3] = {0, 0, 0}, n[3] = {0, 0, 1};
  const double above[3] = {0, -8, 5}, below[3] = {0, -8, -5}, on[3] = {100, 3, 0};
  const double grazing[3] = {0, -1000, 1}; /* 89.94 degrees from the normal */
  double plane[4], clip[4];
  vsh_reflect_plane(p, n, NULL, plane);
  CHECK(vsh_reflect_eye_sees(plane, above, 10, 1e-9) == 1);
  CHECK(vsh_reflect_eye_sees(plane, below, 10, 1e-9) == 0);
  CHECK(vsh_reflect_eye_sees(plane, on, 10, 1e-9) == 0);
  CHECK(vsh_reflect_eye_sees(plane, grazing, 10, 1e-9) == 1);
  {
    const double just[3] = {0, 0, 1e-12};
    CHECK(vsh_reflect_eye_sees(plane, just, 10, 1e-9) == 0);
    CHECK(vsh_reflect_eye_sees(plane, just, 1e-6, 1e-9) == 1); /* a tiny mirror */
  }
  CHECK(vsh_reflect_eye_sees(NULL, above, 10, 1e-9) == 0);
  /* Clip plane keeps the side away from the eye: the reflected sphere below
   * the floor, not a reflection brought up above it. */
  vsh_reflect_clip_plane(plane, above, clip);
  {
    const double mirrored[3] = {0, 0, -1.2}, front[3] = {0, 0, 1.2};
    CHECK(vsh_reflect_side(clip, mirrored) > 0);
    CHECK(vsh_reflect_side(clip, front) < 0);
  }
  vsh_reflect_clip_plane(plane, below, clip);
  CHECK(clip[2] == 1);
}

/* A floor at z = 1e6 + 0.25 seen from 5 units above: relative to the eye
 * the plane, matrix and reflected points carry the same digits as at the
 * origin; in world coordinates the translation 2e6 would eat them. */
static void test_offset(void) {
  const double off = 1e6;
  const double floor_pt[3] = {off + 3, off - 2, off + 0.25}, n[3] = {0, 0, 1};
  const double eye[3] = {off, off - 8, off + 5.25}, x[3] = {off + 0.1, off + 0.2, off + 1.45};
  double plane[4], m[16], rel[3], out[3], world_plane[4], wm[16], wout[3];
  CHECK(vsh_reflect_plane(floor_pt, n, eye, plane) == VSH_REFLECT_OK);
  CHECK(plane[3] == 5.0); /* the eye is 5 above: N.(eye - eye) + d = 5 */
  CHECK(vsh_reflect_eye_sees(plane, (const double[3]){0, 0, 0}, 10, 1e-9) == 1);
  CHECK(vsh_reflect_matrix(plane, m) == VSH_REFLECT_OK);
  for (int k = 0; k < 3; ++k) rel[k] = x[k] - eye[k];
  vsh_mat4_transform_point(m, rel, out);
  /* x is 1.2 above the floor: its image 1.2 below, i.e. 6.2 below the eye. */
  CHECK_NEAR(out[2], -6.2, 1e-9);
  CHECK_NEAR(out[0], 0.1, 1e-9);
  /* The world-coordinate matrix agrees to double rounding of 1e6, 1e-10 here. */
  CHECK(vsh_reflect_plane(floor_pt, n, NULL, world_plane) == VSH_REFLECT_OK);
  CHECK(vsh_reflect_matrix(world_plane, wm) == VSH_REFLECT_OK);
  CHECK_NEAR(wm[11], 2 * (off + 0.25), 0);
  vsh_mat4_transform_point(wm, x, wout);
  CHECK_NEAR(wout[2] - eye[2], -6.2, 1e-9);
  /* Relative results stay good at 1e15 where the world form cannot: */
  {
    const double far = 1e15, fp[3] = {far, far, far}, fe[3] = {far, far, far + 2};
    CHECK(vsh_reflect_plane(fp, n, fe, plane) == VSH_REFLECT_OK);
    CHECK(plane[3] == 2.0);
  }
}

int main(void) {
  test_floor();
  test_random_planes();
  test_degenerate();
  test_eye_side();
  test_offset();
  return vsh_check_report("core.reflect");
}
