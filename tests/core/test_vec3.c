/* test_vec3.c - unit tests of vsh_vec3: values, aliasing and every
 * degenerate input (zero, tiny, huge, NaN, Inf). */
#include "vsh_check.h"
#include "vsh_vec3.h"

#include <float.h>
#include <math.h>

static void test_basic(void) {
  const double a[3] = {1, 2, 3}, b[3] = {-4, 5, 0.5};
  double o[3];
  CHECK_NEAR(vsh_vec3_dot(a, b), -4 + 10 + 1.5, 0);
  vsh_vec3_cross(a, b, o);
  CHECK_NEAR(o[0], 2 * 0.5 - 3 * 5, 0);
  CHECK_NEAR(o[1], 3 * -4 - 1 * 0.5, 0);
  CHECK_NEAR(o[2], 1 * 5 - 2 * -4, 0);
  CHECK_NEAR(vsh_vec3_dot(o, a), 0, 1e-12);
  vsh_vec3_add(a, b, o);
  CHECK(o[0] == -3 && o[1] == 7 && o[2] == 3.5);
  vsh_vec3_sub(a, b, o);
  CHECK(o[0] == 5 && o[1] == -3 && o[2] == 2.5);
  vsh_vec3_scale(a, -2, o);
  CHECK(o[0] == -2 && o[1] == -4 && o[2] == -6);
  CHECK_NEAR(vsh_vec3_length(a), sqrt(14.0), 1e-15);
}

static void test_aliasing(void) {
  double a[3] = {1, 0, 0};
  const double b[3] = {0, 1, 0};
  vsh_vec3_cross(a, b, a); /* out == a */
  CHECK(a[0] == 0 && a[1] == 0 && a[2] == 1);
  double v[3] = {3, 4, 0};
  CHECK_NEAR(vsh_vec3_normalize(v, v), 5, 0);
  CHECK_NEAR(v[0], 0.6, 1e-16);
  CHECK_NEAR(v[1], 0.8, 1e-16);
  double c[3] = {1, 1, 1};
  vsh_vec3_lerp(c, b, 0.5, c);
  CHECK(c[0] == 0.5 && c[1] == 1 && c[2] == 0.5);
}

static void test_normalize_degenerate(void) {
  double o[3] = {7, 7, 7};
  const double zero[3] = {0, 0, 0};
  CHECK(vsh_vec3_normalize(zero, o) == 0.0);
  CHECK(o[0] == 0 && o[1] == 0 && o[2] == 0);

  const double nan3[3] = {NAN, 1, 0};
  o[0] = 7;
  CHECK(vsh_vec3_normalize(nan3, o) == 0.0);
  CHECK(o[0] == 0 && o[1] == 0 && o[2] == 0);

  /* A NaN after a finite largest component (the unscaled path's check). */
  const double nan_y[3] = {1, NAN, 0}, nan_z[3] = {2, 0, NAN};
  CHECK(vsh_vec3_normalize(nan_y, o) == 0.0);
  CHECK(o[0] == 0 && o[1] == 0 && o[2] == 0);
  CHECK(vsh_vec3_normalize(nan_z, o) == 0.0);
  CHECK(o[0] == 0 && o[1] == 0 && o[2] == 0);
  CHECK(isnan(vsh_vec3_length(nan_y)));

  /* Either side of the unscaled range's limits (1e150, 1e-150): the same
   * answer, and a component far below the largest one underflows harmlessly. */
  const double edges[6][3] = {{0.99e150, -0.99e150, 0.99e150}, {1.01e150, -1.01e150, 1.01e150},
                              {0.99e-150, 0.99e-150, 0.99e-150},
                              {1.01e-150, 1.01e-150, 1.01e-150}, {1.01e-150, 1e-170, 0},
                              {1e300, 1e300, 1e300}};
  for (int k = 0; k < 6; ++k) {
    const double m = fabs(edges[k][0]);
    const double expect = m * (edges[k][1] == 1e-170 ? 1.0 : sqrt(3.0));
    CHECK_NEAR(vsh_vec3_length(edges[k]) / expect, 1, 1e-15);
    CHECK_NEAR(vsh_vec3_normalize(edges[k], o) / expect, 1, 1e-15);
    CHECK_NEAR(o[0] * o[0] + o[1] * o[1] + o[2] * o[2], 1, 1e-15);
  }

  const double inf3[3] = {INFINITY, 0, 0};
  CHECK(vsh_vec3_normalize(inf3, o) == 0.0);
  CHECK(o[0] == 0 && o[1] == 0 && o[2] == 0);

  /* Huge and tiny components: naive sqrt(dot) would overflow / underflow. */
  const double huge[3] = {3e200, 4e200, 0};
  CHECK_NEAR(vsh_vec3_length(huge) / 5e200, 1, 1e-15);
  CHECK_NEAR(vsh_vec3_normalize(huge, o) / 5e200, 1, 1e-15);
  CHECK_NEAR(o[0], 0.6, 1e-15);
  CHECK_NEAR(o[1], 0.8, 1e-15);
  const double tiny[3] = {3e-200, 0, -4e-200};
  CHECK_NEAR(vsh_vec3_length(tiny) / 5e-200, 1, 1e-15);
  CHECK(vsh_vec3_normalize(tiny, o) > 0);
  CHECK_NEAR(o[0], 0.6, 1e-15);
  CHECK_NEAR(o[2], -0.8, 1e-15);
  const double denorm[3] = {DBL_TRUE_MIN, 0, 0};
  CHECK(vsh_vec3_normalize(denorm, o) > 0);
  CHECK(o[0] == 1 && o[1] == 0 && o[2] == 0);
  CHECK(vsh_vec3_is_finite(o));
}

