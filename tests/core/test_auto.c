/* vsh_auto: the conservative "may A shadow B" tests behind technique auto. */
#include "vsh_auto.h"

#include <math.h>

#include "vsh_check.h"

/* ---- the per-light decision on plain objects ---------------------------- */

static void floor_and_ball(vsh_auto_object objects[3])
{
  vsh_auto_object_init(&objects[0], (double[6]){-5, 5, -5, 5, 0, 0}, 1, 1, NULL);
  objects[0].flat = 1;
  objects[0].plane[2] = 1.0;
  vsh_auto_object_init(&objects[1], (double[6]){-0.5, 0.5, -0.5, 0.5, 1, 2}, 0, 1, NULL);
  /* between the ball and the floor */
  vsh_auto_object_init(&objects[2], (double[6]){-0.5, 0.5, -0.5, 0.5, 0.2, 0.6}, 0, 1, NULL);
}

static void test_objects(void)
{
  vsh_auto_object o;
  vsh_auto_object_init(&o, (double[6]){0, 2, 0, 4, 0, 4}, 1, 0, NULL);
  CHECK(o.center[0] == 1 && o.center[1] == 2 && o.center[2] == 2);
  CHECK_NEAR(o.radius, 3.0, 1e-15);
  CHECK(o.receiver == 1 && o.casts == 0 && o.flat == 0 && o.in_view == 1);
  /* The cube [-1, 1]^3 as 6 inward planes. */
  const double cube[24] = {1, 0, 0, 1, -1, 0, 0, 1, 0, 1, 0, 1, 0, -1, 0, 1, 0, 0, 1, 1, 0, 0, -1, 1};
  CHECK(vsh_auto_sphere_in_frustum(cube, (double[3]){0, 0, 0}, 0.1) == 1);
  CHECK(vsh_auto_sphere_in_frustum(cube, (double[3]){1.5, 0, 0}, 1) == 1);
  CHECK(vsh_auto_sphere_in_frustum(cube, (double[3]){3, 0, 0}, 1) == 0);
  CHECK(vsh_auto_sphere_in_frustum(cube, (double[3]){0, 0, -2.5}, 1) == 0);
  vsh_auto_object_init(&o, (double[6]){2.5, 3.5, -0.5, 0.5, -0.5, 0.5}, 0, 1, cube);
  CHECK(o.in_view == 0);
  vsh_auto_object_init(&o, (double[6]){0.5, 1.5, -0.5, 0.5, -0.5, 0.5}, 0, 1, cube);
  CHECK(o.in_view == 1);
}

static void test_choose_light(void)
{
  const double sun[4] = {0, 0, 1, 0}, lamp[4] = {0, 0, 10, 1};
  vsh_auto_object objects[3];
  floor_and_ball(objects);
  vsh_auto_light_choice c = vsh_auto_choose_light(objects, 2, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_PLANAR && c.reason == VSH_AUTO_REASON_PLANES_ONLY);
  CHECK(c.a == -1 && c.b == -1);
  c = vsh_auto_choose_light(objects, 2, lamp, 0, -1);
  CHECK(c.technique == VSH_AUTO_PLANAR && c.reason == VSH_AUTO_REASON_PLANES_ONLY);
  /* The headlight first, then "no caster", then a concave caster. */
  c = vsh_auto_choose_light(objects, 2, sun, 1, 1);
  CHECK(c.technique == VSH_AUTO_NONE && c.reason == VSH_AUTO_REASON_HEADLIGHT);
  c = vsh_auto_choose_light(objects, 2, sun, 0, 1);
  CHECK(c.technique == VSH_AUTO_CSM && c.reason == VSH_AUTO_REASON_CONCAVE && c.a == 1);
  c = vsh_auto_choose_light(objects, 0, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_NONE && c.reason == VSH_AUTO_REASON_NO_CASTER);
  /* A caster over another object that is not a receiver: csm, naming both. */
  c = vsh_auto_choose_light(objects, 3, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_CSM && c.reason == VSH_AUTO_REASON_SHADOWS_OTHER);
  CHECK(c.a == 1 && c.b == 2);
  /* ... unless it is out of view, or casts nothing itself and is not shadowed. */
  objects[2].in_view = 0;
  c = vsh_auto_choose_light(objects, 3, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_PLANAR);
  objects[2].in_view = 1;
  objects[1].casts = 0;
  c = vsh_auto_choose_light(objects, 3, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_PLANAR); /* the small box shadows the floor only */
  objects[1].casts = 1;
  /* A receiver that is not flat is no plane receiver. */
  objects[0].flat = 0;
  c = vsh_auto_choose_light(objects, 2, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_CSM && c.reason == VSH_AUTO_REASON_SHADOWS_OTHER);
  CHECK(c.a == 1 && c.b == 0);
  /* Nothing under the caster: no shadow to draw. */
  vsh_auto_object_init(&objects[0], (double[6]){-1, 1, -1, 1, 0, 0}, 1, 1, NULL);
  objects[0].flat = 1;
  objects[0].plane[2] = 1.0;
  vsh_auto_object_init(&objects[1], (double[6]){9.5, 10.5, -0.5, 0.5, 1, 2}, 0, 1, NULL);
  c = vsh_auto_choose_light(objects, 2, sun, 0, -1);
  CHECK(c.technique == VSH_AUTO_NONE && c.reason == VSH_AUTO_REASON_NO_SHADOW);
}

