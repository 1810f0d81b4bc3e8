/* test_planar.c - unit tests of vsh_planar: the shadow matrix against the
 * closed form on seeded random scenes, every degenerate light/plane case,
 * clipping (w <= 0, caster behind the receiver) and the precision of the
 * camera-relative form at 1e6 / 1e12 offsets and 1e-6 scale. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_planar.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* ---- helpers ------------------------------------------------------------ */

static int all_zero(const double *m, int n) {
  for (int k = 0; k < n; ++k)
    if (m[k] != 0.0) return 0;
  return 1;
}

static double plane_eval(const double pi[4], const double p[3]) {
  return pi[0] * p[0] + pi[1] * p[1] + pi[2] * p[2] + pi[3];
}

/* Closed form for a point light: P' = L + ((E - L).N / ((P - L).N)) (P - L),
 * E any point on the plane. */
static void closed_form_point(const double N[3], const double E[3], const double L[3],
                              const double P[3], double out[3]) {
  double el[3], pl[3];
  vsh_vec3_sub(E, L, el);
  vsh_vec3_sub(P, L, pl);
  const double t = vsh_vec3_dot(el, N) / vsh_vec3_dot(pl, N);
  for (int k = 0; k < 3; ++k) out[k] = L[k] + t * pl[k];
}

/* Closed form for a directional light travelling along D: P' = P + s D with
 * (P + s D - E).N = 0. */
static void closed_form_dir(const double N[3], const double E[3], const double D[3],
                            const double P[3], double out[3]) {
  double ep[3];
  vsh_vec3_sub(E, P, ep);
  const double s = vsh_vec3_dot(ep, N) / vsh_vec3_dot(D, N);
  for (int k = 0; k < 3; ++k) out[k] = P[k] + s * D[k];
}

static double dist3(const double a[3], const double b[3]) {
  double d[3];
  vsh_vec3_sub(a, b, d);
  return vsh_vec3_length(d);
}

/* ---- the matrix itself ---------------------------------------------------- */

static void test_ground_plane_by_hand(void) {
  const double plane[4] = {0, 0, 1, 0}, light[4] = {0, 0, 10, 1};
  double M[16], out[3];
  CHECK(vsh_planar_shadow_matrix(plane, light, M) == VSH_PLANAR_OK);
  /* M = (pi.l) I - l pi^T with pi.l = 10. */
  const double expect[16] = {10, 0, 0, 0, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, -1, 10};
  for (int k = 0; k < 16; ++k) CHECK_NEAR(M[k], expect[k], 0);
  const double P[3] = {1, 0, 5}; /* halfway up: shadow twice as far out */
  CHECK(vsh_planar_project_point(M, P, out) == 1);
  CHECK(out[0] == 2 && out[1] == 0 && out[2] == 0);
  /* A point on the plane is its own shadow. */
  const double Q[3] = {3, -4, 0};
  CHECK(vsh_planar_project_point(M, Q, out) == 1);
  CHECK(out[0] == 3 && out[1] == -4 && out[2] == 0);
  /* Scaling the inputs changes nothing: (0,0,2,0) and (0,0,20,2). */
  const double plane2[4] = {0, 0, 2, 0}, light2[4] = {0, 0, 20, 2};
  double M2[16];
  CHECK(vsh_planar_shadow_matrix(plane2, light2, M2) == VSH_PLANAR_OK);
  for (int k = 0; k < 16; ++k) CHECK_NEAR(M2[k], M[k], 1e-15);
  /* Negative homogeneous w (-L, -1) is the same point light. */
  const double light3[4] = {0, 0, -10, -1};
  CHECK(vsh_planar_shadow_matrix(plane, light3, M2) == VSH_PLANAR_OK);
  for (int k = 0; k < 16; ++k) CHECK_NEAR(M2[k], M[k], 0);
  /* Directional straight down, any length: M = I with z flattened. */
  const double sun[4] = {0, 0, 3, 0}; /* = -D for D = (0,0,-3) */
  CHECK(vsh_planar_shadow_matrix(plane, sun, M) == VSH_PLANAR_OK);
  const double P2[3] = {1, 2, 7};
  CHECK(vsh_planar_project_point(M, P2, out) == 1);
  CHECK(out[0] == 1 && out[1] == 2 && out[2] == 0);
}

