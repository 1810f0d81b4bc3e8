/* test_csm_plan.c - unit tests of vsh_csm_plan and vsh_csm_select, the
 * GL-free stages of a cascaded-shadow-map frame: the depth range the
 * shadows cover, resolution and cascades (fewest cascades first for a texel
 * target, raised for spot and point lights), tiles per light kind (cascades,
 * one spot map, six cube faces, empty maps, the light and tile limits), the
 * atlas layout, and which tiles an earlier frame's maps stand in for. Each
 * expectation comes from the documented rule or from the core call the
 * stage is built on, called directly with the stage's inputs. */
#include "vsh_check.h"
#include "vsh_csm_plan.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

/* ---- a small scene: a floor, a box on it, a camera above ---------------- */

static vsh_csm_light directional(void) {
  vsh_csm_light l = {{5, 10, 5}, {0, 0, 0}, 0, 30, 1};
  return l;
}

static vsh_csm_light spot(void) {
  vsh_csm_light l = {{0, 8, 0}, {0, 0, 0}, 1, 30, 1};
  return l;
}

/* Above the box and below nothing: its +y face sees no geometry. */
static vsh_csm_light point(void) {
  vsh_csm_light l = {{0, 4, 0}, {0, 0, 0}, 1, 180, 1};
  return l;
}

static vsh_csm_scene make_scene(const vsh_csm_light *lights, int count) {
  vsh_csm_scene s;
  memset(&s, 0, sizeof s);
  const vsh_camera cam = {{0, 5, 10}, {0, 0, 0}, {0, 1, 0}, 30};
  s.camera = cam;
  s.clip[0] = 1;
  s.clip[1] = 50;
  s.aspect = 4.0 / 3.0;
  s.viewport_height = 300;
  const vsh_bounds floor_ = {{-10, 0, -10}, {10, 0, 10}}, box = {{-1, 0, -1}, {1, 2, 1}};
  s.casters = box;
  s.receivers = floor_;
  vsh_bounds_merge(&s.receivers, &box);
  s.caster_count = 1;
  s.lights = lights;
  s.light_count = count;
  return s;
}

static vsh_csm_settings make_settings(void) {
  vsh_csm_settings t;
  memset(&t, 0, sizeof t);
  t.ratio_per_cascade = 8;
  t.split_scheme = VSH_SPLIT_PRACTICAL;
  t.split_lambda = 0.75;
  t.stable = 1;
  t.map_resolution = 1024;
  t.memory_budget = 256LL << 20;
  t.fade_fraction = 0.1;
  t.bias_scale = 1;
  return t;
}

static vsh_csm_plan plan_of(const vsh_csm_scene *s, const vsh_csm_settings *t) {
  vsh_csm_plan p;
  memset(&p, 0xA5, sizeof p); /* garbage: every field the plan reads must be written */
  CHECK(vsh_csm_plan_frame(s, t, &p) == VSH_CSM_OK);
  return p;
}

/* ---- stage 1: depth range ------------------------------------------------ */

