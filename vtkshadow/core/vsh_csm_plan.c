/* vsh_csm_plan.c - stages 1 to 3 of a frame's shadow maps: the depth range
 * the shadows cover, the map size and cascades, and per light its maps
 * (fitted by kind). No GL: the pass turns the plan into an atlas. */
#include "vsh_csm_plan.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

/* std::min / std::max's rules (the first argument on ties and NaN), so the
 * plan gives the numbers the pass computed before it was split in stages. */
static double min_d(double a, double b) { return b < a ? b : a; }
static double max_d(double a, double b) { return a < b ? b : a; }
static int max_i(int a, int b) { return a < b ? b : a; }

double vsh_csm_map_half_angle(double cone_angle_deg)
{
  return cone_angle_deg < 90.0 ? min_d(cone_angle_deg * 1.02 + 0.5, 89.0)
                               : VSH_CSM_CUBE_FACE_HALF_ANGLE;
}

/* ---- stage 1: depth range ------------------------------------------------ */

vsh_csm_status vsh_csm_plan_depth(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                  vsh_csm_depth_plan *out)
{
  if (!scene || !settings || !out)
    return VSH_CSM_BAD_INPUT;
  const double *clip = scene->clip;
  double *range = out->range;
  range[0] = clip[0];
  range[1] = clip[1];
  /* Without a caster and a receiver nothing is shadowed: the clip range
   * stands in, so the shader's fade uniforms stay defined. */
  out->have_scene = !vsh_bounds_is_empty(&scene->receivers) && scene->caster_count > 0;
  const vsh_csm_depth_range_params visible = {&scene->camera, scene->aspect, clip[0], clip[1],
                                              &scene->receivers};
  if (out->have_scene && vsh_csm_visible_depth_range(&visible, range) != VSH_CSM_OK) {
    range[0] = clip[0];
    range[1] = clip[1];
  }
  if (settings->max_shadow_distance > 0.0)
    range[1] = max_d(min_d(range[1], settings->max_shadow_distance), range[0] * 1.001);
  /* Shadows fade out only before a cut-off the user asked for. Without one
   * the far end is where the receivers end, and a fade there would erase
   * real shadows on the farthest tenth of them (found when the clipping
   * range came to hug the visible geometry: grazing-85 lost 0.7% of its
   * pixels' shadows). */
  out->max_distance = settings->max_shadow_distance > 0.0 ? range[1] : 0.0;
  out->fade_start = range[1] - settings->fade_fraction * (range[1] - range[0]);
  return out->have_scene ? VSH_CSM_OK : VSH_CSM_EMPTY;
}

/* ---- stage 2: resolution and cascades ------------------------------------ */

/* Everything that casts or receives: what perspective maps are fitted to. */
static vsh_bounds everything(const vsh_csm_scene *scene)
{
  vsh_bounds b = scene->casters;
  vsh_bounds_merge(&b, &scene->receivers);
  return b;
}

/* The resolution and count that meet the texel target: fewest cascades
 * first (every cascade re-renders every caster, so on any renderer a second
 * cascade costs more than a larger map), then the least memory. */
static void choose_for_target(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                              const vsh_csm_depth_plan *depth, vsh_csm_resolution_plan *out)
{
  const int max_count = settings->cascade_count > 0 ? settings->cascade_count : 8;
  for (int k = settings->cascade_count > 0 ? max_count : 1; k <= max_count; ++k) {
    const vsh_csm_choose_params p = {
        .near_depth = depth->range[0], .far_depth = depth->range[1],
        .view_angle_deg = scene->camera.view_angle, .aspect = scene->aspect,
        .viewport_height = scene->viewport_height, .max_texel_px = settings->max_texel_px,
        .budget_bytes = settings->memory_budget, .min_res = 256, .max_res = 8192,
        .max_count = k};
    vsh_csm_choice choice;
    const vsh_csm_status status = vsh_csm_choose(&p, &choice);
    out->resolution = choice.resolution;
    out->cascade_count = choice.count;
    if (status == VSH_CSM_OK)
      break;
  }
}

/* Spot and point-light maps share the atlas resolution: raise it to what
 * they need where the scene's centre is seen. */
static void raise_for_positional(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                 const vsh_csm_depth_plan *depth, vsh_csm_resolution_plan *out)
{
  const vsh_bounds all = everything(scene);
  double centre[3];
  if (!depth->have_scene || vsh_bounds_center(&all, centre) != 0)
    return;
  double forward[3], r[3], u[3];
  vsh_camera_basis(&scene->camera, r, u, forward);
  const double *eye = scene->camera.position;
  const double rel[3] = {centre[0] - eye[0], centre[1] - eye[1], centre[2] - eye[2]};
  const double view_depth = max_d(vsh_vec3_dot(rel, forward), depth->range[0]);
  for (int l = 0; l < scene->light_count; ++l) {
    const vsh_csm_light *light = &scene->lights[l];
    if (!light->casts || !light->positional)
      continue;
    const double *p = light->position;
    const double to_centre[3] = {centre[0] - p[0], centre[1] - p[1], centre[2] - p[2]};
    const vsh_csm_resolution_params need = {
        .half_angle_deg = vsh_csm_map_half_angle(light->cone_angle),
        .light_distance = vsh_vec3_length(to_centre), .view_depth = view_depth,
        .view_angle_deg = scene->camera.view_angle, .viewport_height = scene->viewport_height,
        .max_texel_px = settings->max_texel_px, .min_res = 256, .max_res = 8192};
    int res = 0;
    vsh_csm_perspective_resolution(&need, &res);
    out->resolution = max_i(out->resolution, res);
  }
}