static void test_random_point_lights(void) {
  int checked = 0, clipped_ok = 1;
  double worst_rel = 0, worst_on_plane = 0;
  for (int s = 0; s < 2000; ++s) {
    double N[3], E[3], L[3], P[3], M[16], got[3], want[3];
    vsh_test_rnd_unit(N);
    for (int k = 0; k < 3; ++k) E[k] = vsh_test_rnd(-10, 10);
    const double d = -vsh_vec3_dot(N, E);
    const double scale = vsh_test_rnd(0.5, 3); /* pass an unnormalized plane */
    const double plane[4] = {N[0] * scale, N[1] * scale, N[2] * scale, d * scale};
    const double h = vsh_test_rnd(0.5, 20);
    for (int k = 0; k < 3; ++k) L[k] = E[k] + vsh_test_rnd(-5, 5) + h * N[k];
    if (plane_eval((double[4]){N[0], N[1], N[2], d}, L) < 0.1) continue;
    const double light[4] = {L[0], L[1], L[2], 1};
    CHECK(vsh_planar_shadow_matrix(plane, light, M) == VSH_PLANAR_OK);
    for (int k = 0; k < 3; ++k) P[k] = vsh_test_rnd(-15, 15);
    const double hl = plane_eval((double[4]){N[0], N[1], N[2], d}, L);
    const double hp = plane_eval((double[4]){N[0], N[1], N[2], d}, P);
    const int projected = vsh_planar_project_point(M, P, got);
    /* Clipped exactly when P is at or above the light's height (w <= 0),
     * away from the boundary where rounding decides. */
    if (fabs(hl - hp) > 1e-9) clipped_ok &= (projected == (hp < hl));
    if (!projected || hl - hp < 0.05) continue; /* far shadows are ill-conditioned */
    closed_form_point(N, E, L, P, want);
    const double size = fmax(1, vsh_vec3_length(want));
    worst_rel = fmax(worst_rel, dist3(got, want) / size);
    worst_on_plane = fmax(worst_on_plane, fabs(vsh_vec3_dot(N, got) + d) / size);
    ++checked;
  }
  CHECK(checked > 1000);
  CHECK(clipped_ok);
  CHECK(worst_rel < 1e-11);
  CHECK(worst_on_plane < 1e-12);
}

static void test_random_directional(void) {
  int checked = 0;
  double worst_rel = 0, worst_on_plane = 0;
  for (int s = 0; s < 2000; ++s) {
    double N[3], E[3], D[3], P[3], M[16], got[3], want[3];
    vsh_test_rnd_unit(N);
    vsh_test_rnd_unit(D);
    if (vsh_vec3_dot(D, N) > -0.05) continue; /* must travel toward the lit face */
    for (int k = 0; k < 3; ++k) E[k] = vsh_test_rnd(-10, 10);
    const double d = -vsh_vec3_dot(N, E);
    const double plane[4] = {N[0], N[1], N[2], d};
    const double len = vsh_test_rnd(0.1, 10);
    const double light[4] = {-D[0] * len, -D[1] * len, -D[2] * len, 0};
    CHECK(vsh_planar_shadow_matrix(plane, light, M) == VSH_PLANAR_OK);
    for (int k = 0; k < 3; ++k) P[k] = vsh_test_rnd(-15, 15);
    CHECK(vsh_planar_project_point(M, P, got) == 1); /* w constant > 0 */
    closed_form_dir(N, E, D, P, want);
    const double size = fmax(1, vsh_vec3_length(want));
    worst_rel = fmax(worst_rel, dist3(got, want) / size);
    worst_on_plane = fmax(worst_on_plane, fabs(vsh_vec3_dot(N, got) + d) / size);
    ++checked;
  }
  CHECK(checked > 500);
  CHECK(worst_rel < 1e-11);
  CHECK(worst_on_plane < 1e-12);
}

