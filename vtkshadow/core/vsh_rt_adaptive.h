/* vsh_rt_adaptive.h - adaptive ray counts for ray-traced soft shadows:
 * more rays only where the penumbra is.
 *
 * A pixel under a light with a size first traces a small batch of its
 * `samples` rays, spread over the whole light (not the spiral's first
 * indices, which all lie near the disk's centre); when every ray of the
 * batch agrees (all blocked: umbra, or all free: lit), that answer is the
 * pixel's visibility; otherwise it traces the rest of the `samples`, so a
 * penumbra pixel gets exactly the non-adaptive estimate (the same N
 * spiral points, the same rotation). The saving is the fraction of lit
 * and umbra pixels; the risk is an occluder smaller than the gaps between
 * the batch's points (about a disk radius / sqrt(batch)) that no batch ray
 * sees, which the tests measure against the exact penumbra.
 * Pure functions, no allocation (Schwarzler et al., VMV 2012, report
 * 289-sample quality from about 25 adaptive samples).
 */
#ifndef VSH_RT_ADAPTIVE_H
#define VSH_RT_ADAPTIVE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The first batch: 8 rays spread over the disk. Fewer misses more small
 * occluders; more saves less in lit and umbra regions. */
#define VSH_RT_ADAPTIVE_BATCH 8

/* The size of a pixel's first batch for `samples` rays per pixel: `batch`
 * when adaptive is non-zero and samples > batch, else samples (one batch,
 * nothing decided: samples 1, samples <= batch, adaptive off). Returns 1
 * for samples < 1 and treats batch < 1 as no adaptivity. */
int vsh_rt_adaptive_first(int samples, int adaptive, int batch);

/* Fill order[0..samples-1] with a permutation of the spiral's indices
 * 0..samples-1 (vsh_rt_disk_sample(k, samples, ...)) whose first `first`
 * entries are spread over the whole disk: entry j is the index, in the
 * j-th of `first` equal runs of indices (the j-th ring of equal area),
 * whose spiral angle is nearest the angle of point j of a `first`-point
 * spiral; the rest follow in increasing order. first >= samples (or < 1)
 * gives the identity. Returns -1 for samples < 1 or a null order. */
int vsh_rt_adaptive_order(int samples, int first, int *order);

/* How many more rays a pixel traces after its first batch of `first` rays
 * of which `blocked` were blocked: 0 when they all agree (blocked 0 or
 * first) or nothing is left (first >= samples), else samples - first. */
int vsh_rt_adaptive_rest(int samples, int first, int blocked);

/* The expected rays per pixel of a light: first + penumbra x (samples -
 * first), `penumbra` the fraction (clamped to [0, 1]) of its traced pixels
 * whose first batch disagrees; samples when first >= samples or first < 1. */
double vsh_rt_adaptive_expected_rays(int samples, int first, double penumbra);

#ifdef __cplusplus
}
#endif
#endif