static void test_depth(void) {
  vsh_csm_scene s = make_scene(NULL, 0);
  vsh_csm_settings t = make_settings();
  vsh_csm_depth_plan d;
  CHECK(vsh_csm_plan_depth(&s, &t, &d) == VSH_CSM_OK);
  double visible[2];
  CHECK(vsh_csm_visible_depth_range(
            &(vsh_csm_depth_range_params){.camera = &s.camera, .aspect = s.aspect,
                                          .clip_near = 1, .clip_far = 50, .bounds = &s.receivers},
            visible) == VSH_CSM_OK);
  CHECK(d.have_scene == 1);
  CHECK(d.range[0] == visible[0] && d.range[1] == visible[1]);
  /* No shadow distance: no fade (shadows reach the receivers' far end). */
  CHECK(d.max_distance == 0.0);
  CHECK_NEAR(d.fade_start, d.range[1] - 0.1 * (d.range[1] - d.range[0]), 1e-12);
  /* A shadow distance inside the range ends it there, fading over the last
   * tenth; one before its near end keeps a sliver. */
  t.max_shadow_distance = 0.5 * (visible[0] + visible[1]);
  CHECK(vsh_csm_plan_depth(&s, &t, &d) == VSH_CSM_OK);
  CHECK(d.range[1] == t.max_shadow_distance && d.max_distance == t.max_shadow_distance);
  CHECK_NEAR(d.fade_start, d.range[1] - 0.1 * (d.range[1] - d.range[0]), 1e-12);
  t.max_shadow_distance = 0.5 * visible[0];
  CHECK(vsh_csm_plan_depth(&s, &t, &d) == VSH_CSM_OK);
  CHECK(d.range[1] == visible[0] * 1.001);
  /* No distance and no fade: no fade at all (0). */
  t.max_shadow_distance = 0;
  t.fade_fraction = 0;
  CHECK(vsh_csm_plan_depth(&s, &t, &d) == VSH_CSM_OK);
  CHECK(d.max_distance == 0.0 && d.fade_start == d.range[1]);
  /* Nothing casts, or nothing is visible: the clip range stands in. */
  s.caster_count = 0;
  CHECK(vsh_csm_plan_depth(&s, &t, &d) == VSH_CSM_EMPTY);
  CHECK(d.have_scene == 0 && d.range[0] == 1 && d.range[1] == 50);
  s = make_scene(NULL, 0);
  const vsh_bounds behind = {{-1, -1, 20}, {1, 1, 22}};
  s.receivers = behind;
  CHECK(vsh_csm_plan_depth(&s, &t, &d) == VSH_CSM_OK);
  CHECK(d.have_scene == 1 && d.range[0] == 1 && d.range[1] == 50);
  CHECK(vsh_csm_plan_depth(NULL, &t, &d) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_plan_depth(&s, NULL, &d) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_plan_depth(&s, &t, NULL) == VSH_CSM_BAD_INPUT);
}

/* ---- stage 2: resolution and cascades ------------------------------------ */

static void test_resolution(void) {
  const vsh_csm_light lights[1] = {directional()};
  const vsh_csm_scene s = make_scene(lights, 1);
  vsh_csm_settings t = make_settings();
  vsh_csm_depth_plan d;
  vsh_csm_plan_depth(&s, &t, &d);
  vsh_csm_resolution_plan r;
  /* Defaults: the settings' resolution, the count from the depth ratio,
   * practical splits. */
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &r) == VSH_CSM_OK);
  CHECK(r.resolution == 1024);
  CHECK(r.cascade_count == vsh_csm_default_count(d.range[0], d.range[1], 8));
  double want[VSH_CSM_MAX_CASCADES + 1];
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){VSH_SPLIT_PRACTICAL, r.cascade_count, d.range[0],
                                               d.range[1], 0.75, NULL},
                       want) == VSH_CSM_OK);
  for (int i = 0; i <= r.cascade_count; ++i) CHECK(r.splits[i] == want[i]);
  CHECK(r.split_fallback == 0);
  /* A fixed count; explicit fractions, valid and not. */
  t.cascade_count = 3;
  t.split_scheme = VSH_SPLIT_EXPLICIT;
  t.split_fractions[0] = 0.25;
  t.split_fractions[1] = 0.5;
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &r) == VSH_CSM_OK);
  CHECK(r.cascade_count == 3 && r.split_fallback == 0);
  CHECK_NEAR(r.splits[1], d.range[0] + 0.25 * (d.range[1] - d.range[0]), 1e-12);
  CHECK_NEAR(r.splits[2], d.range[0] + 0.5 * (d.range[1] - d.range[0]), 1e-12);
  t.split_fractions[1] = 0.1; /* not increasing */
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &r) == VSH_CSM_OK);
  CHECK(r.split_fallback == 1);
  CHECK(vsh_csm_splits(&(vsh_csm_split_params){VSH_SPLIT_PRACTICAL, 3, d.range[0], d.range[1],
                                               0.75, NULL},
                       want) == VSH_CSM_OK);
  for (int i = 0; i <= 3; ++i) CHECK(r.splits[i] == want[i]);
  /* A texel target: fewest cascades that meet it, as vsh_csm_choose sees it. */
  t = make_settings();
  const double targets[] = {0.3, 1, 3};
  for (size_t k = 0; k < sizeof targets / sizeof targets[0]; ++k) {
    t.max_texel_px = targets[k];
    CHECK(vsh_csm_plan_resolution(&s, &t, &d, &r) == VSH_CSM_OK);
    vsh_csm_choose_params c = {d.range[0], d.range[1], 30, s.aspect, 300, targets[k],
                               t.memory_budget, 256, 8192, r.cascade_count};
    vsh_csm_choice choice;
    CHECK(vsh_csm_choose(&c, &choice) == VSH_CSM_OK);
    CHECK(choice.resolution == r.resolution && choice.count == r.cascade_count);
    if (r.cascade_count > 1) {
      c.max_count = r.cascade_count - 1;
      CHECK(vsh_csm_choose(&c, &choice) == VSH_CSM_TARGET_MISSED);
    }
  }
}

