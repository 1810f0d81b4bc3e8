/* test_csm_sampled.c - unit tests of vsh_csm_sampled: the light's sample
 * frame (the axes vsh_soft uses), the sample maps derived from a planned
 * map (a directional sample's shear projects every line along the sample's
 * direction to one point; a positional sample's map sees from the sample
 * point vsh_soft_sample_light gives), the memory cap of the resolution,
 * the hard cases and bad input, at the origin and 1e6 away. */
#include "vsh_check.h"
#include "vsh_csm_sampled.h"
#include "vsh_mat4.h"
#include "vsh_soft.h"

#include <math.h>
#include <string.h>

static vsh_csm_scene make_scene(const vsh_csm_light *lights, double offset) {
  vsh_csm_scene s;
  memset(&s, 0, sizeof s);
  const vsh_camera cam = {{offset, 5, 10}, {offset, 0, 0}, {0, 1, 0}, 30};
  s.camera = cam;
  s.clip[0] = 1;
  s.clip[1] = 50;
  s.aspect = 4.0 / 3.0;
  s.viewport_height = 300;
  const vsh_bounds floor_ = {{offset - 10, 0, -10}, {offset + 10, 0, 10}},
                   box = {{offset - 1, 0, -1}, {offset + 1, 2, 1}};
  s.casters = box;
  s.receivers = floor_;
  vsh_bounds_merge(&s.receivers, &box);
  s.caster_count = 1;
  s.lights = lights;
  s.light_count = 1;
  return s;
}

static vsh_csm_plan plan_of(const vsh_csm_scene *s) {
  vsh_csm_settings t;
  vsh_csm_plan p;
  memset(&t, 0, sizeof t);
  t.ratio_per_cascade = 8;
  t.split_scheme = VSH_SPLIT_PRACTICAL;
  t.split_lambda = 0.75;
  t.stable = 1;
  t.map_resolution = 1024;
  t.memory_budget = 256LL << 20;
  t.fade_fraction = 0.1;
  t.bias_scale = 1;
  CHECK(vsh_csm_plan_frame(s, &t, &p) == VSH_CSM_OK);
  return p;
}

