/* test_csm_reuse.c - unit tests of vsh_csm_lookup_region and
 * vsh_csm_view_covers, the decision to sample a cascade rendered in an
 * earlier frame instead of rendering it again.
 *
 * The property that makes reuse exact: whenever vsh_csm_view_covers says
 * yes, every point a lookup of the new frame can touch (inside the new view
 * slice and on a receiver) lands inside the old map, away from its edges by
 * the filter's reach, within its depth range, and on the same world-anchored
 * texel grid as a freshly fitted map, so the old map holds exactly the
 * texels a new one would. That is checked on random scenes and camera moves,
 * near the world origin and 1e6 away from it, together with the known
 * answers and every bad input. */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_csm.h"
#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#define PI 3.14159265358979323846
#define RES 1024

typedef struct scene {
  vsh_camera camera;
  double light[3]; /* where the light travels */
  vsh_bounds receivers, casters;
  double near, far; /* the cascade's slice */
} scene;

/* A floor of half-size `size` at height 0 around `offset`, casters above
 * it, a camera looking down at it from a random side, a light from above. */
static scene random_scene(const double offset[3], double size) {
  scene s;
  const double az = vsh_test_rnd(0.0, 2.0 * PI), el = vsh_test_rnd(0.2, 1.2), dist = vsh_test_rnd(0.8, 1.5) * size;
  for (int k = 0; k < 3; ++k)
    s.camera.focal_point[k] = offset[k];
  s.camera.position[0] = offset[0] + dist * cos(el) * cos(az);
  s.camera.position[1] = offset[1] + dist * cos(el) * sin(az);
  s.camera.position[2] = offset[2] + dist * sin(el);
  s.camera.view_up[0] = 0.0;
  s.camera.view_up[1] = 0.0;
  s.camera.view_up[2] = 1.0;
  s.camera.view_angle = vsh_test_rnd(20.0, 60.0);
  s.light[0] = vsh_test_rnd(-0.6, 0.6);
  s.light[1] = vsh_test_rnd(-0.6, 0.6);
  s.light[2] = -1.0;
  const vsh_bounds floor = {{offset[0] - size, offset[1] - size, offset[2] - 0.01 * size},
                            {offset[0] + size, offset[1] + size, offset[2]}};
  const vsh_bounds up = {{offset[0] - 0.3 * size, offset[1] - 0.3 * size, offset[2]},
                         {offset[0] + 0.3 * size, offset[1] + 0.3 * size, offset[2] + 0.4 * size}};
  s.receivers = floor;
  s.casters = up;
  s.near = 0.2 * dist;
  s.far = 2.5 * dist;
  return s;
}

/* Rotate the camera about its focal point by `deg` around z and move it by
 * `shift` (a fraction of the distance). */
static vsh_camera moved(const vsh_camera *c, double deg, double shift) {
  vsh_camera m = *c;
  const double a = deg * PI / 180.0;
  double rel[3];
  vsh_vec3_sub(c->position, c->focal_point, rel);
  const double d = vsh_vec3_length(rel);
  m.position[0] = c->focal_point[0] + cos(a) * rel[0] - sin(a) * rel[1] + shift * d;
  m.position[1] = c->focal_point[1] + sin(a) * rel[0] + cos(a) * rel[1] - 0.5 * shift * d;
  m.position[2] = c->focal_point[2] + rel[2];
  m.focal_point[0] += shift * d;
  m.focal_point[1] -= 0.5 * shift * d;
  return m;
}

static vsh_csm_status fit(const scene *s, const vsh_camera *camera, vsh_shadow_view *out) {
  return vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = camera,
      .aspect = 4.0 / 3.0, .slice_near = s->near, .slice_far = s->far, .light_direction = s->light,
      .receivers = &s->receivers, .casters = &s->casters, .stable = 1, .resolution = RES}, out);
}

/* A random world point inside `camera`'s slice [near, far] and on the
 * receivers' box, or 0 when 200 tries find none. */
static int lookup_point(const scene *s, const vsh_camera *camera, double out[3]) {
  double r[3], u[3], f[3];
  vsh_camera_basis(camera, r, u, f);
  const double t = tan(camera->view_angle * PI / 360.0);
  for (int tries = 0; tries < 200; ++tries) {
    const double d = vsh_test_rnd(s->near, s->far), x = vsh_test_rnd(-1, 1), y = vsh_test_rnd(-1, 1);
    for (int k = 0; k < 3; ++k)
      out[k] = camera->position[k] + d * (f[k] + x * t * (4.0 / 3.0) * r[k] + y * t * u[k]);
    int inside = 1;
    for (int k = 0; k < 3; ++k)
      inside = inside && out[k] >= s->receivers.min[k] && out[k] <= s->receivers.max[k];
    if (inside)
      return 1;
  }
  return 0;
}

