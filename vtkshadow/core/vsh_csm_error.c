/* vsh_csm_error.c - how big a shadow texel looks on screen, the bias that
 * follows from its size, and the resolution/count that keeps it small. */
#include "vsh_csm.h"

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#define VSH_PI 3.14159265358979323846

double vsh_csm_texel_pixels(double texel_world, double depth, double view_angle_deg,
                            int viewport_height)
{
  if (!(texel_world > 0.0) || !(depth > 0.0) || !(view_angle_deg > 0.0) ||
      !(view_angle_deg < 180.0) || viewport_height < 1 || !isfinite(texel_world) ||
      !isfinite(depth))
    return 0.0;
  /* World size of one screen pixel at this depth. */
  const double pixel_world = 2.0 * depth * tan(view_angle_deg * 0.5 * VSH_PI / 180.0) /
                             viewport_height;
  return texel_world / pixel_world;
}

void vsh_csm_bias(double texel_world, double depth_extent, double scale, double *depth_bias,
                  double *normal_offset)
{
  const double s = (scale >= 0.0 && isfinite(scale)) ? scale : 1.0;
  const bool valid = texel_world > 0.0 && depth_extent > 0.0 && isfinite(texel_world) &&
                     isfinite(depth_extent);
  /* A surface at 45 degrees to the light changes depth by one texel's width
   * across a texel; half of that, in normalized depth, covers the sampling
   * offset of a texel centre. The normal offset moves the lookup one texel
   * diagonal off the surface, which removes acne on steep slopes where a
   * depth offset alone would need to be large (and cause peter-panning). */
  if (depth_bias)
    *depth_bias = valid ? s * 0.5 * texel_world / depth_extent : 0.0;
  if (normal_offset)
    *normal_offset = valid ? s * 1.5 * texel_world : 0.0;
}

/* The stable fit's texel size for the view slice [n, f] at resolution res
 * (see vsh_csm_fit.c: the sphere around the slice, rounded up to 2^(1/8)
 * steps, plus half a texel on each side for the snapping). */
static double slice_texel(double n, double f, double t, double aspect, long long res)
{
  const double half = 0.5 * (f - n);
  const double radius = sqrt(half * half + f * f * t * t * (1.0 + aspect * aspect));
  const double quantized = exp2(ceil(8.0 * log2(radius) - 1e-9) / 8.0);
  return res > 1 ? 2.0 * quantized / (double)(res - 1) : 2.0 * quantized;
}

/* The worst on-screen texel size of `count` logarithmic cascades. */
static double worst_texel_px(double near_depth, double far_depth, double t, double aspect,
                             double view_angle_deg, int viewport_height, int count, long long res)
{
  double splits[VSH_CSM_MAX_CASCADES + 1];
  if (vsh_csm_splits(VSH_SPLIT_LOG, count, near_depth, far_depth, 0.0, NULL, splits) != 0)
    return INFINITY;
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const double texel = slice_texel(splits[i], splits[i + 1], t, aspect, res);
    worst = fmax(worst, vsh_csm_texel_pixels(texel, splits[i], view_angle_deg, viewport_height));
  }
  return worst;
}

int vsh_csm_choose(double near_depth, double far_depth, double view_angle_deg, double aspect,
                   int viewport_height, double max_texel_px, long long budget_bytes,
                   int min_res, int max_res, int max_count, int *out_resolution,
                   int *out_count, double *out_texel_px)
{
  if (!(near_depth > 0.0) || !(far_depth > near_depth) || !isfinite(far_depth) ||
      !(view_angle_deg > 0.0 && view_angle_deg < 180.0) || !(aspect > 0.0) || !isfinite(aspect) ||
      viewport_height < 1 || !(max_texel_px > 0.0) || min_res < 1 || max_res < min_res ||
      max_count < 1) {
    if (out_resolution)
      *out_resolution = min_res > 0 ? min_res : 1;
    if (out_count)
      *out_count = 1;
    if (out_texel_px)
      *out_texel_px = 0.0;
    return 1;
  }
  if (max_count > VSH_CSM_MAX_CASCADES)
    max_count = VSH_CSM_MAX_CASCADES;
  /* The resolutions are the powers of two in [min_res, max_res]. */
  long long first_res = 1;
  while (first_res < min_res)
    first_res *= 2;
  if (first_res > max_res) {
    if (out_resolution)
      *out_resolution = min_res;
    if (out_count)
      *out_count = 1;
    if (out_texel_px)
      *out_texel_px = 0.0;
    return 1;
  }
  const double t = tan(view_angle_deg * 0.5 * VSH_PI / 180.0);
  int best_res = (int)first_res, best_count = 1, found = 0;
  double best_px = INFINITY, best_mem = INFINITY;
  for (int count = 1; count <= max_count; ++count) {
    for (long long res = first_res; res <= max_res; res *= 2) {
      const double memory = (double)count * (double)res * (double)res * 4.0;
      if (memory > (double)budget_bytes)
        break;
      const double worst = worst_texel_px(near_depth, far_depth, t, aspect, view_angle_deg,
                                          viewport_height, count, res);
      if (!isfinite(worst))
        continue;
      const int meets = worst <= max_texel_px;
      if ((meets && (!found || memory < best_mem)) || (!found && !meets && worst < best_px)) {
        found = found || meets;
        best_res = (int)res;
        best_count = count;
        best_px = worst;
        best_mem = memory;
      }
    }
  }
  /* Nothing fits the budget: the smallest choice, with its real texel size. */
  if (!isfinite(best_px))
    best_px = worst_texel_px(near_depth, far_depth, t, aspect, view_angle_deg, viewport_height,
                             best_count, best_res);
  if (out_resolution)
    *out_resolution = best_res;
  if (out_count)
    *out_count = best_count;
  if (out_texel_px)
    *out_texel_px = isfinite(best_px) ? best_px : 0.0;
  return found ? 0 : 1;
}

int vsh_csm_perspective_resolution(double half_angle_deg, double light_distance,
                                   double view_depth, double view_angle_deg, int viewport_height,
                                   double max_texel_px, int min_res, int max_res)
{
  if (min_res < 1 || max_res < min_res || !(half_angle_deg > 0.0 && half_angle_deg < 90.0) ||
      !(light_distance > 0.0) || !isfinite(light_distance) || !(view_depth > 0.0) ||
      !isfinite(view_depth) || !(view_angle_deg > 0.0 && view_angle_deg < 180.0) ||
      viewport_height < 1 || !(max_texel_px > 0.0) || !isfinite(max_texel_px))
    return min_res > 0 ? min_res : 1;
  const double need = tan(half_angle_deg * VSH_PI / 180.0) * light_distance * viewport_height /
                      (max_texel_px * view_depth * tan(view_angle_deg * 0.5 * VSH_PI / 180.0));
  long long res = 1;
  while (res < min_res)
    res *= 2;
  while (res < need && res * 2 <= max_res)
    res *= 2;
  return (int)(res > max_res ? max_res : res);
}
