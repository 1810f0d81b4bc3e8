/* vshm_penumbra.h - how well a technique reproduces a soft shadow's penumbra
 * (definitions: docs/metrics.md, "Penumbra metrics").
 *
 * Same inputs and conventions as vshm_metrics.h: visibility images in [0,1]
 * (1 lit), row major, top row first; `valid` the reference's mask; `exclude`
 * (may be NULL) pixels left out of every figure.
 */
#ifndef VSHM_PENUMBRA_H
#define VSHM_PENUMBRA_H

#ifdef __cplusplus
extern "C" {
#endif

/* The reference's classes: umbra v_ref <= 0.02, lit v_ref >= 0.98, the
 * penumbra in between (strictly). */
#define VSHM_PENUMBRA_LO 0.02f
#define VSHM_PENUMBRA_HI 0.98f

typedef struct vshm_penumbra {
  long penumbra_pixels; /* compared pixels in the dilated penumbra mask */
  long umbra_pixels;    /* compared pixels with v_ref <= 0.02 */
  long lit_pixels;      /* compared pixels with v_ref >= 0.98 */
  double pen_mae;       /* mean |v - v_ref| over the penumbra mask */
  double pen_bias;      /* mean (v - v_ref) there: < 0 too dark, > 0 too bright */
  double leak_pct;      /* 100 * (umbra pixels with v > 0.1) / max(umbra_pixels, 1) */
  double false_shadow_pct; /* 100 * (lit pixels with v < 0.9) / max(lit_pixels, 1) */
  /* Penumbra width W = (compared pixels with 0.1 < v < 0.9) / (counted
   * cracks of the 0.5 contour), in pixels; 0 when there is no contour. */
  double width_px, ref_width_px;
  double width_ratio; /* width_px / ref_width_px; 0 when the reference has no width */
  /* Symmetric mean distance (pixels) between the contours v = L and
   * v_ref = L, L = 0.1, 0.5, 0.9 (vshm_edge_px on the images thresholded
   * at L; the same conventions when a contour is missing). */
  double contour_px[3];
} vshm_penumbra;

/* mask[i] = 1 for valid pixels with 0.02 < v_ref < 0.98, dilated by one
 * pixel (3 x 3, staying on valid pixels), else 0. Returns VSHM_METRICS_OK,
 * _EINVAL or _ENOMEM (vshm_metrics.h). */
int vshm_penumbra_mask(const float *v_ref, const unsigned char *valid, int width, int height,
                       unsigned char *mask);

/* Every penumbra figure over the compared pixels (valid, not excluded).
 * Returns VSHM_METRICS_OK, VSHM_METRICS_EMPTY when the penumbra mask has no
 * compared pixel (pen_mae and pen_bias are then 0; the other figures are
 * still computed), _EINVAL or _ENOMEM (out all zero). */
int vshm_penumbra_compute(const float *v, const float *v_ref, const unsigned char *valid,
                          const unsigned char *exclude, int width, int height, vshm_penumbra *out);

/* Penumbra heat map, 3 bytes per pixel: inside the penumbra mask the signed
 * error e = v - v_ref, white at 0, blue (too dark) or red (too bright),
 * saturated at |e| = 0.25 (penumbra errors are small); outside it the
 * reference's visibility as a dark grey ramp (0..96), so the shadow's shape
 * shows; invalid pixels mid grey (128). Returns VSHM_METRICS_OK, _EINVAL or
 * _ENOMEM. */
int vshm_penumbra_heatmap_rgb(const float *v, const float *v_ref, const unsigned char *valid,
                              int width, int height, unsigned char *rgb);

#ifdef __cplusplus
}
#endif

#endif
