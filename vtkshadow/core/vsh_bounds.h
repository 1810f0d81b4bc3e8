/* vsh_bounds.h - axis-aligned bounding boxes.
 *
 * The empty box is min = +Inf, max = -Inf on every axis, so adding the first
 * point needs no special case. A box with min == max on some or all axes (a
 * single point, a flat plane) is NOT empty: it is a valid zero-volume box,
 * and shadow code must handle it (ground planes are exactly that).
 */
#ifndef VSH_BOUNDS_H
#define VSH_BOUNDS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vsh_bounds {
  double min[3];
  double max[3];
} vsh_bounds;

/* b = the empty box. */
void vsh_bounds_init_empty(vsh_bounds *b);

/* b = the box from VTK's order (xmin, xmax, ymin, ymax, zmin, zmax), as
 * returned by vtkProp::GetBounds. Copied verbatim: VTK's "uninitialized"
 * bounds (min > max) come out empty. */
void vsh_bounds_from_vtk(vsh_bounds *b, const double vtk_bounds[6]);

/* vtk_bounds = b in VTK's order (xmin, xmax, ymin, ymax, zmin, zmax). */
void vsh_bounds_to_vtk(const vsh_bounds *b, double vtk_bounds[6]);

/* Grows b to contain p. Returns 1, or 0 when p is not finite: such points
 * are ignored rather than turning the whole box into NaN/Inf. */
int vsh_bounds_add_point(vsh_bounds *b, const double p[3]);

/* Grows into to contain other (no-op if other is empty). */
void vsh_bounds_merge(vsh_bounds *into, const vsh_bounds *other);

/* Non-zero when b contains no point: min > max on some axis, or NaN. */
int vsh_bounds_is_empty(const vsh_bounds *b);

/* Non-zero when all six numbers are finite (so never for the empty box). */
int vsh_bounds_is_finite(const vsh_bounds *b);

/* out = centre of b. Returns 0 on success, non-zero for an empty or
 * non-finite box (out = 0,0,0). */
int vsh_bounds_center(const vsh_bounds *b, double out[3]);

/* Length of the diagonal; 0 for a point, and also 0 for an empty or
 * non-finite box (test vsh_bounds_is_empty to tell them apart). */
double vsh_bounds_diagonal_length(const vsh_bounds *b);

/* The 8 corners; corner k takes x from max if bit 0 of k is set (else min),
 * y from bit 1, z from bit 2. Returns 0, or non-zero for an empty box (out
 * is then all zeros). Zero-volume boxes give repeated corners. */
int vsh_bounds_corners(const vsh_bounds *b, double out[8][3]);

/* out = the bounds of the 8 corners of b transformed by m (with the
 * perspective divide). Returns 0 on success. An empty b gives an empty out
 * and returns 0. Returns non-zero, with out empty, when b or m is not finite
 * or when some corner gets w <= 0 (the box crosses the plane at infinity of
 * a projective m, where "bounds of the corners" would be wrong). */
int vsh_bounds_transform(const vsh_bounds *b, const double m[16], vsh_bounds *out);

/* Depth range of b seen through a world->eye view matrix (such as
 * vsh_camera_view_matrix): depth = -z_eye of the 8 corners, since the camera
 * looks down -z. out_near_far = {min depth, max depth}. Values are NOT
 * clamped: negative depth means behind the eye. The matrix is taken as
 * affine (its last row is ignored). Returns 0 on success,
 * non-zero for an empty or non-finite box or non-finite matrix (out = 0,0). */
int vsh_bounds_depth_range_in_view(const vsh_bounds *b, const double view_matrix[16],
                                   double out_near_far[2]);

#ifdef __cplusplus
}
#endif

#endif
