/* vsh_csm_screen.c - per screen tile, which lookups the resolve needs (see
 * vsh_csm_screen.h). Everything here is conservative: a tile is decided only
 * where every pixel's own lookup would give the same answer. */
#include "vsh_csm_screen.h"

#include "vsh_mat4.h"

#include <math.h>
#include <stddef.h>

/* The tile's box of view space: its four pixel corners at its nearest and
 * farthest window depth, in camera-relative world coordinates, and its view
 * depth range. 0 when a corner does not project (w <= 0). */
static int tile_corners(const vsh_csm_screen_params *p, const vsh_csm_screen_tile *t,
                        double corners[8][3], double depth_range[2])
{
  depth_range[0] = INFINITY;
  depth_range[1] = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const double x = (k & 1) ? t->x1 : t->x0, y = (k & 2) ? t->y1 : t->y0;
    const double d = (k & 4) ? t->depth_max : t->depth_min;
    const double ndc[4] = {2.0 * x / p->viewport[0] - 1.0, 2.0 * y / p->viewport[1] - 1.0,
                           2.0 * d - 1.0, 1.0};
    double v[4];
    vsh_mat4_transform_point4(p->ndc_to_view, ndc, v);
    if (!(v[3] > 0.0) || !isfinite(v[0] / v[3]) || !isfinite(v[1] / v[3]) ||
        !isfinite(v[2] / v[3]))
      return 0;
    const double view[3] = {v[0] / v[3], v[1] / v[3], v[2] / v[3]};
    depth_range[0] = fmin(depth_range[0], -view[2]);
    depth_range[1] = fmax(depth_range[1], -view[2]);
    vsh_mat4_transform_direction(p->view_to_relative, view, corners[k]);
  }
  return 1;
}

/* The casters' box relative to the camera. */
static void caster_corners(const vsh_csm_screen_params *p, double corners[8][3])
{
  const vsh_bounds *b = p->casters;
  for (int k = 0; k < 8; ++k) {
    corners[k][0] = ((k & 1) ? b->max[0] : b->min[0]) - p->origin[0];
    corners[k][1] = ((k & 2) ? b->max[1] : b->min[1]) - p->origin[1];
    corners[k][2] = ((k & 4) ? b->max[2] : b->min[2]) - p->origin[2];
  }
}

/* Whether orthographic map `tile` may read a caster for a point of the
 * tile's box: their boxes overlap in the map's x and y (widened by the
 * filter's reach, a texel for rasterization, and the normal offset), and
 * the box reaches behind the nearest caster (widened by the normal offset).
 * An empty map (texel 0) holds no caster. */
static int ortho_map_may_shadow(const vsh_csm_screen_params *p, const vsh_csm_tile *tile,
                                double box[8][3], double casters[8][3])
{
  const vsh_shadow_view *view = &tile->view;
  if (!(view->texel_world > 0.0))
    return 0;
  double lo[2][3], hi[2][3]; /* [0] box, [1] casters */
  for (int s = 0; s < 2; ++s) {
    for (int a = 0; a < 3; ++a) {
      lo[s][a] = INFINITY;
      hi[s][a] = -INFINITY;
    }
    for (int k = 0; k < 8; ++k) {
      double c[3];
      vsh_mat4_transform_point(view->world_to_clip, s == 0 ? box[k] : casters[k], c);
      for (int a = 0; a < 3; ++a) {
        lo[s][a] = fmin(lo[s][a], c[a]);
        hi[s][a] = fmax(hi[s][a], c[a]);
      }
    }
  }
  const double offset_texels = tile->bias[1] / view->texel_world;
  const double margin_xy = (p->reach_texels + 1.0 + offset_texels) * 2.0 / p->resolution;
  const double margin_z =
      view->depth_extent > 0.0 ? 2.0 * tile->bias[1] / view->depth_extent + 1e-9 : INFINITY;
  for (int a = 0; a < 2; ++a) {
    if (lo[0][a] - margin_xy > hi[1][a] || hi[0][a] + margin_xy < lo[1][a])
      return 0;
  }
  return !(hi[0][2] + margin_z < lo[1][2]);
}

