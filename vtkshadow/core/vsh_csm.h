/* vsh_csm.h - cascaded shadow map math: splits, fitting, snapping, bias and
 * the on-screen size of a shadow texel. Pure functions in double precision.
 *
 * Conventions: matrices are row-major (m[r*4+c]) acting on column vectors,
 * like vsh_mat4. Every light matrix maps CAMERA-RELATIVE world coordinates
 * (P - origin, with origin the camera position) to clip space, so scenes far
 * from the world origin keep their precision; texel snapping still happens on
 * a grid anchored to the world origin, computed in double. Depths are
 * positive distances along the view direction. */
#ifndef VSH_CSM_H
#define VSH_CSM_H

#include "vsh_bounds.h"
#include "vsh_camera.h"

#ifdef __cplusplus
extern "C" {
#endif

#define VSH_CSM_MAX_CASCADES 8

typedef enum vsh_split_scheme {
  VSH_SPLIT_UNIFORM = 0,   /* equal depth steps */
  VSH_SPLIT_LOG = 1,       /* equal depth ratios */
  VSH_SPLIT_PRACTICAL = 2, /* lambda * log + (1 - lambda) * uniform (PSSM) */
  VSH_SPLIT_EXPLICIT = 3   /* caller's fractions of [near, far] */
} vsh_split_scheme;

/* The depth range [near, far] of the part of `bounds` inside the camera's
 * view frustum (clipped by [clip_near, clip_far]): the box is clipped
 * against the frustum planes exactly (polygon clipping of its faces).
 * Returns 0 on success, 1 when nothing of the box is visible, 2 on bad input
 * (degenerate camera, empty or non-finite bounds, aspect or range <= 0). */
int vsh_csm_visible_depth_range(const vsh_camera *camera, double aspect, double clip_near,
                                double clip_far, const vsh_bounds *bounds,
                                double out_near_far[2]);

/* The cascade count the depth ratio asks for: each cascade covers at most a
 * ratio of `ratio_per_cascade` (e.g. 8) between its far and near depth;
 * clamped to [1, VSH_CSM_MAX_CASCADES]. 1 for bad input. */
int vsh_csm_default_count(double near_depth, double far_depth, double ratio_per_cascade);

/* Split depths out[0] = near ... out[count] = far, strictly increasing.
 * `fractions` (count - 1 values in (0, 1), increasing) is read only for
 * VSH_SPLIT_EXPLICIT; lambda in [0, 1] only for VSH_SPLIT_PRACTICAL.
 * Returns 0, or non-zero on bad input (out untouched). */
int vsh_csm_splits(vsh_split_scheme scheme, int count, double near_depth, double far_depth,
                   double lambda, const double *fractions, double *out);

/* One shadow map's view: camera-relative world -> clip space. */
typedef struct vsh_shadow_view {
  double world_to_clip[16]; /* applies to (P - origin, 1) */
  double texel_world;       /* world size of one texel (at distance 1 for perspective) */
  int perspective;          /* 0 orthographic (directional), 1 perspective (spot, point) */
  double depth_extent;      /* far - near of the map's depth range, world units */
  double near_far[2];       /* perspective: near/far distances from the light */
} vsh_shadow_view;

/* Fit a directional light's cascade to the view slice [slice_near,
 * slice_far] of the camera.
 * light_direction: where the light travels. receivers: bounds the shadow
 * may fall on (clips the slice; may be NULL); casters: bounds of every
 * caster (the map's near plane reaches back to them so casters outside the
 * view still cast; may be NULL).
 * stable != 0: the map's size depends only on the slice's depths, the field
 * of view and aspect (not on the camera's rotation), rounded up to a
 * geometric grid so small depth changes do not resize it, and its centre is
 * snapped to whole texels of a grid anchored to the world origin.
 * Returns 0, 1 when the slice and receivers do not overlap (no map needed),
 * 2 on bad input (light parallel to nothing is fine; zero direction is not). */
int vsh_csm_fit_directional(const vsh_camera *camera, double aspect, double slice_near,
                            double slice_far, const double light_direction[3],
                            const vsh_bounds *receivers, const vsh_bounds *casters, int stable,
                            int resolution, vsh_shadow_view *out);

/* The box, in `view`'s clip coordinates (xmin, xmax, ymin, ymax, zmin,
 * zmax), that shadow lookups of the view slice [lookup_near, slice_far] can
 * reach: the slice's corners bounded in clip space, intersected with the
 * receivers' box (lookups only happen on receivers; may be NULL), and in
 * depth widened to the casters' box (the map must hold them; may be NULL);
 * clamped to the view's [-1, 1]. Directional (orthographic) views only.
 * Pass a lookup_near below the slice's near to include a blend band.
 * Returns 0, 1 when the slice and receivers do not overlap, 2 on bad input. */
int vsh_csm_lookup_region(const vsh_camera *camera, double aspect, double lookup_near,
                          double slice_far, const vsh_bounds *receivers,
                          const vsh_bounds *casters, const vsh_shadow_view *view,
                          double out_clip[6]);

/* 1 when an orthographic map rendered with `rendered` (its world_to_clip
 * relative to rendered_origin) can stand in for `needed` (relative to
 * needed_origin): both have the same light direction and texel size (equal
 * x and y rows), depth rows that differ at most in scale, and
 * needed_region (needed's clip coordinates, from vsh_csm_lookup_region)
 * maps inside the rendered map, margin_texels texels (the filter's reach)
 * inside its x and y edges and within its depth range. 0 otherwise,
 * including bad input and perspective views. The caller then samples the
 * rendered map with the rendered view's matrix and bias. */
int vsh_csm_view_covers(const vsh_shadow_view *rendered, const double rendered_origin[3],
                        const vsh_shadow_view *needed, const double needed_origin[3],
                        const double needed_region[6], int resolution, double margin_texels);

/* A perspective map from `position` looking along `direction` with half
 * angle `half_angle_deg` (< 90), its depth range fitted to `bounds` (the
 * casters and receivers). For spot lights (the cone) and point-light cube
 * faces (45 degrees, square). Returns 0, 1 when the bounds are all behind
 * the light, 2 on bad input. `origin` is the camera position. */
int vsh_csm_fit_perspective(const double position[3], const double direction[3],
                            double half_angle_deg, const vsh_bounds *bounds,
                            const double origin[3], int resolution, vsh_shadow_view *out);

/* The depth terms of a perspective view's projection, for turning a
 * distance d along its axis into its normalised device depth:
 * ndc z = -out[0] + out[1] / d (the projection's [2][2] and [2][3]
 * entries, from near_far). Both 0 for a view that is not perspective or
 * whose depth range is empty. */
void vsh_csm_perspective_depth_terms(const vsh_shadow_view *view, double out[2]);

/* The direction of cube face `face` (0..5: +x -x +y -y +z -z). */
void vsh_csm_cube_face_direction(int face, double out[3]);

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

/* Pick a map resolution (a power of two in [min_res, max_res]) and cascade
 * count (<= max_count) so that the on-screen texel size at the near end of
 * every cascade of a logarithmic split of [near, far] stays at most
 * `max_texel_px`, using as little memory as possible within
 * `budget_bytes` (4 bytes a texel). Writes the predicted worst texel size.
 * Returns 0 when the target is met, 1 when the budget does not allow it
 * (then the best achievable choice is written). */
int vsh_csm_choose(double near_depth, double far_depth, double view_angle_deg, double aspect,
                   int viewport_height, double max_texel_px, long long budget_bytes,
                   int min_res, int max_res, int max_count, int *out_resolution,
                   int *out_count, double *out_texel_px);

/* The resolution (a power of two in [min_res, max_res]) a perspective map
 * of half angle `half_angle_deg` needs so that one of its texels, at
 * `light_distance` from the light, covers at most `max_texel_px` pixels of
 * a viewport `viewport_height` pixels high that sees it at view depth
 * `view_depth` with vertical angle `view_angle_deg`:
 *   res >= tan(half) * light_distance * viewport_height /
 *          (max_texel_px * view_depth * tan(view_angle / 2)).
 * max_res when even that is not enough; min_res for bad input. */
int vsh_csm_perspective_resolution(double half_angle_deg, double light_distance,
                                   double view_depth, double view_angle_deg, int viewport_height,
                                   double max_texel_px, int min_res, int max_res);

#ifdef __cplusplus
}
#endif
#endif
