/* vsh_soft_adaptive.h - adaptive sample counts for the sampled area light of
 * the rasterizing techniques (vtkShadowVolumePass's soft_samples): a first
 * batch of K of the N light samples is counted for every pixel, and the
 * other N - K only where the batch disagrees (the penumbra).
 *
 * The decisions follow raytrace's (vsh_rt_adaptive.h): a pixel whose batch
 * agrees (all lit or all blocked) keeps that answer, a pixel whose batch is
 * mixed, or that lies next to one that is mixed or next to the other answer,
 * gets all N samples and so exactly the non-adaptive estimate. What differs
 * is the batch. A rasterizer counts one sample for the whole screen, so the
 * batch is the same K points for every pixel (no per-pixel rotation): a
 * penumbra pixel whose blocked part of the light falls between the batch's
 * points is missed on a whole band of pixels, not at random. The blocked
 * part of the light seen from a point near a penumbra's edge is a cap of the
 * disk cut by the occluder's edge, which enters from the disk's rim; so the
 * batch is the centre and K - 1 points near the rim at equal angles
 * (vsh_soft_batch_order): the largest cap holding none of them is then
 * vsh_soft_batch_missed_cap of the light, against a larger one for a
 * spiral-spread batch (test_soft_adaptive prints both). The price: a small
 * occluder whose blocked blob lies inside the disk between the centre and
 * the rim is missed by such a batch (the documented failure mode).
 * Pure functions, no allocation.
 */
#ifndef VSH_SOFT_ADAPTIVE_H
#define VSH_SOFT_ADAPTIVE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The first batch: the centre and 7 rim points. */
#define VSH_SOFT_ADAPTIVE_BATCH 8
/* The largest batch vsh_soft_batch_order spreads. */
#define VSH_SOFT_ADAPTIVE_MAX_BATCH 32

/* The 1/255 steps sample i of n adds to an 8-bit mask channel where it is
 * lit: floor(255 (i+1) / n) - floor(255 i / n), at least 1 for n <= 255 and
 * summing to exactly 255 over i = 0..n-1. 0 for i or n out of range
 * (n < 1 or n > 255). */
int vsh_soft_levels(int sample, int samples);

/* Fill order[0..samples-1] with a permutation of the spiral indices
 * 0..samples-1 (vsh_soft_disk_sample(k, samples, 0, ...)) whose first
 * `first` entries are index 0 (the sample nearest the centre) and then
 * first - 1 indices from the outer part of the spiral (the largest 1.5,
 * 2 or 3 (first - 1) radii) nearest first - 1 equally spaced angles, the
 * pool and the angles' turn chosen to miss the smallest cap
 * (vsh_soft_batch_missed_cap); the rest follow in increasing order.
 * Deterministic; about 1e6 operations, so a caller computes it once per
 * (samples, first). first >= samples, first < 2 or first >
 * VSH_SOFT_ADAPTIVE_MAX_BATCH gives the identity. Returns -1 for samples
 * < 1 or a null order. */
int vsh_soft_batch_order(int samples, int first, int *order);

/* The levels the first `first` entries of order add together (the channel
 * of a pixel where the whole batch is lit): sum of vsh_soft_levels(order[j],
 * samples). Between 1 and 255; 255 when first >= samples. -1 for bad
 * arguments. */
int vsh_soft_batch_levels(int samples, int first, const int *order);

/* The state of a pixel's batch from its channel level (0..255) after the
 * batch, `batch_levels` from vsh_soft_batch_levels: VSH_RT_BATCH_BLOCKED
 * for 0, VSH_RT_BATCH_FREE for batch_levels, VSH_RT_BATCH_MIXED between
 * (every sample adds at least one level, so the level tells exactly), and
 * VSH_RT_BATCH_NONE for a level outside [0, batch_levels]. The shader of
 * vtkShadowScreenMask::MarkBatch computes the same. */
int vsh_soft_batch_state(int level, int batch_levels);

/* The largest fraction of the unit disk in a cap (the part beyond a chord)
 * that holds none of the `count` points xy[2 j], xy[2 j + 1]: the most of
 * the light an occluder's straight edge can block while the batch sees it
 * all lit (or, from the other side, all blocked). Evaluated at 8192
 * directions. 1 for count < 1. */
double vsh_soft_batch_missed_cap(const double *xy, int count);

/* Planar's adaptive mark (vtkPlanarShadowPass, adaptive=1). Its
 * accumulation channel holds the shadowed share: each blocked sample adds
 * 1 / samples (a float), so after a batch of `batch` samples a pixel holds
 * k / samples for k of them blocked. vsh_soft_share_state tells the batch's
 * state from that share: VSH_RT_BATCH_FREE below 0.5 / samples (k = 0),
 * VSH_RT_BATCH_BLOCKED above (batch - 0.5) / samples (k = batch),
 * VSH_RT_BATCH_MIXED between, VSH_RT_BATCH_NONE for bad arguments or a
 * share that is not finite. */
int vsh_soft_share_state(double share, int batch, int samples);

/* The per-pixel marks of vsh_soft_mark_pixels. */
#define VSH_SOFT_MARK_LIT 0     /* batch all lit, keeps 0 shadowed share */
#define VSH_SOFT_MARK_BLOCKED 1 /* batch all blocked, set to exactly 1 */
#define VSH_SOFT_MARK_REFINE 2  /* gets the other samples */

/* Marks every pixel of a width x height channel after the batch: share[(y
 * width + x) stride] is pixel (x, y)'s shadowed share (stride 4 picks one
 * channel of RGBA). As volume's vtkShadowScreenBatchFS and raytrace's
 * vsh_rt_adaptive_rest_near, a pixel is refined when any pixel of its 3x3
 * neighbourhood (clamped at the borders) is mixed or the neighbourhood holds
 * both all-lit and all-blocked pixels; the others keep their batch's answer.
 * mark (width x height bytes) gets VSH_SOFT_MARK_*; box (x0, y0, x1, y1,
 * half-open, may be null) the bounding box of the refined pixels, all 0 when
 * none. Returns the number of refined pixels, -1 for bad arguments. */
long vsh_soft_mark_pixels(const float *share, int stride, int width, int height, int batch,
  int samples, unsigned char *mark, int box[4]);

#ifdef __cplusplus
}
#endif
#endif
