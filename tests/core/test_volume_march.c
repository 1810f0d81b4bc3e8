/* test_volume_march.c - unit tests of vsh_volume_march: a constant opacity
 * box keeps exactly (1 - a)^(L / u) over a crossing of length L (straight,
 * diagonal, starting inside, ending inside, under a scaling), a ray that
 * misses or only touches the box keeps 1, the cutoff, the ray-box clip,
 * trilinear samples of a linear field, the transfer function table, the
 * opacity correction, and degenerate inputs (zero, negative or NaN
 * spacing, flat grids, NaN rays, a zero direction). */
#include "vsh_check.h"
#include "vsh_volume_march.h"

#include <math.h>

/* A constant opacity everywhere. */
static double constant(void *user, const double p[3])
{
  (void)p;
  return *(const double *)user;
}

/* A 20^3 grid of spacing 0.1 centred at (0, 0, 2): the box
 * [-0.95, 0.95]^2 x [1.05, 2.95]. */
static vsh_volume_grid box_grid(void)
{
  vsh_volume_grid g = {{-0.95, -0.95, 1.05}, {0.1, 0.1, 0.1}, {20, 20, 20}};
  return g;
}

static double march(const vsh_volume_grid *g, double alpha, double unit, const double o[3],
                    const double d[3], double t_max, int *samples)
{
  vsh_volume_march_input in = {g, unit, 0.0};
  vsh_volume_ray r = {{o[0], o[1], o[2]}, {d[0], d[1], d[2]}, 0.0, t_max};
  return vsh_volume_march(&in, &r, constant, &alpha, samples);
}

static void test_constant_box(void)
{
  const vsh_volume_grid g = box_grid();
  const double up[3] = {0, 0, 1}, floor[3] = {0.3, -0.2, 0};
  int n = 0;
  /* Straight up through the box: L = 1.9, (1 - 0.2)^(1.9 / 0.1). */
  CHECK_NEAR(march(&g, 0.2, 0.1, floor, up, INFINITY, &n), pow(0.8, 19.0), 1e-12);
  CHECK(n == 38); /* 1.9 at a step of 0.05 */
  /* A step that does not divide the length: still exact. */
  vsh_volume_grid odd = g;
  odd.spacing[0] = 0.07;
  CHECK_NEAR(march(&odd, 0.2, 0.1, floor, up, INFINITY, &n), pow(0.8, 19.0), 1e-12);
  CHECK(n == 55); /* ceil(1.9 / 0.035) */
  /* Diagonal: the crossing's length from the clip. */
  const double o[3] = {-2, -2, 0}, dir[3] = {1 / sqrt(3.0), 1 / sqrt(3.0), 1 / sqrt(3.0)};
  double lo[3], hi[3], t0 = 0, t1 = INFINITY;
  vsh_volume_grid_box(&g, lo, hi);
  CHECK(vsh_volume_clip_ray(lo, hi, o, dir, &t0, &t1) == 1);
  CHECK_NEAR((t1 - t0) / sqrt(3.0), 1.9, 1e-12); /* x, y and z each cross 1.9 */
  CHECK_NEAR(march(&g, 0.3, 0.5, o, dir, INFINITY, NULL), pow(0.7, (t1 - t0) / 0.5), 1e-12);
  /* Starting inside (t from 0) and ending inside (a point light). */
  const double inside[3] = {0, 0, 2};
  CHECK_NEAR(march(&g, 0.2, 0.1, inside, up, INFINITY, NULL), pow(0.8, 9.5), 1e-12);
  CHECK_NEAR(march(&g, 0.2, 0.1, floor, up, 1.55, NULL), pow(0.8, 5.0), 1e-12);
  /* Opacity 0 and 1. */
  CHECK(march(&g, 0.0, 0.1, floor, up, INFINITY, NULL) == 1.0);
  CHECK(march(&g, 1.0, 0.1, floor, up, INFINITY, NULL) == 0.0);
}

static void test_scaled(void)
{
  /* The world is the data scaled by 2 (a volume matrix): a world unit
   * direction is 0.5 long in data coordinates, so the crossing of 1.9 data
   * units is 3.8 world units, at unit distance 0.1 world: (0.8)^38; the
   * steps are still half the data spacing (38 of 0.05 data units). */
  const vsh_volume_grid g = box_grid();
  const double o[3] = {0, 0, 0}, d[3] = {0, 0, 0.5};
  int n = 0;
  CHECK_NEAR(march(&g, 0.2, 0.1, o, d, INFINITY, &n), pow(0.8, 38.0), 1e-12);
  CHECK(n == 38);
}

