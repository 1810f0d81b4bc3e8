/* vsh_auto: the conservative "may A shadow B" tests behind technique auto. */
#include "vsh_auto.h"

#include <math.h>

#include "vsh_check.h"

int main(void)
{
  const double sun[4] = {0, 0, 1, 0}; /* light from straight above */
  const double a[3] = {0, 0, 2}, below[3] = {0, 0, 0}, beside[3] = {5, 0, 0};
  const double above[3] = {0, 0, 4};
  /* Directional, spheres */
  CHECK(vsh_auto_may_shadow(a, 1, below, 0.5, sun) == 1);
  CHECK(vsh_auto_may_shadow(a, 1, beside, 0.5, sun) == 0);
  CHECK(vsh_auto_may_shadow(a, 1, above, 0.5, sun) == 0);
  CHECK(vsh_auto_may_shadow(a, 1, (double[3]){1.4, 0, 0}, 0.5, sun) == 1); /* grazes the cylinder */
  CHECK(vsh_auto_may_shadow(a, 1, (double[3]){1.6, 0, 0}, 0.5, sun) == 0);
  /* Positional: cone from the light through A */
  const double lamp[4] = {0, 0, 10, 1};
  CHECK(vsh_auto_may_shadow(a, 1, below, 0.5, lamp) == 1);
  CHECK(vsh_auto_may_shadow(a, 1, (double[3]){3, 0, 0}, 0.5, lamp) == 0);
  CHECK(vsh_auto_may_shadow(a, 1, above, 0.5, lamp) == 0); /* nearer to the lamp */
  const double lamp_w2[4] = {0, 0, 20, 2};                 /* same lamp, w = 2 */
  CHECK(vsh_auto_may_shadow(a, 1, below, 0.5, lamp_w2) == 1);
  CHECK(vsh_auto_may_shadow(a, 1, below, 0.5, (double[4]){0, 0, 2.5, 1}) == 1); /* inside A */
  /* Bad input is answered conservatively */
  CHECK(vsh_auto_may_shadow(a, -1, below, 0.5, sun) == 1);
  CHECK(vsh_auto_may_shadow(a, 1, below, NAN, sun) == 1);
  CHECK(vsh_auto_may_shadow(a, 1, below, 0.5, (double[4]){0, 0, 0, 0}) == 1);
  CHECK(vsh_auto_may_shadow(a, 1, below, 0.5, (double[4]){INFINITY, 0, 1, 0}) == 1);

  /* Boxes, directional */
  const double amin[3] = {-1, -1, 1}, amax[3] = {1, 1, 2};
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){-0.5, -0.5, 0}, (double[3]){0.5, 0.5, 0.5},
                                sun) == 1);
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){2, 2, 0}, (double[3]){3, 3, 0.5}, sun) ==
        0);
  /* touching from below (B's top is A's bottom): the ray leaves at once */
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){-1, -1, 0}, (double[3]){1, 1, 1},
                                (double[3]){0, 0, -1}) == 0);
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){-1, -1, 0}, (double[3]){1, 1, 1}, sun) ==
        1);
  /* a plate under a sphere, light from above: the plate cannot shadow it */
  CHECK(vsh_auto_box_may_shadow((double[3]){-1.5, -1, 0}, (double[3]){1.5, 1, 0.01},
                                (double[3]){-0.1, -0.3, 0.01}, (double[3]){1.1, 0.9, 1.21},
                                (double[3]){1, -0.5, 0.95}) == 0);
  /* overlapping volumes: conservative yes */
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){0, 0, 1.5}, (double[3]){3, 3, 3}, sun) ==
        1);
  /* a light parallel to an axis with B outside that slab */
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){5, -1, 0}, (double[3]){6, 1, 3},
                                (double[3]){0, 1, 0}) == 0);
  CHECK(vsh_auto_box_may_shadow(amin, amax, (double[3]){0, 0, 0}, (double[3]){1, 1, 1},
                                (double[3]){0, 0, 0}) == 1);

  /* Plane side */
  const double floor[4] = {0, 0, 1, 0};
  CHECK(vsh_auto_on_lit_side(floor, sun, (double[3]){0, 0, 2}, 1) == 1);
  CHECK(vsh_auto_on_lit_side(floor, sun, (double[3]){0, 0, 0.5}, 1) == 0); /* crosses it */
  CHECK(vsh_auto_on_lit_side(floor, sun, (double[3]){0, 0, -2}, 1) == 0);
  const double flipped[4] = {0, 0, -1, 0}; /* the normal's sign does not matter */
  CHECK(vsh_auto_on_lit_side(flipped, sun, (double[3]){0, 0, 2}, 1) == 1);
  CHECK(vsh_auto_on_lit_side(floor, (double[4]){0, 0, -5, 1}, (double[3]){0, 0, -2}, 1) == 1);
  CHECK(vsh_auto_on_lit_side(floor, (double[4]){1, 0, 0, 0}, (double[3]){0, 0, 2}, 1) == 0);
  CHECK(vsh_auto_on_lit_side((double[4]){0, 0, 0, 1}, sun, (double[3]){0, 0, 2}, 1) == 0);
  /* Texel target from an error target: closed form, monotone, bad input. */
  CHECK_NEAR(vsh_auto_texel_target(0.0, 120000, 1400, 1.0, 1.0), 2.0, 1e-15); /* band only */
  CHECK_NEAR(vsh_auto_texel_target(0.5, 120000, 1400, 1.0, 1.0), 2.0 * (1.0 + 600.0 / 1400.0),
             1e-12);
  CHECK(vsh_auto_texel_target(1.0, 120000, 1400, 1.0, 1.0) >
        vsh_auto_texel_target(0.5, 120000, 1400, 1.0, 1.0));
  CHECK(vsh_auto_texel_target(0.5, 120000, 2800, 1.0, 1.0) <
        vsh_auto_texel_target(0.5, 120000, 1400, 1.0, 1.0));
  /* A stretch of 2 is the same as an edge twice as long. */
  CHECK_NEAR(vsh_auto_texel_target(0.5, 120000, 1400, 2.0, 1.0),
             vsh_auto_texel_target(0.5, 120000, 2800, 1.0, 1.0), 1e-12);
  /* A grazing light (85 degrees, stretch 11.5) leaves little beyond the band. */
  CHECK(vsh_auto_texel_target(0.5, 120000, 1400, 1.0 / cos(85.0 * 3.14159265358979 / 180.0), 1.0) <
        2.1);
  CHECK(vsh_auto_texel_target(0.5, 120000, 1400, 0.5, 1.0) == 0.0); /* stretch < 1 */
  CHECK(vsh_auto_texel_target(0.5, 120000, 1400, NAN, 1.0) == 0.0);
  /* Its prediction met exactly: an edge of L px at that texel size gives
   * L * (t/2 - band) wrong px = the allowed share of the frame. */
  {
    const double t = vsh_auto_texel_target(0.25, 1e6, 5000, 1.0, 1.0);
    CHECK_NEAR(5000 * (t / 2 - 1.0) / 1e6 * 100.0, 0.25, 1e-12);
  }
  CHECK(vsh_auto_texel_target(-0.1, 120000, 1400, 1.0, 1.0) == 0.0);
  CHECK(vsh_auto_texel_target(NAN, 120000, 1400, 1.0, 1.0) == 0.0);
  CHECK(vsh_auto_texel_target(0.5, 0.0, 1400, 1.0, 1.0) == 0.0);
  CHECK(vsh_auto_texel_target(0.5, 120000, 0.0, 1.0, 1.0) == 0.0);
  CHECK(vsh_auto_texel_target(0.5, 120000, 1400, 1.0, -1.0) == 0.0);
  CHECK(vsh_auto_texel_target(0.5, INFINITY, 1400, 1.0, 1.0) == 0.0);
  CHECK(vsh_auto_texel_target(1e308, 1e308, 1e-308, 1.0, 1.0) == 0.0); /* overflow */
  return vsh_check_report("core.auto");
}
