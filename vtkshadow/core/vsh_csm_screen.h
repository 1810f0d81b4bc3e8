/* vsh_csm_screen.h - which shadow lookups a tile of the screen needs, for
 * the cascaded pass's screen-space resolve.
 *
 * The resolve looks up every light's maps once per visible pixel. Over a
 * tile of pixels (16x16) the depth range is known from the depth pre-pass,
 * and with it most of that work is decided for the whole tile at once:
 *   - a directional light whose cascades the tile's depths fall into: one
 *     cascade, no per-pixel cascade choice and no blend with the next one;
 *   - beyond the last cascade or the shadow distance: lit, no lookup;
 *   - no caster anywhere near the tile's part of the light's maps (the
 *     tile's box of view space, projected into each map it may use, does
 *     not meet the casters' box there, or lies in front of every caster
 *     towards the light): lit, no lookup.
 * The answers are conservative: a tile gets LIT or one cascade only when
 * every pixel's per-pixel lookup would give exactly that, with the filter's
 * reach and the normal offset as margins. Anything undecided is ANY (the
 * per-pixel code, as without tiles). */
#ifndef VSH_CSM_SCREEN_H
#define VSH_CSM_SCREEN_H

#include "vsh_bounds.h"
#include "vsh_csm.h"
#include "vsh_csm_plan.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Per light and tile: what the resolve runs. */
#define VSH_CSM_SCREEN_LIT 0     /* visibility 1, no lookup */
#define VSH_CSM_SCREEN_ANY 1     /* the per-pixel code (cascade choice, blend) */
#define VSH_CSM_SCREEN_CASCADE 2 /* + c: directional light, its cascade c alone */

typedef struct vsh_csm_screen_params {
  const vsh_csm_tile_plan *plan;  /* the frame's maps (matrices camera-relative) */
  const vsh_csm_light *lights;    /* plan->light_count lights, world */
  const double *origin;           /* camera position: what matrices are relative to */
  const double *ndc_to_view;      /* 16, row-major: inverse projection (camera at 0) */
  const double *view_to_relative; /* 16, row-major: view -> camera-relative world */
  const vsh_bounds *casters;      /* world; empty: nothing casts */
  int viewport[2];                /* pixels */
  double blend_band;              /* fraction of a cascade blended with the next */
  double max_distance;            /* view depth where shadows end; 0: none */
  double reach_texels;            /* how far the filter reads from a lookup, texels */
  int resolution;                 /* texels per map edge */
  int cull_casters;               /* 0: depth decisions only (e.g. PCSS, whose search reaches far) */
} vsh_csm_screen_params;

/* A tile: pixels [x0, x1) x [y0, y1) (row 0 at the bottom) and the window
 * depths [0, 1) of its covered pixels; depth_min > depth_max when none is
 * covered (all background). */
typedef struct vsh_csm_screen_tile {
  int x0, y0, x1, y1;
  double depth_min, depth_max;
} vsh_csm_screen_tile;

/* out[l] for l < plan->light_count (VSH_CSM_SCREEN_*). A tile with no
 * covered pixel is LIT for every light (the resolve draws nothing there).
 * Lights without shadow are LIT. A corner of the tile's box with w <= 0
 * after ndc_to_view makes every casting light ANY. BAD_INPUT for NULL
 * pointers, a non-positive viewport or resolution, an empty or inverted
 * pixel rectangle, or non-finite depths; OK otherwise. */
vsh_csm_status vsh_csm_screen_tile_needs(const vsh_csm_screen_params *p,
                                         const vsh_csm_screen_tile *tile,
                                         int out[VSH_CSM_MAX_LIGHTS]);

/* The min and max window depth below 1 of each tile_px x tile_px tile of a
 * width x height depth image (row 0 at the bottom), tiles in rows from the
 * bottom: ceil(width / tile_px) * ceil(height / tile_px) of them. A tile
 * with no depth below 1 gets min 1, max 0. *covered (may be NULL) counts
 * the pixels below 1. BAD_INPUT for NULL arrays or sizes <= 0, else OK. */
vsh_csm_status vsh_csm_screen_depth_ranges(const float *depth, int width, int height,
                                           int tile_px, float *out_min, float *out_max,
                                           long long *covered);

#ifdef __cplusplus
}
#endif
#endif