static void clip_of_world(const vsh_shadow_view *v, const double origin[3], const double p[3],
                          double out[3]) {
  double rel[3];
  vsh_vec3_sub(p, origin, rel);
  vsh_mat4_transform_point(v->world_to_clip, rel, out);
}

/* Random scenes and camera moves: a yes must be exact, and small moves must
 * give yes often enough for the reuse to matter. */
static void test_property(const double offset[3], double size, int *yes_small, int *tried_small) {
  const double margin = 3.0;
  for (int trial = 0; trial < 300; ++trial) {
    scene s = random_scene(offset, size);
    vsh_shadow_view held, needed;
    if (fit(&s, &s.camera, &held) != VSH_CSM_OK)
      continue;
    const int small = trial % 3 != 0;
    const vsh_camera next =
        small ? moved(&s.camera, vsh_test_rnd(-1.0, 1.0), vsh_test_rnd(-0.01, 0.01))
              : moved(&s.camera, vsh_test_rnd(-40.0, 40.0), vsh_test_rnd(-0.3, 0.3));
    if (fit(&s, &next, &needed) != VSH_CSM_OK)
      continue;
    double region[6];
    if (vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &next, .aspect = 4.0 / 3.0,
        .lookup_near = s.near, .slice_far = s.far, .receivers = &s.receivers, .casters = &s.casters,
        .view = &needed}, region) != VSH_CSM_OK)
      continue;
    for (int k = 0; k < 6; ++k)
      CHECK(region[k] >= -1.0 && region[k] <= 1.0);
    const int yes =
        vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &held,
            .rendered_origin = s.camera.position, .needed = &needed, .needed_origin = next.position,
            .needed_region = region, .resolution = RES, .margin_texels = margin});
    if (small) {
      ++*tried_small;
      *yes_small += yes;
    }
    if (!yes)
      continue;
    const double m = 2.0 * margin / RES;
    for (int i = 0; i < 50; ++i) {
      double p[3], a[3], b[3];
      if (!lookup_point(&s, &next, p))
        break;
      clip_of_world(&held, s.camera.position, p, a);
      clip_of_world(&needed, next.position, p, b);
      CHECK(a[0] >= -1.0 + m && a[0] <= 1.0 - m && a[1] >= -1.0 + m && a[1] <= 1.0 - m);
      /* Depth: what the new map would hold, the held one holds (a point in
       * front of both near planes, higher than every caster along the
       * light, is lit in both). */
      if (b[2] >= -1.0 && b[2] <= 1.0)
        CHECK(a[2] >= -1.0 - 1e-9 && a[2] <= 1.0 + 1e-9);
      /* The same world-anchored texel grid: the two maps' texel coordinates
       * of any point differ by whole texels. */
      for (int k = 0; k < 2; ++k) {
        const double texels = (a[k] - b[k]) * 0.5 * RES;
        CHECK_NEAR(texels, floor(texels + 0.5), 1e-6);
      }
    }
    /* Every caster corner above the receivers stays within the held map's
     * near plane: nothing that casts is clipped away. */
    double corners[8][3];
    vsh_bounds_corners(&s.casters, corners);
    for (int i = 0; i < 8; ++i) {
      double a[3];
      clip_of_world(&held, s.camera.position, corners[i], a);
      CHECK(a[2] >= -1.0 - 1e-9);
    }
  }
}

static void test_random_moves(void) {
  const double origin[3] = {0, 0, 0}, far_away[3] = {1e6, -2e6, 5e5};
  int yes = 0, tried = 0;
  test_property(origin, 10.0, &yes, &tried);
  CHECK(tried > 100);
  /* Stable squares are much larger than one frame's lookups: most small
   * moves keep the map. */
  CHECK(yes * 2 > tried);
  int yes_far = 0, tried_far = 0;
  test_property(far_away, 10.0, &yes_far, &tried_far);
  CHECK(tried_far > 100);
  CHECK(yes_far * 2 > tried_far);
  int yes_tiny = 0, tried_tiny = 0;
  test_property(origin, 1e-4, &yes_tiny, &tried_tiny);
  CHECK(yes_tiny * 2 > tried_tiny);
  printf("small moves keeping the map: %d/%d near the origin, %d/%d at 1e6, %d/%d at scale 1e-4\n",
         yes, tried, yes_far, tried_far, yes_tiny, tried_tiny);
}

