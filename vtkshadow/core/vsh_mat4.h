/* vsh_mat4.h - 4x4 matrices as plain double[16].
 *
 * Layout: ROW-MAJOR, m[r*4 + c], acting on COLUMN vectors p' = M p. This is
 * exactly vtkMatrix4x4::Element flattened, so a vsh matrix can be handed to
 * vtkMatrix4x4::DeepCopy(const double[16]) and back with no transpose.
 * (OpenGL's glUniformMatrix4fv wants column-major: pass transpose = GL_TRUE
 * or transpose first.)
 *
 * Every function accepts outputs that alias inputs.
 */
#ifndef VSH_MAT4_H
#define VSH_MAT4_H

#ifdef __cplusplus
extern "C" {
#endif

/* Relative singularity threshold used by vsh_mat4_inverse (see there). */
#define VSH_MAT4_SINGULAR_TOL 1e-12

/* out = I */
void vsh_mat4_identity(double out[16]);

/* out = a * b, i.e. b is applied first: out p = a (b p). */
void vsh_mat4_multiply(const double a[16], const double b[16], double out[16]);

/* out4 = m * in4 for a homogeneous point (x, y, z, w). */
void vsh_mat4_transform_point4(const double m[16], const double in4[4], double out4[4]);

/* Transforms the point (p3, 1) and returns the resulting w.
 * out3 = (x/w, y/w, z/w) when that quotient is finite; when |w| is so tiny
 * that it is not (w == 0, a point at infinity, or overflow) out3 receives the
 * UNDIVIDED (x, y, z) instead. Callers that care test the returned w (e.g.
 * w > 0 for "in front of the eye / below the light"). Never divides by 0. */
double vsh_mat4_transform_point(const double m[16], const double p3[3], double out3[3]);

/* out3 = upper-left 3x3 of m times d: directions ignore translation and the
 * projective row. (For normals use the inverse transpose.) */
void vsh_mat4_transform_direction(const double m[16], const double d[3], double out3[3]);

/* out = m^T */
void vsh_mat4_transpose(const double m[16], double out[16]);

/* det(m), by cofactor expansion. */
double vsh_mat4_determinant(const double m[16]);

/* out = m^-1. Returns 1 on success, 0 when m is singular or not finite (out
 * is then set to the identity so it never holds garbage or NaN).
 *
 * "Singular" is a RELATIVE test, so a matrix is judged the same at every
 * scale: rows and then columns are scaled by powers of two (exact) so that
 * each has largest entry in [0.5, 1); the equilibrated matrix S is singular
 * when |det S| <= VSH_MAT4_SINGULAR_TOL * prod(row norms of S) (Hadamard's
 * bound, so the ratio is in [0, 1]). Thanks to the equilibration, diag(1e-9)
 * or a translation by 1e12 are invertible, while a rank-3 matrix is not. The
 * inverse itself is Gauss-Jordan with partial pivoting on S. */
int vsh_mat4_inverse(const double m[16], double out[16]);

/* out = translation by t. */
void vsh_mat4_translation(const double t[3], double out[16]);

/* out = diag(s[0], s[1], s[2], 1). */
void vsh_mat4_scale(const double s[3], double out[16]);

/* Non-zero when all 16 entries are finite. */
int vsh_mat4_is_finite(const double m[16]);

#ifdef __cplusplus
}
#endif

#endif
