/* vsh_csm.h - cascaded shadow map math: splits, fitting, snapping, bias and
 * the on-screen size of a shadow texel. Pure functions in double precision.
 *
 * Conventions: matrices are row-major (m[r*4+c]) acting on column vectors,
 * like vsh_mat4. Every light matrix maps CAMERA-RELATIVE world coordinates
 * (P - origin, with origin the camera position) to clip space, so scenes far
 * from the world origin keep their precision; texel snapping still happens on
 * a grid anchored to the world origin, computed in double. Depths are
 * positive distances along the view direction.
 *
 * Calls that can fail return a vsh_csm_status and take their inputs as one
 * parameter struct (fields named like the quantities they hold, so a call
 * reads `.slice_near = 1, .slice_far = 20` instead of ten numbers in a row).
 * Pointer fields may be NULL only where the field's comment says so. */
#ifndef VSH_CSM_H
#define VSH_CSM_H

#include "vsh_bounds.h"
#include "vsh_camera.h"

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VSH_CSM_MAX_CASCADES 8

/* What a csm call did. Outputs are written only for OK, except where a
 * function says it writes a best effort (TARGET_MISSED, BAD_INPUT of the
 * choosers). */
typedef enum vsh_csm_status {
  VSH_CSM_OK = 0,            /* done, outputs written */
  VSH_CSM_EMPTY = 1,         /* valid input with nothing to do (nothing visible, no overlap) */
  VSH_CSM_BAD_INPUT = 2,     /* a NULL, non-finite or out-of-range input */
  VSH_CSM_TARGET_MISSED = 3  /* the texel-size target is out of reach (budget, max_res) */
} vsh_csm_status;

/* A status's name ("ok", "empty", "bad input", "target missed"), for messages. */
const char *vsh_csm_status_name(vsh_csm_status status);

typedef enum vsh_split_scheme {
  VSH_SPLIT_UNIFORM = 0,   /* equal depth steps */
  VSH_SPLIT_LOG = 1,       /* equal depth ratios */
  VSH_SPLIT_PRACTICAL = 2, /* lambda * log + (1 - lambda) * uniform (PSSM) */
  VSH_SPLIT_EXPLICIT = 3   /* caller's fractions of [near, far] */
} vsh_split_scheme;

/* ---- how far cascades reach (vsh_csm_split.c) ---------------------------- */

typedef struct vsh_csm_depth_range_params {
  const vsh_camera *camera;
  double aspect;           /* viewport width / height */
  double clip_near;        /* the camera's clipping range */
  double clip_far;
  const vsh_bounds *bounds;
} vsh_csm_depth_range_params;

/* The depth range [near, far] of the part of `bounds` inside the camera's
 * view frustum (clipped by [clip_near, clip_far]): the box is clipped
 * against the frustum planes exactly (polygon clipping of its faces).
 * OK, EMPTY when nothing of the box is visible, BAD_INPUT for a degenerate
 * camera, empty or non-finite bounds, aspect or range <= 0. */
vsh_csm_status vsh_csm_visible_depth_range(const vsh_csm_depth_range_params *p,
                                           double out_near_far[2]);

/* The cascade count the depth ratio asks for: each cascade covers at most a
 * ratio of `ratio_per_cascade` (e.g. 8) between its far and near depth;
 * clamped to [1, VSH_CSM_MAX_CASCADES]. 1 for bad input. */
int vsh_csm_default_count(double near_depth, double far_depth, double ratio_per_cascade);

typedef struct vsh_csm_split_params {
  vsh_split_scheme scheme;
  int count;               /* cascades, 1..VSH_CSM_MAX_CASCADES */
  double near_depth;
  double far_depth;
  double lambda;           /* PRACTICAL only, in [0, 1] */
  const double *fractions; /* EXPLICIT only: count - 1 values in (0, 1), increasing */
  double max_ratio;        /* PRACTICAL only: > 1 caps each cascade's far/near (0: no cap) */
} vsh_csm_split_params;

/* Split depths out[0] = near ... out[count] = far, strictly increasing.
 * PRACTICAL with max_ratio > 1: each split is also at most max_ratio times
 * the one before, where that can hold for every cascade (max_ratio^count >=
 * far/near). The uniform half of the blend otherwise gives a wide depth
 * range (1e5) a first cascade thousands of times deeper than its near end,
 * whose texels then cover thousands of pixels near the camera; the capped
 * splits stay at or above the logarithmic ones, so the last cascade's ratio
 * stays within max_ratio too.
 * OK, or BAD_INPUT (out untouched). */
