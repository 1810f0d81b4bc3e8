/* vsh_vec3.h - 3-vectors as plain double[3].
 *
 * Every function accepts outputs that alias inputs (out == a is fine): the
 * result is computed into locals first. Nothing here ever produces NaN from
 * finite input; degenerate cases (zero vectors) have a documented answer.
 */
#ifndef VSH_VEC3_H
#define VSH_VEC3_H

#ifdef __cplusplus
extern "C" {
#endif

/* a . b */
double vsh_vec3_dot(const double a[3], const double b[3]);

/* out = a x b (right-handed). */
void vsh_vec3_cross(const double a[3], const double b[3], double out[3]);

/* |v|, computed with scaling so that components near 1e200 or 1e-200 neither
 * overflow nor underflow. Returns NaN/Inf only for non-finite input. */
double vsh_vec3_length(const double v[3]);

/* out = v / |v| and returns |v|. A zero or non-finite v gives out = (0,0,0)
 * and returns 0: the result is never NaN, and "returned 0" is the one test
 * callers need for "no direction". */
double vsh_vec3_normalize(const double v[3], double out[3]);

/* out = a - b */
void vsh_vec3_sub(const double a[3], const double b[3], double out[3]);

/* out = a + b */
void vsh_vec3_add(const double a[3], const double b[3], double out[3]);

/* out = s * v */
void vsh_vec3_scale(const double v[3], double s, double out[3]);

/* out = (1 - t) a + t b; exact at t = 0 and t = 1 (which a + t (b - a) is not). */
void vsh_vec3_lerp(const double a[3], const double b[3], double t, double out[3]);

/* Non-zero when |a x b| <= rel_tol |a| |b|, i.e. the sine of the angle between
 * them is at most rel_tol (parallel or anti-parallel). Also non-zero when
 * either vector is zero, since a zero vector spans no direction that could
 * make a basis with the other. Scale-invariant: both are normalized first.
 * Non-finite input counts as parallel (unusable as a basis). */
int vsh_vec3_parallel(const double a[3], const double b[3], double rel_tol);

/* Non-zero when all three components are finite. */
int vsh_vec3_is_finite(const double v[3]);

#ifdef __cplusplus
}
#endif

#endif