/* The split depths; invalid explicit fractions fall back to practical ones. */
static void split_depths(const vsh_csm_settings *settings, const vsh_csm_depth_plan *depth,
                         vsh_csm_resolution_plan *out)
{
  const vsh_csm_split_params asked = {settings->split_scheme, out->cascade_count,
                                      depth->range[0], depth->range[1], settings->split_lambda,
                                      settings->split_fractions, settings->ratio_per_cascade};
  out->split_fallback = 0;
  if (vsh_csm_splits(&asked, out->splits) != VSH_CSM_OK) {
    out->split_fallback = settings->split_scheme == VSH_SPLIT_EXPLICIT;
    const vsh_csm_split_params practical = {VSH_SPLIT_PRACTICAL, out->cascade_count,
                                            depth->range[0], depth->range[1], 0.75, NULL,
                                            settings->ratio_per_cascade};
    vsh_csm_splits(&practical, out->splits);
  }
}

vsh_csm_status vsh_csm_plan_resolution(const vsh_csm_scene *scene,
                                       const vsh_csm_settings *settings,
                                       const vsh_csm_depth_plan *depth,
                                       vsh_csm_resolution_plan *out)
{
  if (!scene || !settings || !depth || !out || (scene->light_count > 0 && !scene->lights))
    return VSH_CSM_BAD_INPUT;
  memset(out, 0, sizeof *out);
  out->resolution = settings->map_resolution;
  out->cascade_count =
      settings->cascade_count > 0
          ? settings->cascade_count
          : vsh_csm_default_count(depth->range[0], depth->range[1], settings->ratio_per_cascade);
  if (settings->max_texel_px > 0.0) {
    choose_for_target(scene, settings, depth, out);
    raise_for_positional(scene, settings, depth, out);
  }
  split_depths(settings, depth, out);
  return VSH_CSM_OK;
}

/* ---- stage 3: tiles, fitted per light kind -------------------------------- */

/* Bias from the map's texel size and depth range, and the absolute world ->
 * clip matrix. A perspective map's texels grow with the distance from the
 * light, and its depth is not linear: both biases are per unit of distance
 * there, and the shader scales them by the fragment's distance and applies
 * the depth bias in linear depth (a constant offset in the map's depth would
 * swamp the depth differences far from a light whose near plane is close). */
static void finish_tile(vsh_csm_tile *tile, const double eye[3], double bias_scale)
{
  vsh_csm_bias(tile->view.texel_world, tile->view.perspective ? 1.0 : tile->view.depth_extent,
               bias_scale, &tile->bias[0], &tile->bias[1]);
  double to_relative[16];
  const double neg_eye[3] = {-eye[0], -eye[1], -eye[2]};
  vsh_mat4_translation(neg_eye, to_relative);
  vsh_mat4_multiply(tile->view.world_to_clip, to_relative, tile->absolute);
}

static vsh_csm_tile *new_tile(vsh_csm_tile_plan *out, int light)
{
  vsh_csm_tile *tile = &out->tiles[out->tile_count++];
  memset(tile, 0, sizeof *tile);
  tile->light = light;
  return tile;
}

/* A directional light: one cascade per view slice. */
static void plan_cascades(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                          const vsh_csm_resolution_plan *res, int l, const double travel[3],
                          vsh_csm_tile_plan *out)
{
  int made = 0;
  const double *splits = res->splits;
  for (int c = 0; c < res->cascade_count && out->tile_count < VSH_CSM_MAX_TILES; ++c) {
    vsh_csm_tile tile;
    memset(&tile, 0, sizeof tile);
    const vsh_csm_directional_params fit = {
        .camera = &scene->camera, .aspect = scene->aspect, .slice_near = splits[c],
        .slice_far = splits[c + 1], .light_direction = travel, .receivers = &scene->receivers,
        .casters = &scene->casters, .stable = settings->stable ? 1 : 0,
        .resolution = res->resolution};
    const vsh_csm_status status = vsh_csm_fit_directional(&fit, &tile.view);
    if (status == VSH_CSM_BAD_INPUT)
      break;
    if (status == VSH_CSM_EMPTY) {
      /* The slice sees no receiver: an empty map that nothing samples. */
      vsh_mat4_identity(tile.view.world_to_clip);
      tile.view.world_to_clip[10] = 0.0;
      tile.view.texel_world = 0.0;
      tile.view.depth_extent = 1.0;
    }
    tile.near_depth = splits[c];
    tile.far_depth = splits[c + 1];
    tile.texel_px = vsh_csm_texel_pixels(tile.view.texel_world, splits[c],
                                         scene->camera.view_angle, scene->viewport_height);
    tile.light = l;
    out->tiles[out->tile_count++] = tile;
    ++made;
  }
  if (made > 0) {
    out->kind[l] = VSH_CSM_CASCADES;
    out->count[l] = made;
  }
}

