/* vsh_csm_reuse.c - may a shadow map rendered for an earlier frame serve
 * this frame? A stable cascade is a square around the bounding sphere of its
 * view slice, so it covers much more than the lookups of one frame reach;
 * when the camera moves a little, the map rendered before still holds every
 * texel this frame reads, at the same texel size and light direction. Reusing
 * it saves re-rendering every caster into every cascade on each camera move. */
#include "vsh_csm.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>

#ifndef VSH_PI
#define VSH_PI 3.14159265358979323846
#endif

/* Clip coordinates of a camera-relative point under an orthographic view. */
static void to_clip(const vsh_shadow_view *view, const double p[3], double out[3])
{
  vsh_mat4_transform_point(view->world_to_clip, p, out);
}

static int has_nan(const vsh_bounds *b)
{
  for (int k = 0; k < 3; ++k)
    if (isnan(b->min[k]) || isnan(b->max[k]))
      return 1;
  return 0;
}

static void grow(double box[6], const double q[3])
{
  for (int k = 0; k < 3; ++k) {
    box[2 * k] = fmin(box[2 * k], q[k]);
    box[2 * k + 1] = fmax(box[2 * k + 1], q[k]);
  }
}

vsh_csm_status vsh_csm_lookup_region(const vsh_csm_region_params *in, double out_clip[6])
{
  if (!in)
    return VSH_CSM_BAD_INPUT;
  const vsh_camera *camera = in->camera;
  const vsh_bounds *receivers = in->receivers, *casters = in->casters;
  const vsh_shadow_view *view = in->view;
  const double aspect = in->aspect, lookup_near = in->lookup_near, slice_far = in->slice_far;
  double r[3], u[3], f[3];
  if (!camera || !view || !out_clip || view->perspective || !(aspect > 0.0) ||
      !isfinite(aspect) || !(lookup_near > 0.0) || !(slice_far > lookup_near) ||
      !isfinite(slice_far) || !(camera->view_angle > 0.0 && camera->view_angle < 180.0) ||
      vsh_camera_basis(camera, r, u, f) != 0 || !vsh_mat4_is_finite(view->world_to_clip) ||
      (receivers && has_nan(receivers)) || (casters && has_nan(casters)))
    return VSH_CSM_BAD_INPUT;
  const double t = tan(camera->view_angle * 0.5 * VSH_PI / 180.0);
  double slice[6] = { INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY };
  for (int i = 0; i < 8; ++i) {
    const double d = (i & 4) ? slice_far : lookup_near;
    const double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
    double p[3], q[3];
    for (int k = 0; k < 3; ++k)
      p[k] = d * (f[k] + sx * t * aspect * r[k] + sy * t * u[k]);
    to_clip(view, p, q);
    grow(slice, q);
  }
  /* Receivers bound where a lookup can happen; casters bound the depths the
   * map must hold (the shadow of the highest caster). Both camera-relative. */
  double depth_lo = slice[4], depth_hi = slice[5];
  if (receivers && !vsh_bounds_is_empty(receivers)) {
    if (!vsh_bounds_is_finite(receivers))
      return VSH_CSM_BAD_INPUT;
    double corners[8][3], rec[6] = { INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY };
    vsh_bounds_corners(receivers, corners);
    for (int i = 0; i < 8; ++i) {
      double p[3], q[3];
      vsh_vec3_sub(corners[i], camera->position, p);
      to_clip(view, p, q);
      grow(rec, q);
    }
    for (int k = 0; k < 3; ++k) {
      slice[2 * k] = fmax(slice[2 * k], rec[2 * k]);
      slice[2 * k + 1] = fmin(slice[2 * k + 1], rec[2 * k + 1]);
      if (slice[2 * k] > slice[2 * k + 1])
        return VSH_CSM_EMPTY;
    }
    depth_lo = slice[4];
    depth_hi = slice[5];
  }
  if (casters && !vsh_bounds_is_empty(casters)) {
    if (!vsh_bounds_is_finite(casters))
      return VSH_CSM_BAD_INPUT;
    double corners[8][3];
    vsh_bounds_corners(casters, corners);
    for (int i = 0; i < 8; ++i) {
      double p[3], q[3];
      vsh_vec3_sub(corners[i], camera->position, p);
      to_clip(view, p, q);
      depth_lo = fmin(depth_lo, q[2]);
      depth_hi = fmax(depth_hi, q[2]);
    }
  }
  /* The view itself holds only [-1, 1]: beyond that nothing was needed. */
  for (int k = 0; k < 2; ++k) {
    out_clip[2 * k] = fmax(slice[2 * k], -1.0);
    out_clip[2 * k + 1] = fmin(slice[2 * k + 1], 1.0);
  }
  out_clip[4] = fmax(depth_lo, -1.0);
  out_clip[5] = fmin(depth_hi, 1.0);
  if (out_clip[0] > out_clip[1] || out_clip[2] > out_clip[3] || out_clip[4] > out_clip[5])
    return VSH_CSM_EMPTY;
  return VSH_CSM_OK;
}

