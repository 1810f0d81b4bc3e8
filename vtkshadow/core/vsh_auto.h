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

/* ---- the per-light decision (plain data, no VTK) ------------------------ */

/* Techniques, as bits of a set (vtkshadow::TechniqueSet has the same values). */
enum {
  VSH_AUTO_NONE = 0,
  VSH_AUTO_PLANAR = 1,
  VSH_AUTO_CSM = 2,
  VSH_AUTO_VOLUME = 4,  /* exact: stencil shadow volumes */
  VSH_AUTO_RAYTRACE = 8 /* exact: ray-traced shadows */
};

/* Why a light got its technique. */
typedef enum vsh_auto_reason {
  VSH_AUTO_REASON_HEADLIGHT = 0, /* none: its shadows hide behind the casters */
  VSH_AUTO_REASON_NO_CASTER,     /* none: no object casts */
  VSH_AUTO_REASON_CONCAVE,       /* csm: object `a` is not convex, may shadow itself */
  VSH_AUTO_REASON_SHADOWS_OTHER, /* csm: `a` may shadow `b`, which is not a plane receiver */
  VSH_AUTO_REASON_PLANES_ONLY,   /* planar: every shadow falls on plane receivers */
  VSH_AUTO_REASON_NO_SHADOW      /* none: no caster can shadow a visible object */
} vsh_auto_reason;

/* An object of the frame, bounded by its box and sphere (world coordinates). */
typedef struct vsh_auto_object {
  double bounds[6]; /* VTK order: xmin, xmax, ymin, ymax, zmin, zmax */
  double center[3]; /* of the box */
  double radius;    /* half the box's diagonal */
  int receiver;     /* marked as a receiver */
  int casts;        /* casts shadows (not marked no-cast) */
  int flat;         /* a receiver whose geometry is a plane ... */
  double plane[4];  /* ... this one (N, d) */
  int in_view;      /* its sphere meets the view frustum */
} vsh_auto_object;

/* o = the object with box `bounds` and the given flags, not flat, its sphere
 * tested against `frustum` (6 planes a, b, c, d pointing inwards, as
 * vtkCamera::GetFrustumPlanes gives them; NULL: in view). */
void vsh_auto_object_init(vsh_auto_object *o, const double bounds[6], int receiver, int casts,
                          const double frustum[24]);

/* Whether a sphere meets the frustum (6 inward planes): not wholly outside
 * any one plane. */
int vsh_auto_sphere_in_frustum(const double frustum[24], const double center[3], double radius);

/* The choice for one light (homogeneous, world coordinates). */
typedef struct vsh_auto_light_choice {
  int technique;          /* VSH_AUTO_NONE, VSH_AUTO_PLANAR or VSH_AUTO_CSM */
  vsh_auto_reason reason;
  int a, b;               /* the objects the reason names, else -1 */
} vsh_auto_light_choice;

/* Chooses for one light, in this order: the headlight gets none; with no
 * caster, none; with a caster that is not convex (`concave`, an index into
 * objects, or -1: planar puts nothing on casters themselves, which is only
 * right for convex ones), csm; else csm when some caster may shadow a
 * visible object that is not a plane receiver (the first such pair), planar
 * when casters may shadow only plane receivers, none when they shadow
 * nothing visible. A flat caster blocks light only from what lies behind it.
 * "May shadow" is vsh_auto_box_may_shadow for a directional light,
 * vsh_auto_may_shadow for a positional one. */
vsh_auto_light_choice vsh_auto_choose_light(const vsh_auto_object *objects, int count,
                                            const double light[4], int headlight, int concave);

/* The shadow stretch a map light causes on the plane receivers in view:
 * 1 / cos of its steepest incidence at a receiver's centre, at most 64; 1
 * when there is none. */
double vsh_auto_plane_stretch(const vsh_auto_object *objects, int count, const double light[4]);

/* Bit l of *planar / *csm for each of the first 32 lights whose technique is
 * planar / csm (a pass skips the lights whose bit is clear). */
void vsh_auto_light_masks(const int *techniques, int count, unsigned int *planar,
                          unsigned int *csm);

/* The frame's texel target (pixels): max_texel_px when > 0, else
 * vsh_auto_texel_target for the whole viewport (`pixels`), the outline length
 * (at least one pixel), the stretch and a one-pixel band. */
double vsh_auto_frame_texel_target(double max_texel_px, double max_wrong_pct, double pixels,
                                   double edge_length_px, double stretch);

#ifdef __cplusplus
}
#endif
#endif
