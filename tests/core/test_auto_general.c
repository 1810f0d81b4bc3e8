/* core.auto_general: auto's choice among csm, volume and raytrace, the
 * thin-caster rule and the thinnest width of a mesh's components. */
#include "vsh_auto_general.h"
#include "vsh_check.h"
#include "vsh_random.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* p turned by the unit quaternion q. */
static void rotate(const double q[4], const double p[3], double out[3])
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int k = 0; k < 3; ++k)
    out[k] = r[k][0] * p[0] + r[k][1] * p[1] + r[k][2] * p[2];
}

/* A capped cone like vtkConeSource's: `res` base vertices on a circle of
 * radius r at x = 0, the apex at x = h, turned by the unit quaternion q and
 * moved by `at`. Base first, apex last: res + 1 vertices, 2 res - 2
 * triangles (res sides, a fan of res - 2 for the cap). */
static void cone(int res, double r, double h, const double q[4], const double at[3],
                 double *pos, unsigned int *tri, unsigned int first)
{
  for (int i = 0; i <= res; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / res;
    const double p[3] = {i == res ? h : 0.0, i == res ? 0.0 : r * cos(a),
                         i == res ? 0.0 : r * sin(a)};
    rotate(q, p, pos + 3 * i);
    for (int k = 0; k < 3; ++k)
      pos[3 * i + k] += at[k];
  }
  int t = 0;
  for (int i = 0; i < res; ++i, ++t) {
    tri[3 * t] = first + (unsigned)res;
    tri[3 * t + 1] = first + (unsigned)i;
    tri[3 * t + 2] = first + (unsigned)((i + 1) % res);
  }
  for (int i = 1; i + 1 < res; ++i, ++t) {
    tri[3 * t] = first;
    tri[3 * t + 1] = first + (unsigned)(i + 1);
    tri[3 * t + 2] = first + (unsigned)i;
  }
}

