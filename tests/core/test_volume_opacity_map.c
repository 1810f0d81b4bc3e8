/* test_volume_opacity_map.c - unit tests of vsh_volume_opacity_map: the
 * directional and the perspective frame over a box, the texel under it
 * keeping (1 - a)^(L / u) with its entry and exit, the rim texels missing
 * it, a receiver's partial transmittance, two volumes along a ray, a volume
 * placed by a turning matrix, the view matrix, and the degenerate cases:
 * a light inside or on a volume's box, a zero-size box, no volumes, a bad
 * light, a light parallel to the box's faces. */
#include "vsh_check.h"
#include "vsh_mat4.h"
#include "vsh_volume_opacity_map.h"

#include <math.h>
#include <stdlib.h>

/* A constant opacity everywhere. */
static double constant(void *user, const double p[3])
{
  (void)p;
  return *(const double *)user;
}

static double alpha = 0.06;

/* The 20^3 grid of spacing 0.1 centred at (0, 0, 2) (test_volume_march's),
 * placed by the identity: the box [-0.95, 0.95]^2 x [1.05, 2.95]. */
static vsh_volume_map_volume box_volume(void)
{
  vsh_volume_map_volume v = {{{-0.95, -0.95, 1.05}, {0.1, 0.1, 0.1}, {20, 20, 20}},
                             0.1,
                             {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0},
                             constant,
                             &alpha};
  return v;
}

/* The map of `count` volumes for `light`, size x size texels (malloc'ed;
 * null when the plan is not OK). */
static float *map_of(const vsh_volume_map_volume *v, int count, const double light[4], int size,
                     vsh_volume_map_plan *plan)
{
  if (vsh_volume_opacity_map_plan(v, count, light, size, plan) != VSH_VOLUME_MAP_OK) {
    return NULL;
  }
  float *texels = malloc(sizeof(float) * 4 * (size_t)size * (size_t)size);
  CHECK(vsh_volume_opacity_map_fill(plan, v, count, 1.0 / 1024, 0, size, texels) > 0);
  return texels;
}

static const float *texel_at(const float *texels, int size, int i, int j)
{
  return texels + 4 * (j * size + i);
}

/* Straight down, parallel to four faces: the centre texel crosses 1.9, the
 * rim texels miss; a receiver keeps 1 above the box, T^(1/2) halfway, T
 * below. */
static void test_directional_down(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double down[4] = {0, 0, 1, 0}; /* towards the light: up */
  vsh_volume_map_plan plan;
  float *m = map_of(&v, 1, down, 33, &plan);
  CHECK(m != NULL);
  if (!m) {
    return;
  }
  CHECK(!plan.perspective);
  CHECK_NEAR(plan.axes[8], -1.0, 1e-15); /* w: the light travels down */
  const double T = pow(1.0 - alpha, 19.0);
  const float *c = texel_at(m, 33, 16, 16);
  CHECK_NEAR(c[0], T, 1e-6);
  CHECK_NEAR(c[1], 0.0, 1e-6); /* the plane through the top face */
  CHECK_NEAR(c[2], 1.9, 1e-6);
  CHECK_NEAR(vsh_volume_opacity_map_kept(c, -0.5), 1.0, 0.0);
  CHECK_NEAR(vsh_volume_opacity_map_kept(c, 0.95), sqrt(T), 1e-6);
  CHECK_NEAR(vsh_volume_opacity_map_kept(c, 2.95), T, 1e-6); /* the floor */
  /* Every texel inside the footprint crosses 1.9 (the faces are parallel
   * to the rays); the rim misses. */
  int inside = 0;
  for (int j = 0; j < 33; ++j) {
    for (int i = 0; i < 33; ++i) {
      const float *t = texel_at(m, 33, i, j);
      const int rim = i == 0 || j == 0 || i == 32 || j == 32;
      CHECK(rim ? t[0] == 1.0f && t[1] == (float)VSH_VOLUME_MAP_NONE : fabs(t[0] - T) < 1e-6);
      inside += rim ? 0 : 1;
    }
  }
  CHECK(inside == 31 * 31);
  CHECK_NEAR(vsh_volume_opacity_map_kept(texel_at(m, 33, 0, 0), 100.0), 1.0, 0.0);
  free(m);
}

/* A point light above the box: the axis texel crosses 1.9 at distances 7.05
 * and 8.95 from the light. */