static void test_orientations(void) {
  double M[16], out[3];
  /* Vertical wall x = 2 lit from +x, point light at x = 6. */
  const double wall[4] = {1, 0, 0, -2}, lw[4] = {6, 1, 1, 1};
  CHECK(vsh_planar_shadow_matrix(wall, lw, M) == VSH_PLANAR_OK);
  CHECK(vsh_planar_project_point(M, (double[3]){4, 1, 3}, out) == 1);
  CHECK_NEAR(out[0], 2, 1e-15);
  CHECK_NEAR(out[2], 5, 1e-15); /* halfway: twice the offset */
  /* Ceiling facing -z at z = 5, light below it at z = 1: lit. */
  const double ceil_[4] = {0, 0, -1, 5}, lc[4] = {0, 0, 1, 1};
  CHECK(vsh_planar_shadow_matrix(ceil_, lc, M) == VSH_PLANAR_OK);
  CHECK(vsh_planar_project_point(M, (double[3]){1, 0, 3}, out) == 1);
  CHECK_NEAR(out[0], 2, 1e-15);
  CHECK_NEAR(out[2], 5, 1e-15);
  /* ... and the same ceiling with the light above it: unlit face. */
  const double la[4] = {0, 0, 9, 1};
  CHECK(vsh_planar_shadow_matrix(ceil_, la, M) == VSH_PLANAR_NO_SHADOW);
  /* Tilted plane through the origin, normal (1,1,1)/sqrt3, light on the normal. */
  const double tilt[4] = {1, 1, 1, 0}, lt[4] = {3, 3, 3, 1};
  CHECK(vsh_planar_shadow_matrix(tilt, lt, M) == VSH_PLANAR_OK);
  CHECK(vsh_planar_project_point(M, (double[3]){2, 2, 2}, out) == 1);
  CHECK(fabs(out[0]) < 1e-15 && fabs(out[1]) < 1e-15 && fabs(out[2]) < 1e-15);
  CHECK(vsh_planar_project_point(M, (double[3]){2, 2, 1}, out) == 1);
  CHECK_NEAR(out[0] + out[1] + out[2], 0, 1e-14);
}

