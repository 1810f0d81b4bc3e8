/* vsh_csm_plan.h - one frame of the cascaded shadow map pass, planned
 * without GL: from the camera, the lights, the scene's bounds and the
 * pass's settings to the list of shadow maps (tiles) to use, and which of
 * them an earlier frame's maps can stand in for.
 *
 * The stages, in order (vsh_csm_plan_frame runs the first three):
 *   1. depth range: what part of the view the shadows cover;
 *   2. resolution: the map size and cascade count, and the split depths;
 *   3. tiles: per light, its maps - cascades for a directional light, one
 *      perspective map for a spot light, six cube faces for a point light -
 *      each with its bias and absolute matrix;
 * then, once the atlas's real resolution is known (vsh_csm_atlas_layout),
 *   4. reuse: which tiles must be baked, and which keep an earlier map. */
#ifndef VSH_CSM_PLAN_H
#define VSH_CSM_PLAN_H

#include "vsh_csm.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VSH_CSM_MAX_LIGHTS 8 /* lights with shadows, in the mappers' numbering */
#define VSH_CSM_MAX_TILES 24 /* maps in the atlas */

/* Half angle of a point light's cube face: a little over 45 degrees, so the
 * face a direction's major axis picks always contains it. */
#define VSH_CSM_CUBE_FACE_HALF_ANGLE 45.5

/* What each light gets; the values are compiled into the receivers' shader. */
typedef enum vsh_csm_light_kind {
  VSH_CSM_NO_SHADOW = 0,
  VSH_CSM_CASCADES = 1, /* directional */
  VSH_CSM_SPOT = 2,
  VSH_CSM_POINT = 3
} vsh_csm_light_kind;

/* A switched-on light, in the mappers' numbering. */
typedef struct vsh_csm_light {
  double position[3];    /* world (transformed) */
  double focal_point[3]; /* world (transformed) */
  int positional;        /* 0: directional */
  double cone_angle;     /* degrees; >= 90 makes a positional light a point light */
  int casts;             /* the pass lets it cast (skipped lights, headlight rule) */
} vsh_csm_light;

/* The pass's settings (see vtkCascadedShadowMapPass.h). */
typedef struct vsh_csm_settings {
  int cascade_count;          /* 0: from the depth ratio */
  double ratio_per_cascade;
  vsh_split_scheme split_scheme;
  double split_lambda;
  double split_fractions[VSH_CSM_MAX_CASCADES];
  int stable;
  int map_resolution;
  double max_texel_px;        /* > 0: choose resolution and count for it */
  long long memory_budget;    /* bytes */
  double max_shadow_distance; /* > 0: shadows end there */
  double fade_fraction;
  double bias_scale;
} vsh_csm_settings;

/* The frame: camera, viewport, bounds and lights. */
typedef struct vsh_csm_scene {
  vsh_camera camera;
  double clip[2];             /* the camera's clipping range */
  double aspect;              /* viewport width / height */
  int viewport_height;        /* pixels */
  vsh_bounds casters;         /* every actor that casts */
  vsh_bounds receivers;       /* every actor (all receive) */
  int caster_count;
  const vsh_csm_light *lights;
  int light_count;            /* may exceed VSH_CSM_MAX_LIGHTS: the rest get no shadow */
} vsh_csm_scene;

/* Stage 1: the depth range the shadows cover. */
typedef struct vsh_csm_depth_plan {
  int have_scene;       /* something casts onto something */
  double range[2];      /* visible depth range of the receivers (or the clip range) */
  double max_distance;  /* where shadows end (0: no fade) */
  double fade_start;    /* where they start fading */
} vsh_csm_depth_plan;

/* Stage 2: map size and cascades. */
typedef struct vsh_csm_resolution_plan {
  int resolution;       /* texels per map edge, before the GL's limit */
  int cascade_count;
  double splits[VSH_CSM_MAX_CASCADES + 1];
  int split_fallback;   /* the explicit fractions were invalid: practical splits used */
} vsh_csm_resolution_plan;

/* One shadow map of the atlas. */
typedef struct vsh_csm_tile {
  vsh_shadow_view view; /* camera-relative world -> clip; texel_world 0: an empty map */
  double absolute[16];  /* world -> clip, to tell whether a map changed */
  double near_depth;    /* cascades: the view slice */
  double far_depth;
  double texel_px;      /* on-screen size of a texel at the slice's near end */
  double bias[2];       /* depth bias, normal offset */
  int light;            /* mappers' numbering */
} vsh_csm_tile;

