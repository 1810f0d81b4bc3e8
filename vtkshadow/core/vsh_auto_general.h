/* vsh_auto_general.h - auto's choice for a light whose shadows fall on
 * more than plane receivers: cascaded maps, shadow volumes or ray tracing.
 *
 * Maps are approximate, volumes and rays are exact for the triangles they
 * see. The choice is the cheapest candidate whose predicted error meets the
 * target; exact candidates predict 0. A map's error is predicted by two
 * terms: the texel model (vsh_auto_texel_target sizes the map so edges meet
 * the target) and the thin-caster term below, which the texel model cannot
 * see: a caster part narrower than about two map texels is sampled at texel
 * centres and can lose its whole shadow. Plain data, no VTK. */
#ifndef VSH_AUTO_GENERAL_H
#define VSH_AUTO_GENERAL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The general candidates, in the order of their bits in vtkshadow::TechniqueSet
 * after planar (csm 2, volume 4, raytrace 8). */
typedef enum vsh_auto_general {
  VSH_AUTO_GENERAL_CSM = 0,
  VSH_AUTO_GENERAL_VOLUME = 1,
  VSH_AUTO_GENERAL_RAYTRACE = 2,
  VSH_AUTO_GENERAL_COUNT = 3
} vsh_auto_general;

/* One candidate: whether it can draw this light at all, its predicted
 * wrong_pct and its predicted cost (any unit shared by all candidates). */
typedef struct vsh_auto_candidate {
  int available;
  double predicted_error_pct;
  double cost;
} vsh_auto_candidate;

/* The index of the cheapest available candidate whose predicted error is at
 * most max_error_pct (ties: the lower index). When none meets the target,
 * the available one with the lowest predicted error (ties: cheaper, then
 * lower index), and *met = 0. -1 when none is available or the input is bad
 * (NULL, count <= 0, a NaN error or cost counts as unavailable). */
int vsh_auto_pick_cheapest(const vsh_auto_candidate *candidates, int count,
                           double max_error_pct, int *met);

/* Bit l for each of the first 32 lights whose technique (VSH_AUTO_* value)
 * is `technique`: the lights a pass draws (it skips the others). 0 for bad
 * input. */
unsigned int vsh_auto_light_mask(const int *techniques, int count, int technique);

/* The wrong_pct a map predicts when a caster part `thickness_px` pixels wide
 * is narrower than it resolves (vsh_auto_map_resolves false): the part's
 * whole shadow, up to half the outline `edge_length_px` long and as wide as
 * the part (at least a pixel), counted wrong, over `pixels`. When the map
 * resolves the part this term is 0 (the texel model covers the edges). NaN
 * or non-positive pixels give +inf (not trusted). */
double vsh_auto_thin_caster_error(double thickness_px, double texel_px, double edge_length_px,
                                  double pixels);

/* Whether a caster part `thickness_px` pixels wide on screen keeps its
 * shadow in a map whose texels are `texel_px` pixels on screen: it must be
 * at least `min_texels` texels wide (2: a part narrower than two texels can
 * fall between texel centres). Returns 1 when it keeps it; 1 for no caster
 * (thickness_px = +inf); 0 for NaN or non-positive texel sizes (the
 * conservative answer: maps not trusted). */
int vsh_auto_map_resolves(double thickness_px, double texel_px, double min_texels);

/* The thinnest part of a mesh: for every connected component (`component`
 * per vertex, VSH_MESH_NONE = 0xffffffff for unused vertices, values below
 * `component_count`), the extents of its vertices along their principal
 * axes (covariance eigenvectors), sorted e0 <= e1 <= e2; the component's
 * width is e1, the narrowest shadow it casts from a generic direction (a
 * needle is thin in two axes, a plate in one only: a plate seen from above
 * casts a wide shadow). Returns the smallest width over components with at
 * least 2 vertices, +inf when there is none. `positions` are 3 doubles per
 * vertex. Components with a single vertex are ignored. */
double vsh_mesh_thinnest_width(const double *positions, size_t vertex_count,
                               const unsigned int *component, size_t component_count);

