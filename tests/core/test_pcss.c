/* test_pcss.c - unit tests of vsh_pcss: the light's size term, the PCSS
 * penumbra half-widths of a directional and a disk light (closed forms, the
 * exact penumbra of vsh_soft as a cross-check, scale invariance), the
 * conversion to a clamped kernel in texels, and the degenerate cases: zero
 * size, a blocker at the receiver, a receiver or blocker behind the light,
 * huge sizes and distances, bad input. */
#include "vsh_check.h"
#include "vsh_pcss.h"
#include "vsh_soft.h"

#include <float.h>
#include <math.h>

#define VSH_TEST_PI 3.14159265358979323846

static void test_light_term(void) {
  CHECK_NEAR(vsh_pcss_light_term(1, 0.5, 99.0), 0.5, 0.0); /* positional: angle ignored */
  CHECK_NEAR(vsh_pcss_light_term(0, 7.0, 90.0), 1.0, 1e-15); /* tan 45 deg */
  CHECK_NEAR(vsh_pcss_light_term(0, 0.0, 6.0), tan(3.0 * VSH_TEST_PI / 180.0), 1e-15);
  /* No size and bad sizes: the hard shadow. */
  CHECK(vsh_pcss_light_term(1, 0.0, 0.0) == 0.0);
  CHECK(vsh_pcss_light_term(0, 0.0, 0.0) == 0.0);
  CHECK(vsh_pcss_light_term(1, -1.0, 0.0) == 0.0);
  CHECK(vsh_pcss_light_term(1, NAN, 0.0) == 0.0);
  CHECK(vsh_pcss_light_term(1, INFINITY, 0.0) == 0.0);
  CHECK(vsh_pcss_light_term(0, 0.0, 180.0) == 0.0);
  CHECK(vsh_pcss_light_term(0, 0.0, -3.0) == 0.0);
  CHECK(vsh_pcss_light_term(0, 0.0, NAN) == 0.0);
  /* Huge but valid: finite and large. */
  CHECK(vsh_pcss_light_term(1, 1e300, 0.0) == 1e300);
  CHECK(vsh_pcss_light_term(0, 0.0, 179.999999) > 1e6);
  CHECK(isfinite(vsh_pcss_light_term(0, 0.0, 179.999999)));
}

static void test_sun(void) {
  const double t = tan(3.0 * VSH_TEST_PI / 180.0);
  /* Parallel planes h apart: the penumbra is 2 h t wide (an edge seen over
   * the light's angular radius on each side). */
  CHECK_NEAR(vsh_pcss_sun_halfwidth(t, 10.0, 9.3), 0.7 * t, 1e-15);
  /* Only the difference counts: any origin along the light. */
  CHECK_NEAR(vsh_pcss_sun_halfwidth(t, 1e6 + 0.7, 1e6), vsh_pcss_sun_halfwidth(t, 0.7, 0.0),
             1e-10 * t);
  /* 1e-6 scales scale. */
  CHECK_NEAR(vsh_pcss_sun_halfwidth(t, 0.7e-6, 0.0), 0.7e-6 * t, 1e-21);
  /* Degenerate: no size, a blocker at or behind the receiver. */
  CHECK(vsh_pcss_sun_halfwidth(0.0, 10.0, 1.0) == 0.0);
  CHECK(vsh_pcss_sun_halfwidth(t, 5.0, 5.0) == 0.0);
  CHECK(vsh_pcss_sun_halfwidth(t, 5.0, 6.0) == 0.0);
  /* Huge: finite or +inf, never NaN; the kernel clamps it. */
  CHECK(vsh_pcss_sun_halfwidth(1e300, 1e10, 0.0) == INFINITY);
  CHECK(vsh_pcss_kernel_texels(vsh_pcss_sun_halfwidth(1e300, 1e10, 0.0), 0.01, 48.0) == 48.0);
  /* Bad input. */
  CHECK(vsh_pcss_sun_halfwidth(-t, 1.0, 0.0) == -1.0);
  CHECK(vsh_pcss_sun_halfwidth(NAN, 1.0, 0.0) == -1.0);
  CHECK(vsh_pcss_sun_halfwidth(t, INFINITY, 0.0) == -1.0);
  CHECK(vsh_pcss_sun_halfwidth(t, 1.0, NAN) == -1.0);
}

