/* vsh_mat4.c - see vsh_mat4.h. */
#include "vsh_mat4.h"

#include <math.h>
#include <string.h>

void vsh_mat4_identity(double out[16]) {
  memset(out, 0, 16 * sizeof(double));
  out[0] = out[5] = out[10] = out[15] = 1.0;
}

void vsh_mat4_multiply(const double a[16], const double b[16], double out[16]) {
  double r[16];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      r[i * 4 + j] = a[i * 4 + 0] * b[0 * 4 + j] + a[i * 4 + 1] * b[1 * 4 + j] +
                     a[i * 4 + 2] * b[2 * 4 + j] + a[i * 4 + 3] * b[3 * 4 + j];
  memcpy(out, r, sizeof r);
}

void vsh_mat4_transform_point4(const double m[16], const double in4[4], double out4[4]) {
  double r[4];
  for (int i = 0; i < 4; ++i)
    r[i] = m[i * 4 + 0] * in4[0] + m[i * 4 + 1] * in4[1] + m[i * 4 + 2] * in4[2] +
           m[i * 4 + 3] * in4[3];
  memcpy(out4, r, sizeof r);
}

double vsh_mat4_transform_point(const double m[16], const double p3[3], double out3[3]) {
  const double in4[4] = {p3[0], p3[1], p3[2], 1.0};
  double r[4];
  vsh_mat4_transform_point4(m, in4, r);
  const double w = r[3];
  if (w != 0.0) {
    const double x = r[0] / w, y = r[1] / w, z = r[2] / w;
    /* Only divide when the quotient is representable; a finite point with a
     * denormal w would otherwise become Inf. */
    if (isfinite(x) && isfinite(y) && isfinite(z)) {
      out3[0] = x;
      out3[1] = y;
      out3[2] = z;
      return w;
    }
  }
  out3[0] = r[0];
  out3[1] = r[1];
  out3[2] = r[2];
  return w;
}

void vsh_mat4_transform_direction(const double m[16], const double d[3], double out3[3]) {
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = m[i * 4 + 0] * d[0] + m[i * 4 + 1] * d[1] + m[i * 4 + 2] * d[2];
  memcpy(out3, r, sizeof r);
}

void vsh_mat4_transpose(const double m[16], double out[16]) {
  double r[16];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[j * 4 + i] = m[i * 4 + j];
  memcpy(out, r, sizeof r);
}

/* det of the 3x3 minor made of rows r0<r1<r2 and columns c0<c1<c2. */
static double det3(const double m[16], int r0, int r1, int r2, int c0, int c1, int c2) {
#define E(r, c) m[(r) * 4 + (c)]
  return E(r0, c0) * (E(r1, c1) * E(r2, c2) - E(r1, c2) * E(r2, c1)) -
         E(r0, c1) * (E(r1, c0) * E(r2, c2) - E(r1, c2) * E(r2, c0)) +
         E(r0, c2) * (E(r1, c0) * E(r2, c1) - E(r1, c1) * E(r2, c0));
#undef E
}

double vsh_mat4_determinant(const double m[16]) {
  /* Expansion along the first row. */
  return m[0] * det3(m, 1, 2, 3, 1, 2, 3) - m[1] * det3(m, 1, 2, 3, 0, 2, 3) +
         m[2] * det3(m, 1, 2, 3, 0, 1, 3) - m[3] * det3(m, 1, 2, 3, 0, 1, 2);
}

/* Power-of-two exponent e such that x * 2^-e has magnitude in [0.5, 1). */
static int exponent_of(double x) {
  int e = 0;
  (void)frexp(x, &e);
  return e;
}