static void test_resolution_positional(void) {
  vsh_csm_light lights[2] = {directional(), spot()};
  lights[1].position[1] = 200; /* far from the scene: its texels are large */
  vsh_csm_scene s = make_scene(lights, 1);
  vsh_csm_settings t = make_settings();
  t.max_texel_px = 2;
  vsh_csm_depth_plan d;
  vsh_csm_plan_depth(&s, &t, &d);
  vsh_csm_resolution_plan alone, with_spot;
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &alone) == VSH_CSM_OK);
  s.light_count = 2;
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &with_spot) == VSH_CSM_OK);
  /* What the spot needs where the scene's centre is seen (the centre of the
   * bounds, at its view depth). */
  vsh_bounds all = s.casters;
  vsh_bounds_merge(&all, &s.receivers);
  double centre[3], r[3], u[3], f[3], rel[3], to_centre[3];
  vsh_bounds_center(&all, centre);
  vsh_camera_basis(&s.camera, r, u, f);
  vsh_vec3_sub(centre, s.camera.position, rel);
  vsh_vec3_sub(centre, lights[1].position, to_centre);
  int need = 0;
  vsh_csm_perspective_resolution(
      &(vsh_csm_resolution_params){vsh_csm_map_half_angle(30), vsh_vec3_length(to_centre),
                                   fmax(vsh_vec3_dot(rel, f), d.range[0]), 30, 300, 2, 256, 8192},
      &need);
  if (!(need > alone.resolution)) fprintf(stderr, "need %d alone %d\n", need, alone.resolution);
  CHECK(need > alone.resolution); /* the case this test is about */
  CHECK(with_spot.resolution == need);
  CHECK(with_spot.cascade_count == alone.cascade_count);
  /* A spot that does not cast asks for nothing. */
  lights[1].casts = 0;
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &with_spot) == VSH_CSM_OK);
  CHECK(with_spot.resolution == alone.resolution);
  CHECK(vsh_csm_plan_resolution(&s, &t, NULL, &with_spot) == VSH_CSM_BAD_INPUT);
  s.lights = NULL;
  CHECK(vsh_csm_plan_resolution(&s, &t, &d, &with_spot) == VSH_CSM_BAD_INPUT);
}

/* ---- stage 3: tiles ------------------------------------------------------- */

/* The tile's absolute matrix is its camera-relative one after P - eye. */
static void check_absolute(const vsh_csm_tile *tile, const double eye[3]) {
  const double P[3] = {0.3, 0.7, -0.2};
  double rel[3], a[3], b[3];
  vsh_vec3_sub(P, eye, rel);
  vsh_mat4_transform_point(tile->absolute, P, a);
  vsh_mat4_transform_point(tile->view.world_to_clip, rel, b);
  for (int k = 0; k < 3; ++k) CHECK_NEAR(a[k], b[k], 1e-9);
}

