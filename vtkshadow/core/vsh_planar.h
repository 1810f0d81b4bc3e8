/* vsh_planar.h - planar ("projected") shadows: the classic ground-shadow
 * matrix that flattens casters onto a receiver plane from a light.
 *
 * Plane: pi = (N, d), the points X with N.X + d = 0. Every function
 * normalizes N itself (dividing d too), so callers may pass any non-zero
 * finite N. The LIT side is the side N points to (N.X + d > 0).
 *
 * Light: homogeneous l.
 *   point or spot light at L:                 l = (L, 1)
 *   directional light travelling along D:     l = (-D, 0)
 * Any point light (L*w, w) with w != 0 is accepted and rescaled to (L, 1);
 * a directional l is rescaled to unit length. The rescaling matters: it
 * fixes the sign and size of w below, so clipping is consistent.
 *
 * Shadow matrix (row-major, column vectors, vsh_mat4.h):
 *   M = (pi.l) I - l pi^T,    M (P, 1) = (pi.l) (P, 1) - l (pi.P)
 * For a point light P' = L + ((E - L).N / ((P - L).N)) (P - L), E any point
 * of the plane; for a directional light P' = P - D (pi.P) / (N.D).
 * The homogeneous w of M (P, 1) is (pi.l) - l_w (pi.P): for a point light
 * the height of the light above P measured along N; for a directional light
 * the constant cos(angle between -D and N).
 *
 * What must not cast: a caster point with w <= 0 (at or above the light's
 * height) would project to the far side of the plane as an "anti-shadow";
 * a caster point behind the receiver (pi.P < 0) is hidden by it. Neither is
 * expressible in M alone: clip them with vsh_planar_caster_clip_planes (GPU)
 * or use vsh_planar_project_point_clipped (CPU).
 *
 * No depth offset is built into M: z-fighting with the receiver is the GPU
 * layer's job (stencil / polygon offset); vsh_planar_plane_offset exists for
 * callers that do want to lift the plane.
 *
 * Status codes: VSH_PLANAR_OK is 0. On anything else every output is fully
 * written with finite values (never NaN/Inf): the matrix is all zeros, which
 * maps every point to (0,0,0,0), i.e. w = 0 -> clipped, projects nothing.
 */
#ifndef VSH_PLANAR_H
#define VSH_PLANAR_H

#ifdef __cplusplus
extern "C" {
#endif

enum {
  VSH_PLANAR_OK = 0,
  /* Valid input, but no shadow on the lit face: the light is on the plane,
   * on the unlit side, or a directional light runs parallel to the plane. */
  VSH_PLANAR_NO_SHADOW = 1,
  /* Non-finite numbers, zero normal, collinear points, ... */
  VSH_PLANAR_INVALID = 2
};

/* Relative threshold for "these three points are collinear" in
 * vsh_planar_plane_from_points: |(p1-o) x (p2-o)| <= this |p1-o| |p2-o|. */
#define VSH_PLANAR_COLLINEAR_TOL 1e-12

/* out = (N/|N|, d/|N|). VSH_PLANAR_OK, or VSH_PLANAR_INVALID (out = 0) for a
 * zero or non-finite normal or non-finite d. */
int vsh_planar_normalize_plane(const double plane[4], double out[4]);

/* The shadow matrix M described above.
 * VSH_PLANAR_NO_SHADOW when pi.l <= eps, i.e. the light is on the plane or
 * below it, or a directional light is parallel to the plane or travels away
 * from the lit face. eps is scale-aware: 8 DBL_EPSILON times the sum of the
 * magnitudes of the terms of pi.l, so "on the plane" means "within rounding
 * of the inputs" at 1e-6 and at 1e6 alike; a directional light 1e-12 rad
 * off parallel is still a (very long) valid shadow.
 * VSH_PLANAR_INVALID for non-finite input, a zero normal, a zero directional
 * vector, or a matrix that would overflow. out = zeros unless OK. */
int vsh_planar_shadow_matrix(const double plane[4], const double light[4], double out[16]);

/* The same matrix in coordinates relative to origin (e.g. the camera
 * position): M_rel (P - origin, 1) gives P' - origin. Built by translating
 * the plane (d += N.origin, with a compensated dot product) and a point
 * light (L - origin) in double BEFORE forming M, so at a 1e6 offset or 1e-6
 * scale the matrix is as accurate as for a scene at the origin, which is
 * what a float GPU pipeline fed camera-relative vertices needs.
 * Same status codes; origin must be finite. */
int vsh_planar_shadow_matrix_relative(const double plane[4], const double light[4],
                                      const double origin[3], double out[16]);

/* Plane through origin, point1, point2 as vtkPlaneSource defines it:
 * N = normalize((point1 - origin) x (point2 - origin)), d = -N.origin.
 * VSH_PLANAR_INVALID (out = 0) for non-finite input or zero area
 * (coincident or collinear points, VSH_PLANAR_COLLINEAR_TOL). */
int vsh_planar_plane_from_points(const double origin[3], const double point1[3],
                                 const double point2[3], double out_plane[4]);

/* Two homogeneous clip planes c for casters: keep a caster point P when
 * c.(P, 1) >= 0 (gl_ClipDistance = dot(c, P)).
 *   out_clip[0] = pi normalized: receiver side, pi.P >= 0.
 *   out_clip[1] = last row of M for normalized pi and l: w > 0. For a point
 *                 light it is (-N, N.L), i.e. the light's height above P,
 *                 so it is in world units like clip 0. For a directional
 *                 light w is a positive constant and this is (0, 0, 0, 1),
 *                 always keep.
 * Same status as vsh_planar_shadow_matrix; unless OK both planes are
 * (0, 0, 0, -1), clip everything. */
int vsh_planar_caster_clip_planes(const double plane[4], const double light[4],
                                  double out_clip[2][4]);

/* vsh_planar_caster_clip_planes for coordinates relative to origin, to go
 * with vsh_planar_shadow_matrix_relative. */
int vsh_planar_caster_clip_planes_relative(const double plane[4], const double light[4],
                                           const double origin[3], double out_clip[2][4]);

/* Projects P with a shadow matrix M. Returns 1 and out = P' when the
 * homogeneous w of M (P, 1) is > 0 and P' is finite; returns 0 (out = P,
 * unchanged copy) when clipped: w <= 0, i.e. P at or above the light, or M
 * is the all-zero "no shadow" matrix. The receiver-side test (pi.P < 0)
 * needs the plane, which M does not carry unambiguously (M is unchanged
 * when pi and l are both negated): use vsh_planar_project_point_clipped. */
int vsh_planar_project_point(const double M[16], const double P[3], double out[3]);

/* Full CPU reference of what the GPU draws: builds M, applies both clip
 * planes, projects. Returns 1 and out = P' when P casts a shadow point;
 * 0 (out = P) when it does not: P behind the receiver (pi.P < 0), w <= 0,
 * or no shadow / invalid input. */
int vsh_planar_project_point_clipped(const double plane[4], const double light[4],
                                     const double P[3], double out[3]);

/* out_plane = the plane moved by distance along its (normalized) normal:
 * (N, d - distance). Positive distance moves it toward the lit side.
 * VSH_PLANAR_OK or VSH_PLANAR_INVALID (out = 0) for a bad plane or a
 * non-finite distance. */
int vsh_planar_plane_offset(const double plane[4], double distance, double out_plane[4]);

#ifdef __cplusplus
}
#endif

#endif
