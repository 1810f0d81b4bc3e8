/* vsh_volume_cost.h - what one light's stencil shadow volumes cost per
 * frame, in milliseconds, from what the CPU knows before drawing, and what
 * they are predicted to get wrong: auto's `volume` candidate
 * (vsh_auto_general.h). Plain data, no VTK.
 *
 * The model (linear; one light):
 *   ms = MS_PER_PIXEL   * pixels            the light's share of the screen
 *                                           work: the depth pre-pass, the
 *                                           stencil clear and resolve, the
 *                                           mask lookup in the lighting
 *      + MS_PER_TRIANGLE * scene_triangles  the depth pre-pass draws the
 *                                           opaque scene once more (the
 *                                           first measurements showed this
 *                                           term dominating on big meshes)
 *      + MS_PER_EDGE    * silhouette_edges  per side quad (sum of the edges'
 *                                           multiplicities over the casters):
 *                                           the CPU's silhouette and volume
 *                                           work plus the vertex work
 *      + MS_PER_FILL_PX * fill_px           the volumes' scissored screen
 *                                           rectangles (vsh_volume_screen_rect),
 *                                           summed over the casters: stencil
 *                                           fill, two volume layers a pixel
 *                                           for a convex caster
 *      + MS_PER_TRIANGLE * cap_triangles    the caps of the volumes counted
 *                                           z-fail (casters that are not
 *                                           closed: a cap per face), drawn
 *                                           like the pre-pass's triangles
 *                                           (elevation's 28,322: 7.6 ms
 *                                           measured, 5.0 predicted)
 * The coefficients are fitted by bench/bench_volume_cost.py (see the
 * comment at their definition in vsh_volume_cost.c for where and when).
 * The CPU rebuild of a volume (only when the light moves relative to a
 * caster or its mesh changes) is not a term: the fit's frames reuse them,
 * and auto decides per frame with the volumes it would reuse. */
#ifndef VSH_VOLUME_COST_H
#define VSH_VOLUME_COST_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vsh_volume_ms_input {
  double pixels;           /* the viewport's pixels */
  double scene_triangles;  /* the opaque scene's triangles (the depth pre-pass) */
  double silhouette_edges; /* sum of the silhouette multiplicities: side quads */
  double fill_px;          /* sum of the casters' scissor rectangles, pixels */
  double cap_triangles;    /* caps of the volumes counted z-fail (0 when all are z-pass) */
} vsh_volume_ms_input;

/* The fitted coefficients (vsh_volume_cost.c). */
extern const double VSH_VOLUME_MS_PER_PIXEL;
extern const double VSH_VOLUME_MS_PER_TRIANGLE;
extern const double VSH_VOLUME_MS_PER_EDGE;
extern const double VSH_VOLUME_MS_PER_FILL_PX;

/* The model above. 0 edges and 0 fill leave the screen and scene terms
 * (the depth pre-pass is paid even when no volume reaches the view). Returns +inf
 * (never cheaper than anything finite) for NULL, NaN or negative inputs
 * and when the sum overflows; +inf inputs give +inf. */
double vsh_volume_cost_ms(const vsh_volume_ms_input *in);

/* The wrong_pct volumes are predicted to have for one light: 0 (exact)
 * when every caster is one they draw exactly and the light is a point
 * (hard shadows), +inf (never meets a target) when `unsupported_casters` >
 * 0 or `soft_light` is set. Volumes are exact for polygonal meshes,
 * closed, open or non-manifold, glyph instances included (their
 * silhouettes are built per instance). They do not support: casters
 * without triangles (lines, vertices: the pass has no mesh to extrude),
 * translucent casters (the pass skips them), and lights with a size (a
 * radius or angle: volumes have no penumbra). */
double vsh_volume_predicted_error(int unsupported_casters, int soft_light);

#ifdef __cplusplus
}
#endif
#endif