/* Stage 3: the maps, per light. */
typedef struct vsh_csm_tile_plan {
  int light_count;                 /* min(lights, VSH_CSM_MAX_LIGHTS) */
  int lights_dropped;              /* lights beyond VSH_CSM_MAX_LIGHTS */
  int kind[VSH_CSM_MAX_LIGHTS];    /* vsh_csm_light_kind (int: a shader uniform) */
  int first[VSH_CSM_MAX_LIGHTS];   /* its first tile */
  int count[VSH_CSM_MAX_LIGHTS];   /* its tiles */
  int tile_count;
  vsh_csm_tile tiles[VSH_CSM_MAX_TILES];
} vsh_csm_tile_plan;

typedef struct vsh_csm_plan {
  vsh_csm_depth_plan depth;
  vsh_csm_resolution_plan resolution;
  vsh_csm_tile_plan tiles;
} vsh_csm_plan;

/* The half angle of a positional light's map: a spot's cone a little wider
 * (so its edge is inside the map), or a cube face. */
double vsh_csm_map_half_angle(double cone_angle_deg);

/* Stage 1. BAD_INPUT for a NULL argument; otherwise OK (EMPTY when nothing
 * casts or receives: the range is then the clip range). */
vsh_csm_status vsh_csm_plan_depth(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                  vsh_csm_depth_plan *out);

/* Stage 2. BAD_INPUT for a NULL argument, else OK. */
vsh_csm_status vsh_csm_plan_resolution(const vsh_csm_scene *scene,
                                       const vsh_csm_settings *settings,
                                       const vsh_csm_depth_plan *depth,
                                       vsh_csm_resolution_plan *out);

/* Stage 3. BAD_INPUT for a NULL argument, else OK. */
vsh_csm_status vsh_csm_plan_tiles(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                  const vsh_csm_depth_plan *depth,
                                  const vsh_csm_resolution_plan *resolution,
                                  vsh_csm_tile_plan *out);

/* Stages 1 to 3. */
vsh_csm_status vsh_csm_plan_frame(const vsh_csm_scene *scene, const vsh_csm_settings *settings,
                                  vsh_csm_plan *out);

/* ---- the atlas and reuse (vsh_csm_select.c) ------------------------------ */

/* The atlas: a grid of square tiles, as square as possible. */
typedef struct vsh_csm_atlas_layout {
  int columns;
  int rows;
  int resolution;       /* per tile, clamped to the GL's texture size limit */
  int clamped;          /* the requested resolution did not fit */
  int width;            /* texels */
  int height;
} vsh_csm_atlas_layout;

/* Lay `tiles` tiles (at least one slot) of `resolution` texels out in a
 * texture at most `max_texture_size` texels wide. BAD_INPUT for a NULL out,
 * else OK. */
vsh_csm_status vsh_csm_atlas_layout_for(int tiles, int resolution, int max_texture_size,
                                        vsh_csm_atlas_layout *out);

/* What an atlas slot holds from an earlier frame. */
typedef struct vsh_csm_held_map {
  int valid;
  vsh_csm_tile map;
  double origin[3];      /* the camera position its view is relative to */
  uint64_t caster_time;  /* the casters' state it was baked from */
} vsh_csm_held_map;

typedef struct vsh_csm_reuse_params {
  const vsh_camera *camera;
  double aspect;
  double depth_near;           /* the plan's range[0]: the first cascade has no blend band */
  double blend_band;
  const vsh_bounds *receivers;
  const vsh_bounds *casters;
  int stable;                  /* only stable cascades are reused */
  int resolution;              /* the atlas's */
  double reach_texels;         /* how far the filter and bias reach from a lookup */
  uint64_t caster_time;        /* the casters' state now */
} vsh_csm_reuse_params;

typedef struct vsh_csm_selection {
  int bake[VSH_CSM_MAX_TILES]; /* tiles to render, in order */
  int bake_count;
  int reused_count;            /* tiles that keep an earlier, different map */
} vsh_csm_selection;

/* Stage 4: for each tile, keep the held map when it is the same one, or,
 * for a stable cascade, when the held map still covers every lookup of this
 * frame (then the tile becomes the held map, re-expressed relative to this
 * camera position, keeping its own slice and texel size); otherwise list
 * it for baking and remember it in `held`. `held` has `tile_count` slots.
 * BAD_INPUT for NULL arguments or a count out of range, else OK. */
vsh_csm_status vsh_csm_select_reusable(const vsh_csm_reuse_params *p, vsh_csm_tile *tiles,
                                       int tile_count, vsh_csm_held_map *held,
                                       vsh_csm_selection *out);

#ifdef __cplusplus
}
#endif
#endif
