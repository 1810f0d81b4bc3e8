/* test_mat4.c - unit tests of vsh_mat4: layout convention, products,
 * inverse with its relative singularity test, w handling. */
#include "vsh_check.h"
#include "vsh_mat4.h"

#include <float.h>
#include <math.h>
#include <string.h>

static double max_abs_diff(const double a[16], const double b[16]) {
  double m = 0;
  for (int k = 0; k < 16; ++k) m = fmax(m, fabs(a[k] - b[k]));
  return m;
}

static void check_identity(const double m[16], double tol) {
  double id[16];
  vsh_mat4_identity(id);
  CHECK(max_abs_diff(m, id) <= tol);
}

static void test_layout(void) {
  /* Row-major, column vectors: the translation sits in m[3], m[7], m[11]
   * exactly as in vtkMatrix4x4::Element[0][3], [1][3], [2][3]. */
  const double t[3] = {10, 20, 30};
  double m[16], p[3];
  vsh_mat4_translation(t, m);
  CHECK(m[3] == 10 && m[7] == 20 && m[11] == 30 && m[15] == 1 && m[12] == 0);
  const double o[3] = {1, 2, 3};
  CHECK(vsh_mat4_transform_point(m, o, p) == 1.0);
  CHECK(p[0] == 11 && p[1] == 22 && p[2] == 33);
  vsh_mat4_transform_direction(m, o, p);
  CHECK(p[0] == 1 && p[1] == 2 && p[2] == 3); /* directions ignore translation */

  const double s[3] = {2, -3, 0.5};
  vsh_mat4_scale(s, m);
  vsh_mat4_transform_direction(m, o, p);
  CHECK(p[0] == 2 && p[1] == -6 && p[2] == 1.5);
}

static void test_multiply_order(void) {
  /* out = a * b applies b first: translate then scale != scale then translate. */
  const double t[3] = {1, 0, 0}, s[3] = {2, 2, 2}, o[3] = {0, 0, 0};
  double T[16], S[16], ST[16], TS[16], p[3];
  vsh_mat4_translation(t, T);
  vsh_mat4_scale(s, S);
  vsh_mat4_multiply(S, T, ST);
  vsh_mat4_multiply(T, S, TS);
  vsh_mat4_transform_point(ST, o, p);
  CHECK(p[0] == 2);
  vsh_mat4_transform_point(TS, o, p);
  CHECK(p[0] == 1);
  /* aliasing out == a */
  vsh_mat4_multiply(S, T, S);
  CHECK(max_abs_diff(S, ST) == 0);

  double M[16], MT[16], MTT[16];
  for (int k = 0; k < 16; ++k) M[k] = k * 0.5 - 3;
  vsh_mat4_transpose(M, MT);
  CHECK(MT[1] == M[4] && MT[4] == M[1] && MT[11] == M[14]);
  vsh_mat4_transpose(MT, MTT);
  CHECK(max_abs_diff(M, MTT) == 0);
  vsh_mat4_transpose(M, M); /* in place */
  CHECK(max_abs_diff(M, MT) == 0);
}

