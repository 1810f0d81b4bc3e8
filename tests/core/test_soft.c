/* test_soft.c - unit tests of vsh_soft: the frame of a disk light, the
 * spiral samples (inside, uniform by area, turnable), light points and sun
 * directions, the sphere shadow test, and the numerically integrated
 * penumbra against closed forms (a sphere straight between the point and
 * the light's centre occludes a concentric disk), the hard limit r -> 0,
 * 1e6 offsets and 1e-6 scales, and bad arguments. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_soft.h"

#include <math.h>

#define VSH_TEST_PI 3.14159265358979323846

static double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void test_frame(void) {
  double u[3], v[3], n[3];
  int k;
  for (k = 0; k < 1000; ++k) {
    double w[3], len = vsh_test_rnd(1e-3, 1e3);
    vsh_test_rnd_unit(w);
    n[0] = w[0] * len, n[1] = w[1] * len, n[2] = w[2] * len;
    CHECK(vsh_soft_frame(n, u, v) == 0);
    CHECK_NEAR(dot(u, u), 1, 1e-14);
    CHECK_NEAR(dot(v, v), 1, 1e-14);
    CHECK_NEAR(dot(u, v), 0, 1e-14);
    CHECK_NEAR(dot(u, w), 0, 1e-14);
    /* right-handed: (u x v) . w = 1 */
    CHECK_NEAR((u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] +
                   (u[0] * v[1] - u[1] * v[0]) * w[2],
               1, 1e-14);
  }
  /* Axis-aligned, tiny and huge normals. */
  {
    const double cases[4][3] = {{0, 0, 1}, {0, -1e-300, 0}, {1e300, 0, 1e300}, {3, 0, 0}};
    for (k = 0; k < 4; ++k) {
      CHECK(vsh_soft_frame(cases[k], u, v) == 0);
      CHECK_NEAR(dot(u, u), 1, 1e-14);
      CHECK_NEAR(dot(u, v), 0, 1e-14);
      CHECK(fabs(dot(u, cases[k])) <= 1e-14 * fabs(cases[k][0] + cases[k][1] + cases[k][2]));
    }
  }
  n[0] = n[1] = n[2] = 0.0;
  CHECK(vsh_soft_frame(n, u, v) == -1 && u[0] == 1 && v[1] == 1);
  n[0] = INFINITY;
  CHECK(vsh_soft_frame(n, u, v) == -1);
  n[0] = NAN;
  CHECK(vsh_soft_frame(n, u, v) == -1);
}

static void test_disk_samples(void) {
  const int sizes[5] = {1, 4, 16, 61, 256};
  int s, i;
  double q[2];
  for (s = 0; s < 5; ++s) {
    const int n = sizes[s];
    int inner = 0;
    double mx = 0, my = 0;
    for (i = 0; i < n; ++i) {
      CHECK(vsh_soft_disk_sample(i, n, 0.3, q) == 0);
      CHECK(q[0] * q[0] + q[1] * q[1] < 1.0);
      inner += q[0] * q[0] + q[1] * q[1] < 0.25;
      mx += q[0] / n;
      my += q[1] / n;
    }
    /* Uniform by area: a quarter within half the radius, to one sample. */
    CHECK(fabs(inner - 0.25 * n) <= 1.0);
    /* Centred (the spiral is balanced): the mean within 1/sqrt(n)-ish. */
    if (n >= 16) CHECK(sqrt(mx * mx + my * my) < 1.5 / sqrt((double)n));
  }
  /* A turn rotates every sample by that angle. */
  {
    double a[2], b[2];
    for (i = 0; i < 32; ++i) {
      vsh_soft_disk_sample(i, 32, 0.0, a);
      vsh_soft_disk_sample(i, 32, 1.0, b);
      CHECK_NEAR(b[0], cos(1.0) * a[0] - sin(1.0) * a[1], 1e-12);
      CHECK_NEAR(b[1], sin(1.0) * a[0] + cos(1.0) * a[1], 1e-12);
    }
  }
  CHECK(vsh_soft_disk_sample(4, 4, 0, q) == -1);
  CHECK(vsh_soft_disk_sample(-1, 4, 0, q) == -1);
  CHECK(vsh_soft_disk_sample(0, 0, 0, q) == -1);
  CHECK(vsh_soft_disk_sample(0, 4, NAN, q) == -1);
}

