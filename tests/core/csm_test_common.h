/* csm_test_common.h - what the csm unit tests (test_csm_split.c,
 * test_csm_fit.c, test_csm_error.c) share: cameras, boxes, angles. */
#ifndef CSM_TEST_COMMON_H
#define CSM_TEST_COMMON_H

#include "vsh_csm.h"
#include "vsh_random.h"
#include "vsh_vec3.h"

#include <math.h>

#define PI 3.14159265358979323846

static inline vsh_camera make_camera(double ex, double ey, double ez, double fx, double fy,
                                     double fz, double ux, double uy, double uz, double angle) {
  vsh_camera c = {{ex, ey, ez}, {fx, fy, fz}, {ux, uy, uz}, angle};
  return c;
}

/* A camera at E looking along the unit direction dir (random non-parallel up). */
static inline vsh_camera camera_looking(const double E[3], const double dir[3],
                                        double angle) {
  double up[3];
  do {
    vsh_test_rnd_unit(up);
  } while (vsh_vec3_parallel(up, dir, 0.2));
  return make_camera(E[0], E[1], E[2], E[0] + dir[0], E[1] + dir[1], E[2] + dir[2], up[0], up[1],
                     up[2], angle);
}

static inline vsh_bounds box(double x0, double x1, double y0, double y1, double z0, double z1) {
  vsh_bounds b = {{x0, y0, z0}, {x1, y1, z1}};
  return b;
}

static inline double tan_half(double angle_deg) { return tan(angle_deg * 0.5 * PI / 180.0); }

static inline vsh_bounds shifted(vsh_bounds b, const double s[3]) {
  for (int k = 0; k < 3; ++k) {
    b.min[k] += s[k];
    b.max[k] += s[k];
  }
  return b;
}

#endif