vsh_csm_status vsh_csm_splits(const vsh_csm_split_params *p, double *out);

/* ---- where each map looks (vsh_csm_fit.c) -------------------------------- */

/* One shadow map's view: camera-relative world -> clip space. */
typedef struct vsh_shadow_view {
  double world_to_clip[16]; /* applies to (P - origin, 1) */
  double texel_world;       /* world size of one texel (at distance 1 for perspective) */
  int perspective;          /* 0 orthographic (directional), 1 perspective (spot, point) */
  double depth_extent;      /* far - near of the map's depth range, world units */
  double near_far[2];       /* perspective: near/far distances from the light */
} vsh_shadow_view;

typedef struct vsh_csm_directional_params {
  const vsh_camera *camera;
  double aspect;
  double slice_near;              /* the view slice the cascade covers */
  double slice_far;
  const double *light_direction;  /* where the light travels (3 values) */
  const vsh_bounds *receivers;    /* where the shadow may fall; clips the slice; may be NULL */
  const vsh_bounds *casters;      /* every caster: the near plane reaches back to them; may be NULL */
  int stable;                     /* rotation-invariant size, snapped texels */
  int resolution;                 /* texels along each edge */
} vsh_csm_directional_params;

/* Fit a directional light's cascade to the view slice [slice_near,
 * slice_far] of the camera. Casters outside the view still cast: the map's
 * near plane reaches back to the highest caster.
 * stable != 0: the map's size depends only on the slice's depths, the field
 * of view and aspect (not on the camera's rotation), rounded up to a
 * geometric grid so small depth changes do not resize it, and its centre is
 * snapped to whole texels of a grid anchored to the world origin.
 * OK, EMPTY when the slice and receivers do not overlap (no map needed),
 * BAD_INPUT (a light parallel to anything is fine; a zero direction is not). */
vsh_csm_status vsh_csm_fit_directional(const vsh_csm_directional_params *p,
                                       vsh_shadow_view *out);

typedef struct vsh_csm_perspective_params {
  const double *position;   /* the light (3 values, world) */
  const double *direction;  /* the map's axis (3 values) */
  double half_angle_deg;    /* in (0, 90) */
  const vsh_bounds *bounds; /* casters and receivers: the depth range */
  const double *origin;     /* the camera position (3 values) */
  int resolution;
} vsh_csm_perspective_params;

/* A perspective map from `position` looking along `direction`, its depth
 * range fitted to `bounds`. For spot lights (the cone) and point-light cube
 * faces (45 degrees, square). OK, EMPTY when the bounds are all behind the
 * light, BAD_INPUT. */
vsh_csm_status vsh_csm_fit_perspective(const vsh_csm_perspective_params *p,
                                       vsh_shadow_view *out);

/* The depth terms of a perspective view's projection, for turning a
 * distance d along its axis into its normalised device depth:
 * ndc z = -out[0] + out[1] / d (the projection's [2][2] and [2][3]
 * entries, from near_far). Both 0 for a view that is not perspective or
 * whose depth range is empty. */
void vsh_csm_perspective_depth_terms(const vsh_shadow_view *view, double out[2]);

/* The direction of cube face `face` (0..5: +x -x +y -y +z -z). */
void vsh_csm_cube_face_direction(int face, double out[3]);

/* ---- may an earlier map serve this frame (vsh_csm_reuse.c) --------------- */

typedef struct vsh_csm_region_params {
  const vsh_camera *camera;
  double aspect;
  double lookup_near;           /* the slice's near, lowered to include a blend band */
  double slice_far;
  const vsh_bounds *receivers;  /* lookups only happen on receivers; may be NULL */
  const vsh_bounds *casters;    /* the depths the map must hold; may be NULL */
  const vsh_shadow_view *view;  /* an orthographic (directional) view */
} vsh_csm_region_params;

/* The box, in `view`'s clip coordinates (xmin, xmax, ymin, ymax, zmin,
 * zmax), that shadow lookups of the view slice [lookup_near, slice_far] can
 * reach: the slice's corners bounded in clip space, intersected with the
 * receivers' box, and in depth widened to the casters' box; clamped to the
 * view's [-1, 1]. OK, EMPTY when the slice and receivers do not overlap,
 * BAD_INPUT (including perspective views). */
