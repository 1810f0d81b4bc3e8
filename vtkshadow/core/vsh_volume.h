/* vsh_volume.h - stencil shadow volumes as plain data: the volume of a
 * mesh for a light (side quads from the silhouette, near and far caps), when
 * the cheaper z-pass counting is safe, the screen rectangle a volume can
 * touch (scissor, culling) and a cost estimate.
 *
 * Coordinates: whatever the caller uses consistently (the VTK pass uses the
 * caster's data coordinates for the geometry and camera-relative world
 * coordinates for the tests). Lights are homogeneous as in vsh_silhouette.h:
 * positional (L, 1), directional (towards the light, 0).
 *
 * Which volume. A point p is in shadow when the segment from p to the light
 * meets the caster. The volume is built so that its winding number around p
 * (what the stencil counts) is non-zero exactly there, and 0 on the
 * caster's own surface where it faces the light:
 *   closed, consistently oriented meshes ("dark caps"): the union of the
 *     prisms behind every face that does NOT face the light; p's winding
 *     number is the number of times the segment p -> light enters the solid.
 *     The silhouette is vsh_silhouette's LIT_FACES one (m = 1). Faces that
 *     turn away from the light only by their facets (the terminator of a
 *     tessellated sphere, which smooth normals still light) are not inside
 *     any other face's prism, so they stay lit in the mask and the lighting's
 *     own N.L shades them, as for the true surface;
 *   open or non-manifold meshes (and meshes with degenerate triangles): the
 *     sum of the prisms behind EVERY face turned to face the light; the
 *     winding number is the number of faces the segment crosses. The
 *     silhouette is the BOTH_SIDES one, each edge emitted m times.
 * Orientation: every triangle is wound counter-clockwise seen from outside
 * its prism, so a fragment of a front-facing triangle enters a prism. For a
 * directional light every extruded vertex is the same point at infinity, so
 * the side quads are triangles and there is no far cap.
 *
 * Extruded vertices are points at infinity, w = 0: (p - L, 0) for a
 * positional light, (-towards, 0) for a directional one. They are drawn
 * with depth clamping so the far cap lands on the far plane. */
#ifndef VSH_VOLUME_H
#define VSH_VOLUME_H

#include "vsh_mesh_topology.h"
#include "vsh_silhouette.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A shadow volume: triangles of homogeneous vertices, three (x, y, z, w)
 * per triangle, 12 doubles a triangle, in this order: sides (drawn in
 * z-pass and z-fail), then near caps and far caps (z-fail only). */
typedef struct vsh_volume {
  size_t side_triangles;
  size_t cap_triangles; /* near + far */
  double *vertices;     /* 12 * (side_triangles + cap_triangles) doubles */
  /* What it was made of, for statistics. */
  int dark_caps;              /* 1: closed mesh, dark caps; 0: both sides */
  size_t silhouette_edges;    /* distinct edges with m != 0 */
  size_t silhouette_quads;    /* sum of m: one quad (or triangle) each */
} vsh_volume;

/* The volume of `topology` for `light`. `out` is overwritten (not freed
 * first); on failure it is left zeroed. VSH_MESH_INVALID for NULL or an
 * unusable light (vsh_silhouette_build's rule); a positional light exactly
 * at a vertex extrudes that vertex to (0, 0, 0, 0), which draws nothing
 * (the faces there are edge-on to the light anyway). */
vsh_mesh_status vsh_volume_build(const vsh_mesh_topology *topology, const double light[4],
                                 vsh_volume *out);

/* The volume of every face turned to face the light, closed mesh or not
 * (the open meshes' volume above): its winding number around p is the
 * number of faces the segment p -> light crosses, which a translucent caster
 * needs (each crossing lets 1 - opacity through, docs/translucency.md)
 * where the dark caps count only the entries. dark_caps is 0; the same
 * errors as vsh_volume_build. */
vsh_mesh_status vsh_volume_build_crossings(const vsh_mesh_topology *topology,
                                           const double light[4], vsh_volume *out);