/* Whether a positional light may shadow any point of the box: the cone from
 * the light around the casters' bounding sphere, widened by the filter's
 * reach and the normal offset (both angles: texel_world is the texel at
 * distance 1), meets the cone around the box's bounding sphere. A light
 * inside either sphere may. */
static int positional_may_shadow(const vsh_csm_screen_params *p, int l, double box[8][3],
                                 double casters[8][3])
{
  double light[3];
  for (int a = 0; a < 3; ++a)
    light[a] = p->lights[l].position[a] - p->origin[a];
  double texel = 0.0, offset = 0.0;
  for (int t = p->plan->first[l]; t < p->plan->first[l] + p->plan->count[l]; ++t) {
    texel = fmax(texel, p->plan->tiles[t].view.texel_world);
    offset = fmax(offset, p->plan->tiles[t].bias[1]);
  }
  if (!(texel > 0.0))
    return 0; /* every face empty */
  double angle[2], dir[2][3];
  for (int s = 0; s < 2; ++s) {
    double (*pts)[3] = s == 0 ? box : casters;
    double c[3] = {0.0, 0.0, 0.0}, r = 0.0;
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a)
        c[a] += pts[k][a] / 8.0;
    for (int k = 0; k < 8; ++k) {
      const double d[3] = {pts[k][0] - c[0], pts[k][1] - c[1], pts[k][2] - c[2]};
      r = fmax(r, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
    const double to[3] = {c[0] - light[0], c[1] - light[1], c[2] - light[2]};
    const double dist = sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
    if (!(dist > r * (1.0 + 1e-9)))
      return 1;
    for (int a = 0; a < 3; ++a)
      dir[s][a] = to[a] / dist;
    angle[s] = asin(r / dist);
  }
  const double cosine = dir[0][0] * dir[1][0] + dir[0][1] * dir[1][1] + dir[0][2] * dir[1][2];
  const double between = acos(fmax(-1.0, fmin(1.0, cosine)));
  const double margin = (p->reach_texels + 1.0) * texel * 1.5 + offset;
  return between <= angle[0] + angle[1] + margin;
}

/* The cascade (0-based) the per-pixel code picks at view depth z. */
static int cascade_at(const vsh_csm_tile_plan *plan, int l, double z)
{
  int c = 0;
  while (c < plan->count[l] - 1 && z > plan->tiles[plan->first[l] + c].far_depth)
    ++c;
  return c;
}

/* A directional light over the tile's depths [z0, z1]. */
static int directional_need(const vsh_csm_screen_params *p, int l, const double z[2],
                            double box[8][3], double casters[8][3])
{
  const vsh_csm_tile_plan *plan = p->plan;
  const int first = plan->first[l], count = plan->count[l];
  const double last_far = plan->tiles[first + count - 1].far_depth;
  if (z[0] > last_far)
    return VSH_CSM_SCREEN_LIT;
  const double z1 = fmin(z[1], last_far);
  const int c0 = cascade_at(plan, l, z[0]), c1 = cascade_at(plan, l, z1);
  int used_last = c1;
  int single = c0 == c1;
  if (c1 < count - 1 && p->blend_band > 0.0) {
    const double far_d = plan->tiles[first + c1].far_depth;
    const double near_d = c1 == 0 ? 0.0 : plan->tiles[first + c1 - 1].far_depth;
    if (z1 > far_d - p->blend_band * (far_d - near_d)) {
      single = 0; /* blended with the next cascade */
      used_last = c1 + 1;
    }
  }
  if (p->cull_casters) {
    int may = 0;
    for (int c = c0; c <= used_last && !may; ++c)
      may = ortho_map_may_shadow(p, &plan->tiles[first + c], box, casters);
    if (!may)
      return VSH_CSM_SCREEN_LIT;
  }
  return single ? VSH_CSM_SCREEN_CASCADE + c0 : VSH_CSM_SCREEN_ANY;
}

static int valid_params(const vsh_csm_screen_params *p, const vsh_csm_screen_tile *t)
{
  if (!p || !t || !p->plan || !p->ndc_to_view || !p->view_to_relative || !p->origin)
    return 0;
  if (p->cull_casters && (!p->casters || !p->lights))
    return 0;
  if (p->viewport[0] <= 0 || p->viewport[1] <= 0 || p->resolution <= 0)
    return 0;
  if (!(p->reach_texels >= 0.0) || !(p->blend_band >= 0.0) || !(p->max_distance >= 0.0))
    return 0;
  if (t->x1 <= t->x0 || t->y1 <= t->y0)
    return 0;
  return isfinite(t->depth_min) && isfinite(t->depth_max);
}

vsh_csm_status vsh_csm_screen_tile_needs(const vsh_csm_screen_params *p,
                                         const vsh_csm_screen_tile *t,
                                         int out[VSH_CSM_MAX_LIGHTS])
{
  if (!valid_params(p, t) || !out)
    return VSH_CSM_BAD_INPUT;
  const vsh_csm_tile_plan *plan = p->plan;
  const int lights = plan->light_count < VSH_CSM_MAX_LIGHTS ? plan->light_count
                                                             : VSH_CSM_MAX_LIGHTS;
  for (int l = 0; l < VSH_CSM_MAX_LIGHTS; ++l)
    out[l] = VSH_CSM_SCREEN_LIT;
  if (t->depth_min > t->depth_max)
    return VSH_CSM_OK; /* background only */
  double box[8][3], casters[8][3], z[2];
  const int projects = tile_corners(p, t, box, z);
  const int no_casters = p->cull_casters && vsh_bounds_is_empty(p->casters);
  if (p->cull_casters && !no_casters)
    caster_corners(p, casters);
  for (int l = 0; l < lights; ++l) {
    const int kind = plan->kind[l];
    if (kind == VSH_CSM_NO_SHADOW || plan->count[l] <= 0)
      continue;
    if (!projects) {
      out[l] = VSH_CSM_SCREEN_ANY;
      continue;
    }
    if ((p->max_distance > 0.0 && z[0] >= p->max_distance) || no_casters)
      continue; /* faded out entirely, or nothing casts */
    if (kind == VSH_CSM_CASCADES)
      out[l] = directional_need(p, l, z, box, casters);
    else
      out[l] = (p->cull_casters && !positional_may_shadow(p, l, box, casters))
                   ? VSH_CSM_SCREEN_LIT
                   : VSH_CSM_SCREEN_ANY;
  }
  return VSH_CSM_OK;
}

vsh_csm_status vsh_csm_screen_depth_ranges(const float *depth, int width, int height,
                                           int tile_px, float *out_min, float *out_max,
                                           long long *covered)
{
  if (!depth || !out_min || !out_max || width <= 0 || height <= 0 || tile_px <= 0)
    return VSH_CSM_BAD_INPUT;
  const int cols = (width + tile_px - 1) / tile_px, rows = (height + tile_px - 1) / tile_px;
  for (int i = 0; i < cols * rows; ++i) {
    out_min[i] = 1.0f;
    out_max[i] = 0.0f;
  }
  long long count = 0;
  for (int y = 0; y < height; ++y) {
    const float *row = depth + (size_t)y * (size_t)width;
    float *mins = out_min + (size_t)(y / tile_px) * (size_t)cols;
    float *maxs = out_max + (size_t)(y / tile_px) * (size_t)cols;
    for (int x = 0; x < width; ++x) {
      const float d = row[x];
      if (!(d < 1.0f))
        continue; /* background (or NaN) */
      const int tx = x / tile_px;
      ++count;
      mins[tx] = d < mins[tx] ? d : mins[tx];
      maxs[tx] = d > maxs[tx] ? d : maxs[tx];
    }
  }
  if (covered)
    *covered = count;
  return VSH_CSM_OK;
}