static void test_point_above(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double light[4] = {0, 0, 10, 1};
  vsh_volume_map_plan plan;
  float *m = map_of(&v, 1, light, 33, &plan);
  CHECK(m != NULL);
  if (!m) {
    return;
  }
  CHECK(plan.perspective);
  const float *c = texel_at(m, 33, 16, 16);
  CHECK_NEAR(c[0], pow(1.0 - alpha, 19.0), 1e-6);
  CHECK_NEAR(c[1], 7.05, 1e-5);
  CHECK_NEAR(c[2], 8.95, 1e-5);
  /* A homogeneous light (x, y, z, w) is the point (x, y, z) / w. */
  const double scaled[4] = {0, 0, 20, 2};
  vsh_volume_map_plan same;
  vsh_volume_opacity_map_plan(&v, 1, scaled, 33, &same);
  CHECK_NEAR(same.eye[2], 10.0, 1e-12);
  free(m);
}

/* An oblique light through a volume turned about z and moved: the texel
 * under the centre keeps what a direct march keeps. */
static void test_oblique_moved(void)
{
  vsh_volume_map_volume v = box_volume();
  /* data = R^-1 (frame - (1, 2, 3)): the box turned 30 degrees about z. */
  const double c30 = cos(0.5235987755982988), s30 = 0.5;
  const double m[12] = {c30, s30, 0, 0, -s30, c30, 0, 0, 0, 0, 1, 0};
  for (int i = 0; i < 12; ++i) {
    v.to_data[i] = m[i];
  }
  v.to_data[3] = -(c30 * 1 + s30 * 2);
  v.to_data[7] = -(-s30 * 1 + c30 * 2);
  v.to_data[11] = -3;
  const double light[4] = {0.3, -0.2, 1.0, 0};
  vsh_volume_map_plan plan;
  float *t = map_of(&v, 1, light, 64, &plan);
  CHECK(t != NULL);
  if (!t) {
    return;
  }
  /* Every texel against the march of its own ray. */
  double worst = 0.0;
  for (int j = 0; j < 64; j += 7) {
    for (int i = 0; i < 64; i += 5) {
      const double s = plan.lo[0] + (i + 0.5) * (plan.hi[0] - plan.lo[0]) / 64;
      const double r = plan.lo[1] + (j + 0.5) * (plan.hi[1] - plan.lo[1]) / 64;
      vsh_volume_ray ray = {{0, 0, 0}, {0, 0, 0}, 0.0, INFINITY};
      for (int k = 0; k < 3; ++k) {
        const double o = plan.eye[k] + s * plan.axes[k] + r * plan.axes[3 + k];
        ray.origin[k] = o; /* rotated below */
        ray.direction[k] = plan.axes[6 + k];
      }
      double od[3], dd[3];
      for (int k = 0; k < 3; ++k) {
        const double *row = v.to_data + 4 * k;
        od[k] = row[0] * ray.origin[0] + row[1] * ray.origin[1] + row[2] * ray.origin[2] + row[3];
        dd[k] = row[0] * ray.direction[0] + row[1] * ray.direction[1] + row[2] * ray.direction[2];
      }
      vsh_volume_ray data = {{od[0], od[1], od[2]}, {dd[0], dd[1], dd[2]}, 0.0, INFINITY};
      const vsh_volume_march_input in = {&v.grid, v.unit, 1.0 / 1024};
      const double want = vsh_volume_march(&in, &data, constant, &alpha, NULL);
      const double diff = fabs(texel_at(t, 64, i, j)[0] - want);
      worst = diff > worst ? diff : worst;
    }
  }
  CHECK(worst < 1e-6);
  free(t);
}

/* Two boxes along the ray: the product, the first's entry, the second's
 * exit. */
static void test_two_volumes(void)
{
  vsh_volume_map_volume v[2] = {box_volume(), box_volume()};
  v[1].to_data[11] = 3.0; /* the second 3 lower: z in [-1.95, -0.05] */
  const double down[4] = {0, 0, 1, 0};
  vsh_volume_map_plan plan;
  float *m = map_of(v, 2, down, 33, &plan);
  CHECK(m != NULL);
  if (!m) {
    return;
  }
  const float *c = texel_at(m, 33, 16, 16);
  CHECK_NEAR(c[0], pow(1.0 - alpha, 38.0), 1e-6);
  CHECK_NEAR(c[1], 0.0, 1e-6);
  CHECK_NEAR(c[2], 4.9, 1e-5);
  free(m);
}