static void test_miss(void)
{
  const vsh_volume_grid g = box_grid();
  const double beside[3] = {2, 0, 0}, up[3] = {0, 0, 1}, down[3] = {0, 0, -1};
  const double floor[3] = {0, 0, 0}, edge[3] = {0.95, 0, 0};
  int n = 7;
  CHECK(march(&g, 0.9, 0.1, beside, up, INFINITY, &n) == 1.0);
  CHECK(n == 0);
  /* Away from the box, or stopping short of it (a light under it). */
  CHECK(march(&g, 0.9, 0.1, floor, down, INFINITY, NULL) == 1.0);
  CHECK(march(&g, 0.9, 0.1, floor, up, 1.0, NULL) == 1.0);
  /* The box is closed: a ray along a face crosses it. */
  double lo[3], hi[3], t0 = 0, t1 = INFINITY;
  vsh_volume_grid_box(&g, lo, hi);
  const double face[3] = {2, 0, 1.05}, left[3] = {-1, 0, 0};
  CHECK(vsh_volume_clip_ray(lo, hi, face, left, &t0, &t1) == 1);
  CHECK_NEAR(t0, 1.05, 1e-12);
  CHECK_NEAR(t1, 2.95, 1e-12);
  CHECK(march(&g, 0.9, 0.1, edge, up, INFINITY, NULL) < 1.0);
  /* Touching an edge at one point: no length inside, a miss. */
  const double unit_lo[3] = {0, 0, 0}, unit_hi[3] = {1, 1, 1};
  const double corner[3] = {-1, 1, 0.5}, grazing[3] = {1, -1, 0};
  t0 = 0;
  t1 = INFINITY;
  CHECK(vsh_volume_clip_ray(unit_lo, unit_hi, corner, grazing, &t0, &t1) == 0);
  CHECK(t0 == 0 && t1 == INFINITY); /* left as they were */
}

static void test_cutoff(void)
{
  const vsh_volume_grid g = box_grid();
  double alpha = 0.6;
  vsh_volume_march_input in = {&g, 0.1, 1.0 / 1024};
  vsh_volume_ray r = {{0, 0, 0}, {0, 0, 1}, 0.0, INFINITY};
  int n = 0;
  /* 0.6 per 0.1: 0.4^(0.5 k) falls under 1/1024 at step 16 (of 38), where
   * the march stops with 0. */
  CHECK(vsh_volume_march(&in, &r, constant, &alpha, &n) == 0.0);
  CHECK(n == 16);
  alpha = 0.02;
  CHECK_NEAR(vsh_volume_march(&in, &r, constant, &alpha, &n), pow(0.98, 19.0), 1e-12);
  CHECK(n == 38);
}

static void test_trilinear(void)
{
  /* f = 1 + 2x + 3y + 4z: trilinear interpolation is exact for it. */
  vsh_volume_grid g = {{-1, 0, 2}, {0.5, 0.25, 1.0}, {5, 3, 4}};
  float v[5 * 3 * 4];
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 5; ++i) {
        const double x = -1 + 0.5 * i, y = 0.25 * j, z = 2 + k;
        v[i + 5 * (j + 3 * k)] = (float)(1 + 2 * x + 3 * y + 4 * z);
      }
    }
  }
  const double p[3] = {0.3, 0.41, 3.7};
  CHECK_NEAR(vsh_volume_trilinear(&g, v, p), 1 + 0.6 + 1.23 + 14.8, 1e-5);
  const double corner[3] = {1.0, 0.5, 5.0}; /* the last point: the last cell's end */
  CHECK_NEAR(vsh_volume_trilinear(&g, v, corner), 1 + 2 + 1.5 + 20, 1e-5);
  const double outside[3] = {-3, 0.1, 2.5}; /* clamped to x = -1 */
  CHECK_NEAR(vsh_volume_trilinear(&g, v, outside), 1 - 2 + 0.3 + 10, 1e-5);
  const double nan_point[3] = {NAN, 0, 2};
  CHECK(isnan(vsh_volume_trilinear(&g, v, nan_point)));
  g.spacing[1] = 0;
  CHECK(isnan(vsh_volume_trilinear(&g, v, p)));
}

