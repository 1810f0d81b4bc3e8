/* vsh_csm_sampled.h - csm's sampled area light (soft = 2): N hard shadow
 * maps, one from each of N stratified points on the light (the lecture's
 * method; docs/soft-shadows.md, "csm: sampled area light"), averaged per
 * pixel. The planned map of a light (vsh_csm_plan_tiles: its centre's view)
 * stays the base of each sample's map:
 *  - a spot or point light's sample map is the base view moved to the
 *    sample point (same orientation, projection and depth range): world ->
 *    clip becomes M T(-o) for the sample's offset o on the light's disk,
 *    which faces the casters' centre (vsh_soft_sample_light);
 *  - a directional light's sample map keeps the base map's plane and depth
 *    and shears its x, y so that lines along the sample's direction
 *    normalize(l + tan(a/2) q) project to one texel: clip.xy -= s(q) clip.z.
 * Both are a few numbers per light or map, so the lookup shader rebuilds
 * each sample's matrix from the base matrix (literal indices) instead of
 * reading N x tiles matrices. Pure double-precision C.
 */
#ifndef VSH_CSM_SAMPLED_H
#define VSH_CSM_SAMPLED_H

#include "vsh_csm_plan.h"

#ifdef __cplusplus
extern "C" {
#endif

#define VSH_CSM_MAX_SAMPLES 64

/* How a light's samples move its map. */
typedef struct vsh_csm_sample_frame {
  int sampled;       /* 0: the hard path (no size, n < 2, does not cast, degenerate) */
  int positional;
  int n;             /* samples */
  double u[3], v[3]; /* positional: radius x the disk's axes (world); directional:
                        tan(angle / 2) x two axes perpendicular to l */
  double l[3];       /* directional: unit direction towards the light */
} vsh_csm_sample_frame;

/* The sample frame of `light` with size `size` (radius for a positional
 * light, angular diameter in degrees for a directional one) and `n`
 * samples; a positional light's disk faces `toward` (the casters' centre).
 * Writes sampled = 0 (and returns OK) for size 0, n < 2, a light that does
 * not cast, or toward at the light. BAD_INPUT for NULL, n out of
 * 1..VSH_CSM_MAX_SAMPLES, a negative or non-finite size, an angle >= 180,
 * or a directional light without a direction. */
vsh_csm_status vsh_csm_sample_frame_for(const vsh_csm_light *light, double size,
                                        const double toward[3], int n,
                                        vsh_csm_sample_frame *out);

/* Disk sample i of n (Vogel spiral, no turn: the maps are shared by every
 * pixel). BAD_INPUT for i or n out of range. */
vsh_csm_status vsh_csm_sample_disk(int i, int n, double out[2]);

/* An orthographic map's shear per unit of disk sample: a directional sample
 * q changes clip.xy by -(q[0] out[0..1] + q[1] out[2..3]) clip.z. BAD_INPUT
 * for a perspective view, a NULL, or a view that does not look along
 * f->l (clip z does not change along it). */
vsh_csm_status vsh_csm_sample_shear(const vsh_shadow_view *view, const vsh_csm_sample_frame *f,
                                    double out[4]);

/* Sample i of f->n of map `base`: a copy whose view.world_to_clip and
 * absolute are the sample's projection (slice, texel size and bias kept).
 * BAD_INPUT for NULLs, f not sampled, i out of range, or no shear. */
vsh_csm_status vsh_csm_sample_tile(const vsh_csm_tile *base, const vsh_csm_sample_frame *f,
                                   int i, vsh_csm_tile *out);

/* A perspective map of a sampled positional light widened in depth by the
 * light's radius r (near n -> max(n - r, n / 4), far f -> f + r; the
 * projection's depth rows, depth terms and near_far rewritten): a sample's
 * eye is up to r from the centre's, and a map fitted from the centre would
 * clip casters nearer than its near plane and receivers past its far plane
 * (read as lit). Applied to the planned map before its samples are derived
 * (the lookup reads the planned map's depth terms). No-op for an
 * orthographic or empty map or a frame that is not sampled; BAD_INPUT for
 * NULLs. */
vsh_csm_status vsh_csm_sample_widen(vsh_csm_tile *tile, const vsh_csm_sample_frame *f);

/* The map resolution for an atlas of `tiles` maps within `budget` bytes (4
 * a texel): min(requested, floor(sqrt(budget / (4 tiles)))) rounded down
 * to a multiple of 16, at least 16. N maps per light otherwise need N times
 * the memory of the hard maps (64 spot maps at 2048: 1 GiB). */
int vsh_csm_sampled_resolution(int requested, int tiles, long long budget);

#ifdef __cplusplus
}
#endif
#endif
