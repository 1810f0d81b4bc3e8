/* vsh_frustum.c - sphere and box culling against frustum planes
 * (vsh_frustum.h). */
#include "vsh_frustum.h"

#include <math.h>

/* The plane's normal length, or 0 when the plane is unusable. */
static double normal_length(const double *plane) {
  for (int k = 0; k < 4; ++k)
    if (!isfinite(plane[k])) return 0.0;
  const double n = sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
  return isfinite(n) ? n : 0.0;
}

int vsh_frustum_sphere_visible(const double planes[24], const double center[3], double radius) {
  if (!planes || !center || !(radius >= 0.0) || !isfinite(radius)) return 1;
  for (int k = 0; k < 3; ++k)
    if (!isfinite(center[k])) return 1;
  for (int p = 0; p < 6; ++p) {
    const double *plane = planes + 4 * p;
    const double n = normal_length(plane);
    if (n == 0.0) return 1;
    const double side =
        plane[0] * center[0] + plane[1] * center[1] + plane[2] * center[2] + plane[3];
    if (side < -radius * n) return 0;
  }
  return 1;
}

int vsh_frustum_box_visible(const double planes[24], const vsh_bounds *box) {
  if (!planes || !box) return 1;
  if (vsh_bounds_is_empty(box)) return 0;
  double corners[8][3];
  if (!vsh_bounds_is_finite(box) || vsh_bounds_corners(box, corners) != 0) return 1;
  for (int p = 0; p < 6; ++p) {
    const double *plane = planes + 4 * p;
    if (normal_length(plane) == 0.0) return 1;
    int behind = 0;
    for (int k = 0; k < 8; ++k)
      behind += plane[0] * corners[k][0] + plane[1] * corners[k][1] +
                    plane[2] * corners[k][2] + plane[3] < 0.0;
    if (behind == 8) return 0;
  }
  return 1;
}