static void test_taper(void)
{
  enum { S = VSH_MESH_TAPER_SLICES, RES = 24, V = RES + 1, T = 2 * RES - 2 };
  const double identity[4] = {1, 0, 0, 0}, origin[3] = {0, 0, 0};
  double pos[3 * V * 2], widths[2 * S], lengths[2 * S];
  unsigned int tri[3 * T * 2], comp[2 * V];
  /* A cone glyph as in cone-glyphs (height 0.5, base radius 0.125): the
   * width falls linearly to 0 at the apex, although no vertex lies between
   * base and apex. Slice k's centre is at (k + 0.5) / S of the height. */
  cone(RES, 0.125, 0.5, identity, origin, pos, tri, 0);
  for (int i = 0; i < V; ++i)
    comp[i] = 0;
  CHECK(vsh_mesh_taper_profile(pos, V, tri, T, comp, 1, widths, lengths) == S);
  /* The widest cross-section of a 24-gon along the middle axis lies between
   * its width across flats and across corners. */
  const double flats = 0.25 * cos(3.14159265358979323846 / RES);
  const int base_first = widths[0] > widths[S - 1]; /* the axis may point either way */
  for (int k = 0; k < S; ++k) {
    const double fraction = 1.0 - (k + 0.5) / S;
    const double w = base_first ? widths[k] : widths[S - 1 - k];
    CHECK(w >= flats * fraction - 1e-9 && w <= 0.25 * fraction + 1e-9);
    CHECK_NEAR(lengths[k], 0.5 / S, 1e-12);
  }
  /* Its tip loses its shadow under coarse texels. At 50 px per unit the cone
   * is 25 px long and 12.5 px wide; 2 texels of 2 px lose the slices
   * narrower than 4 px: the last 8 px of the tip, about half of 8 x 4 px.
   * Analytically 0.5 * 8 * 4 = 16 px; the slices give within a slice. */
  const double tip = vsh_auto_taper_error(widths, lengths, S, 50.0, 2.0, 2.0, 1.0, 1e4);
  CHECK(tip > 100.0 * 12.0 / 1e4 && tip < 100.0 * 20.0 / 1e4);
  /* The stretch of the receivers lengthens the lost shadow. */
  CHECK_NEAR(vsh_auto_taper_error(widths, lengths, S, 50.0, 2.0, 2.0, 2.0, 1e4), 2.0 * tip,
             1e-12);
  /* Finer texels lose less, fine enough nothing; coarse enough, everything
   * (about half of 25 x 12.5 px). */
  CHECK(vsh_auto_taper_error(widths, lengths, S, 50.0, 1.0, 2.0, 1.0, 1e4) < tip / 3.0);
  CHECK(vsh_auto_taper_error(widths, lengths, S, 50.0, 0.01, 2.0, 1.0, 1e4) == 0.0);
  const double all = vsh_auto_taper_error(widths, lengths, S, 50.0, 100.0, 2.0, 1.0, 1e4);
  CHECK(all > 100.0 * 140.0 / 1e4 && all < 100.0 * 160.0 / 1e4);
  /* A cylinder does not taper: at the same scale and texels nothing of it
   * is lost (this is what the thinnest-width rule already judged). */
  double cyl[3 * 16];
  unsigned int ctri[3 * 28], ccomp[16];
  for (int i = 0; i < 16; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * (i % 8) / 8;
    cyl[3 * i] = i < 8 ? 0.0 : 2.0;
    cyl[3 * i + 1] = 0.1 * cos(a);
    cyl[3 * i + 2] = 0.1 * sin(a);
    ccomp[i] = 0;
  }
  int t = 0;
  for (int i = 0; i < 8; ++i) {
    const unsigned a = (unsigned)i, b = (unsigned)((i + 1) % 8);
    const unsigned quad[6] = {a, b, b + 8, a, b + 8, a + 8};
    memcpy(ctri + 3 * t, quad, sizeof quad);
    t += 2;
  }
  for (int i = 1; i + 1 < 8; ++i, t += 2) {
    const unsigned caps[6] = {0, (unsigned)i + 1, (unsigned)i, 8, (unsigned)i + 8, (unsigned)i + 9};
    memcpy(ctri + 3 * t, caps, sizeof caps);
  }
  CHECK(vsh_mesh_taper_profile(cyl, 16, ctri, 28, ccomp, 1, widths, lengths) == S);
  CHECK(vsh_auto_taper_error(widths, lengths, S, 50.0, 2.0, 2.0, 1.0, 1e4) == 0.0);
  /* 49 cones, turned at random and 1e6 from the origin, as one mesh of 49
   * components (cone-glyphs): 49 times one cone's loss, whatever the turn. */
  enum { N = 49 };
  static double many[3 * V * N];
  static unsigned int mtri[3 * T * N], mcomp[V * N];
  static double mw[N * S], ml[N * S];
  vsh_test_seed(777);
  for (int g = 0; g < N; ++g) {
    double q[4], n = 0.0;
    do {
      n = 0.0;
      for (int k = 0; k < 4; ++k) {
        q[k] = vsh_test_rnd(-1.0, 1.0);
        n += q[k] * q[k];
      }
    } while (n < 1e-3);
    for (int k = 0; k < 4; ++k)
      q[k] /= sqrt(n);
    const double at[3] = {1e6 + 0.5 * (g % 7), -1e6 + 0.5 * (g / 7), 0.35};
    cone(RES, 0.125, 0.5, q, at, many + 3 * V * g, mtri + 3 * T * g, (unsigned)(V * g));
    for (int i = 0; i < V; ++i)
      mcomp[V * g + i] = (unsigned)g;
  }
  CHECK(vsh_mesh_taper_profile(many, V * N, mtri, T * N, mcomp, N, mw, ml) == (size_t)N * S);
  CHECK_NEAR(vsh_auto_taper_error(mw, ml, (size_t)N * S, 50.0, 2.0, 2.0, 1.0, 1e4), N * tip,
             0.02 * N * tip);
  /* Bad input: nothing written, or not trusted. */
  CHECK(vsh_mesh_taper_profile(NULL, V, tri, T, comp, 1, widths, lengths) == 0);
  CHECK(vsh_mesh_taper_profile(pos, V, NULL, T, comp, 1, widths, lengths) == 0);
  CHECK(vsh_mesh_taper_profile(pos, V, tri, T, comp, 0, widths, lengths) == 0);
  tri[4] = V; /* out of range */
  CHECK(vsh_mesh_taper_profile(pos, V, tri, T, comp, 1, widths, lengths) == 0);
  CHECK(isinf(vsh_auto_taper_error(widths, lengths, S, 50.0, NAN, 2.0, 1.0, 1e4)));
  CHECK(isinf(vsh_auto_taper_error(widths, lengths, S, 50.0, 2.0, 2.0, 1.0, 0.0)));
  CHECK(isinf(vsh_auto_taper_error(widths, lengths, S, -1.0, 2.0, 2.0, 1.0, 1e4)));
  CHECK(isinf(vsh_auto_taper_error(widths, lengths, S, 50.0, 2.0, 2.0, 0.5, 1e4)));
  CHECK(vsh_auto_taper_error(NULL, NULL, 0, 50.0, 2.0, 2.0, 1.0, 1e4) == 0.0);
  /* A single vertex and a degenerate (collinear) component give width 0:
   * nothing lost, never NaN. */
  const double line[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2};
  const unsigned int ltri[3] = {0, 1, 2}, lc[3] = {0, 0, 0};
  CHECK(vsh_mesh_taper_profile(line, 3, ltri, 1, lc, 1, widths, lengths) == S);
  const double flat = vsh_auto_taper_error(widths, lengths, S, 50.0, 2.0, 2.0, 1.0, 1e4);
  CHECK(flat >= 0.0 && flat < 1e-9);
}