/* ndc of camera-relative point p under m. */
static void ndc(const double m[16], const double p[3], double out[3]) {
  const double in[4] = {p[0], p[1], p[2], 1.0};
  double c[4];
  vsh_mat4_transform_point4(m, in, c);
  out[0] = c[0] / c[3], out[1] = c[1] / c[3], out[2] = c[2] / c[3];
}

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void test_frame(void) {
  const vsh_csm_light point = {{0, 8, 0}, {0, 0, 0}, 1, 180, 1};
  const vsh_csm_light sun = {{1, 3, 2}, {0, 0, 0}, 0, 0, 1};
  const double toward[3] = {0.5, 1, 0.2};
  vsh_csm_sample_frame f;
  CHECK(vsh_csm_sample_frame_for(&point, 0.5, toward, 16, &f) == VSH_CSM_OK);
  CHECK(f.sampled == 1 && f.positional == 1 && f.n == 16);
  {
    const double n[3] = {toward[0], toward[1] - 8, toward[2]};
    CHECK_NEAR(sqrt(dot3(f.u, f.u)), 0.5, 1e-15);
    CHECK_NEAR(sqrt(dot3(f.v, f.v)), 0.5, 1e-15);
    CHECK_NEAR(dot3(f.u, n), 0.0, 1e-14);
    CHECK_NEAR(dot3(f.v, n), 0.0, 1e-14);
    CHECK_NEAR(dot3(f.u, f.v), 0.0, 1e-15);
  }
  /* The sample points are vsh_soft_sample_light's. */
  for (int i = 0; i < 16; ++i) {
    const double light[4] = {0, 8, 0, 1};
    double q[2], want[4];
    CHECK(vsh_csm_sample_disk(i, 16, q) == VSH_CSM_OK);
    CHECK(vsh_soft_sample_light(light, 0.5, toward, i, 16, 0.0, want) == 0);
    for (int k = 0; k < 3; ++k)
      CHECK_NEAR(point.position[k] + q[0] * f.u[k] + q[1] * f.v[k], want[k], 1e-14);
  }
  CHECK(vsh_csm_sample_frame_for(&sun, 6.0, NULL, 4, &f) == VSH_CSM_OK);
  CHECK(f.sampled == 1 && f.positional == 0);
  CHECK_NEAR(sqrt(dot3(f.u, f.u)), tan(3.0 * 3.14159265358979323846 / 180.0), 1e-15);
  CHECK_NEAR(dot3(f.u, f.l), 0.0, 1e-15);
  CHECK_NEAR(dot3(f.l, f.l), 1.0, 1e-15);
  /* The hard path: no size, one sample, not casting, toward at the light. */
  CHECK(vsh_csm_sample_frame_for(&point, 0.0, toward, 16, &f) == VSH_CSM_OK && !f.sampled);
  CHECK(vsh_csm_sample_frame_for(&point, 0.5, toward, 1, &f) == VSH_CSM_OK && !f.sampled);
  CHECK(vsh_csm_sample_frame_for(&point, 0.5, point.position, 16, &f) == VSH_CSM_OK &&
        !f.sampled);
  {
    vsh_csm_light off = point;
    off.casts = 0;
    CHECK(vsh_csm_sample_frame_for(&off, 0.5, toward, 16, &f) == VSH_CSM_OK && !f.sampled);
  }
  /* Bad input. */
  CHECK(vsh_csm_sample_frame_for(NULL, 0.5, toward, 16, &f) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_frame_for(&point, 0.5, toward, 0, &f) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_frame_for(&point, 0.5, toward, 65, &f) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_frame_for(&point, -1.0, toward, 16, &f) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_frame_for(&point, NAN, toward, 16, &f) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_frame_for(&point, 0.5, NULL, 16, &f) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_frame_for(&sun, 180.0, NULL, 16, &f) == VSH_CSM_BAD_INPUT);
  {
    vsh_csm_light none = sun;
    memcpy(none.position, none.focal_point, sizeof none.position);
    CHECK(vsh_csm_sample_frame_for(&none, 6.0, NULL, 16, &f) == VSH_CSM_BAD_INPUT);
  }
  CHECK(vsh_csm_sample_disk(16, 16, (double[2]){0, 0}) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_sample_disk(0, 65, (double[2]){0, 0}) == VSH_CSM_BAD_INPUT);
}

/* A directional sample's map projects p and p + t d (d the sample's
 * direction, vsh_soft_sun_direction) to the same x, y; the base map does
 * not (for a sample off the centre). */
static void check_directional(double offset) {
  const vsh_csm_light sun = {{offset + 1, 3, 2}, {offset, 0, 0}, 0, 0, 1};
  const vsh_csm_scene s = make_scene(&sun, offset);
  const vsh_csm_plan p = plan_of(&s);
  vsh_csm_sample_frame f;
  CHECK(p.tiles.tile_count >= 1);
  CHECK(vsh_csm_sample_frame_for(&sun, 8.0, NULL, 16, &f) == VSH_CSM_OK && f.sampled);
  for (int t = 0; t < p.tiles.tile_count; ++t) {
    for (int i = 0; i < 16; ++i) {
      vsh_csm_tile tile;
      double q[2], d[3], a[3], b[3], base_a[3], base_b[3];
      const double pt[3] = {0.3, 0.1, -4.0}; /* camera-relative, near the floor */
      CHECK(vsh_csm_sample_tile(&p.tiles.tiles[t], &f, i, &tile) == VSH_CSM_OK);
      vsh_csm_sample_disk(i, 16, q);
      CHECK(vsh_soft_sun_direction(f.l, 8.0, q, d) == 0);
      const double far_[3] = {pt[0] + 3 * d[0], pt[1] + 3 * d[1], pt[2] + 3 * d[2]};
      ndc(tile.view.world_to_clip, pt, a);
      ndc(tile.view.world_to_clip, far_, b);
      CHECK_NEAR(a[0], b[0], 1e-9);
      CHECK_NEAR(a[1], b[1], 1e-9);
      CHECK(a[2] != b[2]); /* depth still orders along the ray */
      ndc(p.tiles.tiles[t].view.world_to_clip, pt, base_a);
      ndc(p.tiles.tiles[t].view.world_to_clip, far_, base_b);
      CHECK(fabs(base_a[0] - base_b[0]) + fabs(base_a[1] - base_b[1]) > 1e-4);
      CHECK_NEAR(base_a[2], a[2], 1e-12); /* depth kept */
      CHECK(tile.bias[0] == p.tiles.tiles[t].bias[0] && tile.light == p.tiles.tiles[t].light);
      /* absolute agrees with the camera-relative matrix. */
      {
        const double world[3] = {pt[0] + s.camera.position[0], pt[1] + s.camera.position[1],
                                 pt[2] + s.camera.position[2]};
        double w[3];
        ndc(tile.absolute, world, w);
        CHECK_NEAR(w[0], a[0], 1e-6);
        CHECK_NEAR(w[1], a[1], 1e-6);
      }
    }
  }
}

