/* test_rt_weight.c - unit tests of vsh_rt_weight: the N.L-weighted
 * visibility equals the plain fraction for a small light far above a
 * facing plane, is 1 on a convex caster's own terminator (where the plain
 * fraction is the part of the light above the horizon), a closed form of
 * two rays, 0/0 (every ray below the horizon), nothing traced, and
 * degenerate normals and weights (zero, non-finite, 1e-6 and 1e6 long). */
#include "vsh_check.h"
#include "vsh_raytrace.h"
#include "vsh_rt_weight.h"

#include <math.h>
#include <string.h>

/* Visibility of the light from `point` with `normal`, the rays whose
 * direction has dir . block_axis < 0 blocked; the plain fraction too. */
static double trace(const vsh_rt_light *light, const double point[3], const double normal[3],
                    const double block_axis[3], int n, double *plain)
{
  vsh_rt_visibility v;
  memset(&v, 0, sizeof v);
  for (int k = 0; k < n; ++k) {
    double dir[3], distance;
    CHECK(vsh_rt_light_sample(light, point, k, n, 0.3, dir, &distance) == VSH_RT_OK);
    const int blocked = dir[0] * block_axis[0] + dir[1] * block_axis[1] + dir[2] * block_axis[2] < 0;
    vsh_rt_visibility_add(&v, vsh_rt_sample_weight(normal, dir), blocked);
  }
  *plain = 1.0 - (double)v.blocked / v.traced;
  return vsh_rt_visibility_value(&v);
}

static vsh_rt_light point_light(double x, double y, double z, double radius)
{
  const double h[4] = { x, y, z, 1.0 }, focal[3] = { 0, 0, 0 };
  vsh_rt_light light;
  CHECK(vsh_rt_light_init(h, focal, 180.0, radius, 0.0, &light) == VSH_RT_OK);
  return light;
}

static void test_far_light_over_plane(void)
{
  /* Radius 1 at height 1000: N.L varies by 5e-7 over the disk. Half of
   * the disk blocked (an edge through the centre). */
  const vsh_rt_light light = point_light(0.0, 0.0, 1000.0, 1.0);
  const double p[3] = { 0, 0, 0 }, up[3] = { 0, 0, 1 }, edge[3] = { 1, 0, 0 };
  double plain;
  const double v = trace(&light, p, up, edge, 256, &plain);
  CHECK(plain > 0.3 && plain < 0.7);
  CHECK_NEAR(v, plain, 1e-6);
  /* The same at 1e6 from the origin (camera-relative inputs keep it). */
  const vsh_rt_light far = point_light(1e6, 1e6, 1000.0, 1.0);
  const double q[3] = { 1e6, 1e6, 0 };
  CHECK_NEAR(trace(&far, q, up, edge, 256, &plain), plain, 1e-6);
}

static void test_terminator(void)
{
  /* A point on a caster's terminator (the light's centre in its tangent
   * plane), a disk light straight above: normal horizontal; the half of
   * the light below its horizon is blocked by the (convex) caster itself
   * and has weight 0. */
  const vsh_rt_light light = point_light(0.0, 0.0, 5.0, 0.5);
  const double p[3] = { 0, 0, 0 }, n[3] = { 1, 0, 0 };
  double plain;
  const double v = trace(&light, p, n, n, 256, &plain);
  CHECK(plain > 0.3 && plain < 0.7); /* the part of the disk above the horizon */
  CHECK_NEAR(v, 1.0, 1e-12);
}

static void test_closed_form(void)
{
  const double n[3] = { 0, 0, 2 }; /* length 2: the weight is a cosine */
  const double a[3] = { 0, 0, 1 }, b[3] = { sqrt(0.75), 0, 0.5 };
  vsh_rt_visibility v;
  memset(&v, 0, sizeof v);
  CHECK_NEAR(vsh_rt_sample_weight(n, a), 1.0, 1e-15);
  CHECK_NEAR(vsh_rt_sample_weight(n, b), 0.5, 1e-15);
  vsh_rt_visibility_add(&v, vsh_rt_sample_weight(n, a), 0);
  vsh_rt_visibility_add(&v, vsh_rt_sample_weight(n, b), 1);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 1.0 / 1.5, 1e-15);
  CHECK(v.traced == 2 && v.blocked == 1);
}

static void test_below_horizon(void)
{
  /* Every ray below the horizon: 0/0, the plain fraction (1 of 4 free). */
  const double n[3] = { 0, 0, -1 }, up[3] = { 0, 0, 1 };
  vsh_rt_visibility v;
  memset(&v, 0, sizeof v);
  for (int k = 0; k < 4; ++k) {
    CHECK(vsh_rt_sample_weight(n, up) == 0.0);
    vsh_rt_visibility_add(&v, vsh_rt_sample_weight(n, up), k != 0);
  }
  CHECK_NEAR(vsh_rt_visibility_value(&v), 0.25, 1e-15);
  /* A ray exactly in the tangent plane has weight 0 too. */
  const double side[3] = { 1, 0, 0 };
  CHECK(vsh_rt_sample_weight(up, side) == 0.0);
}

