/* test_csm_screen.c - unit tests of vsh_csm_screen_tile_needs and
 * vsh_csm_screen_depth_ranges, the per-tile planning of the cascaded pass's
 * screen resolve.
 *
 * The decisions are checked against what the per-pixel code does, computed
 * here independently at many points of each tile's box: a tile given one
 * cascade must have every point in that cascade and outside the blend band;
 * a tile declared lit must have no point whose ray towards the light hits
 * the casters' box. Known answers cover the degenerate tiles (background,
 * one spanning every cascade, a projection giving w <= 0, beyond the last
 * cascade and the shadow distance), the same answers 1e6 from the origin,
 * and every bad input. */
#include "vsh_check.h"
#include "vsh_camera.h"
#include "vsh_csm_plan.h"
#include "vsh_csm_screen.h"
#include "vsh_mat4.h"
#include "vsh_random.h"

#include <math.h>
#include <string.h>

#define W 400
#define H 300
#define TILE 16

typedef struct world {
  vsh_csm_light lights[2];
  vsh_csm_scene scene;
  vsh_csm_settings settings;
  vsh_csm_plan plan;
  double projection[16], ndc_to_view[16], view_to_relative[16];
  vsh_csm_screen_params params;
} world;

/* A floor, a box on it, a camera above; light 0 directional, light 1 a
 * point light (or, with `spot`, a spot), everything moved by `offset`. */
static void make_world(world *w, const double offset[3], int spot)
{
  memset(w, 0, sizeof *w);
  const vsh_csm_light sun = {{5, 10, 5}, {0, 0, 0}, 0, 30, 1};
  const vsh_csm_light lamp = {{3, 5, 0}, {0, 0, 0}, 1, spot ? 40 : 180, 1};
  w->lights[0] = sun;
  w->lights[1] = lamp;
  const vsh_camera cam = {{0, 5, 10}, {0, 0, 0}, {0, 1, 0}, 30};
  w->scene.camera = cam;
  vsh_bounds floor_ = {{-10, 0, -10}, {10, 0, 10}}, box = {{-1, 0, -1}, {1, 2, 1}};
  for (int a = 0; a < 3; ++a) {
    w->scene.camera.position[a] += offset[a];
    w->scene.camera.focal_point[a] += offset[a];
    for (int l = 0; l < 2; ++l) {
      w->lights[l].position[a] += offset[a];
      w->lights[l].focal_point[a] += offset[a];
    }
    floor_.min[a] += offset[a];
    floor_.max[a] += offset[a];
    box.min[a] += offset[a];
    box.max[a] += offset[a];
  }
  w->scene.clip[0] = 1;
  w->scene.clip[1] = 50;
  w->scene.aspect = (double)W / H;
  w->scene.viewport_height = H;
  w->scene.casters = box;
  w->scene.receivers = floor_;
  vsh_bounds_merge(&w->scene.receivers, &box);
  w->scene.caster_count = 1;
  w->scene.lights = w->lights;
  w->scene.light_count = 2;
  w->settings.ratio_per_cascade = 3;
  w->settings.split_scheme = VSH_SPLIT_PRACTICAL;
  w->settings.split_lambda = 0.75;
  w->settings.stable = 1;
  w->settings.map_resolution = 1024;
  w->settings.memory_budget = 256LL << 20;
  w->settings.fade_fraction = 0.1;
  w->settings.bias_scale = 1;
  CHECK(vsh_csm_plan_frame(&w->scene, &w->settings, &w->plan) == VSH_CSM_OK);
  vsh_camera_projection_matrix(cam.view_angle, w->scene.aspect, 1, 50, w->projection);
  CHECK(vsh_mat4_inverse(w->projection, w->ndc_to_view));
  double rot[16];
  vsh_camera_view_matrix_relative(&w->scene.camera, rot);
  vsh_mat4_transpose(rot, w->view_to_relative);
  vsh_csm_screen_params p = {&w->plan.tiles, w->lights, w->scene.camera.position,
                             w->ndc_to_view, w->view_to_relative, &w->scene.casters,
                             {W, H}, 0.1, 0.0, 2.0, 1024, 1};
  w->params = p;
}

/* Window depth of view depth z. */
static double window_depth(const world *w, double z)
{
  const double v[4] = {0, 0, -z, 1};
  double c[4];
  vsh_mat4_transform_point4(w->projection, v, c);
  return 0.5 * c[2] / c[3] + 0.5;
}

/* View position (camera at 0) and camera-relative world position of the
 * window point (x, y, d). */
