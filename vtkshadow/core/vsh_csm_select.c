/* vsh_csm_select.c - the atlas's layout, and stage 4 of a frame's shadow
 * maps: which tiles must be baked, and which keep a map an earlier frame
 * rendered (the same one, or a stable cascade that still covers every
 * lookup of this frame). */
#include "vsh_csm_plan.h"

#include "vsh_mat4.h"

#include <math.h>
#include <string.h>

vsh_csm_status vsh_csm_atlas_layout_for(int tiles, int resolution, int max_texture_size,
                                        vsh_csm_atlas_layout *out)
{
  if (!out)
    return VSH_CSM_BAD_INPUT;
  const int slots = tiles > 1 ? tiles : 1;
  const int columns = (int)ceil(sqrt((double)slots));
  out->columns = columns > 1 ? columns : 1;
  const int rows = (slots + out->columns - 1) / out->columns;
  out->rows = rows > 1 ? rows : 1;
  const int longest = out->columns > out->rows ? out->columns : out->rows;
  out->clamped = resolution * longest > max_texture_size;
  out->resolution = out->clamped ? max_texture_size / longest : resolution;
  out->width = out->columns * out->resolution;
  out->height = out->rows * out->resolution;
  return VSH_CSM_OK;
}

/* Whether `held` holds exactly `tile`'s map: the same kind of view and
 * matrix, or two empty maps (nothing in front of a cube face, no receiver
 * in a slice), which are the same whatever their placeholder matrices say. */
static int same_map(const vsh_csm_held_map *held, const vsh_csm_tile *tile)
{
  if (held->map.view.perspective != tile->view.perspective)
    return 0;
  if (tile->view.texel_world <= 0.0)
    return held->map.view.texel_world <= 0.0;
  for (int k = 0; k < 16; ++k) {
    const double a = tile->absolute[k], b = held->map.absolute[k];
    const double scale = fmax(1.0, fmax(fabs(a), fabs(b)));
    if (!(fabs(a - b) <= 1e-12 * scale))
      return 0;
  }
  return 1;
}

/* Whether the held map covers every lookup of `tile` this frame; then
 * `tile` becomes the held map, its view re-expressed relative to this
 * frame's camera position (a small shift, exact enough in double), keeping
 * its own slice and texel size. (The core refuses perspective and empty
 * maps itself.) */
static int reuse_covering(const vsh_csm_reuse_params *p, const vsh_csm_held_map *held,
                          vsh_csm_tile *tile)
{
  const double *eye = p->camera->position;
  const double band = tile->near_depth > p->depth_near ? p->blend_band : 0.0;
  const vsh_csm_region_params lookups = {
      .camera = p->camera, .aspect = p->aspect, .lookup_near = tile->near_depth * (1.0 - band),
      .slice_far = tile->far_depth, .receivers = p->receivers, .casters = p->casters,
      .view = &tile->view};
  double region[6];
  if (vsh_csm_lookup_region(&lookups, region) != VSH_CSM_OK)
    return 0;
  const vsh_csm_cover_params cover = {
      .rendered = &held->map.view, .rendered_origin = held->origin, .needed = &tile->view,
      .needed_origin = eye, .needed_region = region, .resolution = p->resolution,
      .margin_texels = p->reach_texels};
  if (!vsh_csm_view_covers(&cover))
    return 0;
  const double shift[3] = {eye[0] - held->origin[0], eye[1] - held->origin[1],
                           eye[2] - held->origin[2]};
  double to_held[16];
  vsh_mat4_translation(shift, to_held);
  const double near_depth = tile->near_depth, far_depth = tile->far_depth;
  const double texel_px = tile->texel_px;
  *tile = held->map;
  vsh_mat4_multiply(held->map.view.world_to_clip, to_held, tile->view.world_to_clip);
  tile->near_depth = near_depth;
  tile->far_depth = far_depth;
  tile->texel_px = texel_px;
  return 1;
}

vsh_csm_status vsh_csm_select_reusable(const vsh_csm_reuse_params *p, vsh_csm_tile *tiles,
                                       int tile_count, vsh_csm_held_map *held,
                                       vsh_csm_selection *out)
{
  if (!p || !p->camera || !out || tile_count < 0 || tile_count > VSH_CSM_MAX_TILES ||
      (tile_count > 0 && (!tiles || !held)))
    return VSH_CSM_BAD_INPUT;
  out->bake_count = 0;
  out->reused_count = 0;
  for (int t = 0; t < tile_count; ++t) {
    vsh_csm_tile *tile = &tiles[t];
    vsh_csm_held_map *slot = &held[t];
    /* A map of the same light and casters: the same one, or perhaps reusable. */
    const int comparable =
        slot->valid && slot->caster_time == p->caster_time && slot->map.light == tile->light;
    int keep = comparable && same_map(slot, tile);
    if (!keep && comparable && p->stable && tile->near_depth > 0.0 &&
        reuse_covering(p, slot, tile)) {
      ++out->reused_count;
      keep = 1;
    }
    if (!keep) {
      out->bake[out->bake_count++] = t;
      slot->valid = 1;
      slot->map = *tile;
      memcpy(slot->origin, p->camera->position, sizeof slot->origin);
      slot->caster_time = p->caster_time;
    }
  }
  return VSH_CSM_OK;
}