static void test_no_shadow_and_invalid(void) {
  double M[16], clip[2][4];
  const double ground[4] = {0, 0, 1, 0};
  struct { double plane[4], light[4]; int want; } cases[] = {
      {{0, 0, 1, 0}, {3, 4, 0, 1}, VSH_PLANAR_NO_SHADOW},      /* light exactly on the plane */
      {{0, 0, 1, 0}, {3, 4, -2, 1}, VSH_PLANAR_NO_SHADOW},     /* light below the plane */
      {{0, 0, 1, -1e6}, {7, 8, 1e6, 1}, VSH_PLANAR_NO_SHADOW}, /* on the plane at 1e6 */
      {{0, 0, 1, 0}, {1, 0, 0, 0}, VSH_PLANAR_NO_SHADOW},      /* directional exactly parallel */
      {{0.6, 0.8, 0, 3}, {-0.8, 0.6, 0, 0}, VSH_PLANAR_NO_SHADOW}, /* ... for a tilted plane */
      {{0, 0, 1, 0}, {1, 0, -1e-12, 0}, VSH_PLANAR_NO_SHADOW}, /* 1e-12 off, travelling up */
      {{0, 0, 1, 0}, {0, 0, -1, 0}, VSH_PLANAR_NO_SHADOW},     /* travelling away from lit face */
      {{0, 0, 0, 1}, {0, 0, 5, 1}, VSH_PLANAR_INVALID},        /* zero normal */
      {{NAN, 0, 1, 0}, {0, 0, 5, 1}, VSH_PLANAR_INVALID},
      {{0, 0, 1, INFINITY}, {0, 0, 5, 1}, VSH_PLANAR_INVALID},
      {{0, 0, 1, 0}, {0, INFINITY, 5, 1}, VSH_PLANAR_INVALID},
      {{0, 0, 1, 0}, {0, 0, 5, NAN}, VSH_PLANAR_INVALID},
      {{0, 0, 1, 0}, {0, 0, 0, 0}, VSH_PLANAR_INVALID},        /* zero directional vector */
      {{0, 0, 1, 0}, {0, 0, 1, 1e-320}, VSH_PLANAR_INVALID},   /* L = (0,0,1/1e-320): Inf */
      {{0, 0, 1, -1e308}, {0, 0, 1e308, 1}, VSH_PLANAR_NO_SHADOW}, /* on plane, huge */
      {{1, 1, 0, 1e308}, {1e308, 1e308, 0, 1}, VSH_PLANAR_INVALID}, /* pi.l overflows */
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    for (int i = 0; i < 16; ++i) M[i] = NAN; /* must be overwritten */
    const int st = vsh_planar_shadow_matrix(cases[k].plane, cases[k].light, M);
    if (st != cases[k].want) fprintf(stderr, "case %zu: status %d, want %d\n", k, st, cases[k].want);
    CHECK(st == cases[k].want);
    CHECK(all_zero(M, 16)); /* projects nothing, no NaN/Inf */
    const double origin[3] = {1, 2, 3};
    CHECK(vsh_planar_shadow_matrix_relative(cases[k].plane, cases[k].light, origin, M) ==
          cases[k].want);
    CHECK(all_zero(M, 16));
    CHECK(vsh_planar_caster_clip_planes(cases[k].plane, cases[k].light, clip) == cases[k].want);
    CHECK(clip[0][3] == -1 && clip[1][3] == -1 && clip[0][0] == 0 && clip[1][2] == 0);
    double out[3];
    CHECK(vsh_planar_project_point_clipped(cases[k].plane, cases[k].light,
                                           (double[3]){0.5, 0.5, 0.5}, out) == 0);
  }
  /* The all-zero matrix projects nothing. */
  double Z[16] = {0}, out[3];
  const double P[3] = {1, 2, 3};
  CHECK(vsh_planar_project_point(Z, P, out) == 0);
  CHECK(out[0] == 1 && out[1] == 2 && out[2] == 3);
  /* Non-finite origin for the relative form. */
  CHECK(vsh_planar_shadow_matrix_relative(ground, (double[4]){0, 0, 5, 1},
                                          (double[3]){0, NAN, 0}, M) == VSH_PLANAR_INVALID);
  CHECK(all_zero(M, 16));
}

static void test_nearly_parallel_sun(void) {
  /* 1e-12 rad toward the lit face: a valid, very long shadow. */
  const double plane[4] = {0, 0, 1, 0}, sun[4] = {-1, 0, 1e-12, 0}; /* D = (1, 0, -1e-12) */
  double M[16], out[3];
  CHECK(vsh_planar_shadow_matrix(plane, sun, M) == VSH_PLANAR_OK);
  CHECK(vsh_mat4_is_finite(M));
  CHECK(vsh_planar_project_point(M, (double[3]){0, 0, 1}, out) == 1);
  CHECK(vsh_vec3_is_finite(out));
  CHECK_NEAR(out[0] / 1e12, 1, 1e-9); /* shadow 1e12 away */
  CHECK(fabs(out[2]) <= 1e-3);       /* on the plane (relative 1e-15) */
  /* 1e-12 off for a tilted plane, too. */
  double N[3], T[3];
  vsh_vec3_normalize((double[3]){1, 2, 3}, N);
  vsh_vec3_cross(N, (double[3]){0, 0, 1}, T);
  vsh_vec3_normalize(T, T); /* in the plane */
  const double tilt[4] = {N[0], N[1], N[2], -2};
  const double l2[4] = {-T[0] + 1e-12 * N[0], -T[1] + 1e-12 * N[1], -T[2] + 1e-12 * N[2], 0};
  CHECK(vsh_planar_shadow_matrix(tilt, l2, M) == VSH_PLANAR_OK);
  const double l3[4] = {-T[0] - 1e-12 * N[0], -T[1] - 1e-12 * N[1], -T[2] - 1e-12 * N[2], 0};
  CHECK(vsh_planar_shadow_matrix(tilt, l3, M) == VSH_PLANAR_NO_SHADOW);
}

