/* vsh_camera.c - see vsh_camera.h. */
#include "vsh_camera.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#define VSH_PI 3.14159265358979323846

static double max_abs3(const double v[3]) {
  return fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
}

static int valid_view_angle(double a) { return isfinite(a) && a > 0.0 && a < 180.0; }

int vsh_camera_basis(const vsh_camera *camera, double right[3], double up[3], double forward[3]) {
  double f[3] = {0, 0, 0}, r[3] = {0, 0, 0}, u[3] = {0, 0, 0};
  int ok = 0;
  if (vsh_vec3_is_finite(camera->position) && vsh_vec3_is_finite(camera->focal_point) &&
      vsh_vec3_is_finite(camera->view_up)) {
    double d[3];
    vsh_vec3_sub(camera->focal_point, camera->position, d);
    const double len = vsh_vec3_normalize(d, f);
    /* A distance of a few ulps of the coordinates is rounding noise, not a
     * direction (e.g. E = 1e16, F = E + 1). */
    const double noise =
        4.0 * DBL_EPSILON * fmax(max_abs3(camera->position), max_abs3(camera->focal_point));
    if (len > 0.0 && len > noise && !vsh_vec3_parallel(f, camera->view_up, VSH_CAMERA_PARALLEL_TOL)) {
      double c[3];
      vsh_vec3_cross(f, camera->view_up, c);
      if (vsh_vec3_normalize(c, r) > 0.0) {
        vsh_vec3_cross(r, f, u);
        ok = 1;
      }
    }
  }
  if (!ok) {
    f[0] = f[1] = f[2] = r[0] = r[1] = r[2] = u[0] = u[1] = u[2] = 0.0;
  }
  for (int k = 0; k < 3; ++k) {
    if (right) right[k] = r[k];
    if (up) up[k] = u[k];
    if (forward) forward[k] = f[k];
  }
  return ok ? 0 : 1;
}

/* Rotation rows right, up, -forward: eye x = right, y = up, z = -forward. */
static void rotation_rows(const double r[3], const double u[3], const double f[3], double out[16]) {
  vsh_mat4_identity(out);
  for (int k = 0; k < 3; ++k) {
    out[0 * 4 + k] = r[k];
    out[1 * 4 + k] = u[k];
    out[2 * 4 + k] = -f[k];
  }
}

int vsh_camera_view_matrix(const vsh_camera *camera, double out[16]) {
  double r[3], u[3], f[3];
  if (vsh_camera_basis(camera, r, u, f) != 0) {
    vsh_mat4_identity(out);
    return 1;
  }
  rotation_rows(r, u, f, out);
  const double *e = camera->position;
  out[3] = -vsh_vec3_dot(r, e);
  out[7] = -vsh_vec3_dot(u, e);
  out[11] = vsh_vec3_dot(f, e);
  return 0;
}

int vsh_camera_view_matrix_relative(const vsh_camera *camera, double out[16]) {
  double r[3], u[3], f[3];
  if (vsh_camera_basis(camera, r, u, f) != 0) {
    vsh_mat4_identity(out);
    return 1;
  }
  rotation_rows(r, u, f, out);
  return 0;
}

int vsh_camera_projection_matrix(double view_angle, double aspect, double near_dist,
                                 double far_dist, double out[16]) {
  vsh_mat4_identity(out);
  if (!valid_view_angle(view_angle) || !isfinite(aspect) || !(aspect > 0.0) ||
      !isfinite(near_dist) || !isfinite(far_dist) || !(near_dist > 0.0) ||
      !(far_dist > near_dist))
    return 1;
  const double c = 1.0 / tan(view_angle * VSH_PI / 360.0);
  const double depth = far_dist - near_dist;
  double m[16] = {0};
  m[0] = c / aspect;
  m[5] = c;
  m[10] = -(far_dist + near_dist) / depth;
  m[11] = -2.0 * far_dist * near_dist / depth;
  m[14] = -1.0;
  if (!vsh_mat4_is_finite(m)) return 1; /* e.g. aspect denormal */
  for (int k = 0; k < 16; ++k) out[k] = m[k];
  return 0;
}

int vsh_camera_pixel_ray(const vsh_camera *camera, int width, int height, double i, double j,
                         double dir_out[3]) {
  double r[3], u[3], f[3];
  dir_out[0] = dir_out[1] = dir_out[2] = 0.0;
  if (width < 1 || height < 1 || !valid_view_angle(camera->view_angle) || !isfinite(i) ||
      !isfinite(j) || vsh_camera_basis(camera, r, u, f) != 0)
    return 1;
  const double t = tan(camera->view_angle * VSH_PI / 360.0);
  const double a = (double)width / (double)height;
  const double sx = (2.0 * (i + 0.5) / width - 1.0) * t * a;
  const double sy = (1.0 - 2.0 * (j + 0.5) / height) * t;
  for (int k = 0; k < 3; ++k) dir_out[k] = f[k] + sx * r[k] + sy * u[k];
  return 0;
}

int vsh_camera_clipping_range(const vsh_camera *camera, const vsh_bounds *bounds,
                              double near_far_ratio_min, double out_near_far[2]) {
  const int ratio_ok =
      isfinite(near_far_ratio_min) && near_far_ratio_min > 0.0 && near_far_ratio_min < 1.0;
  out_near_far[0] = ratio_ok ? near_far_ratio_min : 0.001;
  out_near_far[1] = 1.0;

  double f[3];
  if (!ratio_ok || !valid_view_angle(camera->view_angle) ||
      vsh_camera_basis(camera, NULL, NULL, f) != 0 || vsh_bounds_is_empty(bounds) ||
      !vsh_bounds_is_finite(bounds))
    return 1;

  /* 1. Depth of the corners along forward, measured from the eye. Differences
   * first, so a scene at 1e6 keeps its precision. */
  double corners[8][3];
  vsh_bounds_corners(bounds, corners);
  double n = INFINITY, fa = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    double d[3];
    vsh_vec3_sub(corners[k], camera->position, d);
    const double depth = vsh_vec3_dot(f, d);
    n = fmin(n, depth);
    fa = fmax(fa, depth);
  }
  /* 2. Minimum gap, so flat or point scenes get a non-empty slab. */
  const double min_gap = 0.2 * tan(camera->view_angle * VSH_PI / 360.0) * fa;
  if (fa - n < min_gap) {
    const double grow = min_gap - (fa - n);
    fa += 0.5 * grow;
    n -= 0.5 * grow;
  }
  if (!(fa > 0.0) || !isfinite(fa) || !isfinite(n)) return 1; /* all behind the eye */
  /* 3. Parts behind the eye do not count. */
  if (n < 0.0) n = 0.0;
  /* 4. Breathing room, in VTK's order (far uses the already widened near). */
  n = 0.99 * n - 0.5 * (fa - n);
  fa = 1.01 * fa + 0.5 * (fa - n);
  /* 5./6. Keep near in front of the eye and not too small against far, for
   * depth-buffer precision. */
  if (n >= fa) n = 0.01 * fa;
  if (n < near_far_ratio_min * fa) n = near_far_ratio_min * fa;
  if (!isfinite(n) || !isfinite(fa)) return 1;
  out_near_far[0] = n;
  out_near_far[1] = fa;
  return 0;
}