static void test_tiles_by_kind(void) {
  const vsh_csm_light lights[3] = {directional(), spot(), point()};
  const vsh_csm_scene s = make_scene(lights, 3);
  vsh_csm_settings t = make_settings();
  t.cascade_count = 3;
  const vsh_csm_plan p = plan_of(&s, &t);
  const vsh_csm_tile_plan *tp = &p.tiles;
  CHECK(tp->light_count == 3 && tp->lights_dropped == 0);
  CHECK(tp->kind[0] == VSH_CSM_CASCADES && tp->first[0] == 0 && tp->count[0] == 3);
  CHECK(tp->kind[1] == VSH_CSM_SPOT && tp->first[1] == 3 && tp->count[1] == 1);
  CHECK(tp->kind[2] == VSH_CSM_POINT && tp->first[2] == 4 && tp->count[2] == 6);
  CHECK(tp->tile_count == 10);
  for (int c = 0; c < 3; ++c) {
    const vsh_csm_tile *tile = &tp->tiles[c];
    CHECK(tile->light == 0 && tile->view.perspective == 0 && tile->view.texel_world > 0);
    CHECK(tile->near_depth == p.resolution.splits[c]);
    CHECK(tile->far_depth == p.resolution.splits[c + 1]);
    CHECK(tile->texel_px == vsh_csm_texel_pixels(tile->view.texel_world, tile->near_depth, 30,
                                                 300));
    double db, no;
    vsh_csm_bias(tile->view.texel_world, tile->view.depth_extent, 1, &db, &no);
    CHECK(tile->bias[0] == db && tile->bias[1] == no);
    check_absolute(tile, s.camera.position);
  }
  const vsh_csm_tile *sp = &tp->tiles[3];
  CHECK(sp->light == 1 && sp->view.perspective == 1 && sp->near_depth == 0);
  double db, no;
  vsh_csm_bias(sp->view.texel_world, 1.0, 1, &db, &no); /* per unit of distance */
  CHECK(sp->bias[0] == db && sp->bias[1] == no);
  check_absolute(sp, s.camera.position);
  /* Cube faces: +y sees nothing above the light, so it is an empty map
   * whose w < 0 makes every lookup lit; the others are perspective maps. */
  for (int face = 0; face < 6; ++face) {
    const vsh_csm_tile *tile = &tp->tiles[4 + face];
    CHECK(tile->light == 2);
    if (face == 2) {
      CHECK(tile->view.texel_world == 0 && tile->view.world_to_clip[15] == -1.0);
    } else {
      CHECK(tile->view.perspective == 1 && tile->view.texel_world > 0);
    }
  }
}

static void test_tiles_limits(void) {
  vsh_csm_settings t = make_settings();
  t.cascade_count = 2;
  /* A light that may not cast, and a scene where nothing casts. */
  vsh_csm_light lights[9];
  for (int i = 0; i < 9; ++i) lights[i] = directional();
  lights[0].casts = 0;
  vsh_csm_scene s = make_scene(lights, 2);
  vsh_csm_plan p = plan_of(&s, &t);
  CHECK(p.tiles.kind[0] == VSH_CSM_NO_SHADOW && p.tiles.count[0] == 0 && p.tiles.first[0] == 0);
  CHECK(p.tiles.kind[1] == VSH_CSM_CASCADES && p.tiles.first[1] == 0 && p.tiles.count[1] == 2);
  s.caster_count = 0;
  vsh_csm_plan none;
  memset(&none, 0, sizeof none);
  CHECK(vsh_csm_plan_frame(&s, &t, &none) == VSH_CSM_EMPTY);
  CHECK(none.tiles.tile_count == 0 && none.tiles.kind[1] == VSH_CSM_NO_SHADOW);
  /* Nine lights: the ninth gets nothing and is reported. */
  s = make_scene(lights, 9);
  p = plan_of(&s, &t);
  CHECK(p.tiles.light_count == VSH_CSM_MAX_LIGHTS && p.tiles.lights_dropped == 1);
  CHECK(p.tiles.tile_count == 2 * 7);
  /* Five point lights: four cubes fill the atlas's 24 tiles, the fifth and
   * a directional light after them get none. */
  vsh_csm_light many[6];
  for (int i = 0; i < 5; ++i) many[i] = point();
  many[5] = directional();
  s = make_scene(many, 6);
  p = plan_of(&s, &t);
  CHECK(p.tiles.tile_count == VSH_CSM_MAX_TILES);
  for (int i = 0; i < 4; ++i) CHECK(p.tiles.kind[i] == VSH_CSM_POINT);
  CHECK(p.tiles.kind[4] == VSH_CSM_NO_SHADOW && p.tiles.kind[5] == VSH_CSM_NO_SHADOW);
  /* A cascade whose slice sees no receiver: an empty map, still a tile.
   * (Receivers behind the camera: the slices span the clip range.) */
  s = make_scene(lights + 1, 1);
  const vsh_bounds behind = {{-1, 4, 20}, {1, 6, 22}};
  s.receivers = behind;
  t.cascade_count = 4;
  p = plan_of(&s, &t);
  CHECK(p.depth.range[0] == 1 && p.depth.range[1] == 50);
  int empty = 0;
  for (int c = 0; c < p.tiles.count[0]; ++c) {
    const vsh_csm_tile *tile = &p.tiles.tiles[c];
    if (tile->view.texel_world == 0) {
      ++empty;
      CHECK(tile->view.world_to_clip[10] == 0 && tile->view.depth_extent == 1);
      CHECK(tile->texel_px == 0 && tile->near_depth == p.resolution.splits[c]);
    }
  }
  CHECK(p.tiles.count[0] == 4 && empty >= 1);
  CHECK(vsh_csm_plan_tiles(&s, &t, &p.depth, NULL, &p.tiles) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_plan_frame(&s, &t, NULL) == VSH_CSM_BAD_INPUT);
}

