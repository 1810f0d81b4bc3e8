/* vsh_transmit.h - how much light a translucent surface lets through: the
 * semantics every technique and both references share
 * (docs/translucency.md).
 *
 * A surface of opacity a lets (1 - a) of the light through at each
 * crossing. Of that part, the fraction `filter` (f) is tinted by the
 * surface's colour c and the rest passes unchanged, as POV-Ray's filter and
 * transmit do: per channel k the transmittance of one crossing is
 *   t_k = (1 - a) ((1 - f) + f c_k).
 * Crossings multiply: a closed sphere of opacity 0.5 crossed twice leaves
 * 0.25. Visibility becomes per channel where a filter tints it. */
#ifndef VSH_TRANSMIT_H
#define VSH_TRANSMIT_H

#ifdef __cplusplus
extern "C" {
#endif

/* The transmittance of one crossing, per channel, into out[3]. Opacity and
 * filter are clamped to [0, 1] (NaN counts as opaque: no light through) and
 * colour channels to [0, 1]. */
void vsh_transmit_crossing(const double color[3], double opacity, double filter,
                           double out[3]);

/* inout[k] *= the crossing's transmittance: one more surface on the way to
 * the light. */
void vsh_transmit_accumulate(const double color[3], double opacity, double filter,
                             double inout[3]);

/* 1 when the crossing lets any light through (opacity < 1 after clamping),
 * so a ray must look past it; 0 for an opaque surface (the ray stops). */
int vsh_transmit_passes(double opacity);

/* How many crossings of transmittance `transmit` (one crossing, clamped to
 * [0, 1]) matter to an 8-bit visibility: the smallest k >= 1 with
 * transmit^k below half a step (1/510), at most 255 (an 8-bit stencil
 * count). A technique that multiplies once per crossing stops there: more
 * crossings change no stored value. 1 for an opaque crossing (or NaN), 255
 * for one that lets nearly everything through. */
int vsh_transmit_steps(double transmit);

#ifdef __cplusplus
}
#endif

#endif