static void test_disk(void) {
  /* Light of radius 0.5, blocker edge 3 from it, receiver 5: world
   * half-width 0.5 * 2 / 3 at the receiver, per unit distance / 5. */
  CHECK_NEAR(vsh_pcss_disk_halfwidth(0.5, 5.0, 3.0), 0.5 * 2.0 / 3.0 / 5.0, 1e-15);
  /* Scale invariance: the per-distance width does not change when the
   * whole scene scales (r, distances) by s, from 1e-6 to 1e6. */
  {
    const double ref = vsh_pcss_disk_halfwidth(0.5, 5.0, 3.0);
    const double scales[4] = {1e-6, 1e-3, 1e3, 1e6};
    int k;
    for (k = 0; k < 4; ++k) {
      const double s = scales[k];
      CHECK_NEAR(vsh_pcss_disk_halfwidth(0.5 * s, 5.0 * s, 3.0 * s), ref, 1e-13);
    }
  }
  /* Degenerate: zero size, blocker at the receiver, receiver or blocker at
   * or behind the light. */
  CHECK(vsh_pcss_disk_halfwidth(0.0, 5.0, 3.0) == 0.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, 5.0, 5.0) == 0.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, 5.0, 7.0) == 0.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, 0.0, -1.0) == 0.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, -5.0, -6.0) == 0.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, 5.0, 0.0) == 0.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, 5.0, -1.0) == 0.0);
  /* A blocker almost at the light: huge, finite, clamped in texels. */
  {
    const double w = vsh_pcss_disk_halfwidth(0.5, 5.0, 1e-300);
    CHECK(w > 1e299 && isfinite(w));
    CHECK(vsh_pcss_kernel_texels(w, 1e-3, 48.0) == 48.0);
    CHECK(vsh_pcss_disk_halfwidth(1e300, 5.0, 1e-300) == INFINITY);
  }
  /* Bad input. */
  CHECK(vsh_pcss_disk_halfwidth(-0.5, 5.0, 3.0) == -1.0);
  CHECK(vsh_pcss_disk_halfwidth(NAN, 5.0, 3.0) == -1.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, NAN, 3.0) == -1.0);
  CHECK(vsh_pcss_disk_halfwidth(0.5, 5.0, -INFINITY) == -1.0);
}

/* Radial distance from the axis where the exact visibility of the shadow of
 * a sphere (centre (0,0,H), radius R) on the plane z = 0 crosses v, by
 * bisection between a (inside) and b (outside). */
static double crossing(double v, double a, double b, int sun, double size, double L) {
  const double s[3] = {0, 0, 1.2}, c[3] = {0, 0, L}, l[3] = {0, 0, 1};
  int k;
  for (k = 0; k < 40; ++k) {
    const double m = 0.5 * (a + b), p[3] = {m, 0, 0};
    const double vis = sun ? vsh_soft_sphere_visibility_sun(p, s, 0.5, l, size, 64, 256)
                           : vsh_soft_sphere_visibility_disk(p, s, 0.5, c, size, 64, 256);
    if (vis < v) {
      a = m;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

/* Against the exact penumbra (vsh_soft): a sphere of radius 0.5 at height
 * 1.2 over a plane, the light straight above. Its silhouette is near the
 * equator, a blocker at distance 1.2 above the receiver, so the exact
 * penumbra (visibility 0.02 .. 0.98) should span about the PCSS width
 * 2 x half-width; a sphere's curved silhouette makes it a little
 * different, hence the 15 % tolerance. */
static void test_against_exact(void) {
  {
    const double angle = 6.0, t = vsh_pcss_light_term(0, 0.0, angle);
    const double w = 2.0 * vsh_pcss_sun_halfwidth(t, 1.2, 0.0);
    const double inner = crossing(0.02, 0.0, 1.0, 1, angle, 0.0);
    const double outer = crossing(0.98, 0.0, 1.0, 1, angle, 0.0);
    printf("sun 6 deg: exact penumbra %.4f, PCSS %.4f\n", outer - inner, w);
    CHECK(fabs((outer - inner) / w - 1.0) < 0.15);
  }
  {
    const double r = 0.5, L = 5.0, d_r = L, d_b = L - 1.2;
    const double w = 2.0 * vsh_pcss_disk_halfwidth(r, d_r, d_b) * d_r; /* world */
    const double inner = crossing(0.02, 0.0, 2.0, 0, r, L);
    const double outer = crossing(0.98, 0.0, 2.0, 0, r, L);
    printf("disk r 0.5: exact penumbra %.4f, PCSS %.4f\n", outer - inner, w);
    CHECK(fabs((outer - inner) / w - 1.0) < 0.15);
  }
}

static void test_kernel(void) {
  CHECK_NEAR(vsh_pcss_kernel_texels(0.05, 0.01, 48.0), 5.0, 1e-12);
  CHECK(vsh_pcss_kernel_texels(1.0, 0.01, 48.0) == 48.0);
  CHECK(vsh_pcss_kernel_texels(INFINITY, 0.01, 48.0) == 48.0);
  CHECK(vsh_pcss_kernel_texels(1e300, 1e-300, 48.0) == 48.0);
  CHECK(vsh_pcss_kernel_texels(0.0, 0.01, 48.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(-1.0, 0.01, 48.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(NAN, 0.01, 48.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(0.05, 0.0, 48.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(0.05, -1.0, 48.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(0.05, INFINITY, 48.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(0.05, 0.01, 0.0) == 0.0);
  CHECK(vsh_pcss_kernel_texels(0.05, 0.01, NAN) == 0.0);
  /* Tiny scales convert like unit ones. */
  CHECK_NEAR(vsh_pcss_kernel_texels(0.05e-6, 0.01e-6, 48.0), 5.0, 1e-9);
}

int main(void) {
  test_light_term();
  test_sun();
  test_disk();
  test_against_exact();
  test_kernel();
  return vsh_check_report("pcss");
}