static void test_half_angle(void) {
  CHECK_NEAR(vsh_csm_map_half_angle(30), 31.1, 1e-12);
  CHECK(vsh_csm_map_half_angle(88) == 89.0);
  CHECK(vsh_csm_map_half_angle(90) == VSH_CSM_CUBE_FACE_HALF_ANGLE);
  CHECK(vsh_csm_map_half_angle(180) == VSH_CSM_CUBE_FACE_HALF_ANGLE);
}

/* ---- the atlas ------------------------------------------------------------ */

static void test_atlas_layout(void) {
  const int cases[][3] = {/* tiles, columns, rows */
                          {0, 1, 1}, {1, 1, 1}, {2, 2, 1}, {3, 2, 2},  {5, 3, 2},
                          {9, 3, 3}, {10, 4, 3}, {24, 5, 5}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    vsh_csm_atlas_layout a;
    CHECK(vsh_csm_atlas_layout_for(cases[k][0], 1024, 16384, &a) == VSH_CSM_OK);
    CHECK(a.columns == cases[k][1] && a.rows == cases[k][2]);
    CHECK(a.columns * a.rows >= cases[k][0]);
    CHECK(a.resolution == 1024 && !a.clamped);
    CHECK(a.width == a.columns * 1024 && a.height == a.rows * 1024);
  }
  vsh_csm_atlas_layout a;
  CHECK(vsh_csm_atlas_layout_for(10, 4096, 16384, &a) == VSH_CSM_OK);
  CHECK(!a.clamped && a.width == 16384);
  CHECK(vsh_csm_atlas_layout_for(24, 4096, 16384, &a) == VSH_CSM_OK);
  CHECK(a.clamped && a.resolution == 16384 / 5 && a.width <= 16384);
  CHECK(vsh_csm_atlas_layout_for(1, 1024, 16384, NULL) == VSH_CSM_BAD_INPUT);
}

/* ---- stage 4: reuse ------------------------------------------------------- */

static vsh_csm_reuse_params reuse_params(const vsh_csm_scene *s, const vsh_csm_plan *p,
                                         uint64_t caster_time) {
  vsh_csm_reuse_params r = {&s->camera, s->aspect, p->depth.range[0], 0.1, &s->receivers,
                            &s->casters, 1, p->resolution.resolution, 4.0, caster_time};
  return r;
}