/* An opaque box: T 0 (the cutoff), also for a receiver inside it. */
static void test_opaque(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double down[4] = {0, 0, 1, 0};
  const double saved = alpha;
  alpha = 1.0;
  vsh_volume_map_plan plan;
  float *m = map_of(&v, 1, down, 9, &plan);
  alpha = saved;
  CHECK(m != NULL);
  if (m) {
    CHECK(texel_at(m, 9, 4, 4)[0] == 0.0f);
    CHECK(vsh_volume_opacity_map_kept(texel_at(m, 9, 4, 4), 1.0) == 0.0);
    free(m);
  }
}

/* A point light inside the box, on its top face and just above it: not
 * planned (INSIDE); fill writes nothing for it. */
static void test_light_inside(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double lights[3][4] = {{0, 0, 2, 1}, {0.3, 0.1, 2.95, 1}, {0, 0, 3.0, 1}};
  for (int l = 0; l < 3; ++l) {
    vsh_volume_map_plan plan;
    CHECK(vsh_volume_opacity_map_plan(&v, 1, lights[l], 16, &plan) == VSH_VOLUME_MAP_INSIDE);
    float texel[4] = {7, 7, 7, 7};
    CHECK(vsh_volume_opacity_map_fill(&plan, &v, 1, 0.0, 0, 1, texel) == 0);
    CHECK(texel[0] == 7.0f);
    double view[16];
    vsh_mat4_identity(view);
    CHECK(vsh_volume_opacity_map_view_matrix(&plan, view, lights[l], view) == 0);
  }
}

/* A zero-size box (a flat grid), a singular matrix, no volumes, a bad
 * light: EMPTY or BAD_LIGHT. */
static void test_degenerate(void)
{
  vsh_volume_map_volume flat = box_volume(), squashed = box_volume();
  flat.grid.dims[2] = 1;
  squashed.to_data[10] = 0.0;
  const double down[4] = {0, 0, 1, 0};
  vsh_volume_map_plan plan;
  CHECK(vsh_volume_opacity_map_plan(&flat, 1, down, 16, &plan) == VSH_VOLUME_MAP_EMPTY);
  CHECK(vsh_volume_opacity_map_plan(&squashed, 1, down, 16, &plan) == VSH_VOLUME_MAP_EMPTY);
  CHECK(vsh_volume_opacity_map_plan(NULL, 0, down, 16, &plan) == VSH_VOLUME_MAP_EMPTY);
  CHECK(vsh_volume_opacity_map_plan(&flat, 0, down, 16, &plan) == VSH_VOLUME_MAP_EMPTY);
  const vsh_volume_map_volume good = box_volume();
  const double zero[4] = {0, 0, 0, 0}, nan[4] = {NAN, 0, 1, 0}, inf[4] = {0, 0, INFINITY, 1};
  CHECK(vsh_volume_opacity_map_plan(&good, 1, zero, 16, &plan) == VSH_VOLUME_MAP_BAD_LIGHT);
  CHECK(vsh_volume_opacity_map_plan(&good, 1, nan, 16, &plan) == VSH_VOLUME_MAP_BAD_LIGHT);
  CHECK(vsh_volume_opacity_map_plan(&good, 1, inf, 16, &plan) == VSH_VOLUME_MAP_BAD_LIGHT);
  /* A flat box beside a good one: the good one alone is mapped. */
  vsh_volume_map_volume pair[2] = {flat, good};
  float *m = map_of(pair, 2, down, 33, &plan);
  CHECK(m != NULL);
  if (m) {
    CHECK_NEAR(texel_at(m, 33, 16, 16)[0], pow(1.0 - alpha, 19.0), 1e-6);
    free(m);
  }
  /* The smallest map is 3 texels a side (a texel of margin each side). */
  CHECK(vsh_volume_opacity_map_plan(&good, 1, down, 1, &plan) == VSH_VOLUME_MAP_OK);
  CHECK(plan.size[0] == 3 && plan.size[1] == 3);
}

/* A light along a diagonal of the faces' planes (parallel to the z faces
 * only): every texel's T is between T over the shortest crossing and 1. */
static void test_parallel_to_faces(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double side[4] = {1, 1, 0, 0}; /* horizontal: parallel to top and bottom */
  vsh_volume_map_plan plan;
  float *m = map_of(&v, 1, side, 17, &plan);
  CHECK(m != NULL);
  if (!m) {
    return;
  }
  /* Through the centre: the diagonal 1.9 sqrt 2. */
  CHECK_NEAR(texel_at(m, 17, 8, 8)[0], pow(1.0 - alpha, 19.0 * sqrt(2.0)), 1e-5);
  int finite = 1;
  for (int k = 0; k < 17 * 17 * 4; ++k) {
    finite = finite && isfinite(m[k]);
  }
  CHECK(finite);
  free(m);
}

