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
  const vsh_csm_split_params log_split = {VSH_SPLIT_LOG, count, near_depth, far_depth, 0.0, NULL,
                                          0.0};
  if (vsh_csm_splits(&log_split, splits) != VSH_CSM_OK)
    return INFINITY;
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const double texel = slice_texel(splits[i], splits[i + 1], t, aspect, res);
    worst = fmax(worst, vsh_csm_texel_pixels(texel, splits[i], view_angle_deg, viewport_height));
  }
  return worst;
}

/* The choice for bad input (and for a range holding no power of two). */
static vsh_csm_status refuse(int resolution, vsh_csm_choice *out)
{
  if (out) {
    out->resolution = resolution;
    out->count = 1;
    out->texel_px = 0.0;
  }
  return VSH_CSM_BAD_INPUT;
}

static bool choose_input_ok(const vsh_csm_choose_params *p)
{
  return p->near_depth > 0.0 && p->far_depth > p->near_depth && isfinite(p->far_depth) &&
         p->view_angle_deg > 0.0 && p->view_angle_deg < 180.0 && p->aspect > 0.0 &&
         isfinite(p->aspect) && p->viewport_height >= 1 && p->max_texel_px > 0.0 &&
         p->min_res >= 1 && p->max_res >= p->min_res && p->max_count >= 1;
}

vsh_csm_status vsh_csm_choose(const vsh_csm_choose_params *p, vsh_csm_choice *out)
{
  if (!p)
    return refuse(1, out);
  if (!choose_input_ok(p))
    return refuse(p->min_res > 0 ? p->min_res : 1, out);
  const double near_depth = p->near_depth, far_depth = p->far_depth;
  const double view_angle_deg = p->view_angle_deg, aspect = p->aspect;
  const int viewport_height = p->viewport_height, max_res = p->max_res;
  const int max_count = p->max_count > VSH_CSM_MAX_CASCADES ? VSH_CSM_MAX_CASCADES : p->max_count;
  /* The resolutions are the powers of two in [min_res, max_res]. */
  long long first_res = 1;
  while (first_res < p->min_res)
    first_res *= 2;
  if (first_res > max_res)
    return refuse(p->min_res, out);
  const double t = tan(view_angle_deg * 0.5 * VSH_PI / 180.0);
  int best_res = (int)first_res, best_count = 1, found = 0;
  double best_px = INFINITY, best_mem = INFINITY;
  for (int count = 1; count <= max_count; ++count) {
    for (long long res = first_res; res <= max_res; res *= 2) {
      const double memory = (double)count * (double)res * (double)res * 4.0;
      if (memory > (double)p->budget_bytes)
        break;
      const double worst = worst_texel_px(near_depth, far_depth, t, aspect, view_angle_deg,
                                          viewport_height, count, res);
      if (!isfinite(worst))
        continue;
      const int meets = worst <= p->max_texel_px;
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
  if (out) {
    out->resolution = best_res;
    out->count = best_count;
    out->texel_px = isfinite(best_px) ? best_px : 0.0;
  }
  return found ? VSH_CSM_OK : VSH_CSM_TARGET_MISSED;
}

vsh_csm_status vsh_csm_perspective_resolution(const vsh_csm_resolution_params *p,
                                              int *out_resolution)
{
  int ignored;
  int *res_out = out_resolution ? out_resolution : &ignored;
  if (!p) {
    *res_out = 1;
    return VSH_CSM_BAD_INPUT;
  }
  const int min_res = p->min_res, max_res = p->max_res;
  if (min_res < 1 || max_res < min_res || !(p->half_angle_deg > 0.0 && p->half_angle_deg < 90.0) ||
      !(p->light_distance > 0.0) || !isfinite(p->light_distance) || !(p->view_depth > 0.0) ||
      !isfinite(p->view_depth) || !(p->view_angle_deg > 0.0 && p->view_angle_deg < 180.0) ||
      p->viewport_height < 1 || !(p->max_texel_px > 0.0) || !isfinite(p->max_texel_px)) {
    *res_out = min_res > 0 ? min_res : 1;
    return VSH_CSM_BAD_INPUT;
  }
  const double need =
      tan(p->half_angle_deg * VSH_PI / 180.0) * p->light_distance * p->viewport_height /
      (p->max_texel_px * p->view_depth * tan(p->view_angle_deg * 0.5 * VSH_PI / 180.0));
  long long res = 1;
  while (res < min_res)
    res *= 2;
  while (res < need && res * 2 <= max_res)
    res *= 2;
  *res_out = (int)(res > max_res ? max_res : res);
  return *res_out < need ? VSH_CSM_TARGET_MISSED : VSH_CSM_OK;
}