static void test_known_answers(void) {
  const double origin[3] = {0, 0, 0};
  scene s = random_scene(origin, 10.0);
  vsh_shadow_view v;
  CHECK(fit(&s, &s.camera, &v) == VSH_CSM_OK);
  const double inner[6] = {-0.5, 0.5, -0.5, 0.5, -1.0, 1.0};
  const double edge[6] = {-1.0, 0.5, -0.5, 0.5, -1.0, 1.0};
  /* Itself: yes, unless the region reaches the filter margin. */
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &v, .needed_origin = s.camera.position,
      .needed_region = inner, .resolution = RES, .margin_texels = 3.0}) == true);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &v, .needed_origin = s.camera.position,
      .needed_region = edge, .resolution = RES, .margin_texels = 3.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &v, .needed_origin = s.camera.position,
      .needed_region = edge, .resolution = RES, .margin_texels = 0.0}) == true);
  /* Depth outside the held range. */
  const double deep[6] = {-0.5, 0.5, -0.5, 0.5, -1.0, 1.1};
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &v, .needed_origin = s.camera.position,
      .needed_region = deep, .resolution = RES, .margin_texels = 3.0}) == false);
  /* Another light direction, or another texel size: never. */
  scene turned = s;
  turned.light[0] += 0.05;
  vsh_shadow_view w;
  CHECK(fit(&turned, &s.camera, &w) == VSH_CSM_OK);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &w, .needed_origin = s.camera.position,
      .needed_region = inner, .resolution = RES, .margin_texels = 3.0}) == false);
  vsh_shadow_view finer;
  CHECK(vsh_csm_fit_directional(&(vsh_csm_directional_params){.camera = &s.camera,
      .aspect = 4.0 / 3.0, .slice_near = s.near, .slice_far = s.far, .light_direction = s.light,
      .receivers = &s.receivers, .casters = &s.casters, .stable = 1, .resolution = 2 * RES},
      &finer) == VSH_CSM_OK);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &finer, .needed_origin = s.camera.position,
      .needed_region = inner, .resolution = RES, .margin_texels = 3.0}) == false);
  /* A move along the light direction changes nothing the map holds. */
  double along[3];
  vsh_vec3_scale(s.light, 0.5 / vsh_vec3_length(s.light), along);
  double origin2[3];
  vsh_vec3_add(s.camera.position, along, origin2);
  vsh_shadow_view shifted = v;
  double back[16];
  vsh_mat4_translation(along, back);
  vsh_mat4_multiply(v.world_to_clip, back, shifted.world_to_clip);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v,
      .rendered_origin = s.camera.position, .needed = &shifted, .needed_origin = origin2,
      .needed_region = inner, .resolution = RES, .margin_texels = 3.0}) == true);
}

static void test_lookup_region(void) {
  const double origin[3] = {0, 0, 0};
  scene s = random_scene(origin, 10.0);
  vsh_shadow_view v;
  CHECK(fit(&s, &s.camera, &v) == VSH_CSM_OK);
  double with[6], without[6], widened[6];
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 4.0 / 3.0,
      .lookup_near = s.near, .slice_far = s.far, .receivers = &s.receivers, .casters = NULL,
      .view = &v}, with) == VSH_CSM_OK);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 4.0 / 3.0,
      .lookup_near = s.near, .slice_far = s.far, .receivers = NULL, .casters = NULL, .view = &v},
      without) == VSH_CSM_OK);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 4.0 / 3.0,
      .lookup_near = 0.5 * s.near, .slice_far = s.far, .receivers = &s.receivers,
      .casters = &s.casters, .view = &v}, widened) == VSH_CSM_OK);
  /* Receivers only shrink the region in x and y; a nearer start and the
   * casters only grow it. */
  for (int k = 0; k < 2; ++k) {
    CHECK(with[2 * k] >= without[2 * k] - 1e-12);
    CHECK(with[2 * k + 1] <= without[2 * k + 1] + 1e-12);
    CHECK(widened[2 * k] <= with[2 * k] + 1e-12);
    CHECK(widened[2 * k + 1] >= with[2 * k + 1] - 1e-12);
  }
  CHECK(widened[4] <= with[4] + 1e-12 && widened[5] >= with[5] - 1e-12);
  /* Receivers the slice never sees: nothing to look up. */
  const vsh_bounds elsewhere = {{1e3, 1e3, 0}, {1e3 + 1, 1e3 + 1, 1}};
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 4.0 / 3.0,
      .lookup_near = s.near, .slice_far = s.far, .receivers = &elsewhere, .casters = NULL,
      .view = &v}, with) == VSH_CSM_EMPTY);
  /* A zero-volume receiver (a point on the floor in view) still has a region. */
  const vsh_bounds point = {{0, 0, 0}, {0, 0, 0}};
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 4.0 / 3.0,
      .lookup_near = s.near, .slice_far = s.far, .receivers = &point, .casters = NULL, .view = &v},
      with) == VSH_CSM_OK);
  CHECK(with[0] == with[1] && with[2] == with[3]);
}

