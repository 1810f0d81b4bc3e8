/* vsh_auto.h - can a scene's shadows be drawn exactly by planar projection?
 *
 * Planar shadows are exact when every shadow that matters falls on a plane
 * receiver: no caster may shadow another object that is not a receiver.
 * With each object bounded by a sphere, that is a conservative geometric
 * test per light: an answer of "no other object is shadowed" is always
 * right; "shadowed" may be a false alarm (then a general technique is
 * chosen, which is also right, only slower). */
#ifndef VSH_AUTO_H
#define VSH_AUTO_H

#ifdef __cplusplus
extern "C" {
#endif

/* Whether sphere B (center b, radius rb) may lie in the shadow of sphere A
 * (center a, radius ra) for a light: directional (light[3] == 0, light[0..2]
 * pointing towards the light) or positional (light[3] != 0, position
 * light[0..2] / light[3]). Returns 1 when it may, 0 when it cannot. Bad
 * input (non-finite, negative radii, zero direction) returns 1 (the
 * conservative answer). */
int vsh_auto_may_shadow(const double a[3], double ra, const double b[3], double rb,
                        const double light[4]);

/* Directional light, axis-aligned boxes: whether box B may lie in the shadow
 * of box A for light travelling against `towards_light` (exact for the
 * boxes: B meets A swept away from the light, t > 0; boxes that only touch
 * do not count, overlapping ones do). Bad input returns 1. */
int vsh_auto_box_may_shadow(const double amin[3], const double amax[3], const double bmin[3],
                            const double bmax[3], const double towards_light[3]);

/* Whether sphere B lies entirely on the lit side of plane `plane` (N, d with
 * N . x + d = 0), the side of `light` (homogeneous, as above): then the
 * plane, as a caster, cannot shadow it. */
int vsh_auto_on_lit_side(const double plane[4], const double light[4], const double b[3],
                         double rb);

/* The largest on-screen shadow-map texel size (pixels) whose predicted
 * wrong_pct stays at most `max_wrong_pct` (percent of `pixels`): a hard
 * shadow edge drawn from a map whose texels cover t pixels on screen is off
 * by up to t / 2 pixels; wrong_pct ignores a band of `band_px` pixels around
 * the true edge, so an edge `edge_length_px` pixels long adds at most
 * edge_length_px * (t / 2 - band_px) wrong pixels. Light reaching a
 * receiver at a grazing angle stretches the shadow (and its boundary) by
 * `stretch` = 1 / cos(incidence) >= 1, so the boundary is that much longer:
 *   t = 2 * (band_px + max_wrong_pct / 100 * pixels / (edge_length_px * stretch)).
 * 0 for bad input (non-finite, negative error or band, pixels or edge length
 * <= 0, stretch < 1): the caller then keeps its own default. */
double vsh_auto_texel_target(double max_wrong_pct, double pixels, double edge_length_px,
                             double stretch, double band_px);

#ifdef __cplusplus
}
#endif
#endif