static void test_reuse(void) {
  const vsh_csm_light lights[2] = {directional(), point()};
  vsh_csm_scene s = make_scene(lights, 2);
  vsh_csm_settings t = make_settings();
  t.cascade_count = 2;
  vsh_csm_plan p = plan_of(&s, &t);
  const int n = p.tiles.tile_count;
  CHECK(n == 8);
  vsh_csm_held_map held[VSH_CSM_MAX_TILES];
  memset(held, 0, sizeof held);
  vsh_csm_selection sel;
  vsh_csm_reuse_params r = reuse_params(&s, &p, 7);
  /* First frame: everything is baked and remembered. */
  CHECK(vsh_csm_select_reusable(&r, p.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  CHECK(sel.bake_count == n && sel.reused_count == 0);
  for (int i = 0; i < n; ++i) {
    CHECK(sel.bake[i] == i && held[i].valid && held[i].caster_time == 7);
    CHECK(memcmp(&held[i].map, &p.tiles.tiles[i], sizeof held[i].map) == 0);
  }
  /* The same frame again (the empty +y face included): nothing to bake. */
  vsh_csm_plan again = plan_of(&s, &t);
  CHECK(vsh_csm_select_reusable(&r, again.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  CHECK(sel.bake_count == 0 && sel.reused_count == 0);
  /* The casters changed: everything again. */
  r.caster_time = 8;
  CHECK(vsh_csm_select_reusable(&r, again.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  CHECK(sel.bake_count == n);
  /* A small turn of the camera: the stable cascades move, but the maps held
   * still cover every lookup; they are kept, re-expressed relative to the
   * new camera position. The cube faces follow the camera's position only
   * in their relative matrix, so they are the same maps. */
  const vsh_csm_plan before = again;
  vsh_csm_scene turned = s;
  turned.camera.focal_point[0] += 0.05;
  turned.camera.position[0] += 0.02;
  vsh_csm_plan moved = plan_of(&turned, &t);
  r = reuse_params(&turned, &moved, 8);
  CHECK(vsh_csm_select_reusable(&r, moved.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  CHECK(sel.reused_count >= 1);
  CHECK(sel.bake_count == 0);
  for (int c = 0; c < 2; ++c) {
    const vsh_csm_tile *tile = &moved.tiles.tiles[c];
    /* Its own slice, the held map's placement in the world. */
    CHECK(tile->near_depth == moved.resolution.splits[c]);
    double P[3] = {0.5, 0.2, -0.4}, rel_new[3], rel_old[3], a[3], b[3];
    vsh_vec3_sub(P, turned.camera.position, rel_new);
    vsh_vec3_sub(P, s.camera.position, rel_old);
    vsh_mat4_transform_point(tile->view.world_to_clip, rel_new, a);
    vsh_mat4_transform_point(before.tiles.tiles[c].view.world_to_clip, rel_old, b);
    for (int k = 0; k < 3; ++k) CHECK_NEAR(a[k], b[k], 1e-9);
  }
  /* A held map whose recorded placement differs but whose view is the
   * same: a stable cascade keeps it (it covers every lookup), an unstable
   * one is baked again. */
  r = reuse_params(&s, &again, 8);
  CHECK(vsh_csm_select_reusable(&r, again.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  vsh_csm_held_map copy[VSH_CSM_MAX_TILES];
  memcpy(copy, held, sizeof copy);
  held[0].map.absolute[3] += 1.0;
  vsh_csm_plan same = plan_of(&s, &t);
  CHECK(vsh_csm_select_reusable(&r, same.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  CHECK(sel.reused_count == 1 && sel.bake_count == 0);
  memcpy(held, copy, sizeof copy);
  held[0].map.absolute[3] += 1.0;
  r.stable = 0;
  same = plan_of(&s, &t);
  CHECK(vsh_csm_select_reusable(&r, same.tiles.tiles, n, held, &sel) == VSH_CSM_OK);
  CHECK(sel.reused_count == 0 && sel.bake_count == 1 && sel.bake[0] == 0);
  /* A big move leaves the held maps. */
  vsh_csm_scene far_away = s;
  far_away.camera.position[0] += 30;
  far_away.camera.focal_point[0] += 30;
  vsh_csm_plan gone = plan_of(&far_away, &t);
  r = reuse_params(&far_away, &gone, 8);
  CHECK(vsh_csm_select_reusable(&r, gone.tiles.tiles, 2, held, &sel) == VSH_CSM_OK);
  CHECK(sel.reused_count == 0 && sel.bake_count == 2);
  CHECK(vsh_csm_select_reusable(NULL, gone.tiles.tiles, 2, held, &sel) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_select_reusable(&r, gone.tiles.tiles, VSH_CSM_MAX_TILES + 1, held, &sel) ==
        VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_select_reusable(&r, NULL, 2, held, &sel) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_select_reusable(&r, gone.tiles.tiles, 0, NULL, &sel) == VSH_CSM_OK);
}

static void test_status_names(void) {
  CHECK_STR_CONTAINS(vsh_csm_status_name(VSH_CSM_OK), "ok");
  CHECK_STR_CONTAINS(vsh_csm_status_name(VSH_CSM_EMPTY), "empty");
  CHECK_STR_CONTAINS(vsh_csm_status_name(VSH_CSM_BAD_INPUT), "bad input");
  CHECK_STR_CONTAINS(vsh_csm_status_name(VSH_CSM_TARGET_MISSED), "target");
  CHECK_STR_CONTAINS(vsh_csm_status_name((vsh_csm_status)42), "unknown");
}

int main(void) {
  test_depth();
  test_resolution();
  test_resolution_positional();
  test_half_angle();
  test_tiles_by_kind();
  test_tiles_limits();
  test_atlas_layout();
  test_reuse();
  test_status_names();
  return vsh_check_report("core.csm_plan");
}