static void test_table_and_kept(void)
{
  const float ramp[3] = {0.0f, 0.5f, 0.25f};
  CHECK_NEAR(vsh_volume_table(ramp, 3, 10, 20, 1, 12.5), 0.25, 1e-12);
  CHECK_NEAR(vsh_volume_table(ramp, 3, 10, 20, 1, 17.5), 0.375, 1e-12);
  CHECK(vsh_volume_table(ramp, 3, 10, 20, 1, 25) == 0.25f);
  CHECK(vsh_volume_table(ramp, 3, 10, 20, 0, 25) == 0.0);
  CHECK(vsh_volume_table(ramp, 3, 10, 20, 1, 5) == 0.0f);
  CHECK(vsh_volume_table(ramp, 3, 10, 20, 1, NAN) == 0.0);
  CHECK(vsh_volume_table(ramp, 1, 10, 20, 1, 15) == 0.0f);
  CHECK(vsh_volume_table(ramp, 3, 10, 10, 1, 10) == 0.0f); /* one scalar */
  CHECK(vsh_volume_table(NULL, 3, 10, 20, 1, 15) == 0.0);
  /* VTK's opacity correction. */
  CHECK_NEAR(vsh_volume_kept(0.2, 0.05, 0.1), sqrt(0.8), 1e-15);
  CHECK_NEAR(vsh_volume_kept(0.2, 2.0, 0.1), pow(0.8, 20.0), 1e-15);
  CHECK(vsh_volume_kept(0.0, 5.0, 0.1) == 1.0);
  CHECK(vsh_volume_kept(1.0, 0.01, 0.1) == 0.0);
  CHECK(vsh_volume_kept(NAN, 0.01, 0.1) == 0.0);  /* NaN opacity: opaque */
  CHECK(vsh_volume_kept(1.5, 0.01, 0.1) == 0.0);  /* clamped */
  CHECK(vsh_volume_kept(-0.5, 0.01, 0.1) == 1.0); /* clamped */
  CHECK(vsh_volume_kept(1.0, 0.0, 0.1) == 1.0);   /* no length */
  CHECK(vsh_volume_kept(0.2, NAN, 0.1) == 1.0);
  CHECK(vsh_volume_kept(0.2, -1.0, 0.1) == 1.0);
  CHECK_NEAR(vsh_volume_kept(0.2, 1.0, 0.0), 0.8, 1e-15); /* a bad unit counts as 1 */
  CHECK_NEAR(vsh_volume_kept(0.2, 1.0, NAN), 0.8, 1e-15);
}

static void test_degenerate(void)
{
  const double o[3] = {0, 0, 0}, up[3] = {0, 0, 1}, zero[3] = {0, 0, 0};
  const double nan_dir[3] = {0, NAN, 1};
  vsh_volume_grid g = box_grid();
  CHECK(vsh_volume_grid_valid(&g) == 1);
  CHECK_NEAR(vsh_volume_grid_step(&g), 0.05, 1e-15);
  g.spacing[2] = 0; /* zero spacing: no box */
  CHECK(vsh_volume_grid_valid(&g) == 0 && vsh_volume_grid_step(&g) == 0.0);
  CHECK(march(&g, 0.5, 0.1, o, up, INFINITY, NULL) == 1.0);
  g.spacing[2] = -0.1;
  CHECK(vsh_volume_grid_valid(&g) == 0);
  g.spacing[2] = NAN;
  CHECK(march(&g, 0.5, 0.1, o, up, INFINITY, NULL) == 1.0);
  g = box_grid();
  g.dims[0] = 1; /* flat */
  CHECK(vsh_volume_grid_valid(&g) == 0);
  g = box_grid();
  g.origin[1] = NAN;
  CHECK(vsh_volume_grid_valid(&g) == 0);
  CHECK(vsh_volume_grid_valid(NULL) == 0);
  g = box_grid();
  CHECK(march(&g, 0.5, 0.1, o, zero, INFINITY, NULL) == 1.0);
  CHECK(march(&g, 0.5, 0.1, o, nan_dir, INFINITY, NULL) == 1.0);
  CHECK(march(&g, 0.5, 0.1, o, up, NAN, NULL) == 1.0);
  /* A NaN unit distance counts as 1: (0.5)^1.9. */
  CHECK_NEAR(march(&g, 0.5, NAN, o, up, INFINITY, NULL), pow(0.5, 1.9), 1e-12);
  /* A sampler that gives NaN: opaque. */
  CHECK(march(&g, NAN, 0.1, o, up, INFINITY, NULL) == 0.0);
  vsh_volume_march_input in = {&g, 0.1, 0.0};
  vsh_volume_ray r = {{0, 0, 0}, {0, 0, 1}, 0.0, INFINITY};
  CHECK(vsh_volume_march(&in, &r, NULL, NULL, NULL) == 1.0);
  CHECK(vsh_volume_march(NULL, &r, constant, NULL, NULL) == 1.0);
}

int main(void)
{
  test_constant_box();
  test_scaled();
  test_miss();
  test_cutoff();
  test_trilinear();
  test_table_and_kept();
  test_degenerate();
  return vsh_check_report("test_volume_march");
}
