/* vsh_depth_seed.h - whether the lit draw of a screen-space technique
 * should start from its depth pre-pass's depth (vtkShadowDepthSeed).
 * Plain data, no GL.
 *
 * Seeding costs one full-viewport draw that writes depth (the covered
 * pixels' share of it: background pixels discard). It saves the shading of
 * every fragment the lit draw would otherwise shade and then overwrite: a
 * surface drawn before the one in front of it. Both are counted on the GPU
 * (occlusion queries around the opaque step, one frame unseeded, one
 * seeded), so the policy needs no model of draw order:
 *   hidden = unseeded_fragments - seeded_fragments
 * and seeding pays when hidden > VSH_DEPTH_SEED_FRAGMENTS_PER_PIXEL * pixels.
 * The constant is the seed draw's cost per viewport pixel over the lit
 * shader's cost per fragment (see its definition for the fit). */
#ifndef VSH_DEPTH_SEED_H
#define VSH_DEPTH_SEED_H

#ifdef __cplusplus
extern "C" {
#endif

/* Hidden fragments per viewport pixel below which seeding does not pay. */
extern const double VSH_DEPTH_SEED_FRAGMENTS_PER_PIXEL;

/* Frames between two measurements (each measurement is one unseeded and
 * one seeded frame): the camera orbits, and with it the overdraw. */
#define VSH_DEPTH_SEED_MEASURE_EVERY 30

/* 1 when seeding pays for a frame whose opaque step shaded
 * `unseeded_fragments` without the seed and `seeded_fragments` with it, over
 * `pixels` viewport pixels; 0 otherwise, and for NaN, negative or infinite
 * counts and pixels <= 0 (no evidence that it pays). A seeded count above
 * the unseeded one (a frame that changed between the two) gives 0. */
int vsh_depth_seed_pays(double unseeded_fragments, double seeded_fragments, double pixels);

#ifdef __cplusplus
}
#endif
#endif
