/* test_flat_parts.c - unit tests of vsh_flat_parts: a box's six faces, a
 * thin slab's top and bottom, a sphere with none, a stair's treads, a face
 * whose normals straddle a quantization step, far from the origin and tiny,
 * degenerate triangles, the max_parts limit, and bad input. */
#include "vsh_check.h"
#include "vsh_flat_parts.h"

#include <math.h>
#include <stdlib.h>

#define NT 1e-4 /* normal tolerance the VTK layer uses */
#define RT 1e-5 /* offset tolerance, relative to the mesh size */
#define PI 3.14159265358979323846

/* An axis-aligned box as 12 triangles (8 corners). */
static void box(const double lo[3], const double hi[3], double pts[24], long long tris[36]) {
  for (int i = 0; i < 8; ++i) {
    pts[3 * i + 0] = (i & 1) ? hi[0] : lo[0];
    pts[3 * i + 1] = (i & 2) ? hi[1] : lo[1];
    pts[3 * i + 2] = (i & 4) ? hi[2] : lo[2];
  }
  /* Each face as two triangles, wound outwards. */
  static const long long faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                        {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (int f = 0; f < 6; ++f) {
    const long long *q = faces[f];
    const long long t[6] = {q[0], q[2], q[1], q[0], q[3], q[2]};
    for (int k = 0; k < 6; ++k) tris[6 * f + k] = t[k];
  }
}

static void test_box(void) {
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 2, 3};
  double pts[24];
  long long tris[36];
  box(lo, hi, pts, tris);
  vsh_flat_part parts[8];
  const int n = vsh_flat_parts(pts, 8, tris, 12, NT, RT, 0.05, parts, 8);
  CHECK(n == 6);
  /* Largest first: the two 2x3 faces (x = 0 and x = 1). */
  CHECK_NEAR(parts[0].area, 6.0, 1e-12);
  CHECK_NEAR(fabs(parts[0].plane[0]), 1.0, 1e-12);
  double total = 0.0;
  for (int i = 0; i < n; ++i) total += parts[i].area;
  CHECK_NEAR(total, 2 * (2 + 3 + 6), 1e-12);
  /* Normals face outwards: the top (z = 3) has N = +z, d = -3. */
  int top = 0;
  for (int i = 0; i < n; ++i) {
    if (parts[i].plane[2] > 0.5) {
      top = 1;
      CHECK_NEAR(parts[i].plane[3], -3.0, 1e-12);
    }
  }
  CHECK(top);
  /* max_parts keeps the largest. */
  CHECK(vsh_flat_parts(pts, 8, tris, 12, NT, RT, 0.05, parts, 2) == 2);
  CHECK_NEAR(parts[1].area, 6.0, 1e-12);
}

static void test_slab(void) {
  /* A 4 x 4 x 0.05 floor slab: its top and bottom are 48 % each, the sides
   * 0.6 % each: only top and bottom are parts. */
  const double lo[3] = {-2, -2, -0.05}, hi[3] = {2, 2, 0};
  double pts[24];
  long long tris[36];
  box(lo, hi, pts, tris);
  vsh_flat_part parts[8];
  const int n = vsh_flat_parts(pts, 8, tris, 12, NT, RT, 0.05, parts, 8);
  CHECK(n == 2);
  CHECK_NEAR(fabs(parts[0].plane[2]), 1.0, 1e-12);
  CHECK_NEAR(fabs(parts[1].plane[2]), 1.0, 1e-12);
}

/* A UV sphere: no plane holds 5 % of it. */
static void test_sphere(void) {
  enum { NU = 24, NV = 12 };
  static double pts[3 * (NU * (NV + 1))];
  static long long tris[6 * NU * NV];
  int np = 0, nt = 0;
  for (int v = 0; v <= NV; ++v) {
    for (int u = 0; u < NU; ++u) {
      const double th = PI * v / NV, ph = 2 * PI * u / NU;
      pts[3 * np + 0] = sin(th) * cos(ph);
      pts[3 * np + 1] = sin(th) * sin(ph);
      pts[3 * np + 2] = cos(th);
      ++np;
    }
  }
  for (int v = 0; v < NV; ++v) {
    for (int u = 0; u < NU; ++u) {
      const long long a = v * NU + u, b = v * NU + (u + 1) % NU, c = a + NU, d = b + NU;
      const long long t[6] = {a, c, b, b, c, d};
      for (int k = 0; k < 6; ++k) tris[3 * nt + k] = t[k];
      nt += 2;
    }
  }
  vsh_flat_part parts[8];
  /* The pole rows are zero-area triangles (coincident points): skipped. */
  CHECK(vsh_flat_parts(pts, (size_t)np, tris, (size_t)nt, NT, RT, 0.05, parts, 8) == 0);
}