static void test_point4_and_w(void) {
  /* A projective matrix: w = z. */
  double P[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  const double in4[4] = {2, 4, 8, 1};
  double o4[4], o3[3];
  vsh_mat4_transform_point4(P, in4, o4);
  CHECK(o4[0] == 2 && o4[1] == 4 && o4[2] == 8 && o4[3] == 8);
  const double p[3] = {2, 4, 8};
  CHECK(vsh_mat4_transform_point(P, p, o3) == 8);
  CHECK(o3[0] == 0.25 && o3[1] == 0.5 && o3[2] == 1);
  /* w == 0: no division, undivided xyz, never Inf/NaN. */
  const double pz[3] = {2, 4, 0};
  CHECK(vsh_mat4_transform_point(P, pz, o3) == 0);
  CHECK(o3[0] == 2 && o3[1] == 4 && o3[2] == 0);
  /* denormal w: quotient would overflow -> undivided. */
  const double pd[3] = {1e300, 1, DBL_TRUE_MIN};
  const double w = vsh_mat4_transform_point(P, pd, o3);
  CHECK(w == DBL_TRUE_MIN);
  CHECK(o3[0] == 1e300 && isfinite(o3[1]) && isfinite(o3[2]));
  /* negative w divides normally (caller decides what w < 0 means) */
  const double pn[3] = {2, 4, -2};
  CHECK(vsh_mat4_transform_point(P, pn, o3) == -2);
  CHECK(o3[0] == -1 && o3[1] == -2 && o3[2] == 1);
}

static void test_determinant(void) {
  const double s[3] = {2, 3, 4}, t[3] = {1e6, -1e6, 5};
  double S[16], T[16], M[16];
  vsh_mat4_scale(s, S);
  CHECK_NEAR(vsh_mat4_determinant(S), 24, 0);
  vsh_mat4_translation(t, T);
  CHECK_NEAR(vsh_mat4_determinant(T), 1, 0);
  vsh_mat4_multiply(T, S, M);
  CHECK_NEAR(vsh_mat4_determinant(M), 24, 1e-9);
  /* A row swap flips the sign. */
  double W[16];
  vsh_mat4_identity(W);
  W[0] = 0; W[1] = 1; W[4] = 1; W[5] = 0;
  CHECK_NEAR(vsh_mat4_determinant(W), -1, 0);
}

static void test_inverse_general(void) {
  const double M[16] = {2, -1, 0, 3, 1, 4, -2, 0, 0.5, 0, 1, -1, 0.1, 0.2, 0.3, 1};
  double inv[16], prod[16];
  CHECK(vsh_mat4_inverse(M, inv) == 1);
  vsh_mat4_multiply(M, inv, prod);
  check_identity(prod, 1e-14);
  vsh_mat4_multiply(inv, M, prod);
  check_identity(prod, 1e-14);
  CHECK_NEAR(vsh_mat4_determinant(M) * vsh_mat4_determinant(inv), 1, 1e-13);
  /* aliasing */
  double A[16];
  memcpy(A, M, sizeof A);
  CHECK(vsh_mat4_inverse(A, A) == 1);
  CHECK(max_abs_diff(A, inv) == 0);
}

static void test_inverse_scales(void) {
  double M[16], inv[16], prod[16];
  /* Huge translations (1e6, 1e12): invertible and exact. */
  const double offs[2] = {1e6, 1e12};
  for (int k = 0; k < 2; ++k) {
    const double t[3] = {offs[k], -offs[k], 3 * offs[k]};
    vsh_mat4_translation(t, M);
    CHECK(vsh_mat4_inverse(M, inv) == 1);
    CHECK(inv[3] == -t[0] && inv[7] == -t[1] && inv[11] == -t[2]);
    CHECK(inv[0] == 1 && inv[5] == 1 && inv[10] == 1 && inv[15] == 1);
  }
  /* Tiny and mixed scales: the relative test accepts them. */
  const double tiny[3] = {1e-6, 1e-9, 1e-12};
  vsh_mat4_scale(tiny, M);
  CHECK(vsh_mat4_inverse(M, inv) == 1);
  CHECK_NEAR(inv[0], 1e6, 1e-9);
  CHECK_NEAR(inv[5] * 1e-9, 1, 1e-15);
  CHECK_NEAR(inv[10] * 1e-12, 1, 1e-15);
  /* A perspective projection with near 1e-3, far 1e6 (depth range 1e9). */
  const double c = 1.0 / tan(0.25), n = 1e-3, f = 1e6;
  const double Pm[16] = {c, 0, 0, 0, 0, c, 0, 0, 0, 0, -(f + n) / (f - n), -2 * f * n / (f - n),
                         0, 0, -1, 0};
  CHECK(vsh_mat4_inverse(Pm, inv) == 1);
  vsh_mat4_multiply(Pm, inv, prod);
  check_identity(prod, 1e-12);
  /* Scaled singular stays singular: scale-invariance of the test. */
  const double rank3[16] = {1e-8, 2e-8, 3e-8, 0, 4e-8, 5e-8, 6e-8, 0, 7e-8, 8e-8, 9e-8, 0, 0, 0, 0, 1e-8};
  CHECK(vsh_mat4_inverse(rank3, inv) == 0);
}

static void test_inverse_singular(void) {
  double inv[16];
  double Z[16] = {0};
  CHECK(vsh_mat4_inverse(Z, inv) == 0);
  check_identity(inv, 0); /* defined output, no NaN */
  /* Zero column. */
  const double zs[3] = {1, 0, 1};
  double S[16];
  vsh_mat4_scale(zs, S);
  CHECK(vsh_mat4_inverse(S, inv) == 0);
  check_identity(inv, 0);
  /* Two equal rows. */
  const double R[16] = {1, 2, 3, 4, 1, 2, 3, 4, 0, 1, 0, 1, 5, 0, 0, 1};
  CHECK(vsh_mat4_inverse(R, inv) == 0);
  /* Nearly singular: rows differ by 1e-15 relative -> singular. */
  const double N[16] = {1, 2, 3, 4, 1, 2, 3, 4 + 4e-15, 0, 1, 0, 1, 5, 0, 0, 1};
  CHECK(vsh_mat4_inverse(N, inv) == 0);
  /* ... but 1e-6 relative is invertible. */
  const double N2[16] = {1, 2, 3, 4, 1, 2, 3, 4 + 4e-6, 0, 1, 0, 1, 5, 0, 0, 1};
  CHECK(vsh_mat4_inverse(N2, inv) == 1);
  /* A flattening (shadow-like) projection y -> 0 has rank 3. */
  const double flat[16] = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1}; /* y -> 0 */
  CHECK(vsh_mat4_inverse(flat, inv) == 0);
  /* Non-finite input. */
  double B[16];
  vsh_mat4_identity(B);
  B[6] = NAN;
  CHECK(vsh_mat4_inverse(B, inv) == 0);
  check_identity(inv, 0);
  B[6] = INFINITY;
  CHECK(vsh_mat4_inverse(B, inv) == 0);
  /* Inverse out of range (1e-300 scale -> 1e300 * 1e300). */
  const double t2[3] = {1e-300, 1e-300, 1e-300};
  vsh_mat4_scale(t2, S);
  S[15] = 1e-300;
  S[0] = 1e-310;
  CHECK(vsh_mat4_inverse(S, inv) == 0 || vsh_mat4_is_finite(inv));
}

static void test_is_finite(void) {
  double m[16];
  vsh_mat4_identity(m);
  CHECK(vsh_mat4_is_finite(m));
  m[15] = -INFINITY;
  CHECK(!vsh_mat4_is_finite(m));
  m[15] = 1;
  m[0] = NAN;
  CHECK(!vsh_mat4_is_finite(m));
}

int main(void) {
  test_layout();
  test_multiply_order();
  test_point4_and_w();
  test_determinant();
  test_inverse_general();
  test_inverse_scales();
  test_inverse_singular();
  test_is_finite();
  return vsh_check_report("core.mat4");
}
