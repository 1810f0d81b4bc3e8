/* vsh_rt_pixel.c - window depth back to the surface point, the primary ray
 * that refines it, and the shadow ray's origin offset (vsh_raytrace.h). */
#include "vsh_raytrace.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

int vsh_rt_view_init(const double projection[16], const double view[16], int width, int height,
                     vsh_rt_view *out)
{
  double rotation[16], clip[16];
  memcpy(rotation, view, sizeof rotation);
  /* Inputs are already relative to the eye: drop the translation, which at
   * 1e6 from the origin would cancel large numbers. */
  rotation[3] = rotation[7] = rotation[11] = 0.0;
  vsh_mat4_multiply(projection, rotation, clip);
  out->width = width > 0 ? width : 1;
  out->height = height > 0 ? height : 1;
  if (width < 1 || height < 1 || !vsh_mat4_is_finite(clip) ||
      !vsh_mat4_inverse(clip, out->inv_clip)) {
    vsh_mat4_identity(out->inv_clip);
    return VSH_RT_DEGENERATE;
  }
  return VSH_RT_OK;
}

/* A pixel centre's line through the view volume in homogeneous form: the
 * point at window depth d is (a + d b).xyz / (a + d b).w, since the
 * inverse clip transform is linear in NDC z = 2 d - 1. One pixel's five
 * depths then cost one matrix product and five divisions. */
typedef struct pixel_line {
  double a[4], b[4];
} pixel_line;

static void pixel_line_init(const vsh_rt_view *view, double x, double y, pixel_line *out)
{
  const double ndc[4] = { 2.0 * x / view->width - 1.0, 2.0 * y / view->height - 1.0, -1.0, 1.0 };
  vsh_mat4_transform_point4(view->inv_clip, ndc, out->a);
  for (int r = 0; r < 4; ++r) {
    out->b[r] = 2.0 * view->inv_clip[4 * r + 2];
  }
}

static int pixel_line_point(const pixel_line *line, double depth, double out[3])
{
  const double w = line->a[3] + depth * line->b[3];
  /* w <= 0: the point is behind the eye (no visible surface maps there). */
  if (!(w > 0.0) || !isfinite(w)) {
    out[0] = out[1] = out[2] = 0.0;
    return VSH_RT_DEGENERATE;
  }
  for (int k = 0; k < 3; ++k) {
    out[k] = (line->a[k] + depth * line->b[k]) / w;
  }
  if (!vsh_vec3_is_finite(out)) {
    out[0] = out[1] = out[2] = 0.0;
    return VSH_RT_DEGENERATE;
  }
  return VSH_RT_OK;
}

int vsh_rt_unproject(const vsh_rt_view *view, double x, double y, double depth, double out[3])
{
  pixel_line line;
  pixel_line_init(view, x, y, &line);
  return pixel_line_point(&line, depth, out);
}

/* Distance along the ray (origin, unit direction) of the point at `depth`. */
static int depth_distance(const pixel_line *line, double depth, const double origin[3],
                          const double direction[3], double *t)
{
  double p[3], d[3];
  if (pixel_line_point(line, depth, p) != VSH_RT_OK) {
    return VSH_RT_DEGENERATE;
  }
  vsh_vec3_sub(p, origin, d);
  *t = vsh_vec3_dot(d, direction);
  return VSH_RT_OK;
}

int vsh_rt_pixel_ray_init(const vsh_rt_view *view, int i, int j, double depth, double tolerance,
                          vsh_rt_pixel_ray *out)
{
  memset(out, 0, sizeof *out);
  if (!(depth < 1.0)) {
    return VSH_RT_BACKGROUND;
  }
  if (!(depth >= 0.0) || !(tolerance >= 0.0)) {
    return VSH_RT_DEGENERATE;
  }
  pixel_line line;
  pixel_line_init(view, i + 0.5, j + 0.5, &line);
  double near_point[3], far_point[3], axis[3];
  /* The ray from the near plane to the far plane through the pixel centre:
   * the eye ray of a perspective camera, the parallel ray of a parallel one. */
  if (pixel_line_point(&line, 0.0, near_point) != VSH_RT_OK ||
      pixel_line_point(&line, 1.0, far_point) != VSH_RT_OK) {
    return VSH_RT_DEGENERATE;
  }
  vsh_vec3_sub(far_point, near_point, axis);
  if (vsh_vec3_normalize(axis, out->direction) <= 0.0) {
    return VSH_RT_DEGENERATE;
  }
  memcpy(out->origin, near_point, sizeof near_point);
  const double lo_depth = fmax(0.0, depth - tolerance);
  const double hi_depth = fmin(1.0, depth + tolerance);
  if (depth_distance(&line, depth, near_point, out->direction, &out->distance) ||
      depth_distance(&line, lo_depth, near_point, out->direction, &out->lo) ||
      depth_distance(&line, hi_depth, near_point, out->direction, &out->hi)) {
    memset(out, 0, sizeof *out);
    return VSH_RT_DEGENERATE;
  }
  out->lo = fmax(0.0, fmin(out->lo, out->distance));
  out->hi = fmax(out->hi, out->distance);
  for (int k = 0; k < 3; ++k) {
    out->point[k] = out->origin[k] + out->distance * out->direction[k];
  }
  return VSH_RT_OK;
}

double vsh_rt_landing_slack(const vsh_rt_pixel_ray *ray)
{
  return 0.5 * (ray->hi - ray->lo) + 1e-6 * fabs(ray->distance);
}

double vsh_rt_refine_reach(const vsh_rt_pixel_ray *ray)
{
  const double span = ray->hi - ray->lo;
  return span + 1e-5 * span + 4 * VSH_RT_OFFSET_RELATIVE * fabs(ray->distance);
}

double vsh_rt_offset_distance(double magnitude)
{
  const double m = isfinite(magnitude) ? fabs(magnitude) : 0.0;
  return fmax(VSH_RT_OFFSET_RELATIVE * m, 1e-300);
}

int vsh_rt_frame_usable(const double origin_to_eye[3], double near_distance)
{
  const double d = sqrt(origin_to_eye[0] * origin_to_eye[0] +
                        origin_to_eye[1] * origin_to_eye[1] +
                        origin_to_eye[2] * origin_to_eye[2]);
  if (!isfinite(d)) {
    return 0;
  }
  if (!(near_distance > 0) || !isfinite(near_distance)) {
    return d == 0.0;
  }
  return d <= near_distance;
}

void vsh_rt_offset_origin(const double point[3], const double normal[3], double magnitude,
                          double out[3])
{
  const double e = vsh_rt_offset_distance(magnitude);
  for (int k = 0; k < 3; ++k) {
    out[k] = point[k] + e * normal[k];
  }
}

double vsh_rt_impostor_radius(const double projection[16], const double view[16], int width,
                              double pixels, const double p[3])
{
  /* w = (projection row 3) . (view p): the clip w at p. */
  double eye[4];
  for (int r = 0; r < 4; ++r) {
    eye[r] = view[4 * r] * p[0] + view[4 * r + 1] * p[1] + view[4 * r + 2] * p[2] + view[4 * r + 3];
  }
  double w = 0.0;
  for (int c = 0; c < 4; ++c) {
    w += projection[12 + c] * eye[c];
  }
  const double scale = (double)width * projection[0];
  const double r = pixels * fabs(w) / fabs(scale);
  return width >= 1 && scale != 0.0 && isfinite(r) && pixels > 0 ? r : 0.0;
}
