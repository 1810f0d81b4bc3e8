/* vsh_reflect.h - planar mirrors: the reflection through a plane as a 4x4
 * matrix, the plane of a mirror, which side of it the eye is on, and the
 * clip plane that keeps only what lies behind the mirror.
 *
 * Planes are (N, d): the points X with N.X + d = 0, N unit. Matrices are
 * row-major acting on column vectors (vsh_mat4.h).
 *
 * Camera-relative: a mirror at z = 1e6 seen from z = 1e6 + 5 reflects
 * points by X' = X - 2 (N.X + d) N. Written as one matrix in world
 * coordinates its translation is -2 d N (2e6 here), and composing it with a
 * view matrix in single precision would lose the few units that matter. So
 * every function here can take an `origin` (normally the eye): the plane
 * and the matrix are then expressed for coordinates relative to it, where
 * the numbers are as small as the distances the camera sees. */
#ifndef VSH_REFLECT_H
#define VSH_REFLECT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum vsh_reflect_status {
  VSH_REFLECT_OK = 0,
  /* The normal is zero, or too small to normalize (no plane). */
  VSH_REFLECT_DEGENERATE = 1,
  /* NULL or a non-finite number. */
  VSH_REFLECT_INVALID = 2
} vsh_reflect_status;

/* The plane through `point` with normal `normal` (any non-zero length),
 * expressed relative to `origin` (NULL: the world origin): out = (N, d)
 * with N unit and d = -N.(point - origin). The difference point - origin is
 * taken before anything else, so a mirror and an eye both near 1e6 give the
 * same plane as near 0. out = 0 unless OK. */
vsh_reflect_status vsh_reflect_plane(const double point[3], const double normal[3],
                                     const double origin[3], double out_plane[4]);

/* The reflection through plane (N, d), N unit (as vsh_reflect_plane
 * makes it): out = [I - 2 N N^T, -2 d N; 0 0 0 1]. It is its own inverse,
 * its determinant is -1 (it flips the winding of every triangle), and it
 * fixes every point of the plane. out = identity unless OK (INVALID for a
 * non-finite plane, DEGENERATE when |N| is not 1 within 1e-9). */
vsh_reflect_status vsh_reflect_matrix(const double plane[4], double out[16]);

/* Signed distance of `point` from the plane, both relative to the same
 * origin: N.point + d. Positive on the side N points to. */
double vsh_reflect_side(const double plane[4], const double point[3]);

/* 1 when the eye sees the mirror's reflecting face: it lies strictly on the
 * side of `plane` its normal points to, farther than rel_tolerance * scale
 * (scale >= 1e-300; pass the mirror's size so the test is scale-free). A
 * camera below a mirror, or in its plane (seeing it edge-on), sees no
 * reflection: 0. Eye and plane relative to the same origin. */
int vsh_reflect_eye_sees(const double plane[4], const double eye[3], double scale,
                         double rel_tolerance);

/* The clip plane for the mirrored scene: keeps (positive side) the points
 * behind the mirror as seen from the eye, i.e. -plane when the eye is on
 * the positive side. Everything reflected into the space between the eye
 * and the mirror (the reflections of objects behind the mirror) is cut. */
void vsh_reflect_clip_plane(const double plane[4], const double eye[3], double out[4]);

/* A point and a direction through the reflection (no matrix needed):
 * p' = p - 2 (N.p + d) N and v' = v - 2 (N.v) N. Lights are mirrored this
 * way (positions, focal points, directions). */
void vsh_reflect_point(const double plane[4], const double p[3], double out[3]);
void vsh_reflect_direction(const double plane[4], const double v[3], double out[3]);

#ifdef __cplusplus
}
#endif

#endif
