/* vsh_plane.h - planes (N, d: the points X with N.X + d = 0) and the small
 * tests the shadow passes make with them: the plane of a flat receiver's
 * points, whether a box lies in a plane, a plane turned to face a light, a
 * plane carried through a matrix, and whether clip planes keep a whole box.
 *
 * Lights are homogeneous as in vsh_planar.h: (L, 1) positional, (towards
 * the light, 0) directional. Boxes are vsh_bounds. */
#ifndef VSH_PLANE_H
#define VSH_PLANE_H

#include "vsh_bounds.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum vsh_plane_status {
  VSH_PLANE_OK = 0,
  /* Points with area, but some lie off the fitted plane beyond tolerance. */
  VSH_PLANE_NOT_FLAT = 1,
  /* Fewer than three points, or all of them on one line (no normal). */
  VSH_PLANE_NO_AREA = 2,
  /* NULL, a non-finite number, a negative tolerance. */
  VSH_PLANE_INVALID = 3
} vsh_plane_status;

/* The plane of `count` points (x, y, z each), N unit: the normal of the
 * largest triangle fanned from point 0 (robust for slivers and collinear
 * leading points), through point 0. The points are flat when each lies
 * within rel_tolerance * size of it, size = the largest coordinate
 * distance of any point from point 0 (so the test scales with the data
 * and does not depend on where it is). out_plane = 0 unless OK or
 * VSH_PLANE_NOT_FLAT (then it holds the plane that was tried). */
vsh_plane_status vsh_plane_fit_points(const double *points, size_t count, double rel_tolerance,
                                      double out_plane[4]);

/* vsh_plane_fit_points for coordinates that were stored with a relative
 * rounding of stored_eps before they reached double (FLT_EPSILON for a VTK
 * float point array, 0 for exact data): each point may also lie off the
 * plane by 4 * stored_eps * (the largest absolute coordinate of the points),
 * the rounding a float mesh far from the origin cannot avoid, so a tilted
 * floor 1e6 away still counts as flat. This is the flatness test of
 * receiver detection (an actor whose every point lies on one plane is a
 * floor, a cut plane or a slice). stored_eps < 0 or not finite is invalid. */
vsh_plane_status vsh_plane_fit_stored_points(const double *points, size_t count,
                                             double rel_tolerance, double stored_eps,
                                             double out_plane[4]);

/* 1 when every corner of `box` lies within rel_tolerance * size of the
 * plane (|N.X + d| with N as given, normally unit), size = the box's
 * largest extent (at least 1e-300 so a point box is tested against 0+).
 * 0 otherwise, also for an empty box or bad input. */
int vsh_plane_contains_box(const double plane[4], const vsh_bounds *box, double rel_tolerance);

/* out = plane, or -plane when the light lies on its negative side
 * (plane . light < 0), so the light's side is the positive (lit) side. */
void vsh_plane_face_light(const double plane[4], const double light[4], double out[4]);

/* out = plane^T m: the plane acting on m's input space (a point X of that
 * space is on out's positive side when m X is on plane's). Row-major m
 * (vsh_mat4.h). out may not alias m. */
void vsh_plane_times_matrix(const double plane[4], const double m[16], double out[4]);

/* 1 when all 8 corners of box, taken relative to origin (X - origin), lie
 * strictly on the positive side of every one of the `count` planes (given
 * for coordinates relative to origin): clipping by those planes would
 * remove nothing, so it can be skipped. 0 otherwise (also for an empty
 * box: nothing to keep). origin may be NULL (the world origin). */
int vsh_planes_keep_box(const double (*planes)[4], size_t count, const vsh_bounds *box,
                        const double origin[3]);

#ifdef __cplusplus
}
#endif

#endif