static double view_point(const world *w, double x, double y, double d, double rel[3])
{
  const double ndc[4] = {2 * x / W - 1, 2 * y / H - 1, 2 * d - 1, 1};
  double v[4];
  vsh_mat4_transform_point4(w->ndc_to_view, ndc, v);
  const double view[3] = {v[0] / v[3], v[1] / v[3], v[2] / v[3]};
  vsh_mat4_transform_direction(w->view_to_relative, view, rel);
  return -view[2];
}

/* The shader's cascade choice (vshShadowCascades): -1 beyond the last. */
static int shader_cascade(const world *w, int l, double depth, int *blended)
{
  const vsh_csm_tile_plan *t = &w->plan.tiles;
  const int first = t->first[l], count = t->count[l];
  *blended = 0;
  if (depth > t->tiles[first + count - 1].far_depth)
    return -1;
  int c = 0;
  while (c < count - 1 && depth > t->tiles[first + c].far_depth)
    ++c;
  if (c < count - 1) {
    const double nearD = c == 0 ? 0.0 : t->tiles[first + c - 1].far_depth;
    const double farD = t->tiles[first + c].far_depth;
    *blended = depth > farD - w->params.blend_band * (farD - nearD);
  }
  return c;
}

/* Whether the ray from p (camera-relative) in direction d hits box b
 * (camera-relative) at a positive distance below `limit`. */
static int ray_hits(const double p[3], const double d[3], const vsh_bounds *b, double limit)
{
  double t0 = 1e-9, t1 = limit;
  for (int a = 0; a < 3; ++a) {
    if (fabs(d[a]) < 1e-300) {
      if (p[a] < b->min[a] || p[a] > b->max[a])
        return 0;
      continue;
    }
    double u = (b->min[a] - p[a]) / d[a], v = (b->max[a] - p[a]) / d[a];
    if (u > v) {
      const double s = u;
      u = v;
      v = s;
    }
    t0 = fmax(t0, u);
    t1 = fmin(t1, v);
  }
  return t0 <= t1;
}

/* Every decision of random tiles against the per-pixel answer at 64 points
 * of each tile's box. Counts the (tile, light) pairs that came out LIT, ANY
 * and one cascade, and the points in shadow, so the caller can require each
 * to happen (a check that never sees a shadowed point cannot fail). */
static void check_random_tiles(world *w, int counts[4])
{
  vsh_bounds rel = w->scene.casters;
  for (int a = 0; a < 3; ++a) {
    rel.min[a] -= w->scene.camera.position[a];
    rel.max[a] -= w->scene.camera.position[a];
  }
  for (int n = 0; n < 400; ++n) {
    vsh_csm_screen_tile t;
    t.x0 = TILE * (int)vsh_test_rnd(0, W / TILE);
    t.y0 = TILE * (int)vsh_test_rnd(0, H / TILE);
    t.x1 = t.x0 + TILE;
    t.y1 = t.y0 + TILE;
    const double z0 = vsh_test_rnd(1.5, 30.0), z1 = z0 * vsh_test_rnd(1.0, 1.3);
    t.depth_min = window_depth(w, z0);
    t.depth_max = window_depth(w, z1);
    int out[VSH_CSM_MAX_LIGHTS];
    CHECK(vsh_csm_screen_tile_needs(&w->params, &t, out) == VSH_CSM_OK);
    for (int l = 0; l < 2; ++l) {
      counts[out[l] == VSH_CSM_SCREEN_LIT ? 0 : out[l] == VSH_CSM_SCREEN_ANY ? 1 : 2]++;
      for (int k = 0; k < 64; ++k) {
        double p[3];
        const double depth =
            view_point(w, vsh_test_rnd(t.x0, t.x1), vsh_test_rnd(t.y0, t.y1),
                       vsh_test_rnd(t.depth_min, t.depth_max), p);
        int blended = 0;
        const int c = l == 0 ? shader_cascade(w, 0, depth, &blended) : 0;
        if (out[l] >= VSH_CSM_SCREEN_CASCADE) {
          CHECK(l == 0);
          CHECK(c == -1 || (c == out[l] - VSH_CSM_SCREEN_CASCADE && !blended));
        }
        if (c >= 0) {
          double d[3];
          double limit = 1e30;
          for (int a = 0; a < 3; ++a) {
            const double to = w->lights[l].position[a] - w->scene.camera.position[a];
            d[a] = l == 0 ? w->lights[0].position[a] - w->lights[0].focal_point[a] : to - p[a];
          }
          if (l == 1)
            limit = 1.0; /* up to the light */
          const int hit = ray_hits(p, d, &rel, limit);
          CHECK(!(hit && out[l] == VSH_CSM_SCREEN_LIT));
          counts[3] += hit;
        }
      }
    }
  }
}