/* ---- clipping ----------------------------------------------------------- */

static void test_clip_planes(void) {
  const double plane[4] = {0, 0, 2, -2}; /* z = 1, unnormalized */
  const double light[4] = {0, 0, 11, 1}; /* 10 above the plane */
  double clip[2][4], M[16], out[3];
  CHECK(vsh_planar_caster_clip_planes(plane, light, clip) == VSH_PLANAR_OK);
  CHECK(clip[0][0] == 0 && clip[0][1] == 0 && clip[0][2] == 1 && clip[0][3] == -1);
  /* (-N, N.L): the light's height above P. */
  CHECK(clip[1][0] == 0 && clip[1][1] == 0 && clip[1][2] == -1 && clip[1][3] == 11);
  /* clip[1] is exactly row 3 of M. */
  vsh_planar_shadow_matrix(plane, light, M);
  for (int k = 0; k < 4; ++k) CHECK_NEAR(clip[1][k], M[12 + k], 0);

  /* A caster ABOVE the point light: w < 0 -> clipped, never an anti-shadow. */
  const double above[3] = {1, 1, 15};
  CHECK(vsh_planar_project_point(M, above, out) == 0);
  CHECK(out[0] == 1 && out[2] == 15);
  CHECK(plane_eval(clip[1], above) < 0);
  CHECK(vsh_planar_project_point_clipped(plane, light, above, out) == 0);
  /* Exactly at the light's height: w = 0 -> clipped. */
  const double level[3] = {1, 1, 11};
  CHECK(vsh_planar_project_point(M, level, out) == 0);
  CHECK(vsh_planar_project_point_clipped(plane, light, level, out) == 0);
  /* A caster BELOW the receiver casts nothing (clip[0] < 0). */
  const double below[3] = {1, 1, 0.5};
  CHECK(plane_eval(clip[0], below) < 0);
  CHECK(vsh_planar_project_point_clipped(plane, light, below, out) == 0);
  CHECK(out[0] == 1 && out[2] == 0.5);
  /* A normal caster between plane and light. */
  const double mid[3] = {1, 1, 6};
  CHECK(plane_eval(clip[0], mid) > 0 && plane_eval(clip[1], mid) > 0);
  CHECK(vsh_planar_project_point_clipped(plane, light, mid, out) == 1);
  CHECK_NEAR(out[0], 2, 1e-15);
  CHECK_NEAR(out[2], 1, 1e-15);
  /* Touching the receiver: kept, projects onto itself. */
  CHECK(vsh_planar_project_point_clipped(plane, light, (double[3]){4, 5, 1}, out) == 1);
  CHECK(out[0] == 4 && out[1] == 5 && out[2] == 1);

  /* Directional: clip[1] is "always keep"; clip[0] still removes casters below. */
  const double sun[4] = {0.3, 0, 1, 0};
  CHECK(vsh_planar_caster_clip_planes(plane, sun, clip) == VSH_PLANAR_OK);
  CHECK(clip[1][0] == 0 && clip[1][1] == 0 && clip[1][2] == 0 && clip[1][3] == 1);
  CHECK(vsh_planar_project_point_clipped(plane, sun, (double[3]){0, 0, 1e9}, out) == 1);
  CHECK(vsh_planar_project_point_clipped(plane, sun, (double[3]){0, 0, 0.999}, out) == 0);

  /* Relative clip planes: the same half-spaces in coordinates relative to o. */
  const double o[3] = {1e6, -1e6, 5};
  CHECK(vsh_planar_caster_clip_planes_relative(plane, light, o, clip) == VSH_PLANAR_OK);
  const double mid_rel[3] = {1 - o[0], 1 - o[1], 6 - o[2]};
  const double above_rel[3] = {1 - o[0], 1 - o[1], 15 - o[2]};
  const double below_rel[3] = {1 - o[0], 1 - o[1], 0.5 - o[2]};
  CHECK_NEAR(plane_eval(clip[0], mid_rel), 5, 1e-9);
  CHECK_NEAR(plane_eval(clip[1], mid_rel), 5, 1e-9);
  CHECK(plane_eval(clip[1], above_rel) < 0);
  CHECK(plane_eval(clip[0], below_rel) < 0);
}