static void test_stretch_masks_target(void)
{
  vsh_auto_object objects[3];
  floor_and_ball(objects);
  const double pi = 3.14159265358979323846;
  CHECK_NEAR(vsh_auto_plane_stretch(objects, 3, (double[4]){0, 0, 1, 0}), 1.0, 1e-15);
  CHECK_NEAR(vsh_auto_plane_stretch(objects, 3, (double[4]){sin(pi / 3), 0, cos(pi / 3), 0}), 2.0,
             1e-12);
  CHECK(vsh_auto_plane_stretch(objects, 3, (double[4]){1, 0, 0, 0}) == 64.0); /* grazing */
  CHECK_NEAR(vsh_auto_plane_stretch(objects, 3, (double[4]){0, 0, 10, 1}), 1.0, 1e-15);
  /* The light 45 degrees off at the floor's centre (0, 0, 0). */
  CHECK_NEAR(vsh_auto_plane_stretch(objects, 3, (double[4]){4, 0, 4, 1}), sqrt(2.0), 1e-12);
  objects[0].in_view = 0;
  CHECK(vsh_auto_plane_stretch(objects, 3, (double[4]){1, 0, 0, 0}) == 1.0);
  CHECK(vsh_auto_plane_stretch(objects, 0, (double[4]){1, 0, 0, 0}) == 1.0);

  unsigned int planar = 7, csm = 7;
  const int four[4] = {VSH_AUTO_PLANAR, VSH_AUTO_CSM, VSH_AUTO_NONE, VSH_AUTO_PLANAR};
  vsh_auto_light_masks(four, 4, &planar, &csm);
  CHECK(planar == 9u && csm == 2u);
  int forty[40];
  for (int l = 0; l < 40; ++l)
    forty[l] = VSH_AUTO_PLANAR;
  vsh_auto_light_masks(forty, 40, &planar, &csm);
  CHECK(planar == 0xffffffffu && csm == 0u); /* lights past 32 have no bit */
  vsh_auto_light_masks(four, 0, &planar, &csm);
  CHECK(planar == 0u && csm == 0u);

  CHECK(vsh_auto_frame_texel_target(3.0, 0.5, 120000, 1400, 1.0) == 3.0);
  CHECK(vsh_auto_frame_texel_target(0.0, 0.5, 120000, 1400, 2.0) ==
        vsh_auto_texel_target(0.5, 120000, 1400, 2.0, 1.0));
  CHECK(vsh_auto_frame_texel_target(0.0, 0.5, 120000, 0.0, 1.0) ==
        vsh_auto_texel_target(0.5, 120000, 1.0, 1.0, 1.0)); /* at least a pixel of edge */
}

int main(void)
{
  test_objects();
  test_choose_light();
  test_stretch_masks_target();
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