vsh_csm_status vsh_csm_lookup_region(const vsh_csm_region_params *p, double out_clip[6]);

typedef struct vsh_csm_cover_params {
  const vsh_shadow_view *rendered;  /* the map an earlier frame rendered */
  const double *rendered_origin;    /* the camera position it is relative to */
  const vsh_shadow_view *needed;    /* the map this frame would render */
  const double *needed_origin;
  const double *needed_region;      /* 6 values, from vsh_csm_lookup_region */
  int resolution;
  double margin_texels;             /* the filter's reach */
} vsh_csm_cover_params;

/* true when an orthographic map rendered with `rendered` can stand in for
 * `needed`: both have the same light direction and texel size (equal x and
 * y rows), depth rows that differ at most in scale, and needed_region maps
 * inside the rendered map, margin_texels texels inside its x and y edges
 * and within its depth range. false otherwise, including bad input and
 * perspective views. The caller then samples the rendered map with the
 * rendered view's matrix and bias. */
bool vsh_csm_view_covers(const vsh_csm_cover_params *p);

/* ---- how big a texel looks, and what follows (vsh_csm_error.c) ----------- */

/* On-screen size in pixels of one shadow texel of world size `texel_world`
 * seen at view depth `depth` by a camera with vertical angle
 * `view_angle_deg` and a viewport `viewport_height` pixels high (Lloyd et
 * al.'s aliasing measure: 1 none, above ~10 severe). 0 for bad input. */
double vsh_csm_texel_pixels(double texel_world, double depth, double view_angle_deg,
                            int viewport_height);

/* Bias for a map with texels of world size `texel_world` (at the receiver)
 * and depth range `depth_extent`: a constant depth offset in normalized
 * depth units (half a texel of slope at 45 degrees, times scale), and a
 * normal offset in world units (about one texel diagonal, times scale). */
void vsh_csm_bias(double texel_world, double depth_extent, double scale, double *depth_bias,
                  double *normal_offset);

typedef struct vsh_csm_choose_params {
  double near_depth;       /* the visible depth range */
  double far_depth;
  double view_angle_deg;
  double aspect;
  int viewport_height;     /* pixels */
  double max_texel_px;     /* the target */
  long long budget_bytes;  /* 4 bytes a texel */
  int min_res;             /* resolutions: powers of two in [min_res, max_res] */
  int max_res;
  int max_count;           /* cascades */
} vsh_csm_choose_params;

typedef struct vsh_csm_choice {
  int resolution;
  int count;
  double texel_px;         /* the predicted worst on-screen texel size */
} vsh_csm_choice;

/* Pick a map resolution and cascade count so that the on-screen texel size
 * at the near end of every cascade of a logarithmic split of [near, far]
 * stays at most `max_texel_px`, using as little memory as possible within
 * the budget. OK when the target is met; TARGET_MISSED when the budget does
 * not allow it (the best achievable choice is written); BAD_INPUT (out =
 * {max(min_res, 1), 1, 0}). `out` may be NULL. */
vsh_csm_status vsh_csm_choose(const vsh_csm_choose_params *p, vsh_csm_choice *out);

typedef struct vsh_csm_resolution_params {
  double half_angle_deg;   /* the map's half angle, in (0, 90) */
  double light_distance;   /* from the light to where the texel lies */
  double view_depth;       /* where the camera sees it */
  double view_angle_deg;
  int viewport_height;
  double max_texel_px;
  int min_res;             /* resolutions: powers of two in [min_res, max_res] */
  int max_res;
} vsh_csm_resolution_params;

/* The resolution a perspective map needs so that one of its texels, at
 * `light_distance` from the light, covers at most `max_texel_px` pixels of
 * the viewport that sees it at view depth `view_depth`:
 *   res >= tan(half) * light_distance * viewport_height /
 *          (max_texel_px * view_depth * tan(view_angle / 2)).
 * OK; TARGET_MISSED with max_res when even that is not enough; BAD_INPUT
 * with max(min_res, 1). *out_resolution is always written (may be NULL). */
vsh_csm_status vsh_csm_perspective_resolution(const vsh_csm_resolution_params *p,
                                              int *out_resolution);

#ifdef __cplusplus
}
#endif
#endif