static void test_random_tiles(void)
{
  for (int spot = 0; spot < 2; ++spot) {
    world w;
    const double zero[3] = {0, 0, 0};
    make_world(&w, zero, spot);
    CHECK(w.plan.tiles.count[0] >= 2); /* cascades to choose between */
    int counts[4] = {0, 0, 0, 0};
    check_random_tiles(&w, counts);
    CHECK(counts[0] > 50); /* lit tiles happen */
    CHECK(counts[1] > 20); /* undecided ones too */
    CHECK(counts[2] > 10); /* and single cascades */
    CHECK(counts[3] > 100); /* shadowed points, none of them in a lit tile */
  }
}

/* The same tiles 1e6 from the origin: the same decisions (camera-relative). */
static void test_offset(void)
{
  world a, b;
  const double zero[3] = {0, 0, 0}, far_[3] = {1e6, -1e6, 1e6};
  make_world(&a, zero, 0);
  make_world(&b, far_, 0);
  int differ = 0;
  for (int n = 0; n < 300; ++n) {
    vsh_csm_screen_tile t = {TILE * (n % 25), TILE * (n / 25 % 18), 0, 0, 0, 0};
    t.x1 = t.x0 + TILE;
    t.y1 = t.y0 + TILE;
    t.depth_min = window_depth(&a, 2.0 + 0.09 * n);
    t.depth_max = window_depth(&a, 2.5 + 0.09 * n);
    int oa[VSH_CSM_MAX_LIGHTS], ob[VSH_CSM_MAX_LIGHTS];
    CHECK(vsh_csm_screen_tile_needs(&a.params, &t, oa) == VSH_CSM_OK);
    CHECK(vsh_csm_screen_tile_needs(&b.params, &t, ob) == VSH_CSM_OK);
    differ += memcmp(oa, ob, sizeof oa) != 0;
  }
  CHECK(differ == 0);
}

static void test_degenerate_tiles(void)
{
  world w;
  const double zero[3] = {0, 0, 0};
  make_world(&w, zero, 0);
  int out[VSH_CSM_MAX_LIGHTS];
  /* Background only: nothing to draw for any light. */
  vsh_csm_screen_tile empty = {0, 0, TILE, TILE, 1.0, 0.0};
  CHECK(vsh_csm_screen_tile_needs(&w.params, &empty, out) == VSH_CSM_OK);
  for (int l = 0; l < VSH_CSM_MAX_LIGHTS; ++l)
    CHECK(out[l] == VSH_CSM_SCREEN_LIT);
  /* The whole screen from near to far: every cascade, casters in view. */
  vsh_csm_screen_tile all = {0, 0, W, H, window_depth(&w, 1.0), window_depth(&w, 49.0)};
  CHECK(vsh_csm_screen_tile_needs(&w.params, &all, out) == VSH_CSM_OK);
  CHECK(out[0] == VSH_CSM_SCREEN_ANY);
  CHECK(out[1] == VSH_CSM_SCREEN_ANY);
  for (int l = 2; l < VSH_CSM_MAX_LIGHTS; ++l)
    CHECK(out[l] == VSH_CSM_SCREEN_LIT);
  /* Without caster culling the same tile near the camera is one cascade. */
  const int c0 = w.plan.tiles.first[0];
  const double far0 = w.plan.tiles.tiles[c0].far_depth;
  vsh_csm_screen_tile near_ = {0, 0, TILE, TILE, window_depth(&w, 1.2), window_depth(&w, 1.3)};
  CHECK(far0 > 1.3 / (1.0 - w.params.blend_band));
  w.params.cull_casters = 0;
  CHECK(vsh_csm_screen_tile_needs(&w.params, &near_, out) == VSH_CSM_OK);
  CHECK(out[0] == VSH_CSM_SCREEN_CASCADE + 0);
  CHECK(out[1] == VSH_CSM_SCREEN_ANY);
  /* Beyond the last cascade: lit; beyond the shadow distance: lit. */
  const int last = c0 + w.plan.tiles.count[0] - 1;
  const double far_last = w.plan.tiles.tiles[last].far_depth;
  vsh_csm_screen_tile beyond = {0, 0, TILE, TILE, window_depth(&w, far_last * 1.01),
                                window_depth(&w, far_last * 1.1)};
  CHECK(vsh_csm_screen_tile_needs(&w.params, &beyond, out) == VSH_CSM_OK);
  CHECK(out[0] == VSH_CSM_SCREEN_LIT);
  w.params.max_distance = 1.1;
  CHECK(vsh_csm_screen_tile_needs(&w.params, &near_, out) == VSH_CSM_OK);
  CHECK(out[0] == VSH_CSM_SCREEN_LIT && out[1] == VSH_CSM_SCREEN_LIT);
  w.params.max_distance = 0.0;
  /* A projection whose w is negative: nothing decided. */
  double bad[16];
  memcpy(bad, w.ndc_to_view, sizeof bad);
  for (int c = 0; c < 4; ++c)
    bad[12 + c] = c == 3 ? -1.0 : 0.0;
  w.params.ndc_to_view = bad;
  CHECK(vsh_csm_screen_tile_needs(&w.params, &near_, out) == VSH_CSM_OK);
  CHECK(out[0] == VSH_CSM_SCREEN_ANY && out[1] == VSH_CSM_SCREEN_ANY);
  w.params.ndc_to_view = w.ndc_to_view;
  /* No casters at all: lit everywhere. */
  vsh_bounds none;
  vsh_bounds_init_empty(&none);
  w.params.casters = &none;
  w.params.cull_casters = 1;
  CHECK(vsh_csm_screen_tile_needs(&w.params, &all, out) == VSH_CSM_OK);
  CHECK(out[0] == VSH_CSM_SCREEN_LIT && out[1] == VSH_CSM_SCREEN_LIT);
}