static void test_light_points(void) {
  int k;
  for (k = 0; k < 500; ++k) {
    double c[3], p[3], q[2], at[3], d[3], n[3], angle, l[3];
    int i;
    for (i = 0; i < 3; ++i) c[i] = vsh_test_rnd(-5, 5), p[i] = vsh_test_rnd(-5, 5);
    vsh_soft_disk_sample(k % 17, 17, vsh_test_rnd(0, 6.3), q);
    CHECK(vsh_soft_light_point(c, 0.7, p, q, at) == 0);
    for (i = 0; i < 3; ++i) d[i] = at[i] - c[i], n[i] = p[i] - c[i];
    /* On the disk facing p: perpendicular to p - c, within the radius. */
    CHECK_NEAR(dot(d, n) / sqrt(dot(n, n)), 0, 1e-12);
    CHECK_NEAR(sqrt(dot(d, d)), 0.7 * sqrt(q[0] * q[0] + q[1] * q[1]), 1e-12);
    /* Sun: the angle to l is atan(tan(angle/2) |q|). */
    angle = vsh_test_rnd(0, 170);
    vsh_test_rnd_unit(l);
    CHECK(vsh_soft_sun_direction(l, angle, q, d) == 0);
    CHECK_NEAR(dot(d, d), 1, 1e-14);
    CHECK_NEAR(acos(fmin(1.0, dot(d, l))),
               atan(tan(angle * VSH_TEST_PI / 360.0) * sqrt(q[0] * q[0] + q[1] * q[1])), 1e-7);
  }
  {
    const double c[3] = {1, 2, 3}, q[2] = {0.5, 0}, l[3] = {0, 0, 1};
    double out[3];
    CHECK(vsh_soft_light_point(c, 1, c, q, out) == -1);
    CHECK(vsh_soft_sun_direction(l, 180, q, out) == -1);
    CHECK(vsh_soft_sun_direction(l, -1, q, out) == -1);
    CHECK(vsh_soft_sun_direction(c, NAN, q, out) == -1);
  }
}

static void test_ray_sphere(void) {
  const double s[3] = {0, 0, 2}, p[3] = {0, 0, 0}, up[3] = {0, 0, 1}, side[3] = {1, 0, 0};
  /* The line through (x, 0, 2) passes 2x / sqrt(x^2 + 4) from the centre: 0.5 at x = 0.5164. */
  const double graze_in[3] = {0.515, 0, 2}, graze_out[3] = {0.518, 0, 2};
  CHECK(vsh_soft_ray_hits_sphere(p, up, 0, 10, s, 0.5) == 1);
  CHECK(vsh_soft_ray_hits_sphere(p, up, 0, 1.4, s, 0.5) == 0); /* stops before it */
  CHECK(vsh_soft_ray_hits_sphere(p, up, 0, 1.6, s, 0.5) == 1);
  CHECK(vsh_soft_ray_hits_sphere(p, side, 0, 10, s, 0.5) == 0);
  CHECK(vsh_soft_ray_hits_sphere(p, graze_in, 0, 10, s, 0.5) == 1);
  CHECK(vsh_soft_ray_hits_sphere(p, graze_out, 0, 10, s, 0.5) == 0);
  {
    const double down[3] = {0, 0, -1};
    CHECK(vsh_soft_ray_hits_sphere(p, down, 0, 10, s, 0.5) == 0); /* behind */
  }
}

/* The closed form: p on the axis through the sphere's centre s and the
 * light's centre c (c beyond s). The sphere hides the cone of half-angle
 * asin(R / |s - p|), which cuts the disk in a circle of radius
 * D tan(that), D = |c - p|. */
static double closed_disk(double dist_s, double R, double D, double r) {
  double a = asin(R / dist_s), hidden = D * tan(a) / r;
  return 1.0 - fmin(1.0, hidden * hidden);
}

static void test_exact_closed_form(void) {
  const double offsets[3] = {0.0, 1e6, -3e5};
  const double scales[3] = {1.0, 1.0, 1e-6};
  int o, k;
  for (o = 0; o < 3; ++o) {
    const double z0 = offsets[o], sc = scales[o];
    for (k = 0; k < 6; ++k) {
      const double R = (0.2 + 0.1 * k) * sc, r = 0.8 * sc;
      const double p[3] = {z0, z0, z0}, s[3] = {z0, z0, z0 + 1.5 * sc},
                   c[3] = {z0, z0, z0 + 4.0 * sc};
      double v = vsh_soft_sphere_visibility_disk(p, s, R, c, r, 256, 512);
      CHECK_NEAR(v, closed_disk(1.5 * sc, R, 4.0 * sc, r), 4e-3);
    }
  }
  /* The sun: hidden where tan(angle/2) |q| < tan(asin(R / |s - p|)). */
  for (k = 0; k < 5; ++k) {
    const double p[3] = {0, 0, 0}, s[3] = {0, 0, 3}, l[3] = {0, 0, 1}, R = 0.1 + 0.05 * k;
    const double angle = 20.0, h = tan(asin(R / 3.0)) / tan(angle * VSH_TEST_PI / 360.0);
    double v = vsh_soft_sphere_visibility_sun(p, s, R, l, angle, 256, 512);
    CHECK_NEAR(v, 1.0 - fmin(1.0, h * h), 4e-3);
  }
}

/* r -> 0 (and angle -> 0): the soft answer tends to the hard test, away
 * from the shadow's edge. */