/* A positional sample's map: the line from the sample point through p
 * projects to one point, the base map's (from the centre) does not. */
static void check_positional(double offset, double cone) {
  const vsh_csm_light light = {{offset + 1, 6, 1}, {offset, 0, 0}, 1, cone, 1};
  const vsh_csm_scene s = make_scene(&light, offset);
  const vsh_csm_plan p = plan_of(&s);
  const double centre[3] = {offset, 1, 0};
  vsh_csm_sample_frame f;
  CHECK(vsh_csm_sample_frame_for(&light, 0.4, centre, 4, &f) == VSH_CSM_OK && f.sampled);
  CHECK(p.tiles.tile_count == (cone < 90 ? 1 : 6));
  for (int t = 0; t < p.tiles.tile_count; ++t) {
    if (p.tiles.tiles[t].view.texel_world <= 0.0) {
      /* An empty cube face stays empty (and is not moved). */
      vsh_csm_tile tile;
      CHECK(vsh_csm_sample_tile(&p.tiles.tiles[t], &f, 1, &tile) == VSH_CSM_OK);
      CHECK(memcmp(&tile, &p.tiles.tiles[t], sizeof tile) == 0);
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      vsh_csm_tile tile;
      double q[2], x[4], a[3], b[3], rel[3], pt[3];
      const double lit[4] = {light.position[0], light.position[1], light.position[2], 1.0};
      CHECK(vsh_csm_sample_tile(&p.tiles.tiles[t], &f, i, &tile) == VSH_CSM_OK);
      vsh_csm_sample_disk(i, 4, q);
      CHECK(vsh_soft_sample_light(lit, 0.4, centre, i, 4, 0.0, x) == 0);
      for (int k = 0; k < 3; ++k) rel[k] = x[k] - s.camera.position[k];
      /* A point on the floor below the light, then twice as far. */
      const double target[3] = {offset + 0.7, 0.0, 0.4};
      for (int k = 0; k < 3; ++k) pt[k] = target[k] - s.camera.position[k];
      const double twice[3] = {rel[0] + 2 * (pt[0] - rel[0]), rel[1] + 2 * (pt[1] - rel[1]),
                               rel[2] + 2 * (pt[2] - rel[2])};
      ndc(tile.view.world_to_clip, pt, a);
      ndc(tile.view.world_to_clip, twice, b);
      CHECK_NEAR(a[0], b[0], 1e-9);
      CHECK_NEAR(a[1], b[1], 1e-9);
      /* The sample point is the map's eye: w is 0 there. */
      {
        const double in[4] = {rel[0], rel[1], rel[2], 1.0};
        double c[4];
        vsh_mat4_transform_point4(tile.view.world_to_clip, in, c);
        CHECK_NEAR(c[3], 0.0, 1e-9);
      }
    }
  }
  /* A directional shear of a perspective map is bad input. */
  {
    vsh_csm_sample_frame g;
    double sh[4];
    CHECK(vsh_csm_sample_shear(&p.tiles.tiles[0].view, &f, sh) == VSH_CSM_BAD_INPUT);
    g = f;
    g.sampled = 0;
    vsh_csm_tile out;
    CHECK(vsh_csm_sample_tile(&p.tiles.tiles[0], &g, 0, &out) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_sample_tile(&p.tiles.tiles[0], &f, 4, &out) == VSH_CSM_BAD_INPUT);
    CHECK(vsh_csm_sample_tile(NULL, &f, 0, &out) == VSH_CSM_BAD_INPUT);
  }
}