/* Thin impostor casters: the floor every technique shares, the map's
 * texel term, and the texel target they give, at scenes/primitives'
 * figures (320x240; streamlines-tubes light 0: 1810 px of tube outline,
 * texels of 1.73 px at a 512 map; particle-cloud: 3619 px of spheres). */
static void test_thin_impostors(void)
{
  const double pixels = 320.0 * 240.0, tubes = 1810.0, spheres = 3619.0;
  const double floor = vsh_auto_thin_floor_error(0.0, tubes, pixels);
  CHECK(fabs(floor - 100.0 * VSH_AUTO_THIN_LINE_FLOOR * tubes / pixels) < 1e-12);
  /* raytrace measured 0.36 on the tubes, 0.18 on the spheres: within 1.35x */
  CHECK(floor > 0.36 / 1.35 && floor < 0.36 * 1.35);
  const double cloud = vsh_auto_thin_floor_error(spheres, 0.0, pixels);
  CHECK(cloud > 0.176 / 1.35 && cloud < 0.176 * 1.35);
  CHECK(fabs(vsh_auto_thin_floor_error(spheres, tubes, pixels) - floor - cloud) < 1e-12);
  /* csm at 512 (texels 1.73 px) measured 1.32 on the tubes */
  const double map = vsh_auto_thin_map_error(tubes, 1.73, pixels);
  CHECK(floor + map > 1.32 / 1.5 && floor + map < 1.32 * 1.5);
  /* Linear in the texel size: half the texel, half the map's term. */
  CHECK(fabs(vsh_auto_thin_map_error(tubes, 0.865, pixels) - 0.5 * map) < 1e-12);
  /* No impostors: nothing; bad input: not trusted (+inf). */
  CHECK(vsh_auto_thin_floor_error(0.0, 0.0, pixels) == 0.0);
  CHECK(vsh_auto_thin_map_error(0.0, 2.0, pixels) == 0.0);
  CHECK(isinf(vsh_auto_thin_floor_error(NAN, 0.0, pixels)));
  CHECK(isinf(vsh_auto_thin_floor_error(0.0, -1.0, pixels)));
  CHECK(isinf(vsh_auto_thin_floor_error(1.0, 1.0, 0.0)));
  CHECK(isinf(vsh_auto_thin_map_error(tubes, 0.0, pixels)));
  CHECK(isinf(vsh_auto_thin_map_error(tubes, NAN, pixels)));
  CHECK(isinf(vsh_auto_thin_map_error(tubes, 1.0, 0.0)));
  /* The texel target meets its budget exactly. */
  const double t = vsh_auto_thin_texel_target(0.4, tubes, pixels);
  CHECK(fabs(vsh_auto_thin_map_error(tubes, t, pixels) - 0.4) < 1e-9);
  CHECK(isinf(vsh_auto_thin_texel_target(0.4, 0.0, pixels)));
  CHECK(vsh_auto_thin_texel_target(0.0, tubes, pixels) == 0.0);
  CHECK(vsh_auto_thin_texel_target(-1.0, tubes, pixels) == 0.0);
  CHECK(vsh_auto_thin_texel_target(NAN, tubes, pixels) == 0.0);
  /* The frame's target: a light with a little impostor outline tightens it
   * to exactly the target, one that needs texels finer than the minimum
   * does not (it goes to an exact technique), lights without impostors
   * leave it. */
  const double no[3] = {0.0, 0.0, 0.0}, few[3] = {0.0, 1000.0, 0.0};
  const double tight = vsh_auto_thin_frame_texel(2.2, 0.5, few, no, 3, pixels);
  CHECK(tight < 2.2 && tight >= VSH_AUTO_THIN_MIN_TEXEL_PX);
  CHECK(fabs(vsh_auto_thin_map_error(1000.0, tight, pixels) +
             vsh_auto_thin_floor_error(1000.0, 0.0, pixels) - 0.5) < 1e-9);
  const double many_points[2] = {1000.0, 0.0}, many_lines[2] = {0.0, tubes};
  CHECK(vsh_auto_thin_frame_texel(2.2, 0.5, many_points, many_lines, 2, pixels) == tight);
  CHECK(vsh_auto_thin_frame_texel(2.2, 0.5, no, no, 3, pixels) == 2.2);
  CHECK(vsh_auto_thin_frame_texel(2.2, 0.5, NULL, no, 3, pixels) == 2.2);
  CHECK(vsh_auto_thin_frame_texel(0.0, 0.5, few, no, 3, pixels) == 0.0);
  /* An outline target finer than the impostors need stays. */
  CHECK(vsh_auto_thin_frame_texel(0.1, 0.5, few, no, 3, pixels) == 0.1);
}