static void test_hard_limit(void) {
  const double s[3] = {0, 0, 1.2}, c[3] = {1, 0.5, 5}, l[3] = {-0.3, 0.1, 1};
  int k, agree = 0, total = 0;
  for (k = 0; k < 400; ++k) {
    const double p[3] = {vsh_test_rnd(-2, 2), vsh_test_rnd(-2, 2), 0};
    const double hard = vsh_soft_sphere_visibility_disk(p, s, 0.5, c, 0.0, 1, 1);
    const double soft = vsh_soft_sphere_visibility_disk(p, s, 0.5, c, 1e-7, 8, 16);
    const double hsun = vsh_soft_sphere_visibility_sun(p, s, 0.5, l, 0.0, 1, 1);
    const double ssun = vsh_soft_sphere_visibility_sun(p, s, 0.5, l, 1e-6, 8, 16);
    CHECK(hard == 0.0 || hard == 1.0);
    agree += soft == hard;
    agree += ssun == hsun;
    total += 2;
  }
  /* Only points within ~1e-7 of the edge may differ: none of 800 random. */
  CHECK(agree == total);
}

static void test_bad_arguments(void) {
  const double p[3] = {0, 0, 0}, s[3] = {0, 0, 1}, c[3] = {0, 0, 3}, l[3] = {0, 0, 0};
  CHECK(vsh_soft_sphere_visibility_disk(p, s, 0.0, c, 1, 4, 4) == -1.0);
  CHECK(vsh_soft_sphere_visibility_disk(p, s, 0.5, c, -1, 4, 4) == -1.0);
  CHECK(vsh_soft_sphere_visibility_disk(p, s, 0.5, c, NAN, 4, 4) == -1.0);
  CHECK(vsh_soft_sphere_visibility_disk(p, s, 0.5, p, 1, 4, 4) == -1.0);
  CHECK(vsh_soft_sphere_visibility_disk(p, s, 0.5, c, 1, 0, 4) == -1.0);
  CHECK(vsh_soft_sphere_visibility_sun(p, s, 0.5, l, 10, 4, 4) == -1.0);
  CHECK(vsh_soft_sphere_visibility_sun(p, s, 0.5, c, 180, 4, 4) == -1.0);
}

/* Homogeneous light samples: on the disk facing `toward` (positional), in
 * the cone of half-angle angle/2 (directional), the light itself at size 0. */
static void test_sample_light(void) {
  const double point[4] = {2, 4, 6, 2}, c[3] = {1, 2, 3}, toward[3] = {1, 0, 0};
  const double sun[4] = {0, 0, 3, 0}, n[3] = {0, -2, -3};
  double out[4];
  int i, inside = 1, facing = 1, cone = 1;
  CHECK(vsh_soft_sample_light(point, 0.0, toward, 0, 1, 0.0, out) == 0);
  CHECK(fabs(out[0] - 1) + fabs(out[1] - 2) + fabs(out[2] - 3) < 1e-15 && out[3] == 1.0);
  for (i = 0; i < 64; ++i) {
    double d[3];
    CHECK(vsh_soft_sample_light(point, 0.5, toward, i, 64, 0.3, out) == 0);
    d[0] = out[0] - c[0], d[1] = out[1] - c[1], d[2] = out[2] - c[2];
    inside &= d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 0.25;
    facing &= fabs(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) < 1e-12; /* in the disk's plane */
    CHECK(vsh_soft_sample_light(sun, 6.0, toward, i, 64, 0.0, out) == 0);
    cone &= out[3] == 0.0 && out[2] > cos(3.0 * 3.14159265358979 / 180.0) - 1e-12;
  }
  CHECK(inside && facing && cone);
  CHECK(vsh_soft_sample_light(point, -1.0, toward, 0, 4, 0.0, out) == -1);
  CHECK(vsh_soft_sample_light(point, 0.5, c, 0, 4, 0.0, out) == -1); /* toward the centre */
  CHECK(vsh_soft_sample_light(point, 0.5, toward, 4, 4, 0.0, out) == -1);
  {
    const double bad[4] = {0, 0, 1, -1};
    CHECK(vsh_soft_sample_light(bad, 0.5, toward, 0, 4, 0.0, out) == -1);
  }
}

/* A disk facing a fixed point equals the exact one where that point is p,
 * and differs a little (foreshortened disk) away from it. */
static void test_facing(void) {
  const double s[3] = {0, 0, 1.2}, c[3] = {2.5, 1.5, 4}, ground[3] = {-1.07, -0.64, 0};
  const double p[3] = {-1.3, -0.2, 0};
  const double exact = vsh_soft_sphere_visibility_disk(ground, s, 0.5, c, 0.35, 32, 128);
  const double same = vsh_soft_sphere_visibility_disk_facing(ground, s, 0.5, c, 0.35, ground, 32, 128);
  const double a = vsh_soft_sphere_visibility_disk(p, s, 0.5, c, 0.35, 32, 128);
  const double b = vsh_soft_sphere_visibility_disk_facing(p, s, 0.5, c, 0.35, s, 32, 128);
  CHECK(exact == same);
  CHECK(fabs(a - b) < 0.05);
  CHECK(vsh_soft_sphere_visibility_disk_facing(p, s, 0.5, c, 0.35, c, 32, 128) == -1.0);
}

int main(void) {
  test_sample_light();
  test_facing();
  test_frame();
  test_disk_samples();
  test_light_points();
  test_ray_sphere();
  test_exact_closed_form();
  test_hard_limit();
  test_bad_arguments();
  return vsh_check_report("core.soft");
}