/* Two treads at z = 0 and z = 1 with a riser: the treads are the parts. */
static void test_stair(void) {
  const double pts[] = {0, 0, 0, 2, 0, 0, 2, 4, 0, 0, 4, 0,   /* tread 1 */
                        2, 0, 0, 2, 4, 0, 2, 4, 1, 2, 0, 1,   /* riser */
                        2, 0, 1, 4, 0, 1, 4, 4, 1, 2, 4, 1};  /* tread 2 */
  const long long tris[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11};
  vsh_flat_part parts[4];
  const int n = vsh_flat_parts(pts, 12, tris, 6, NT, RT, 0.3, parts, 4);
  CHECK(n == 2);
  CHECK_NEAR(parts[0].area, 8.0, 1e-12);
  CHECK_NEAR(parts[1].area, 8.0, 1e-12);
  CHECK_NEAR(parts[0].plane[2] * parts[1].plane[2], 1.0, 1e-12);
}

/* One face whose triangles' normals fall on both sides of a quantization
 * step (tilted by atan(0.5e-4 +- 1e-9)): still one part. */
static void test_split_face(void) {
  enum { N = 20 };
  static double pts[3 * 3 * N];
  static long long tris[3 * N];
  const double tilt = 0.5 * NT;
  for (int i = 0; i < N; ++i) {
    const double jitter = (i % 2 ? 1e-9 : -1e-9);
    const double x0 = i, s = tilt + jitter;
    const double p[9] = {x0, 0, s * x0, x0 + 1, 0, s * (x0 + 1), x0, 1, s * x0};
    for (int k = 0; k < 9; ++k) pts[9 * i + k] = p[k];
    for (int k = 0; k < 3; ++k) tris[3 * i + k] = 3 * i + k;
  }
  vsh_flat_part parts[4];
  const int n = vsh_flat_parts(pts, 3 * N, tris, N, NT, RT, 0.3, parts, 4);
  CHECK(n == 1);
  CHECK_NEAR(parts[0].area, N * 0.5 * sqrt(1 + tilt * tilt), 1e-6);
}

/* The box far from the origin and at 1e-6 scale: six parts still. */
static void test_scale(void) {
  const double offsets[2] = {1e6, 0.0}, sizes[2] = {1.0, 1e-6};
  for (int c = 0; c < 2; ++c) {
    const double lo[3] = {offsets[c], offsets[c], offsets[c]};
    const double hi[3] = {lo[0] + sizes[c], lo[1] + 2 * sizes[c], lo[2] + 3 * sizes[c]};
    double pts[24];
    long long tris[36];
    box(lo, hi, pts, tris);
    vsh_flat_part parts[8];
    CHECK(vsh_flat_parts(pts, 8, tris, 12, NT, RT, 0.05, parts, 8) == 6);
  }
}

static void test_degenerate_and_bad(void) {
  const double pts[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, NAN, 0, 0};
  const long long collinear[] = {0, 1, 2, 0, 0, 1};
  vsh_flat_part parts[4];
  CHECK(vsh_flat_parts(pts, 3, collinear, 2, NT, RT, 0.05, parts, 4) == 0);
  CHECK(vsh_flat_parts(pts, 3, NULL, 0, NT, RT, 0.05, parts, 4) == 0);
  CHECK(vsh_flat_parts(pts, 3, collinear, 2, NT, RT, 0.05, parts, 0) == 0);
  const long long out_of_range[] = {0, 1, 7};
  CHECK(vsh_flat_parts(pts, 3, out_of_range, 1, NT, RT, 0.05, parts, 4) == -1);
  const long long negative[] = {0, -1, 2};
  CHECK(vsh_flat_parts(pts, 3, negative, 1, NT, RT, 0.05, parts, 4) == -1);
  CHECK(vsh_flat_parts(pts, 4, collinear, 2, NT, RT, 0.05, parts, 4) == -1); /* NaN */
  CHECK(vsh_flat_parts(NULL, 3, collinear, 2, NT, RT, 0.05, parts, 4) == -1);
  CHECK(vsh_flat_parts(pts, 3, NULL, 2, NT, RT, 0.05, parts, 4) == -1);
  CHECK(vsh_flat_parts(pts, 3, collinear, 2, -1.0, RT, 0.05, parts, 4) == -1);
  CHECK(vsh_flat_parts(pts, 3, collinear, 2, NT, NAN, 0.05, parts, 4) == -1);
  CHECK(vsh_flat_parts(pts, 3, collinear, 2, NT, RT, -0.1, parts, 4) == -1);
  CHECK(vsh_flat_parts(pts, 3, collinear, 2, NT, RT, 0.05, NULL, 4) == -1);
}

int main(void) {
  test_box();
  test_slab();
  test_sphere();
  test_stair();
  test_split_face();
  test_scale();
  test_degenerate_and_bad();
  return vsh_check_report("test_flat_parts");
}
