/* vsh_rt_weight.h - a pixel's visibility of a light with a size from its
 * shadow rays, each weighted by the cosine at the surface.
 *
 * The visibility a renderer shades with is v = I_on / I_off, the light's
 * irradiance with shadows over that without (docs/harness.md). For a light
 * with a size, I = sum_i vis_i max(0, N.L_i) over the light's samples L_i,
 * so v = sum_i vis_i max(0, N.L_i) / sum_i max(0, N.L_i): the unoccluded
 * fraction of the light weighted by N.L_i, as Cycles computes it. The
 * plain fraction of free rays differs where the weights differ, which is
 * where the light straddles the surface's horizon: on a curved caster's own
 * terminator the part of the light below the horizon is blocked by the
 * caster itself (the plain fraction is the part above the horizon, < 1)
 * but has weight 0 there (v = 1: the surface is lit as much as its normal
 * allows; the terminator's darkening is the shading's N.L, not a shadow).
 * On a receiver far from a small light every weight is about the same and
 * the two agree.
 *
 * Pure functions on plain data (no allocation). */
#ifndef VSH_RT_WEIGHT_H
#define VSH_RT_WEIGHT_H

#ifdef __cplusplus
extern "C" {
#endif

/* The rays of one (pixel, light) pair so far. */
typedef struct vsh_rt_visibility {
  double free_weight; /* sum of the weights of the free rays */
  double weight;      /* sum of the weights of every ray */
  int traced;         /* rays traced */
  int blocked;        /* rays blocked */
  int partial;        /* rays that crossed translucent surfaces only, 0 < t < 1 */
  double partial_loss; /* sum of (1 - t) over the partial rays */
  /* Per colour channel, the sum of weight x the ray's transmittance in
   * that channel (a grey ray adds the same to all three). The scalar
   * counts a coloured ray by its largest channel, so that channel / scalar
   * is the tint in [0, 1] (vsh_rt_visibility_tint). */
  double channel_weight[3];
} vsh_rt_visibility;

/* The weight of a ray in unit direction `dir` from a surface with normal
 * `normal` (any length, facing the side the ray leaves from):
 * max(0, normal . dir) / |normal|. 1 (every ray alike: the plain
 * fraction) for a null, zero or non-finite normal, a null or non-finite
 * direction: a pixel whose surface has no normal. */
double vsh_rt_sample_weight(const double normal[3], const double dir[3]);

/* Adds one ray of weight `weight` (negative or non-finite: 0), blocked or
 * free. */
void vsh_rt_visibility_add(vsh_rt_visibility *v, double weight, int blocked);

/* Adds one ray of weight `weight` that reached the light with the fraction
 * `transmitted` of its light (the product of (1 - opacity) over the
 * translucent surfaces it crossed, vsh_transmit.h; clamped to [0, 1], NaN
 * counts as blocked): 0 is blocked, 1 free, in between a partial ray, whose
 * weight counts `transmitted` times as free. */
void vsh_rt_visibility_add_transmitted(vsh_rt_visibility *v, double weight, double transmitted);

/* Adds one ray of weight `weight` that reached the light with the fraction
 * `transmitted[k]` of it in colour channel k (tinted by filtering surfaces,
 * vsh_transmit.h). The scalar visibility counts it as
 * vsh_rt_visibility_add_transmitted with its largest channel; the channels
 * keep each fraction. Non-finite values count as 0, values clamp to
 * [0, 1]. */
void vsh_rt_visibility_add_coloured(vsh_rt_visibility *v, double weight,
                                    const double transmitted[3]);

/* The pair's tint: tint[k] = the visibility of channel k over the scalar
 * visibility (vsh_rt_visibility_value), in [0, 1], so value x tint[k] is
 * channel k's visibility. (1, 1, 1) for grey rays, when nothing got
 * through, and when every ray had weight 0. */
void vsh_rt_visibility_tint(const vsh_rt_visibility *v, double tint[3]);

/* The pair's visibility in [0, 1]: free_weight / weight when the weights
 * sum to more than 0; the plain fraction of free rays when every ray had
 * weight 0 (the whole light below the horizon of the surface's geometric
 * normal, where the mapper's interpolated normal may still face the light:
 * 0/0 has no answer, the unweighted one is the value before weighting;
 * partial rays count their transmitted fraction);
 * 1 when nothing was traced. */
double vsh_rt_visibility_value(const vsh_rt_visibility *v);

#ifdef __cplusplus
}
#endif
#endif
