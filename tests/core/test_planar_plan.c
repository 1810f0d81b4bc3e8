/* test_planar_plan.c - unit tests of vsh_planar_plan: which (receiver, light)
 * pairs cast and with what, the mask's bits and channels, the caster tests
 * (in the plane, clipped) and the fans' screen rectangle. */
#include "vsh_check.h"
#include "vsh_mat4.h"
#include "vsh_planar.h"
#include "vsh_planar_plan.h"

#include <math.h>
#include <string.h>

static void test_mask_layout(void)
{
  CHECK(vsh_planar_receiver_fits(127, 1) == 1);
  CHECK(vsh_planar_receiver_fits(128, 1) == 0);
  CHECK(vsh_planar_receiver_fits(31, 4) == 1); /* 32 receivers x 4 lights = 128 */
  CHECK(vsh_planar_receiver_fits(32, 4) == 0);
  CHECK(vsh_planar_receiver_fits(127, 0) == 1); /* no light still takes a bit */
  CHECK(vsh_planar_receiver_fits(128, 0) == 0);
  CHECK(vsh_planar_mask_channels(8, 4) == 1);
  CHECK(vsh_planar_mask_channels(11, 3) == 4); /* 33 pairs */
  CHECK(vsh_planar_mask_channels(0, 5) == 1);
  unsigned int bits[4];
  vsh_planar_pair_bits(0, bits);
  CHECK(bits[0] == 1u && bits[1] == 0u && bits[2] == 0u && bits[3] == 0u);
  vsh_planar_pair_bits(33, bits);
  CHECK(bits[0] == 0u && bits[1] == 2u && bits[2] == 0u && bits[3] == 0u);
  vsh_planar_pair_bits(127, bits);
  CHECK(bits[0] == 0u && bits[1] == 0u && bits[2] == 0u && bits[3] == 0x80000000u);
  vsh_planar_pair_bits(128, bits);
  CHECK(bits[0] == 0u && bits[1] == 0u && bits[2] == 0u && bits[3] == 0u);
  vsh_planar_pair_bits(-1, bits);
  CHECK(bits[0] == 0u && bits[3] == 0u);
}

static void test_plan_pairs(void)
{
  /* Receiver 0: the floor z = 0 (normal down: the plan orients it). Receiver
   * 1: the wall x = 4. Lights: a sun above, a lamp below the floor, a sun
   * that does not cast, a lamp on the floor's plane, a sun parallel to it. */
  const double planes[8] = {0, 0, -1, 0, 1, 0, 0, -4};
  const vsh_planar_light lights[5] = {{{0, 0, 1, 0}, 1},
                                      {{0, 0, -5, 1}, 1},
                                      {{0, 0, 1, 0}, 0},
                                      {{2, 3, 0, 1}, 1},
                                      {{1, 0, 0, 0}, 1}};
  const double eye[3] = {3, -2, 7};
  vsh_planar_pair pairs[10];
  const int n = vsh_planar_plan_pairs(planes, 2, lights, 5, eye, pairs, 10);
  /* floor: the sun (bit 0) and the lamp below (bit 1); the lamp on its
   * plane and the parallel sun cast nothing there. wall: the sun from above
   * runs parallel to it; the lamp below (bit 6), the lamp at (2, 3, 0)
   * (bit 8) and the sun along +x (bit 9) cast. */
  CHECK(n == 5);
  CHECK(pairs[0].receiver == 0 && pairs[0].light == 0 && pairs[0].bit == 0);
  CHECK(pairs[1].receiver == 0 && pairs[1].light == 1 && pairs[1].bit == 1);
  CHECK(pairs[2].receiver == 1 && pairs[2].light == 1 && pairs[2].bit == 6);
  CHECK(pairs[3].receiver == 1 && pairs[3].light == 3 && pairs[3].bit == 8);
  CHECK(pairs[4].receiver == 1 && pairs[4].light == 4 && pairs[4].bit == 9);
  /* Oriented towards the light: the floor faces up for the sun, down for the
   * lamp below; the wall faces -x for lamps at x < 4, +x for the sun at +x. */
  CHECK(pairs[0].plane[2] == 1.0 && pairs[0].plane[3] == 0.0);
  CHECK(pairs[1].plane[2] == -1.0);
  CHECK(pairs[2].plane[0] == -1.0 && pairs[2].plane[3] == 4.0);
  CHECK(pairs[4].plane[0] == 1.0 && pairs[4].plane[3] == -4.0);
  /* The matrices are vsh_planar's for the oriented plane, camera-relative. */
  for (int i = 0; i < n; ++i) {
    double shadow[16], clip[2][4];
    const double *light = lights[pairs[i].light].homogeneous;
    CHECK(vsh_planar_shadow_matrix_relative(pairs[i].plane, light, eye, shadow) == VSH_PLANAR_OK);
    CHECK(vsh_planar_caster_clip_planes_relative(pairs[i].plane, light, eye, clip) ==
          VSH_PLANAR_OK);
    CHECK(memcmp(shadow, pairs[i].shadow, sizeof shadow) == 0);
    CHECK(memcmp(clip, pairs[i].clip, sizeof clip) == 0);
  }
  /* The sun flattens (1, 2, 3) onto the floor at (1, 2, 0), eye-relative. */
  {
    const double p[3] = {1 - eye[0], 2 - eye[1], 3 - eye[2]};
    double q[3];
    CHECK(vsh_planar_project_point(pairs[0].shadow, p, q) == 1);
    CHECK_NEAR(q[0] + eye[0], 1.0, 1e-12);
    CHECK_NEAR(q[1] + eye[1], 2.0, 1e-12);
    CHECK_NEAR(q[2] + eye[2], 0.0, 1e-12);
  }
  /* Capacity: only the first pairs. */
  CHECK(vsh_planar_plan_pairs(planes, 2, lights, 5, eye, pairs, 2) == 2);
  CHECK(pairs[1].bit == 1);
  CHECK(vsh_planar_plan_pairs(planes, 2, lights, 5, eye, NULL, 0) == 0);
  /* Nothing to pair. */
  CHECK(vsh_planar_plan_pairs(NULL, 0, lights, 5, eye, pairs, 10) == 0);
  CHECK(vsh_planar_plan_pairs(planes, 2, NULL, 0, eye, pairs, 10) == 0);
  /* Bad arguments. */
  CHECK(vsh_planar_plan_pairs(planes, -1, lights, 5, eye, pairs, 10) == -1);
  CHECK(vsh_planar_plan_pairs(planes, 2, lights, 5, NULL, pairs, 10) == -1);
  CHECK(vsh_planar_plan_pairs(NULL, 2, lights, 5, eye, pairs, 10) == -1);
  CHECK(vsh_planar_plan_pairs(planes, 2, lights, 5, eye, NULL, 3) == -1);
}