/* The view matrix: a world point's view position maps to axes (p - eye). */
static void test_view_matrix(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double light[4] = {0.2, 0.4, 1, 0};
  vsh_volume_map_plan plan;
  CHECK(vsh_volume_opacity_map_plan(&v, 1, light, 32, &plan) == VSH_VOLUME_MAP_OK);
  /* A camera at (5, -3, 4) turned 40 degrees about x then 25 about z. */
  const double a = 0.7, b = 0.44, eye[3] = {5, -3, 4};
  double rx[16] = {1, 0, 0, 0, 0, cos(a), -sin(a), 0, 0, sin(a), cos(a), 0, 0, 0, 0, 1};
  double rz[16] = {cos(b), -sin(b), 0, 0, sin(b), cos(b), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double r[16], m[16];
  vsh_mat4_multiply(rx, rz, r);
  CHECK(vsh_volume_opacity_map_view_matrix(&plan, r, eye, m) == 1);
  const double p[3] = {0.3, -0.7, 0.4};
  double rel[3] = {p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]}, view[3], q[3];
  vsh_mat4_transform_direction(r, rel, view);
  vsh_mat4_transform_point(m, view, q);
  for (int k = 0; k < 3; ++k) {
    const double *axis = plan.axes + 3 * k;
    const double want = axis[0] * (p[0] - plan.eye[0]) + axis[1] * (p[1] - plan.eye[1]) +
                        axis[2] * (p[2] - plan.eye[2]);
    CHECK_NEAR(q[k], want, 1e-12);
  }
}

/* The texel rays the receiver map traces (vtkShadowVolumeReceiver): a
 * directional light's start on the plane through the box's top, straight
 * down, at the texel's centre; a point light's at the light, through the
 * texel's centre (the centre texel of an odd grid: straight down). */
static void test_texel_ray(void)
{
  const vsh_volume_map_volume v = box_volume();
  const double down[4] = {0, 0, 1, 0}, above[4] = {0, 0, 10, 1};
  vsh_volume_map_plan plan;
  double o[3], d[3];
  CHECK(vsh_volume_opacity_map_plan(&v, 1, down, 33, &plan) == VSH_VOLUME_MAP_OK);
  vsh_volume_opacity_map_texel_ray(&plan, 16, 16, o, d);
  CHECK_NEAR(o[2], 2.95, 1e-12);
  CHECK_NEAR(d[2], -1.0, 1e-12);
  vsh_volume_opacity_map_texel_ray(&plan, 0, 0, o, d);
  /* The rim texel's centre: half a texel in from the window's corner. */
  const double texel = (plan.hi[0] - plan.lo[0]) / 33;
  CHECK_NEAR(fabs(o[0]), fabs(plan.lo[0]) - 0.5 * texel, 1e-12);
  CHECK(vsh_volume_opacity_map_plan(&v, 1, above, 33, &plan) == VSH_VOLUME_MAP_OK);
  vsh_volume_opacity_map_texel_ray(&plan, 16, 16, o, d);
  CHECK_NEAR(o[2], 10.0, 1e-12);
  CHECK_NEAR(d[2], -1.0, 1e-12);
}

/* The light in the maps' frame: a position relative to the origin (w
 * divided out), a direction unchanged. */
static void test_light_in_frame(void)
{
  const double origin[3] = {1, 2, 3}, point[4] = {4, 6, 8, 2}, sun[4] = {0.5, -1, 2, 0};
  double out[4];
  vsh_volume_opacity_map_light(point, origin, out);
  CHECK(out[0] == 1 && out[1] == 1 && out[2] == 1 && out[3] == 1);
  vsh_volume_opacity_map_light(sun, origin, out);
  CHECK(out[0] == 0.5 && out[1] == -1 && out[2] == 2 && out[3] == 0);
}

int main(void)
{
  test_texel_ray();
  test_directional_down();
  test_point_above();
  test_oblique_moved();
  test_two_volumes();
  test_opaque();
  test_light_inside();
  test_degenerate();
  test_parallel_to_faces();
  test_view_matrix();
  test_light_in_frame();
  return vsh_check_report("volume_opacity_map");
}