bool vsh_csm_view_covers(const vsh_csm_cover_params *in)
{
  if (!in)
    return false;
  const vsh_shadow_view *rendered = in->rendered, *needed = in->needed;
  const double *rendered_origin = in->rendered_origin, *needed_origin = in->needed_origin;
  const double *needed_region = in->needed_region;
  const int resolution = in->resolution;
  const double margin_texels = in->margin_texels;
  if (!rendered || !needed || !rendered_origin || !needed_origin || !needed_region ||
      rendered->perspective || needed->perspective || resolution < 1 ||
      !(margin_texels >= 0.0) || !isfinite(margin_texels) ||
      !vsh_vec3_is_finite(rendered_origin) || !vsh_vec3_is_finite(needed_origin) ||
      !vsh_mat4_is_finite(rendered->world_to_clip) || !vsh_mat4_is_finite(needed->world_to_clip) ||
      !(rendered->texel_world > 0.0) || !(needed->texel_world > 0.0))
    return false;
  const double *a = rendered->world_to_clip, *b = needed->world_to_clip;
  /* Same light direction and texel size: the x and y rows agree; the depth
   * row may differ in scale (the depth range follows the slice) but not in
   * direction. */
  for (int row = 0; row < 2; ++row)
    for (int c = 0; c < 3; ++c) {
      const double x = a[row * 4 + c], y = b[row * 4 + c];
      if (fabs(x - y) > 1e-9 * fmax(fabs(x), fabs(y)) + 1e-300 &&
          fabs(x - y) > 1e-12 * vsh_vec3_length(&a[row * 4]))
        return false;
    }
  const double za[3] = { a[8], a[9], a[10] }, zb[3] = { b[8], b[9], b[10] };
  double cross[3];
  vsh_vec3_cross(za, zb, cross);
  const double la = vsh_vec3_length(za), lb = vsh_vec3_length(zb);
  if (!(la > 0.0) || !(lb > 0.0) || vsh_vec3_dot(za, zb) <= 0.0 ||
      vsh_vec3_length(cross) > 1e-9 * la * lb)
    return false;
  double inverse[16];
  if (!vsh_mat4_inverse(b, inverse))
    return false;
  /* The origins differ by a camera move: small, so this difference keeps its
   * precision however far both are from the world origin. */
  double shift[3];
  vsh_vec3_sub(needed_origin, rendered_origin, shift);
  const double m = 2.0 * margin_texels / resolution;
  for (int i = 0; i < 8; ++i) {
    const double c[3] = { needed_region[(i & 1) ? 1 : 0], needed_region[(i & 2) ? 3 : 2],
                          needed_region[(i & 4) ? 5 : 4] };
    double p[3], q[3];
    vsh_mat4_transform_point(inverse, c, p);
    vsh_vec3_add(p, shift, p);
    vsh_mat4_transform_point(a, p, q);
    const double lo = -1.0 + m - 1e-12, hi = 1.0 - m + 1e-12; /* rounding of the round trip */
    if (!(q[0] >= lo && q[0] <= hi && q[1] >= lo && q[1] <= hi &&
          q[2] >= -1.0 - 1e-9 && q[2] <= 1.0 + 1e-9))
      return false;
  }
  return true;
}