/* ---- planes from points and offsets -------------------------------------- */

static void test_plane_from_points(void) {
  double pl[4];
  /* vtkPlaneSource's default: origin (-.5,-.5,0), point1 (.5,-.5,0), point2 (-.5,.5,0). */
  CHECK(vsh_planar_plane_from_points((double[3]){-.5, -.5, 0}, (double[3]){.5, -.5, 0},
                                     (double[3]){-.5, .5, 0}, pl) == VSH_PLANAR_OK);
  CHECK(pl[0] == 0 && pl[1] == 0 && pl[2] == 1 && pl[3] == 0);
  /* Swapping the points flips the normal (and the lit side). */
  CHECK(vsh_planar_plane_from_points((double[3]){-.5, -.5, 0}, (double[3]){-.5, .5, 0},
                                     (double[3]){.5, -.5, 0}, pl) == VSH_PLANAR_OK);
  CHECK(pl[2] == -1 && pl[3] == 0);
  /* A tilted plane at a 1e6 offset: normal exact, the points lie on it. */
  const double o[3] = {1e6, 2e6, 3}, p1[3] = {1e6 + 1, 2e6, 4}, p2[3] = {1e6, 2e6 + 1, 3};
  CHECK(vsh_planar_plane_from_points(o, p1, p2, pl) == VSH_PLANAR_OK);
  CHECK_NEAR(pl[0], -sqrt(0.5), 1e-15);
  CHECK_NEAR(pl[2], sqrt(0.5), 1e-15);
  CHECK(fabs(plane_eval(pl, o)) < 1e-9 && fabs(plane_eval(pl, p1)) < 1e-9 &&
        fabs(plane_eval(pl, p2)) < 1e-9);
  /* Tiny (1e-6) triangle is fine. */
  CHECK(vsh_planar_plane_from_points((double[3]){0, 0, 0}, (double[3]){1e-6, 0, 0},
                                     (double[3]){0, 0, 1e-6}, pl) == VSH_PLANAR_OK);
  CHECK(pl[1] == -1);
  /* Degenerate: coincident, collinear, NaN. */
  const double z[3] = {1, 1, 1};
  pl[0] = 5;
  CHECK(vsh_planar_plane_from_points(z, z, (double[3]){2, 3, 4}, pl) == VSH_PLANAR_INVALID);
  CHECK(all_zero(pl, 4));
  CHECK(vsh_planar_plane_from_points((double[3]){0, 0, 0}, (double[3]){1, 1, 1},
                                     (double[3]){-2, -2, -2}, pl) == VSH_PLANAR_INVALID);
  CHECK(vsh_planar_plane_from_points((double[3]){0, 0, 0}, (double[3]){1, 1, 1},
                                     (double[3]){1, 1, 1 + 1e-14}, pl) == VSH_PLANAR_INVALID);
  CHECK(vsh_planar_plane_from_points((double[3]){0, 0, 0}, (double[3]){1, 0, NAN},
                                     (double[3]){0, 1, 0}, pl) == VSH_PLANAR_INVALID);
}

