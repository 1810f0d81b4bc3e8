/* vsh_camera.h - a perspective camera with VTK's conventions.
 *
 * Eye space: the camera at the origin looking down -z, +y up, +x right
 * (OpenGL / vtkCamera). Clip space: NDC z in [-1, 1]. Matrices follow
 * vsh_mat4.h (row-major, column vectors), so they compare entry for entry
 * with vtkCamera::GetViewTransformMatrix and
 * vtkCamera::GetProjectionTransformMatrix(aspect, -1, 1).
 *
 * Functions returning int return 0 on success and non-zero on failure; on
 * failure outputs are still written with finite values (identity matrices,
 * zero vectors) so that nothing downstream ever sees NaN.
 */
#ifndef VSH_CAMERA_H
#define VSH_CAMERA_H

#include "vsh_bounds.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Sine threshold for the view-up test: |f x U| <= this * |U|
 * (|f| = 1) means U gives no usable "right" direction. */
#define VSH_CAMERA_PARALLEL_TOL 1e-10

typedef struct vsh_camera {
  double position[3];    /* eye E */
  double focal_point[3]; /* F; only the direction F - E matters here */
  double view_up[3];     /* U; need not be orthogonal to F - E, like vtkCamera */
  double view_angle;     /* vertical field of view in degrees, in (0, 180) */
} vsh_camera;

/* Orthonormal right-handed camera frame:
 *   forward = normalize(F - E), right = normalize(forward x U),
 *   up = right x forward.
 * Non-zero (outputs zeroed) when degenerate: non-finite input, E == F (or
 * |F - E| within a few ulps of |E|, where the direction is pure rounding
 * noise), U zero, or U parallel to forward within VSH_CAMERA_PARALLEL_TOL.
 * view_angle is not checked here. Any output pointer may be NULL. */
int vsh_camera_basis(const vsh_camera *camera, double right[3], double up[3], double forward[3]);

/* World -> eye, like vtkCamera::GetViewTransformMatrix: rows right, up,
 * -forward, translation -(R E). Note vtkCamera re-orthogonalizes its
 * view_up; this uses the orthogonalized up from vsh_camera_basis, which is
 * the same thing. Non-zero (out = identity) if the basis fails. */
int vsh_camera_view_matrix(const vsh_camera *camera, double out[16]);

/* The same rotation with NO translation: maps (X - E), a world point already
 * expressed relative to the eye, to eye space. This is the camera-relative
 * path: subtracting E in double on the CPU and then rotating keeps full
 * precision when the scene sits at 1e6 from the origin, where the full view
 * matrix would cancel two large numbers in (float) GPU arithmetic. */
int vsh_camera_view_matrix_relative(const vsh_camera *camera, double out[16]);

/* Eye -> clip for a symmetric perspective frustum, identical to
 * vtkCamera::GetProjectionTransformMatrix(aspect, -1, 1) for a perspective
 * camera without window center, shear or stereo:
 *   c = cot(view_angle / 2)
 *   [ c/aspect  0       0                    0           ]
 *   [ 0         c       0                    0           ]
 *   [ 0         0   -(f + n)/(f - n)   -2 f n/(f - n)    ]
 *   [ 0         0      -1                    0           ]
 * view_angle is vertical, in degrees; aspect = width / height.
 * Non-zero (out = identity) unless 0 < view_angle < 180, aspect > 0,
 * 0 < near < far, all finite. */
int vsh_camera_projection_matrix(double view_angle, double aspect, double near_dist,
                                 double far_dist, double out[16]);

/* World-space direction of the ray from the eye through the CENTRE of pixel
 * (i, j), i counted from the left, j from the TOP (image row order), for an
 * image width x height:
 *   dir = f + (2 (i + 0.5)/W - 1) t a r + (1 - 2 (j + 0.5)/H) t u,
 *   t = tan(view_angle / 2), a = W / H.
 * NOT normalized: its component along forward is exactly 1, so a hit at
 * E + s dir has eye depth s (what a depth buffer compares). Normalize it
 * yourself for unit-speed rays. i and j are doubles so sub-pixel samples
 * work; they are not range-checked. Non-zero (dir = 0) for a degenerate
 * camera, a view_angle outside (0, 180), or width/height < 1. */
int vsh_camera_pixel_ray(const vsh_camera *camera, int width, int height, double i, double j,
                         double dir_out[3]);

/* Near/far distances that enclose bounds, following the steps of VTK 9.1's
 * vtkRenderer::ResetCameraClippingRange(bounds) for a perspective camera:
 *   1. [n, f] = depth range of the 8 corners along forward;
 *   2. widen to at least 0.2 tan(view_angle/2) f (flat scenes facing the
 *      camera would otherwise get n == f);
 *   3. n = max(n, 0);
 *   4. breathing room: n = 0.99 n - 0.5 (f - n), then f = 1.01 f + 0.5 (f - n);
 *   5. if n >= f, n = 0.01 f;
 *   6. n = max(n, near_far_ratio_min * f)  (VTK's NearClippingPlaneTolerance).
 * near_far_ratio_min must be in (0, 1): typically 0.001 for a 24-bit depth
 * buffer, 0.01 for 16-bit. Returns non-zero for a degenerate camera, bad
 * ratio, empty or non-finite bounds, or bounds entirely behind the eye (f
 * <= 0, where VTK produces a meaningless range); out_near_far is then
 * {ratio, 1} (or {0.001, 1} if the ratio itself is bad), finite and usable. */
int vsh_camera_clipping_range(const vsh_camera *camera, const vsh_bounds *bounds,
                              double near_far_ratio_min, double out_near_far[2]);

#ifdef __cplusplus
}
#endif

#endif