static void test_plan_bit_limit(void)
{
  /* 43 floors x 3 casting suns = 129 pairs: bit 128 has no room. */
  double planes[4 * 43];
  for (int r = 0; r < 43; ++r) {
    const double floor_r[4] = {0, 0, 1, -(double)r};
    memcpy(planes + 4 * r, floor_r, sizeof floor_r);
  }
  const vsh_planar_light suns[3] = {{{0, 0, 1, 0}, 1}, {{0.1, 0, 1, 0}, 1}, {{0, 0.1, 1, 0}, 1}};
  static vsh_planar_pair pairs[200];
  const double eye[3] = {0, 0, 100};
  const int n = vsh_planar_plan_pairs(planes, 43, suns, 3, eye, pairs, 200);
  CHECK(n == VSH_PLANAR_MAX_PAIRS);
  CHECK(pairs[n - 1].bit == VSH_PLANAR_MAX_PAIRS - 1);
  CHECK(pairs[n - 1].receiver == 42 && pairs[n - 1].light == 1);
}

static void test_caster_tests(void)
{
  const double floor_plane[4] = {0, 0, 1, 0};
  CHECK(vsh_planar_bounds_in_plane((double[6]){-1, 1, -1, 1, 0, 0}, floor_plane) == 1);
  CHECK(vsh_planar_bounds_in_plane((double[6]){-1, 1, -1, 1, 0, 1e-7}, floor_plane) == 1);
  CHECK(vsh_planar_bounds_in_plane((double[6]){-1, 1, -1, 1, 0, 1e-5}, floor_plane) == 0);
  CHECK(vsh_planar_bounds_in_plane((double[6]){-1, 1, -1, 1, 2, 2}, floor_plane) == 0);
  CHECK(vsh_planar_bounds_in_plane((double[6]){3, 3, 3, 3, 0, 0}, floor_plane) == 1); /* a point */

  /* A lamp 5 above the floor: kept is above the floor and below the lamp. */
  const double lamp[4] = {0, 0, 5, 1};
  const double eye[3] = {3, -2, 7};
  double clip[2][4];
  CHECK(vsh_planar_caster_clip_planes_relative(floor_plane, lamp, eye, clip) == VSH_PLANAR_OK);
  CHECK(vsh_planar_bounds_clipped(clip, (double[6]){-1, 1, -1, 1, 1, 2}, eye) == 0);
  CHECK(vsh_planar_bounds_clipped(clip, (double[6]){-1, 1, -1, 1, -1, 1}, eye) == 1); /* below */
  CHECK(vsh_planar_bounds_clipped(clip, (double[6]){-1, 1, -1, 1, 4, 6}, eye) == 1); /* above */
  CHECK(vsh_planar_bounds_clipped(clip, (double[6]){-1, 1, -1, 1, 0, 1}, eye) == 1); /* touches */
  /* Culled only when a whole box is on the wrong side of one plane. */
  CHECK(vsh_planar_bounds_culled(clip, (double[6]){-1, 1, -1, 1, 1, 2}, eye) == 0);
  CHECK(vsh_planar_bounds_culled(clip, (double[6]){-1, 1, -1, 1, -1, 1}, eye) == 0);
  CHECK(vsh_planar_bounds_culled(clip, (double[6]){-1, 1, -1, 1, -3, -1}, eye) == 1); /* below */
  CHECK(vsh_planar_bounds_culled(clip, (double[6]){-1, 1, -1, 1, 6, 8}, eye) == 1);   /* above */
  CHECK(vsh_planar_bounds_culled(clip, (double[6]){-1, 1, -1, 1, 4, 6}, eye) == 0);
}