static void test_offset_and_normalize(void) {
  double pl[4];
  CHECK(vsh_planar_plane_offset((double[4]){0, 0, 2, -4}, 0.01, pl) == VSH_PLANAR_OK);
  CHECK(pl[2] == 1);
  CHECK_NEAR(pl[3], -2.01, 1e-15); /* z = 2 moved up to z = 2.01 */
  CHECK(vsh_planar_plane_offset((double[4]){0, -3, 0, 0}, 1, pl) == VSH_PLANAR_OK);
  CHECK(pl[1] == -1 && pl[3] == -1); /* toward the lit side (-y): y = -1 */
  CHECK(vsh_planar_plane_offset((double[4]){0, 0, 0, 1}, 1, pl) == VSH_PLANAR_INVALID);
  CHECK(all_zero(pl, 4));
  CHECK(vsh_planar_plane_offset((double[4]){0, 0, 1, 0}, NAN, pl) == VSH_PLANAR_INVALID);
  CHECK(vsh_planar_plane_offset((double[4]){0, 0, 1, 0}, INFINITY, pl) == VSH_PLANAR_INVALID);
  CHECK(vsh_planar_normalize_plane((double[4]){3, 0, 4, 10}, pl) == VSH_PLANAR_OK);
  CHECK_NEAR(pl[0], 0.6, 1e-16);
  CHECK_NEAR(pl[3], 2, 1e-15);
  CHECK(vsh_planar_normalize_plane((double[4]){0, 0, 0, 0}, pl) == VSH_PLANAR_INVALID);
}

/* ---- precision of the camera-relative form ---------------------------- */

/* A fixed scene at the origin: tilted receiver through E, point light L,
 * casters P[k]; want[k] = closed-form shadows. */
static const double scene_E[3] = {0.25, -0.5, 0.125};
static const double scene_L[3] = {1.5, 2.0, 6.0};
static const double scene_P[4][3] = {{0.5, 0.25, 1.5}, {-1.0, 0.75, 2.0}, {0.0, 0.0, 3.5},
                                     {2.0, -1.0, 0.75}};

static void scene_normal(double N[3]) { vsh_vec3_normalize((double[3]){0.2, -0.3, 1.0}, N); }

/* Max error, relative to the scene size (~1), of the relative-form shadows
 * of the scene mapped by X -> s X + O, with origin = s C + O (a camera C).
 * The expected answers are the at-origin closed-form ones mapped the same way,
 * so only the relative-form pipeline is being measured. */
static double relative_form_error(double s, const double O[3], int directional) {
  const double C[3] = {3.0, -2.0, 5.0};
  double N[3], want0[4][3];
  scene_normal(N);
  const double D[3] = {-0.3, 0.1, -1.0};
  for (int k = 0; k < 4; ++k) {
    if (directional) closed_form_dir(N, scene_E, D, scene_P[k], want0[k]);
    else closed_form_point(N, scene_E, scene_L, scene_P[k], want0[k]);
  }
  /* World-space inputs as an application would hold them. */
  double Ew[3], Lw[3], origin[3];
  for (int a = 0; a < 3; ++a) {
    Ew[a] = s * scene_E[a] + O[a];
    Lw[a] = s * scene_L[a] + O[a];
    origin[a] = s * C[a] + O[a];
  }
  const double plane[4] = {N[0], N[1], N[2], -vsh_vec3_dot(N, Ew)};
  const double light[4] = {directional ? -D[0] : Lw[0], directional ? -D[1] : Lw[1],
                           directional ? -D[2] : Lw[2], directional ? 0.0 : 1.0};
  double M[16];
  if (vsh_planar_shadow_matrix_relative(plane, light, origin, M) != VSH_PLANAR_OK) return INFINITY;
  double worst = 0;
  for (int k = 0; k < 4; ++k) {
    double Pw[3], Prel[3], got[3], want[3];
    for (int a = 0; a < 3; ++a) Pw[a] = s * scene_P[k][a] + O[a];
    vsh_vec3_sub(Pw, origin, Prel); /* what the GPU is fed */
    if (vsh_planar_project_point(M, Prel, got) != 1) return INFINITY;
    for (int a = 0; a < 3; ++a) want[a] = s * (want0[k][a] - C[a]); /* relative to origin */
    worst = fmax(worst, dist3(got, want) / s);
  }
  return worst;
}