static void test_bad_input(void) {
  const double origin[3] = {0, 0, 0};
  scene s = random_scene(origin, 10.0);
  vsh_shadow_view v, persp;
  CHECK(fit(&s, &s.camera, &v) == VSH_CSM_OK);
  double region[6];
  const vsh_bounds nan_box = {{NAN, 0, 0}, {1, 1, 1}};
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = NULL, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = NULL},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 0.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 0.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 2.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = INFINITY, .receivers = NULL, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = &nan_box, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = NULL, .casters = &nan_box, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  vsh_camera parallel = s.camera; /* view up parallel to the view direction */
  parallel.view_up[0] = parallel.focal_point[0] - parallel.position[0];
  parallel.view_up[1] = parallel.focal_point[1] - parallel.position[1];
  parallel.view_up[2] = parallel.focal_point[2] - parallel.position[2];
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &parallel, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = &v},
      region) == VSH_CSM_BAD_INPUT);
  const double p[3] = {0, 0, 10}, down[3] = {0, 0, -1};
  CHECK(vsh_csm_fit_perspective(&(vsh_csm_perspective_params){.position = p, .direction = down,
      .half_angle_deg = 30.0, .bounds = &s.receivers, .origin = s.camera.position,
      .resolution = RES}, &persp) == VSH_CSM_OK);
  CHECK(vsh_csm_lookup_region(&(vsh_csm_region_params){.camera = &s.camera, .aspect = 1.0,
      .lookup_near = 1.0, .slice_far = 2.0, .receivers = NULL, .casters = NULL, .view = &persp},
      region) == VSH_CSM_BAD_INPUT);
  const double inner[6] = {-0.5, 0.5, -0.5, 0.5, -1.0, 1.0};
  const double o[3] = {0, 0, 0}, bad[3] = {NAN, 0, 0};
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &persp, .rendered_origin = o,
      .needed = &persp, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = NULL, .rendered_origin = o,
      .needed = &v, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = bad,
      .needed = &v, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &v, .needed_origin = o, .needed_region = NULL, .resolution = RES,
      .margin_texels = 1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &v, .needed_origin = o, .needed_region = inner, .resolution = 0,
      .margin_texels = 1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &v, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = -1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &v, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = NAN}) == false);
  vsh_shadow_view empty = v; /* a map that covers nothing (texel 0) */
  empty.texel_world = 0.0;
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &empty, .rendered_origin = o,
      .needed = &v, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &empty, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
  vsh_shadow_view flat = v; /* zero depth scale: singular */
  flat.world_to_clip[8] = flat.world_to_clip[9] = flat.world_to_clip[10] = 0.0;
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &flat, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
  vsh_shadow_view flipped = v; /* depth reversed */
  for (int k = 8; k < 11; ++k)
    flipped.world_to_clip[k] = -flipped.world_to_clip[k];
  CHECK(vsh_csm_view_covers(&(vsh_csm_cover_params){.rendered = &v, .rendered_origin = o,
      .needed = &flipped, .needed_origin = o, .needed_region = inner, .resolution = RES,
      .margin_texels = 1.0}) == false);
}

int main(void) {
  vsh_test_seed(0x2545F4914F6CDD1Dull);
  test_known_answers();
  test_lookup_region();
  test_bad_input();
  test_random_moves();
  return vsh_check_report("core.csm_reuse");
}
