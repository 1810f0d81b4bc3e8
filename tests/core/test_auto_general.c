/* core.auto_general: auto's choice among csm, volume and raytrace, the
 * thin-caster rule and the thinnest width of a mesh's components. */
#include "vsh_auto_general.h"
#include "vsh_check.h"
#include "vsh_random.h"

#include <math.h>
#include <stdlib.h>

static void test_pick(void)
{
  vsh_auto_candidate c[3] = {{1, 0.3, 5.0}, {1, 0.0, 9.0}, {1, 0.0, 7.0}};
  int met = -1;
  /* csm meets 0.5 and is cheapest. */
  CHECK(vsh_auto_pick_cheapest(c, 3, 0.5, &met) == 0 && met == 1);
  /* A tighter target rules csm out: the cheaper exact one. */
  CHECK(vsh_auto_pick_cheapest(c, 3, 0.1, &met) == 2 && met == 1);
  /* Exact candidates meet a zero target. */
  CHECK(vsh_auto_pick_cheapest(c, 3, 0.0, &met) == 2 && met == 1);
  /* Unavailable candidates are never picked. */
  c[2].available = 0;
  CHECK(vsh_auto_pick_cheapest(c, 3, 0.1, &met) == 1 && met == 1);
  /* Nothing meets: the lowest predicted error, met = 0. */
  vsh_auto_candidate only_maps[2] = {{1, 2.0, 1.0}, {1, 1.0, 3.0}};
  CHECK(vsh_auto_pick_cheapest(only_maps, 2, 0.5, &met) == 1 && met == 0);
  /* Equal errors when nothing meets: the cheaper one. */
  vsh_auto_candidate tie[2] = {{1, 1.0, 3.0}, {1, 1.0, 2.0}};
  CHECK(vsh_auto_pick_cheapest(tie, 2, 0.5, &met) == 1 && met == 0);
  /* Equal costs when both meet: the lower index. */
  vsh_auto_candidate same[2] = {{1, 0.0, 2.0}, {1, 0.0, 2.0}};
  CHECK(vsh_auto_pick_cheapest(same, 2, 0.5, &met) == 0);
  /* NaN counts as unavailable; none available gives -1. */
  vsh_auto_candidate bad[2] = {{1, NAN, 1.0}, {1, 0.0, NAN}};
  CHECK(vsh_auto_pick_cheapest(bad, 2, 0.5, &met) == -1 && met == 0);
  vsh_auto_candidate none[1] = {{0, 0.0, 1.0}};
  CHECK(vsh_auto_pick_cheapest(none, 1, 0.5, &met) == -1);
  CHECK(vsh_auto_pick_cheapest(NULL, 3, 0.5, &met) == -1);
  CHECK(vsh_auto_pick_cheapest(c, 0, 0.5, NULL) == -1);
  /* Infinite cost is still a choice when it is the only one. */
  vsh_auto_candidate inf[1] = {{1, 0.0, INFINITY}};
  CHECK(vsh_auto_pick_cheapest(inf, 1, 0.5, &met) == 0 && met == 1);
}

static void test_map_resolves(void)
{
  CHECK(vsh_auto_map_resolves(10.0, 2.0, 2.0) == 1);
  CHECK(vsh_auto_map_resolves(4.0, 2.0, 2.0) == 1); /* exactly two texels */
  CHECK(vsh_auto_map_resolves(3.99, 2.0, 2.0) == 0);
  CHECK(vsh_auto_map_resolves(INFINITY, 2.0, 2.0) == 1);
  CHECK(vsh_auto_map_resolves(NAN, 2.0, 2.0) == 0);
  CHECK(vsh_auto_map_resolves(10.0, 0.0, 2.0) == 0);
  CHECK(vsh_auto_map_resolves(10.0, -1.0, 2.0) == 0);
  CHECK(vsh_auto_map_resolves(10.0, NAN, 2.0) == 0);
  CHECK(vsh_auto_map_resolves(0.0, 1e-9, 0.0) == 1);
}

/* The 8 corners of a box with half-sizes h, rotated by the unit quaternion q
 * and moved to c, as one component. */
static void box_corners(const double h[3], const double q[4], const double c[3], double out[24])
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int i = 0; i < 8; ++i) {
    const double p[3] = {(i & 1) ? h[0] : -h[0], (i & 2) ? h[1] : -h[1], (i & 4) ? h[2] : -h[2]};
    for (int k = 0; k < 3; ++k)
      out[3 * i + k] = c[k] + r[k][0] * p[0] + r[k][1] * p[1] + r[k][2] * p[2];
  }
}