/* Widening keeps x, y and w and moves the depth range by the radius. */
static void test_widen(void) {
  const vsh_csm_light light = {{1, 6, 1}, {0, 0, 0}, 1, 30, 1};
  const vsh_csm_scene s = make_scene(&light, 0.0);
  const vsh_csm_plan p = plan_of(&s);
  const double centre[3] = {0, 1, 0};
  vsh_csm_sample_frame f;
  vsh_csm_tile t = p.tiles.tiles[0];
  const double *nf = p.tiles.tiles[0].view.near_far;
  CHECK(vsh_csm_sample_frame_for(&light, 0.4, centre, 4, &f) == VSH_CSM_OK && f.sampled);
  CHECK(vsh_csm_sample_widen(&t, &f) == VSH_CSM_OK);
  CHECK_NEAR(t.view.near_far[0], fmax(nf[0] - 0.4, 0.25 * nf[0]), 1e-12);
  CHECK_NEAR(t.view.near_far[1], nf[1] + 0.4, 1e-12);
  for (int c = 0; c < 4; ++c) {
    CHECK(t.view.world_to_clip[c] == p.tiles.tiles[0].view.world_to_clip[c]);
    CHECK(t.view.world_to_clip[12 + c] == p.tiles.tiles[0].view.world_to_clip[12 + c]);
  }
  /* A point at the new near / far distance along the axis maps to ndc z -1 / 1. */
  {
    double terms[2];
    vsh_csm_perspective_depth_terms(&t.view, terms);
    CHECK_NEAR(-terms[0] + terms[1] / t.view.near_far[0], -1.0, 1e-12);
    CHECK_NEAR(-terms[0] + terms[1] / t.view.near_far[1], 1.0, 1e-12);
    const double in[4] = {0.0, 0.0, 0.0, 1.0};
    double c0[4], c1[4];
    /* the light itself (camera-relative): w 0, z the same multiple of -b */
    const double rel[4] = {light.position[0] - s.camera.position[0],
                           light.position[1] - s.camera.position[1],
                           light.position[2] - s.camera.position[2], 1.0};
    (void)in;
    vsh_mat4_transform_point4(t.view.world_to_clip, rel, c0);
    vsh_mat4_transform_point4(p.tiles.tiles[0].view.world_to_clip, rel, c1);
    CHECK_NEAR(c0[3], 0.0, 1e-9);
    CHECK_NEAR(c0[2], terms[1], 1e-9);
  }
  /* A directional map and a hard frame are left alone. */
  {
    vsh_csm_sample_frame g = f;
    vsh_csm_tile u = p.tiles.tiles[0];
    g.sampled = 0;
    CHECK(vsh_csm_sample_widen(&u, &g) == VSH_CSM_OK);
    CHECK(memcmp(&u, &p.tiles.tiles[0], sizeof u) == 0);
    CHECK(vsh_csm_sample_widen(NULL, &f) == VSH_CSM_BAD_INPUT);
  }
}

static void test_resolution(void) {
  CHECK(vsh_csm_sampled_resolution(2048, 1, 256LL << 20) == 2048);
  CHECK(vsh_csm_sampled_resolution(2048, 16, 256LL << 20) == 2048); /* 4 x 4 x 2048^2 x 4 */
  CHECK(vsh_csm_sampled_resolution(2048, 17, 256LL << 20) == 1984); /* sqrt(64 Mi / 17) = 1986 */
  CHECK(vsh_csm_sampled_resolution(2048, 390, 256LL << 20) == 400);
  CHECK(vsh_csm_sampled_resolution(2048, 0, 256LL << 20) == 2048);
  CHECK(vsh_csm_sampled_resolution(8, 4, 256LL << 20) == 16);
  CHECK(vsh_csm_sampled_resolution(2048, 1000000, 1024) == 16);
  CHECK(vsh_csm_sampled_resolution(2048, 4, 0) == 2048);
}

int main(void) {
  test_frame();
  check_directional(0.0);
  check_directional(1e6);
  check_positional(0.0, 30.0);
  check_positional(0.0, 180.0);
  check_positional(1e6, 30.0);
  test_widen();
  test_resolution();
  return vsh_check_report("csm_sampled");
}