/* Tapered caster parts (cone and arrow tips, a sphere's poles): a part's
 * width varies along it, so the thinnest-width rule above, one width per
 * component, says "resolved" while the narrow end still loses its shadow.
 * The profile cuts every component into VSH_MESH_TAPER_SLICES slices along
 * its longest principal extent; a slice's width is the extent, along the
 * component's middle principal axis, of the surface where the slice's
 * centre plane cuts the triangles' edges (the cross-section, so a cone's
 * width falls linearly to 0 at its apex although no vertex lies between
 * its base and apex). */
#define VSH_MESH_TAPER_SLICES 32

/* Writes component_count * VSH_MESH_TAPER_SLICES widths and slice lengths
 * (data units; width 0 where the plane cuts no edge, e.g. components with
 * fewer than 2 vertices). `triangles` are 3 vertex indices each; a triangle
 * belongs to its first vertex's component. Returns the entries written, 0
 * for bad input (NULL, an index out of range: nothing is written then). */
size_t vsh_mesh_taper_profile(const double *positions, size_t vertex_count,
                              const unsigned int *triangles, size_t triangle_count,
                              const unsigned int *component, size_t component_count,
                              double *widths, double *lengths);

/* The wrong_pct a map predicts from tapered parts: every slice narrower on
 * screen (width * px_per_unit) than `min_texels` map texels of `texel_px`
 * loses its whole shadow (sampled at texel centres and moved off the
 * surface by the normal offset, a part narrower than that has no texel
 * whose centre it covers), an area of width x length on screen, times the
 * receivers' `stretch` (a plane at incidence theta lengthens a shadow by
 * 1 / cos theta), over `pixels`. Slices as wide as that are the texel
 * model's (their edges). 0 for no slices; +inf (not trusted) for a NaN or
 * non-positive texel_px, pixels or px_per_unit, or stretch < 1. */
double vsh_auto_taper_error(const double *widths, const double *lengths, size_t count,
                            double px_per_unit, double texel_px, double min_texels,
                            double stretch, double pixels);

/* ---- thin impostor casters ----------------------------------------------
 *
 * VTK draws points as spheres, lines as tubes and splats as discs a few
 * pixels wide on screen, whatever their distance: shapes whose outline is
 * long for their area. A map's error on them grows with its texel size
 * well below the texel model's band (their shadows are a few texels wide,
 * and their own terminators and shadows on each other move with the
 * texels), and even exact techniques miss a little there (VTK's impostor
 * depth is approximate, most of all a tube's). Both in wrong pixels per
 * pixel of the impostors' outline (their silhouettes seen from the light:
 * `point_outline_px` of spheres, splats and squares, `line_outline_px` of
 * tubes and bands), measured on scenes/primitives against POV-Ray at
 * 320x240 (docs/auto.md, "Thin impostor casters"). */
#define VSH_AUTO_THIN_MAP_PER_TEXEL 0.2   /* per outline pixel and texel pixel */
#define VSH_AUTO_THIN_POINT_FLOOR 0.04    /* per outline pixel of points */
#define VSH_AUTO_THIN_LINE_FLOOR 0.2      /* per outline pixel of lines */
/* The finest texel (pixels on screen) auto asks of a map for them: finer
 * maps cost memory and rendering time that the cost model does not weigh,
 * and an exact technique is the better way there. */
#define VSH_AUTO_THIN_MIN_TEXEL_PX 0.5

/* A map's floor along its casters' outlines: bias, filtering and the
 * terminators of curved casters put about one wrong pixel beside every
 * pixel of a caster's outline seen from the light, whatever the texel
 * size (the texel model only counts edges moved by half a texel).
 * Fitted on the library against POV-Ray at 320x240: auto's maps measured
 * 0.06-0.99 wrong pixels per outline pixel (outline x stretch) on every
 * light where it picked csm (docs/auto.md, "The map's outline floor");
 * 1.25 times the largest. */
#define VSH_AUTO_MAP_OUTLINE_FLOOR 1.25

/* csm's wrong_pct along the outline: VSH_AUTO_MAP_OUTLINE_FLOOR x
 * outline_px x stretch over `pixels`. 0 for no outline; +inf for bad input
 * (NaN, pixels <= 0, a negative outline, stretch < 1). */
double vsh_auto_map_outline_error(double outline_px, double stretch, double pixels);

