/* vsh_flat_parts.h - the flat parts of a mesh: the planes on which a large
 * share of its surface lies (a box's faces, the top of a thin slab used as
 * a floor, a stair's treads, a cylinder's caps). Planar shadows are exact
 * on such a part as on a flat actor, so a mesh that is not flat as a whole
 * can still receive them there.
 *
 * Planes are (N, d) as in vsh_plane.h: the points X with N.X + d = 0, N
 * unit. */
#ifndef VSH_FLAT_PARTS_H
#define VSH_FLAT_PARTS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vsh_flat_part {
  double plane[4]; /* N unit, pointing where the part's triangles face */
  double area;     /* the summed area of the triangles on it */
} vsh_flat_part;

/* The flat parts of `n_triangles` triangles (3 indices each into `points`,
 * x, y, z per point). Triangles share a part when their unit normals agree
 * within normal_tolerance (per component) and their planes' offsets within
 * rel_tolerance * size, size = the diagonal of the points' bounding box.
 * A part is kept when its area is at least min_fraction of the whole
 * mesh's area (use min_fraction >= 1/32: smaller ones may be missed); at
 * most max_parts are written to out, the largest first.
 * Zero-area triangles belong to no part. Returns the number written, or -1
 * for bad input (NULL with a count, an index out of range, a non-finite
 * point or a negative or non-finite tolerance or fraction). O(T log T). */
int vsh_flat_parts(const double *points, size_t n_points, const long long *triangles,
                   size_t n_triangles, double normal_tolerance, double rel_tolerance,
                   double min_fraction, vsh_flat_part *out, int max_parts);

#ifdef __cplusplus
}
#endif

#endif