static void test_relative_precision(void) {
  const double zero[3] = {0, 0, 0};
  const double o6[3] = {1e6, -2e6, 1e6};
  const double o12[3] = {1e12, -2e12, 1e12};
  for (int dir = 0; dir <= 1; ++dir) {
    const double e0 = relative_form_error(1, zero, dir);
    const double e6 = relative_form_error(1, o6, dir);
    const double es = relative_form_error(1e-6, zero, dir);
    const double es6 = relative_form_error(1e-6, o6, dir); /* tiny scene far away */
    const double e12 = relative_form_error(1, o12, dir);
    printf("relative form (%s): origin %.3g, 1e6 offset %.3g, 1e-6 scale %.3g, "
           "1e-6 scale at 1e6 %.3g, 1e12 offset %.3g\n",
           dir ? "directional" : "point", e0, e6, es, es6, e12);
    CHECK(e0 < 1e-14);
    CHECK(e6 < 1e-9);  /* the claim: as good at 1e6 as needed, not merely 1e-3 */
    CHECK(es < 1e-14); /* scale-free */
    /* At 1e6 with a 1e-6 scene the INPUT coordinates only carry ~1e-10/1e-6
     * = 1e-4 relative precision; the relative form must not lose more. */
    CHECK(es6 < 1e-3);
    /* At 1e12 the inputs carry ulp(1e12) = 1.2e-4: same argument. */
    CHECK(e12 < 1e-2);
  }
  /* With inputs exactly representable at 1e12 (axis-aligned plane, dyadic
   * coordinates), the relative form is exact to rounding of the scene size. */
  const double O = 1e12;
  const double plane[4] = {0, 0, 1, -(O + 0.5)};       /* z = O + 0.5 */
  const double light[4] = {O + 1, O - 2, O + 8.5, 1};  /* 8 above */
  const double origin[3] = {O + 3, O - 1, O + 4};
  double M[16], got[3];
  CHECK(vsh_planar_shadow_matrix_relative(plane, light, origin, M) == VSH_PLANAR_OK);
  const double P[3] = {O + 2 - origin[0], O - 2 - origin[1], O + 4.5 - origin[2]}; /* halfway */
  CHECK(vsh_planar_project_point(M, P, got) == 1);
  CHECK_NEAR(got[0], (O + 3) - origin[0], 1e-12);
  CHECK_NEAR(got[1], (O - 2) - origin[1], 1e-12);
  CHECK_NEAR(got[2], (O + 0.5) - origin[2], 1e-12);
  /* The non-relative matrix at 1e12 cannot do that in its output (its
   * results are ~1e12, spaced 1.2e-4): that is why the relative form exists. */
}

static void test_scale_aware_epsilon(void) {
  double M[16];
  /* 1e-7 above the plane in a 1e-6 scene: a real light, not "on the plane". */
  CHECK(vsh_planar_shadow_matrix((double[4]){0, 0, 1, -1e-6}, (double[4]){0, 0, 1.1e-6, 1}, M) ==
        VSH_PLANAR_OK);
  /* 1e-6 above a plane at z = 1e6: also real. */
  CHECK(vsh_planar_shadow_matrix((double[4]){0, 0, 1, -1e6}, (double[4]){0, 0, 1e6 + 1e-6, 1},
                                 M) == VSH_PLANAR_OK);
  /* One ulp above the plane at 1e6 is rounding noise: on the plane. */
  CHECK(vsh_planar_shadow_matrix((double[4]){0, 0, 1, -1e6},
                                 (double[4]){0, 0, nextafter(1e6, 2e6), 1}, M) ==
        VSH_PLANAR_NO_SHADOW);
}

int main(void) {
  test_ground_plane_by_hand();
  test_random_point_lights();
  test_random_directional();
  test_orientations();
  test_no_shadow_and_invalid();
  test_nearly_parallel_sun();
  test_clip_planes();
  test_plane_from_points();
  test_offset_and_normalize();
  test_relative_precision();
  test_scale_aware_epsilon();
  return vsh_check_report("core.planar");
}