/* Shadow volumes' floor. Exact in principle, they differ from POV-Ray by a
 * few pixels per frame where the stencil's depth meets contact shadows and
 * sub-pixel shadows (VSH_AUTO_VOLUME_FLOOR_PX), a little along the casters'
 * outline seen from the light (VSH_AUTO_VOLUME_OUTLINE_FLOOR per outline
 * pixel, not stretched: grazing light did not grow it), and on casters
 * that are not closed (no facing test; docs/shadow-volumes.md), per side
 * quad of such casters times the frame's pixels over 320x240's (an open
 * bowl's errors grew with the area): VSH_AUTO_VOLUME_OPEN_QUAD where they
 * are counted z-pass while the camera sees a face's side turned away from
 * the light (the volume pass's open_zfail off: false shadows there, 46 px
 * at 320x240, 294 at 800x600 on the bowl), VSH_AUTO_VOLUME_OPEN_QUAD_ZFAIL
 * otherwise (counted z-fail, the default there, or only their lit side in
 * view; isosurface's 7,478 open quads, z-fail: 96 px at 800x600). Fitted on the library against POV-Ray at 320x240 and
 * 800x600 (docs/auto.md, "Shadow volumes' floor"), 1.25 times the upper
 * envelope of the measurements. */
#define VSH_AUTO_VOLUME_FLOOR_PX 7.5
#define VSH_AUTO_VOLUME_OUTLINE_FLOOR 0.0072
#define VSH_AUTO_VOLUME_OPEN_QUAD 0.045
#define VSH_AUTO_VOLUME_OPEN_QUAD_ZFAIL 0.002
#define VSH_AUTO_VOLUME_REFERENCE_PIXELS (320.0 * 240.0)

/* volume's predicted wrong_pct: (VSH_AUTO_VOLUME_FLOOR_PX +
 * VSH_AUTO_VOLUME_OUTLINE_FLOOR x outline_px + (VSH_AUTO_VOLUME_OPEN_QUAD x
 * zpass_open_quads + VSH_AUTO_VOLUME_OPEN_QUAD_ZFAIL x zfail_open_quads) x
 * pixels / VSH_AUTO_VOLUME_REFERENCE_PIXELS) over `pixels`. 0 when there is
 * neither outline nor open quad (nothing casts in view); +inf for bad
 * input (NaN, pixels <= 0, a negative count). */
double vsh_auto_volume_floor_error(double outline_px, double zpass_open_quads,
                                   double zfail_open_quads, double pixels);

/* The wrong_pct every technique makes on impostor casters: the floors of
 * their outlines over `pixels`. 0 for no outline; +inf for bad input (NaN,
 * pixels <= 0, a negative outline). */
double vsh_auto_thin_floor_error(double point_outline_px, double line_outline_px, double pixels);

/* The wrong_pct a map with texels `texel_px` pixels on screen adds on
 * impostor casters beyond the floor: VSH_AUTO_THIN_MAP_PER_TEXEL x
 * texel_px of each pixel of their outline (`thin_outline_px`, points and
 * lines together), over `pixels`. 0 for no outline; +inf for bad input
 * (NaN, texel_px or pixels <= 0, a negative outline). */
double vsh_auto_thin_map_error(double thin_outline_px, double texel_px, double pixels);

/* The largest texel (pixels on screen) whose vsh_auto_thin_map_error stays
 * within `budget_pct`: +inf for no outline, 0 when there is no budget
 * (budget_pct <= 0) or for bad input. */
double vsh_auto_thin_texel_target(double budget_pct, double thin_outline_px, double pixels);

/* The frame's texel target `texel_px` (> 0) tightened for the map lights'
 * impostor casters: the smallest vsh_auto_thin_texel_target over the
 * `count` lights (`point_outlines`, `line_outlines`: 0 for a light without
 * them), each with the budget max_wrong_pct less its
 * vsh_auto_thin_floor_error, among those at least
 * VSH_AUTO_THIN_MIN_TEXEL_PX (a light that needs finer texels is left to
 * an exact technique: its map then predicts the target missed). texel_px
 * unchanged for bad input or no impostors. */
double vsh_auto_thin_frame_texel(double texel_px, double max_wrong_pct,
                                 const double *point_outlines, const double *line_outlines,
                                 int count, double pixels);

#ifdef __cplusplus
}
#endif
#endif