static void test_lerp(void) {
  const double a[3] = {0.1, -1e6, 3}, b[3] = {0.7, 2e-9, -5};
  double o[3];
  vsh_vec3_lerp(a, b, 0, o);
  CHECK(o[0] == a[0] && o[1] == a[1] && o[2] == a[2]);
  vsh_vec3_lerp(a, b, 1, o);
  CHECK(o[0] == b[0] && o[1] == b[1] && o[2] == b[2]); /* exact at t = 1 */
  vsh_vec3_lerp(a, b, 0.25, o);
  CHECK_NEAR(o[2], 1, 1e-15);
}

static void test_parallel(void) {
  const double x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, zero[3] = {0, 0, 0};
  const double mx[3] = {-5, 0, 0}, nan3[3] = {NAN, 0, 0}, inf3[3] = {0, INFINITY, 0};
  CHECK(vsh_vec3_parallel(x, x, 0));
  CHECK(vsh_vec3_parallel(x, mx, 0)); /* anti-parallel counts */
  CHECK(!vsh_vec3_parallel(x, y, 1e-6));
  CHECK(vsh_vec3_parallel(x, zero, 1e-6));
  CHECK(vsh_vec3_parallel(zero, y, 1e-6));
  CHECK(vsh_vec3_parallel(zero, zero, 0));
  CHECK(vsh_vec3_parallel(x, nan3, 1e-6));
  CHECK(vsh_vec3_parallel(inf3, y, 1e-6));
  /* Threshold on the sine of the angle, independent of the lengths. */
  const double near_x[3] = {1, 1e-9, 0};
  CHECK(vsh_vec3_parallel(x, near_x, 2e-9));
  CHECK(!vsh_vec3_parallel(x, near_x, 0.5e-9));
  const double big[3] = {1e300, 1e291, 0}, small[3] = {1e-300, 0, 0};
  CHECK(vsh_vec3_parallel(big, small, 2e-9));
  CHECK(!vsh_vec3_parallel(big, small, 0.5e-9));
  const double sy[3] = {0, 1e-300, 0};
  CHECK(!vsh_vec3_parallel(big, sy, 1e-6));
}

static void test_finite(void) {
  const double ok[3] = {1, DBL_MAX, -DBL_MAX}, n[3] = {0, 0, NAN}, i[3] = {-INFINITY, 0, 0};
  CHECK(vsh_vec3_is_finite(ok));
  CHECK(!vsh_vec3_is_finite(n));
  CHECK(!vsh_vec3_is_finite(i));
}

int main(void) {
  test_basic();
  test_aliasing();
  test_normalize_degenerate();
  test_lerp();
  test_parallel();
  test_finite();
  return vsh_check_report("core.vec3");
}