int vsh_mat4_inverse(const double m[16], double out[16]) {
  double s[16];
  int row_e[4], col_e[4];

  if (!vsh_mat4_is_finite(m)) {
    vsh_mat4_identity(out);
    return 0;
  }
  memcpy(s, m, sizeof s);

  /* Equilibrate rows, then columns, by exact powers of two. */
  for (int i = 0; i < 4; ++i) {
    double mx = 0.0;
    for (int j = 0; j < 4; ++j) mx = fmax(mx, fabs(s[i * 4 + j]));
    if (mx == 0.0) {
      vsh_mat4_identity(out);
      return 0;
    }
    row_e[i] = exponent_of(mx);
    for (int j = 0; j < 4; ++j) s[i * 4 + j] = ldexp(s[i * 4 + j], -row_e[i]);
  }
  for (int j = 0; j < 4; ++j) {
    double mx = 0.0;
    for (int i = 0; i < 4; ++i) mx = fmax(mx, fabs(s[i * 4 + j]));
    if (mx == 0.0) {
      vsh_mat4_identity(out);
      return 0;
    }
    col_e[j] = exponent_of(mx);
    for (int i = 0; i < 4; ++i) s[i * 4 + j] = ldexp(s[i * 4 + j], -col_e[j]);
  }

  /* Relative singularity test on the equilibrated matrix. */
  double hadamard = 1.0;
  for (int i = 0; i < 4; ++i) {
    double n2 = 0.0;
    for (int j = 0; j < 4; ++j) n2 += s[i * 4 + j] * s[i * 4 + j];
    hadamard *= sqrt(n2);
  }
  if (!(fabs(vsh_mat4_determinant(s)) > VSH_MAT4_SINGULAR_TOL * hadamard)) {
    vsh_mat4_identity(out);
    return 0;
  }

  /* Gauss-Jordan with partial pivoting: [S | I] -> [I | S^-1]. */
  double inv[16];
  vsh_mat4_identity(inv);
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (fabs(s[r * 4 + c]) > fabs(s[p * 4 + c])) p = r;
    if (s[p * 4 + c] == 0.0) { /* cannot happen after the test above */
      vsh_mat4_identity(out);
      return 0;
    }
    if (p != c) {
      for (int j = 0; j < 4; ++j) {
        double t = s[c * 4 + j];
        s[c * 4 + j] = s[p * 4 + j];
        s[p * 4 + j] = t;
        t = inv[c * 4 + j];
        inv[c * 4 + j] = inv[p * 4 + j];
        inv[p * 4 + j] = t;
      }
    }
    const double piv = s[c * 4 + c];
    for (int j = 0; j < 4; ++j) {
      s[c * 4 + j] /= piv;
      inv[c * 4 + j] /= piv;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double f = s[r * 4 + c];
      if (f == 0.0) continue;
      for (int j = 0; j < 4; ++j) {
        s[r * 4 + j] -= f * s[c * 4 + j];
        inv[r * 4 + j] -= f * inv[c * 4 + j];
      }
    }
  }

  /* S = R m C with R = diag(2^-row_e), C = diag(2^-col_e), so
   * m^-1 = C S^-1 R: scale row i of S^-1 by 2^-col_e[i], column j by 2^-row_e[j]. */
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) inv[i * 4 + j] = ldexp(inv[i * 4 + j], -col_e[i] - row_e[j]);

  if (!vsh_mat4_is_finite(inv)) { /* inverse out of double range */
    vsh_mat4_identity(out);
    return 0;
  }
  memcpy(out, inv, sizeof inv);
  return 1;
}

void vsh_mat4_translation(const double t[3], double out[16]) {
  vsh_mat4_identity(out);
  out[3] = t[0];
  out[7] = t[1];
  out[11] = t[2];
}

void vsh_mat4_scale(const double s[3], double out[16]) {
  vsh_mat4_identity(out);
  out[0] = s[0];
  out[5] = s[1];
  out[10] = s[2];
}

int vsh_mat4_is_finite(const double m[16]) {
  for (int i = 0; i < 16; ++i)
    if (!isfinite(m[i])) return 0;
  return 1;
}