static void test_degenerate(void)
{
  const double zero[3] = { 0, 0, 0 }, nan3[3] = { NAN, 0, 1 }, inf3[3] = { INFINITY, 0, 0 };
  const double d[3] = { 0, 0.6, 0.8 }, tiny[3] = { 0, 0, 1e-6 }, huge[3] = { 0, 0, 1e6 };
  CHECK(vsh_rt_sample_weight(zero, d) == 1.0);
  CHECK(vsh_rt_sample_weight(nan3, d) == 1.0);
  CHECK(vsh_rt_sample_weight(inf3, d) == 1.0);
  CHECK(vsh_rt_sample_weight(NULL, d) == 1.0);
  CHECK(vsh_rt_sample_weight(tiny, NULL) == 1.0);
  CHECK(vsh_rt_sample_weight(tiny, nan3) == 1.0);
  CHECK_NEAR(vsh_rt_sample_weight(tiny, d), 0.8, 1e-15);
  CHECK_NEAR(vsh_rt_sample_weight(huge, d), 0.8, 1e-15);
  vsh_rt_visibility v;
  memset(&v, 0, sizeof v);
  CHECK(vsh_rt_visibility_value(&v) == 1.0); /* nothing traced: lit */
  vsh_rt_visibility_add(&v, NAN, 1);
  vsh_rt_visibility_add(&v, -2.0, 0);
  vsh_rt_visibility_add(&v, INFINITY, 0);
  CHECK(v.weight == 0.0);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 2.0 / 3.0, 1e-15);
  vsh_rt_visibility_add(&v, 1e-300, 1); /* the only weight: blocked */
  CHECK(vsh_rt_visibility_value(&v) == 0.0);
}

/* Rays through translucent casters (vsh_transmit.h) count their
 * transmitted fraction: two rays of weight 1 at 0.25 and 1 give 0.625; the
 * plain fraction (every weight 0) too; 0 and 1 are blocked and free; NaN
 * and out-of-range values clamp (NaN blocked). */
static void test_transmitted(void)
{
  const double n[3] = { 0, 0, 1 }, up[3] = { 0, 0, 1 }, side[3] = { 1, 0, 0 };
  vsh_rt_visibility v;
  memset(&v, 0, sizeof v);
  vsh_rt_visibility_add_transmitted(&v, vsh_rt_sample_weight(n, up), 0.25);
  vsh_rt_visibility_add_transmitted(&v, vsh_rt_sample_weight(n, up), 1.0);
  CHECK(v.partial == 1 && v.blocked == 0 && v.traced == 2);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 0.625, 1e-15);
  vsh_rt_visibility_add_transmitted(&v, vsh_rt_sample_weight(n, up), 0.0);
  CHECK(v.blocked == 1);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 1.25 / 3.0, 1e-15);
  memset(&v, 0, sizeof v);
  vsh_rt_visibility_add_transmitted(&v, vsh_rt_sample_weight(n, side), 0.36); /* weight 0 */
  vsh_rt_visibility_add_transmitted(&v, vsh_rt_sample_weight(n, side), 1.0);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 0.68, 1e-15);
  memset(&v, 0, sizeof v);
  vsh_rt_visibility_add_transmitted(&v, 1.0, NAN);
  vsh_rt_visibility_add_transmitted(&v, 1.0, -0.5);
  vsh_rt_visibility_add_transmitted(&v, 1.0, 2.0);
  CHECK(v.blocked == 2 && v.partial == 0);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 1.0 / 3.0, 1e-15);
}

/* Coloured rays (a filter tints what gets through): the scalar counts each
 * ray by its largest channel and the tint gives each channel back:
 * (0.5, 0.25, 0.1) and a free ray of equal weight give 0.75 and tint
 * (1, 0.625/0.75, 0.55/0.75); grey rays tint (1, 1, 1); a ray free in red
 * only is partial; NaN channels count 0; nothing through tints 1. */
static void test_coloured(void)
{
  vsh_rt_visibility v;
  memset(&v, 0, sizeof v);
  const double red[3] = { 0.5, 0.25, 0.1 }, clear[3] = { 1, 1, 1 };
  double tint[3];
  vsh_rt_visibility_add_coloured(&v, 1.0, red);
  vsh_rt_visibility_add_coloured(&v, 1.0, clear);
  CHECK_NEAR(vsh_rt_visibility_value(&v), 0.75, 1e-15);
  vsh_rt_visibility_tint(&v, tint);
  CHECK_NEAR(tint[0], 1.0, 1e-15);
  CHECK_NEAR(tint[1], 0.625 / 0.75, 1e-15);
  CHECK_NEAR(tint[2], 0.55 / 0.75, 1e-15);
  CHECK_NEAR(vsh_rt_visibility_value(&v) * tint[1], 0.625, 1e-15);
  memset(&v, 0, sizeof v);
  vsh_rt_visibility_add_transmitted(&v, 1.0, 0.36);
  vsh_rt_visibility_tint(&v, tint);
  CHECK(tint[0] == 1.0 && tint[1] == 1.0 && tint[2] == 1.0);
  memset(&v, 0, sizeof v);
  const double only_red[3] = { 1.0, 0.0, NAN };
  vsh_rt_visibility_add_coloured(&v, 1.0, only_red);
  CHECK(v.partial == 1 && v.blocked == 0);
  CHECK(vsh_rt_visibility_value(&v) == 1.0);
  vsh_rt_visibility_tint(&v, tint);
  CHECK(tint[0] == 1.0 && tint[1] == 0.0 && tint[2] == 0.0);
  memset(&v, 0, sizeof v);
  vsh_rt_visibility_add(&v, 1.0, 1);
  vsh_rt_visibility_tint(&v, tint);
  CHECK(tint[0] == 1.0 && tint[1] == 1.0 && tint[2] == 1.0);
}

int main(void)
{
  test_far_light_over_plane();
  test_terminator();
  test_closed_form();
  test_below_horizon();
  test_degenerate();
  test_transmitted();
  test_coloured();
  return vsh_check_report("rt_weight");
}