static void test_bad_input(void)
{
  world w;
  const double zero[3] = {0, 0, 0};
  make_world(&w, zero, 0);
  int out[VSH_CSM_MAX_LIGHTS];
  vsh_csm_screen_tile t = {0, 0, TILE, TILE, 0.5, 0.6};
  CHECK(vsh_csm_screen_tile_needs(NULL, &t, out) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_screen_tile_needs(&w.params, NULL, out) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_screen_tile_needs(&w.params, &t, NULL) == VSH_CSM_BAD_INPUT);
  vsh_csm_screen_params p = w.params;
  p.viewport[0] = 0;
  CHECK(vsh_csm_screen_tile_needs(&p, &t, out) == VSH_CSM_BAD_INPUT);
  p = w.params;
  p.resolution = 0;
  CHECK(vsh_csm_screen_tile_needs(&p, &t, out) == VSH_CSM_BAD_INPUT);
  p = w.params;
  p.reach_texels = NAN;
  CHECK(vsh_csm_screen_tile_needs(&p, &t, out) == VSH_CSM_BAD_INPUT);
  p = w.params;
  p.casters = NULL;
  CHECK(vsh_csm_screen_tile_needs(&p, &t, out) == VSH_CSM_BAD_INPUT);
  vsh_csm_screen_tile inverted = {TILE, 0, 0, TILE, 0.5, 0.6};
  CHECK(vsh_csm_screen_tile_needs(&w.params, &inverted, out) == VSH_CSM_BAD_INPUT);
  vsh_csm_screen_tile nan_depth = {0, 0, TILE, TILE, NAN, 0.6};
  CHECK(vsh_csm_screen_tile_needs(&w.params, &nan_depth, out) == VSH_CSM_BAD_INPUT);
}

static void test_depth_ranges(void)
{
  /* 5 x 3 pixels in tiles of 2: 3 x 2 tiles, the last column and row
   * partial. Row 0 at the bottom. */
  const float d[15] = {0.5f, 0.2f, 1.0f, 1.0f, 0.9f, /* y 0 */
                       0.3f, 1.0f, 1.0f, 1.0f, NAN,  /* y 1 */
                       1.0f, 0.0f, 1.0f, 1.0f, 1.0f}; /* y 2 */
  float lo[6], hi[6];
  long long covered = -1;
  CHECK(vsh_csm_screen_depth_ranges(d, 5, 3, 2, lo, hi, &covered) == VSH_CSM_OK);
  CHECK(covered == 5);
  CHECK(lo[0] == 0.2f && hi[0] == 0.5f);
  CHECK(lo[1] > hi[1]); /* background only */
  CHECK(lo[2] == 0.9f && hi[2] == 0.9f);
  CHECK(lo[3] == 0.0f && hi[3] == 0.0f);
  CHECK(lo[4] > hi[4] && lo[5] > hi[5]);
  CHECK(vsh_csm_screen_depth_ranges(d, 5, 3, 2, lo, hi, NULL) == VSH_CSM_OK);
  CHECK(vsh_csm_screen_depth_ranges(NULL, 5, 3, 2, lo, hi, NULL) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_screen_depth_ranges(d, 0, 3, 2, lo, hi, NULL) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_screen_depth_ranges(d, 5, 3, 0, lo, hi, NULL) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_screen_depth_ranges(d, 5, 3, 2, NULL, hi, NULL) == VSH_CSM_BAD_INPUT);
}

int main(void)
{
  test_random_tiles();
  test_offset();
  test_degenerate_tiles();
  test_bad_input();
  test_depth_ranges();
  return vsh_check_report("csm_screen");
}