/* Frees the vertices and zeroes *volume. NULL and zeroed are fine. */
void vsh_volume_free(vsh_volume *volume);

/* Whether z-pass counting is safe for a caster inside the box `bounds`
 * (xmin, xmax, ymin, ymax, zmin, zmax) and `light`, seen from `eye` with
 * the near-plane rectangle `near_corners` (4 points, 12 doubles). Z-pass
 * counts the volume crossings in front of the surface, which is right only
 * when no point P of the region between the eye and the near plane (the
 * convex hull of the eye and the rectangle) lies in a shadow volume. P is in
 * the box's shadow when the segment from P towards the light meets the box,
 * so it is unsafe exactly when the region swept towards the light (its hull
 * with the light for a positional light, with its copy moved far past the
 * box for a directional one) meets the box: a convex-convex test, done
 * exactly by separating axes (face normals of both sets and cross products
 * of edges), with the box grown by `margin` (absolute, >= 0) on every side.
 * Returns 1 when safe, 0 when not or for bad input (non-finite values, an
 * empty box, an unusable light, a negative margin). */
int vsh_volume_zpass_safe(const double eye[3], const double near_corners[12],
                          const double bounds[6], const double light[4], double margin);

/* The near-plane rectangle of `clip_from_eye` (row-major 4x4, eye-relative
 * world -> clip): the clip-space corners (-1,-1), (1,-1), (1,1), (-1,1) at
 * z = -1 back in eye-relative coordinates, 12 doubles in that order, the
 * input of vsh_volume_zpass_safe. Returns 1, or 0 with `out` zeroed when the
 * matrix is singular. */
int vsh_volume_near_corners(const double clip_from_eye[16], double out[12]);

/* Window rectangle (pixels) that the volume of a caster in box `bounds` can
 * cover, for a `width` x `height` viewport and `clip_from_world` (row-major
 * 4x4, world -> clip coordinates of the same frame as bounds and light).
 * The volume lies in the convex hull of the box's corners and their
 * extrusions to infinity (homogeneous points, see above), so:
 *   returns 0 (culled) when all 16 points are outside one clip plane
 *     (-w <= x, y, z <= w);
 *   otherwise 1, with rect = {x, y, w, h} the bounding rectangle of the
 *     projection of the hull's part in front of the eye (the points with
 *     w > 0, and where the segments between points cross w = 0, which
 *     open the rectangle to the viewport's edge in their direction), grown
 *     by one pixel and clipped to the viewport; 0 when nothing is in front.
 * Bad input gives 1 and the whole viewport (the safe answer: draw it). */
int vsh_volume_screen_rect(const double clip_from_world[16], const double bounds[6],
                           const double light[4], int width, int height, int rect[4]);

/* Inputs of the cost estimate for one (caster, light) in one frame. */
typedef struct vsh_volume_cost_input {
  size_t silhouette_quads; /* vsh_volume.silhouette_quads */
  size_t cap_triangles;    /* vsh_volume.cap_triangles (counted only for z-fail) */
  int zfail;               /* 1 when the caps are drawn */
  double fill_px;          /* pixels of the screen rectangle (area of rect) */
  double depth_layers;     /* volume surfaces per pixel: 2 for a convex caster */
} vsh_volume_cost_input;

/* Estimated cost in pixel-equivalents: every covered pixel is rasterised
 * once per volume layer, and each triangle costs as much as
 * VSH_VOLUME_PX_PER_TRIANGLE pixels of fill (set-up and vertex work, a
 * software rasteriser's figure; it is the one constant to calibrate):
 *   cost = fill_px * depth_layers + PX_PER_TRIANGLE * triangles,
 * triangles = 2 * silhouette_quads (+ cap_triangles for z-fail). Sums over
 * casters and lights add; auto compares the sum with other techniques in
 * the same unit. Negative or non-finite inputs count as 0. */
#define VSH_VOLUME_PX_PER_TRIANGLE 32.0
double vsh_volume_cost(const vsh_volume_cost_input *in);

#ifdef __cplusplus
}
#endif

#endif