/* A spot light: one perspective map around its cone. */
static void plan_spot(const vsh_csm_scene *scene, const vsh_csm_resolution_plan *res, int l,
                      const double travel[3], vsh_csm_tile_plan *out)
{
  const vsh_csm_light *light = &scene->lights[l];
  const vsh_bounds all = everything(scene);
  vsh_csm_tile tile;
  memset(&tile, 0, sizeof tile);
  const vsh_csm_perspective_params fit = {
      .position = light->position, .direction = travel,
      .half_angle_deg = vsh_csm_map_half_angle(light->cone_angle), .bounds = &all,
      .origin = scene->camera.position, .resolution = res->resolution};
  if (out->tile_count < VSH_CSM_MAX_TILES && vsh_csm_fit_perspective(&fit, &tile.view) == VSH_CSM_OK) {
    tile.light = l;
    out->tiles[out->tile_count++] = tile;
    out->kind[l] = VSH_CSM_SPOT;
    out->count[l] = 1;
  }
}

/* A point light: six cube faces, a little wider than 90 degrees. */
static void plan_cube(const vsh_csm_scene *scene, const vsh_csm_resolution_plan *res, int l,
                      vsh_csm_tile_plan *out)
{
  if (out->tile_count + 6 > VSH_CSM_MAX_TILES)
    return;
  const vsh_bounds all = everything(scene);
  for (int face = 0; face < 6; ++face) {
    double axis[3];
    vsh_csm_cube_face_direction(face, axis);
    vsh_csm_tile *tile = new_tile(out, l);
    const vsh_csm_perspective_params fit = {
        .position = scene->lights[l].position, .direction = axis,
        .half_angle_deg = VSH_CSM_CUBE_FACE_HALF_ANGLE, .bounds = &all,
        .origin = scene->camera.position, .resolution = res->resolution};
    if (vsh_csm_fit_perspective(&fit, &tile->view) != VSH_CSM_OK) {
      /* Nothing in front of this face: a map that covers nothing. */
      memset(&tile->view, 0, sizeof tile->view);
      vsh_mat4_identity(tile->view.world_to_clip);
      tile->view.world_to_clip[15] = -1.0; /* w < 0: every lookup is lit */
      tile->view.texel_world = 0.0;
      tile->view.depth_extent = 1.0;
    }
  }
  out->kind[l] = VSH_CSM_POINT;
  out->count[l] = 6;
}

vsh_csm_status vsh_csm_plan_tiles(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                  const vsh_csm_depth_plan *depth,
                                  const vsh_csm_resolution_plan *resolution,
                                  vsh_csm_tile_plan *out)
{
  if (!scene || !settings || !depth || !resolution || !out ||
      (scene->light_count > 0 && !scene->lights))
    return VSH_CSM_BAD_INPUT;
  memset(out, 0, sizeof *out);
  const int lights = scene->light_count < 0 ? 0 : scene->light_count;
  out->light_count = lights < VSH_CSM_MAX_LIGHTS ? lights : VSH_CSM_MAX_LIGHTS;
  out->lights_dropped = lights - out->light_count;
  for (int l = 0; l < out->light_count; ++l) {
    const vsh_csm_light *light = &scene->lights[l];
    out->kind[l] = VSH_CSM_NO_SHADOW;
    out->first[l] = out->tile_count;
    out->count[l] = 0;
    if (!depth->have_scene || !light->casts)
      continue;
    const double *p = light->position, *f = light->focal_point;
    const double travel[3] = {f[0] - p[0], f[1] - p[1], f[2] - p[2]};
    if (!light->positional)
      plan_cascades(scene, settings, resolution, l, travel, out);
    else if (light->cone_angle < 90.0)
      plan_spot(scene, resolution, l, travel, out);
    else
      plan_cube(scene, resolution, l, out);
  }
  for (int t = 0; t < out->tile_count; ++t)
    finish_tile(&out->tiles[t], scene->camera.position, settings->bias_scale);
  return VSH_CSM_OK;
}

vsh_csm_status vsh_csm_plan_frame(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                  vsh_csm_plan *out)
{
  if (!out)
    return VSH_CSM_BAD_INPUT;
  const vsh_csm_status depth = vsh_csm_plan_depth(scene, settings, &out->depth);
  if (depth == VSH_CSM_BAD_INPUT)
    return depth;
  vsh_csm_status status = vsh_csm_plan_resolution(scene, settings, &out->depth, &out->resolution);
  if (status == VSH_CSM_OK)
    status = vsh_csm_plan_tiles(scene, settings, &out->depth, &out->resolution, &out->tiles);
  return status == VSH_CSM_OK ? depth : status;
}
