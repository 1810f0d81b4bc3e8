/* vshm_metrics.h - shadow error metrics of a visibility image v against a
 * ray-traced reference v_ref (definitions: docs/metrics.md).
 *
 * Images are width * height floats in [0,1] (1 lit, 0 fully shadowed), row
 * major, top row first. valid (non-zero = valid) is the reference's mask:
 * pixels whose unshadowed reference intensity is above epsilon. exclude
 * (non-zero = leave out, may be NULL) removes further pixels, e.g. a band
 * along the reference's shadow boundary (vshm_boundary_band).
 *
 * Thresholded state: a pixel is lit when v >= 0.5. Inputs must be finite.
 */
#ifndef VSHM_METRICS_H
#define VSHM_METRICS_H

#ifdef __cplusplus
extern "C" {
#endif

/* Return codes. */
#define VSHM_METRICS_OK 0
#define VSHM_METRICS_EMPTY 1     /* no pixel compared: all metrics are 0 */
#define VSHM_METRICS_EINVAL (-1) /* NULL image, size <= 0 or too large */
#define VSHM_METRICS_ENOMEM (-2)

typedef struct vshm_metrics {
  long valid_pixels;    /* valid != 0 */
  long compared_pixels; /* valid and not excluded: the denominator below */
  double vis_mae;       /* mean |v - v_ref| */
  double wrong_pct;     /* 100 * fraction with |v - v_ref| > 0.5 */
  double edge_px;       /* symmetric mean boundary distance, see vshm_edge_px */
  double false_shadow_pct; /* 100 * fraction with v_ref > 0.9 and v < 0.5 */
  double false_light_pct;  /* 100 * fraction with v_ref < 0.1 and v > 0.5 */
  /* Errors relative to the shadow, so that losing a small shadow is a large
   * number (wrong_pct divides by the whole frame, where a small shadow is a
   * fraction of a percent). Counted over the compared pixels, like
   * wrong_pct: the same wrong pixels, the same exclusions. */
  long ref_shadow_pixels;  /* compared pixels with v_ref < 0.5 */
  long test_shadow_pixels; /* compared pixels with v < 0.5 */
  /* 100 * wrong / max(ref_shadow_pixels, 1) and
   * 100 * wrong / max(test_shadow_pixels, 1): an empty shadow counts as one
   * pixel, so the figure is finite, 0 exactly when nothing is wrong, and
   * 100 per wrong pixel when there is no shadow at all. Both can exceed 100
   * (false shadows outside the reference's, or lit pixels missing from a
   * lost shadow). */
  double wrong_of_shadow_pct;      /* of the reference's shadow */
  double wrong_of_test_shadow_pct; /* of the technique's shadow */
} vshm_metrics;

/* Computes every metric over the compared pixels (valid and not excluded).
 * Returns VSHM_METRICS_OK; VSHM_METRICS_EMPTY when no pixel is compared (all
 * metrics 0, valid_pixels still counted); VSHM_METRICS_EINVAL or
 * VSHM_METRICS_ENOMEM (out is then all zero). */
int vshm_metrics_compute(const float *v, const float *v_ref, const unsigned char *valid,
                         const unsigned char *exclude, int width, int height,
                         vshm_metrics *out);

/* edge_px alone. The boundaries of v and v_ref are the cracks between
 * 4-adjacent valid pixels of different state (vshm_boundary.h), found over
 * all valid pixels: exclude does not move a boundary. Every crack of v
 * with neither of its two pixels excluded contributes its Euclidean
 * distance (pixels) to the nearest crack of v_ref, and vice versa;
 * edge_px is the mean over all contributions of both images.
 * Conventions: no contribution at all (neither image has a boundary, or
 * every crack is excluded) gives 0; when one image has no boundary
 * anywhere, each crack of the other contributes the image diagonal
 * sqrt(w^2 + h^2), longer than any real distance, so edge_px is exactly
 * the diagonal. Returns VSHM_METRICS_OK, _EINVAL or _ENOMEM. */
int vshm_edge_px(const float *v, const float *v_ref, const unsigned char *valid,
                 const unsigned char *exclude, int width, int height, double *edge_px);

/* band[i] = 1 for every valid pixel within Chebyshev distance `radius` of
 * a valid pixel of the opposite state in v_ref, else 0. radius 0 marks
 * nothing; radius 1 marks the pixels touching the boundary on both sides
 * (the one-pixel band along the exact shadow boundary); radius N a band N
 * pixels deep on each side. Use it as (part of) exclude. Returns
 * VSHM_METRICS_OK, _EINVAL (also for radius < 0) or _ENOMEM. */
int vshm_boundary_band(const float *v_ref, const unsigned char *valid, int width,
                       int height, int radius, unsigned char *band);

/* wrong[i] = 1 when valid[i] and |v - v_ref| > 0.5, else 0: the per-frame
 * error state that vshm_flicker_pct compares. Returns the number of wrong
 * pixels, or -1 on bad arguments. */
long vshm_error_state(const float *v, const float *v_ref, const unsigned char *valid,
                      int width, int height, unsigned char *wrong);

/* Shimmer along a camera path of `frames` frames of width * height pixels.
 * wrong[f] is frame f's error state (vshm_error_state), valid[f] its mask
 * (non-zero = valid; AND in any exclusion first). For each consecutive pair
 * (f-1, f), the percentage of pixels valid in both frames whose state
 * differs; the result is the mean of those percentages over the pairs that
 * have at least one pixel valid in both. *pairs_used (may be NULL) gets
 * that number of pairs. Fewer than 2 frames, or no usable pair: 0.
 * Bad arguments (NULL arrays, frames < 0, size <= 0): -1. */
double vshm_flicker_pct(const unsigned char *const *wrong, const unsigned char *const *valid,
                        int frames, int width, int height, int *pairs_used);

/* Signed error heat map for the report, 3 bytes (R,G,B) per pixel, with
 * e = v - v_ref: e < 0 (v too dark, false shadow) fades from white to blue
 * as |e| goes to 1, e > 0 (v too bright, false light) from white to red,
 * e = 0 is white, invalid pixels are mid grey (128,128,128). Linear in e,
 * so a 0.5 error is a clearly saturated colour. Returns VSHM_METRICS_OK or
 * VSHM_METRICS_EINVAL. */
int vshm_error_heatmap_rgb(const float *v, const float *v_ref, const unsigned char *valid,
                           int width, int height, unsigned char *rgb);

/* reflection_mae, the colour metric of planar mirrors (docs/reflections.md):
 * rgb and rgb_ref are colour images, 3 floats (linear R, G, B) per pixel,
 * row major; mirror (non-zero = set) the pixels where a mirror is the first
 * surface seen (from the reference renderer); exclude (may be NULL) leaves
 * pixels out. *mae = mean over the mirror's compared pixels of
 * (|R - R_ref| + |G - G_ref| + |B - B_ref|) / 3, each channel clamped to
 * [0,1] first (NaN counts as 0, like an unlit pixel), so it lies in [0,1].
 * *pixels (may be NULL) gets the number of compared pixels. Returns
 * VSHM_METRICS_OK; VSHM_METRICS_EMPTY when no pixel is compared (*mae = 0);
 * VSHM_METRICS_EINVAL (NULL image or mae, bad size; *mae = 0 when mae is
 * not NULL). */
int vshm_reflection_mae(const float *rgb, const float *rgb_ref, const unsigned char *mirror,
                        const unsigned char *exclude, int width, int height, double *mae,
                        long *pixels);

/* The mirror region's heat map for the report: the colours of
 * vshm_error_heatmap_rgb for e = mean(R,G,B) - mean(R_ref,G_ref,B_ref) (channels
 * clamped as in vshm_reflection_mae) on mirror pixels, mid grey elsewhere. */
int vshm_reflection_heatmap_rgb(const float *rgb, const float *rgb_ref,
                                const unsigned char *mirror, int width, int height,
                                unsigned char *out);

#ifdef __cplusplus
}
#endif

#endif