/* The map's outline floor: linear in the outline and the stretch, the
 * library's worst light (basic/two-lights light 1: 358 px of outline,
 * stretch 1.18 at 320x240, auto's map measured 0.547) predicted above what
 * it measured, and bad input refused. */
static void test_map_outline_floor(void)
{
  const double pixels = 320.0 * 240.0;
  const double two_lights = vsh_auto_map_outline_error(358.0, 1.18, pixels);
  CHECK(two_lights > 0.547);
  CHECK(fabs(two_lights - 100.0 * VSH_AUTO_MAP_OUTLINE_FLOOR * 358.0 * 1.18 / pixels) < 1e-12);
  CHECK(fabs(vsh_auto_map_outline_error(716.0, 1.18, pixels) - 2 * two_lights) < 1e-12);
  CHECK(fabs(vsh_auto_map_outline_error(358.0, 2.36, pixels) - 2 * two_lights) < 1e-12);
  /* At 800x600 the same scene's outline is 2.5 times longer over 6.25
   * times the pixels: a map becomes a candidate at the default target. */
  CHECK(vsh_auto_map_outline_error(2.5 * 358.0, 1.18, 800.0 * 600.0) < 0.5);
  CHECK(vsh_auto_map_outline_error(0.0, 1.0, pixels) == 0.0);
  CHECK(isinf(vsh_auto_map_outline_error(-1.0, 1.0, pixels)));
  CHECK(isinf(vsh_auto_map_outline_error(NAN, 1.0, pixels)));
  CHECK(isinf(vsh_auto_map_outline_error(10.0, 0.5, pixels)));
  CHECK(isinf(vsh_auto_map_outline_error(10.0, 1.0, 0.0)));
  CHECK(isinf(vsh_auto_map_outline_error(10.0, INFINITY, pixels)));
  /* Shadow volumes' floor: above what volume measured against POV-Ray on
   * the library (docs/auto.md, "Shadow volumes' floor"), at 320x240 and at
   * 800x600, with the outline and open casters' quads auto counted there. */
  const double hd = 800.0 * 600.0;
  CHECK(vsh_auto_volume_floor_error(1117.0, 0.0, 0.0, pixels) > 0.0071);  /* table-parts 1 */
  CHECK(vsh_auto_volume_floor_error(2733.0, 0.0, 0.0, pixels) > 0.0247);  /* needles 1 */
  CHECK(vsh_auto_volume_floor_error(379.0, 0.0, 0.0, pixels) > 0.0078);   /* grazing-89.9 */
  /* Open casters counted z-pass (open_zfail off) ... */
  CHECK(vsh_auto_volume_floor_error(784.0, 7478.0, 0.0, pixels) > 0.089);   /* isosurface 0 */
  CHECK(vsh_auto_volume_floor_error(1960.0, 7478.0, 0.0, hd) > 0.0698);     /* isosurface 0 */
  CHECK(vsh_auto_volume_floor_error(1382.0, 1168.0, 0.0, pixels) > 0.0594); /* open-casters 0 */
  CHECK(vsh_auto_volume_floor_error(3455.0, 1168.0, 0.0, hd) > 0.0613);     /* open-casters 0 */
  /* ... and z-fail (the default). */
  CHECK(vsh_auto_volume_floor_error(784.0, 0.0, 7478.0, pixels) > 0.0275); /* isosurface 0 */
  CHECK(vsh_auto_volume_floor_error(1960.0, 0.0, 7478.0, hd) > 0.0200);    /* isosurface 0 */
  CHECK(vsh_auto_volume_floor_error(784.0, 0.0, 8190.0, pixels) > 0.0237); /* isosurface 1 */
  CHECK(vsh_auto_volume_floor_error(1382.0, 0.0, 1080.0, pixels) > 0.0039); /* open-casters 1 */
  CHECK(vsh_auto_volume_floor_error(3455.0, 0.0, 1080.0, hd) > 0.0040);     /* open-casters 1 */
  CHECK(vsh_auto_volume_floor_error(1432.0, 0.0, 848.0, pixels) > 0.0056);  /* elevation */
  /* ... and below 0.05 on closed casters with long outlines at 800x600,
   * where the volumes measured 0.004-0.006 (helix-tube, cone-glyphs), and
   * on elevation counted z-fail there (0.0024). */
  CHECK(vsh_auto_volume_floor_error(5975.0, 0.0, 0.0, hd) < 0.05);
  CHECK(vsh_auto_volume_floor_error(7572.0, 0.0, 0.0, hd) < 0.05);
  CHECK(vsh_auto_volume_floor_error(3579.0, 0.0, 848.0, hd) < 0.05);
  /* The formula, its growth with the frame, and the degenerate inputs. */
  CHECK(fabs(vsh_auto_volume_floor_error(1000.0, 0.0, 0.0, pixels) -
             100.0 * (VSH_AUTO_VOLUME_FLOOR_PX + VSH_AUTO_VOLUME_OUTLINE_FLOOR * 1000.0) /
               pixels) < 1e-12);
  CHECK(fabs(vsh_auto_volume_floor_error(0.0, 10.0, 20.0, 4.0 * pixels) -
             100.0 *
               (VSH_AUTO_VOLUME_FLOOR_PX + 4.0 * (VSH_AUTO_VOLUME_OPEN_QUAD * 10.0 +
                                                  VSH_AUTO_VOLUME_OPEN_QUAD_ZFAIL * 20.0)) /
               (4.0 * pixels)) < 1e-12);
  CHECK(vsh_auto_volume_floor_error(0.0, 0.0, 0.0, pixels) == 0.0);
  CHECK(isinf(vsh_auto_volume_floor_error(-1.0, 0.0, 0.0, pixels)));
  CHECK(isinf(vsh_auto_volume_floor_error(1.0, -1.0, 0.0, pixels)));
  CHECK(isinf(vsh_auto_volume_floor_error(1.0, 0.0, -1.0, pixels)));
  CHECK(isinf(vsh_auto_volume_floor_error(NAN, 0.0, 0.0, pixels)));
  CHECK(isinf(vsh_auto_volume_floor_error(1.0, NAN, 0.0, pixels)));
  CHECK(isinf(vsh_auto_volume_floor_error(1.0, 0.0, NAN, pixels)));
  CHECK(isinf(vsh_auto_volume_floor_error(1.0, 0.0, 0.0, 0.0)));
  CHECK(isinf(vsh_auto_volume_floor_error(1.0, 0.0, 0.0, INFINITY)));
}

int main(void)
{
  test_thin_impostors();
  test_map_outline_floor();
  test_masks_and_thin_error();
  test_pick();
  test_map_resolves();
  test_thinnest();
  test_taper();
  return vsh_check_report("core.auto_general");
}
