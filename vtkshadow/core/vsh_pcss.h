/* vsh_pcss.h - the penumbra sizes of percentage-closer soft shadows (PCSS,
 * Fernando 2005) for csm's `soft` option (docs/soft-shadows.md).
 *
 * PCSS looks at the shadow map around a receiver's lookup for blockers (the
 * blocker search), averages their depth, and filters the map with a kernel
 * as wide as the penumbra that a blocker at that depth would cast: exact
 * when blocker and receiver are parallel planes, an estimate otherwise.
 * These are the two sizes, the same formulas the shader
 * (vtkShadowMapLightFS.glsl, vshShadowPCSS) evaluates per pixel, kept here
 * as pure functions so their geometry and degenerate cases are tested.
 *
 * Distances are along the light's travel: for a directional light any
 * origin (the map's near plane), for a point or spot light the distance
 * from the light along the map's axis (a perspective map's w).
 */
#ifndef VSH_PCSS_H
#define VSH_PCSS_H

#ifdef __cplusplus
extern "C" {
#endif

/* The size term of a light, what the shader gets per map: tan(angle / 2)
 * of a directional light (positional 0) of angular diameter angle_deg, or
 * the disk radius of a point or spot light (positional != 0). 0 for a
 * light without a size and for bad sizes (negative, not finite, an angle
 * of 180 degrees or more): such a light keeps the hard shadow. */
double vsh_pcss_light_term(int positional, double radius, double angle_deg);

/* Directional light with size term t = tan(angle / 2): the half-width, in
 * world units across the light, of the penumbra an edge at d_blocker casts
 * on a receiver at d_receiver: t (d_receiver - d_blocker). 0 when t is 0
 * or the blocker is not in front of the receiver (d_blocker >= d_receiver:
 * a blocker at the receiver casts a hard edge). Also the blocker search's
 * half-width with d_blocker = the map's near plane (every blocker the
 * receiver can see lies within it). -1 for bad input (not finite, t < 0). */
double vsh_pcss_sun_halfwidth(double t, double d_receiver, double d_blocker);

/* Point or spot light of disk radius r, perspective map: the penumbra's
 * half-width per unit distance along the map's axis (its world half-width
 * at the receiver, r (d_receiver - d_blocker) / d_blocker by similar
 * triangles, divided by d_receiver: the map's texels grow with the
 * distance, so this divided by the texel size at distance 1 is texels):
 * r (d_receiver - d_blocker) / (d_receiver d_blocker). Also the search
 * half-width with d_blocker = the map's near distance. 0 when r is 0, the
 * receiver is at or behind the light (d_receiver <= 0: the map holds no
 * shadow for it), the blocker is at or behind the light (d_blocker <= 0:
 * it is not in the map) or not in front of the receiver. -1 for bad input
 * (not finite, r < 0). Huge results (a blocker at the light) are finite
 * unless they overflow; vsh_pcss_kernel_texels clamps them. */
double vsh_pcss_disk_halfwidth(double r, double d_receiver, double d_blocker);

/* A half-width in texels of a map whose texel is `texel` (world units, or
 * per unit distance for a perspective map, like the half-width), clamped
 * to [0, max_texels]: the kernel must stay inside the cascade's tile and
 * its sample count is fixed, so a wider kernel would only be sparser. +inf
 * gives max_texels; NaN, a negative half-width, texel <= 0 or a bad max
 * give 0 (the hard lookup). */
double vsh_pcss_kernel_texels(double halfwidth, double texel, double max_texels);

#ifdef __cplusplus
}
#endif
#endif
