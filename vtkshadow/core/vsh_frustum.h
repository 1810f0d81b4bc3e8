/* vsh_frustum.h - culling against a camera's view frustum given as planes,
 * as vtkCamera::GetFrustumPlanes returns them: 6 planes (a, b, c, d) in the
 * order left, right, bottom, top, near, far, normals pointing INTO the
 * frustum, not necessarily unit length. The tests are conservative: "not
 * visible" is always right, "visible" may be a near miss at a corner. */
#ifndef VSH_FRUSTUM_H
#define VSH_FRUSTUM_H

#include "vsh_bounds.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 0 when the sphere lies wholly outside one of the planes (its centre is
 * more than radius behind it), 1 otherwise. Bad input (non-finite, negative
 * radius, a zero plane normal) returns 1: the safe answer is "draw it". */
int vsh_frustum_sphere_visible(const double planes[24], const double center[3], double radius);

/* 0 when all 8 corners of box lie behind one of the planes, 1 otherwise.
 * An empty box is not visible (0); bad input returns 1. */
int vsh_frustum_box_visible(const double planes[24], const vsh_bounds *box);

#ifdef __cplusplus
}
#endif

#endif