static void test_fan_rect(void)
{
  double identity[16];
  vsh_mat4_identity(identity);
  const double origin[3] = {0, 0, 0};
  const int size[2] = {100, 80};
  int box[4];
  vsh_planar_rect rect;
  vsh_planar_rect_init(&rect);
  CHECK(vsh_planar_rect_pixels(&rect, size, box) == 0); /* empty */
  vsh_planar_rect_add_bounds(&rect, identity, (double[6]){-0.5, 0.5, -0.25, 0.25, 0, 1}, origin);
  CHECK(rect.full == 0);
  CHECK(rect.ndc[0] == -0.5 && rect.ndc[1] == -0.25 && rect.ndc[2] == 0.5 && rect.ndc[3] == 0.25);
  CHECK(vsh_planar_rect_pixels(&rect, size, box) == 1);
  /* floor(25) - 1, floor(30) - 1, ceil(75) + 1, ceil(50) + 1 */
  CHECK(box[0] == 24 && box[1] == 29 && box[2] == 76 && box[3] == 51);
  /* Eye-relative: the same box seen from an eye at (1, 0, 0) moves left. */
  vsh_planar_rect_init(&rect);
  vsh_planar_rect_add_bounds(&rect, identity, (double[6]){-0.5, 0.5, -0.25, 0.25, 0, 1},
                             (double[3]){1, 0, 0});
  CHECK(rect.ndc[0] == -1.5 && rect.ndc[2] == -0.5);
  CHECK(vsh_planar_rect_pixels(&rect, size, box) == 1);
  CHECK(box[0] == 0 && box[2] == 26); /* kept inside the viewport */
  /* Entirely off screen: empty. */
  vsh_planar_rect_init(&rect);
  vsh_planar_rect_add_bounds(&rect, identity, (double[6]){2, 3, 0, 0.5, 0, 1}, origin);
  CHECK(vsh_planar_rect_pixels(&rect, size, box) == 0);
  /* A projection whose w is z: corners at z <= 0 make it the whole viewport. */
  double w_is_z[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  vsh_planar_rect_init(&rect);
  vsh_planar_rect_add_bounds(&rect, w_is_z, (double[6]){-1, 1, -1, 1, 0, 1}, origin);
  CHECK(rect.full == 1);
  CHECK(vsh_planar_rect_pixels(&rect, size, box) == 1);
  CHECK(box[0] == 0 && box[1] == 0 && box[2] == 100 && box[3] == 80);
  /* A corner just in front of the camera projects far away: clamped, no
   * overflow into int. */
  vsh_planar_rect_init(&rect);
  vsh_planar_rect_add_bounds(&rect, w_is_z, (double[6]){-1e6, 1e6, 0, 1, 1e-300, 1e-300}, origin);
  CHECK(rect.full == 0);
  CHECK(vsh_planar_rect_pixels(&rect, size, box) == 1);
  CHECK(box[0] == 0 && box[2] == 100 && box[1] == 39 && box[3] == 80);
}

static void test_plane_to_view(void)
{
  /* The plane x = 2 seen from an eye at (5, 0, 0) with a view that turns x
   * into y: normal (0, 1, 0), offset 3 (the plane is 3 to the eye's -x). */
  const double view[16] = {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double out[4];
  vsh_planar_plane_to_view((double[4]){1, 0, 0, -2}, view, (double[3]){5, 0, 0}, out);
  CHECK(out[0] == 0.0 && out[1] == 1.0 && out[2] == 0.0 && out[3] == 3.0);
  /* A point on the plane, eye-relative and turned, lies on the result. */
  double p[3];
  vsh_mat4_transform_direction(view, (double[3]){2 - 5, 7, -1}, p);
  CHECK_NEAR(out[0] * p[0] + out[1] * p[1] + out[2] * p[2] + out[3], 0.0, 1e-15);
}

int main(void)
{
  test_mask_layout();
  test_plan_pairs();
  test_plan_bit_limit();
  test_caster_tests();
  test_fan_rect();
  test_plane_to_view();
  return vsh_check_report("core.planar_plan");
}