static void test_thinnest(void)
{
  const double identity[4] = {1, 0, 0, 0}, origin[3] = {0, 0, 0};
  double pos[48];
  unsigned int comp[16];
  /* A needle 0.02 x 0.02 x 4: width 0.02 (its middle extent). */
  box_corners((double[]){0.01, 0.01, 2.0}, identity, origin, pos);
  for (int i = 0; i < 8; ++i)
    comp[i] = 0;
  CHECK_NEAR(vsh_mesh_thinnest_width(pos, 8, comp, 1), 0.02, 1e-12);
  /* A plate 4 x 4 x 0.001: width 4, it casts a wide shadow. */
  box_corners((double[]){2.0, 2.0, 0.0005}, identity, origin, pos);
  CHECK_NEAR(vsh_mesh_thinnest_width(pos, 8, comp, 1), 4.0, 1e-9);
  /* Two components: the thinner one counts. */
  box_corners((double[]){1.0, 1.0, 1.0}, identity, origin, pos);
  box_corners((double[]){0.05, 0.05, 3.0}, identity, (double[]){5, 0, 0}, pos + 24);
  for (int i = 8; i < 16; ++i)
    comp[i] = 1;
  CHECK_NEAR(vsh_mesh_thinnest_width(pos, 16, comp, 2), 0.1, 1e-9);
  /* Unused vertices (VSH_MESH_NONE) and out-of-range components are ignored. */
  comp[3] = 0xffffffffu;
  comp[12] = 7;
  CHECK(isfinite(vsh_mesh_thinnest_width(pos, 16, comp, 2)));
  /* Rotation invariance and a 1e6 offset: a needle along a random axis. */
  vsh_test_seed(12345);
  for (int t = 0; t < 200; ++t) {
    double q[4];
    double n = 0;
    for (int k = 0; k < 4; ++k) {
      q[k] = vsh_test_rnd(-1.0, 1.0);
      n += q[k] * q[k];
    }
    if (n < 1e-6)
      continue;
    for (int k = 0; k < 4; ++k)
      q[k] /= sqrt(n);
    const double far[3] = {1e6, -2e6, 3e6};
    box_corners((double[]){0.01, 0.03, 2.0}, q, far, pos);
    for (int i = 0; i < 8; ++i)
      comp[i] = 0;
    CHECK_NEAR(vsh_mesh_thinnest_width(pos, 8, comp, 1), 0.06, 1e-6);
    /* A 1e-6 scale. */
    box_corners((double[]){1e-8, 3e-8, 2e-6}, q, origin, pos);
    CHECK_NEAR(vsh_mesh_thinnest_width(pos, 8, comp, 1), 6e-8, 1e-13);
  }
  /* Degenerate input: a single vertex, collinear points, nothing. */
  const double one[3] = {1, 2, 3};
  unsigned int c0 = 0;
  CHECK(isinf(vsh_mesh_thinnest_width(one, 1, &c0, 1)));
  const double line[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2};
  unsigned int c3[3] = {0, 0, 0};
  CHECK_NEAR(vsh_mesh_thinnest_width(line, 3, c3, 1), 0.0, 1e-12);
  CHECK(isinf(vsh_mesh_thinnest_width(NULL, 3, c3, 1)));
  CHECK(isinf(vsh_mesh_thinnest_width(line, 3, NULL, 1)));
  CHECK(isinf(vsh_mesh_thinnest_width(line, 3, c3, 0)));
}

static void test_masks_and_thin_error(void)
{
  const int t[5] = {8, 2, 8, 0, 4};
  CHECK(vsh_auto_light_mask(t, 5, 8) == 0x5u);
  CHECK(vsh_auto_light_mask(t, 5, 2) == 0x2u);
  CHECK(vsh_auto_light_mask(t, 5, 4) == 0x10u);
  CHECK(vsh_auto_light_mask(t, 5, 1) == 0u);
  CHECK(vsh_auto_light_mask(NULL, 5, 8) == 0u);
  int many[40];
  for (int i = 0; i < 40; ++i)
    many[i] = 8;
  CHECK(vsh_auto_light_mask(many, 40, 8) == 0xffffffffu);
  /* Resolved parts add nothing. */
  CHECK(vsh_auto_thin_caster_error(10.0, 2.0, 500.0, 1e5) == 0.0);
  /* A 1 px needle under 2 px texels, 400 px of outline: 200 px lost. */
  CHECK_NEAR(vsh_auto_thin_caster_error(1.0, 2.0, 400.0, 1e5), 0.2, 1e-12);
  /* Sub-pixel parts count a pixel wide. */
  CHECK_NEAR(vsh_auto_thin_caster_error(0.1, 2.0, 400.0, 1e5), 0.2, 1e-12);
  /* A wider part that is still unresolved loses more. */
  CHECK_NEAR(vsh_auto_thin_caster_error(3.0, 2.0, 400.0, 1e5), 0.6, 1e-12);
  CHECK(isinf(vsh_auto_thin_caster_error(1.0, 2.0, 400.0, 0.0)));
  CHECK(isinf(vsh_auto_thin_caster_error(1.0, 2.0, NAN, 1e5)));
  /* Maps not trusted (no texel size): the whole outline counts. */
  CHECK(vsh_auto_thin_caster_error(5.0, NAN, 100.0, 1e4) > 0.0);
}

int main(void)
{
  test_masks_and_thin_error();
  test_pick();
  test_map_resolves();
  test_thinnest();
  return vsh_check_report("core.auto_general");
}
