/* vsh_csm_split.c - how far cascades reach: the visible depth range of the
 * geometry, the cascade count it asks for, and the split depths. */
#include "vsh_csm.h"

#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

/* Clip a convex polygon (n points, camera-relative view coordinates) against
 * the half-space dot(plane.xyz, p) + plane.w >= 0 (Sutherland-Hodgman). */
static int clip_polygon(double in[][3], int n, const double plane[4], double out[][3])
{
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const double *a = in[i], *b = in[(i + 1) % n];
    const double da = vsh_vec3_dot(plane, a) + plane[3];
    const double db = vsh_vec3_dot(plane, b) + plane[3];
    if (da >= 0.0)
      memcpy(out[m++], a, sizeof(double[3]));
    if ((da >= 0.0) != (db >= 0.0)) {
      const double t = da / (da - db);
      for (int k = 0; k < 3; ++k)
        out[m][k] = a[k] + t * (b[k] - a[k]);
      ++m;
    }
  }
  return m;
}

vsh_csm_status vsh_csm_visible_depth_range(const vsh_csm_depth_range_params *in,
                                           double out_near_far[2])
{
  if (!in)
    return VSH_CSM_BAD_INPUT;
  const vsh_camera *camera = in->camera;
  const vsh_bounds *bounds = in->bounds;
  const double aspect = in->aspect, clip_near = in->clip_near, clip_far = in->clip_far;
  double r[3], u[3], f[3];
  if (!camera || !bounds || !out_near_far || !(aspect > 0.0) || !isfinite(aspect) ||
      !(clip_near > 0.0) ||
      !(clip_far > clip_near) || !isfinite(clip_far) || vsh_bounds_is_empty(bounds) ||
      !vsh_bounds_is_finite(bounds) || vsh_camera_basis(camera, r, u, f) != 0 ||
      !(camera->view_angle > 0.0 && camera->view_angle < 180.0))
    return VSH_CSM_BAD_INPUT;
  const double t = tan(camera->view_angle * 0.5 * 3.14159265358979323846 / 180.0);
  /* Frustum planes in view coordinates (x right, y up, z = depth forward),
   * each as dot(n, p) + w >= 0 inside. */
  const double planes[6][4] = {
      {0, 0, 1, -clip_near}, {0, 0, -1, clip_far}, {1, 0, t * aspect, 0},
      {-1, 0, t * aspect, 0}, {0, 1, t, 0},        {0, -1, t, 0}};
  /* The box's corners relative to the eye, in view coordinates: subtracting
   * the eye first keeps precision far from the origin. */
  double corners[8][3], view[8][3];
  vsh_bounds_corners(bounds, corners);
  for (int i = 0; i < 8; ++i) {
    double rel[3];
    vsh_vec3_sub(corners[i], camera->position, rel);
    view[i][0] = vsh_vec3_dot(rel, r);
    view[i][1] = vsh_vec3_dot(rel, u);
    view[i][2] = vsh_vec3_dot(rel, f);
  }
  /* vsh_bounds_corners order: bit 0 x, bit 1 y, bit 2 z (see vsh_bounds.h). */
  static const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                  {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  double lo = INFINITY, hi = -INFINITY;
  for (int fi = 0; fi < 6; ++fi) {
    double a[16][3], b[16][3];
    int n = 4;
    for (int k = 0; k < 4; ++k)
      memcpy(a[k], view[faces[fi][k]], sizeof(double[3]));
    for (int p = 0; p < 6 && n > 0; ++p) {
      n = clip_polygon(a, n, planes[p], b);
      memcpy(a, b, sizeof(double[3]) * (size_t)n);
    }
    for (int k = 0; k < n; ++k) {
      lo = fmin(lo, a[k][2]);
      hi = fmax(hi, a[k][2]);
    }
  }
  /* Clipping the box's faces finds every vertex of box-and-frustum that lies
   * on the box's surface; the others are frustum corners inside the box (a
   * box straddling the near plane, or containing the camera or the whole
   * view). Depth is linear, so its extremes are at these vertices. */
  double rmin[3], rmax[3];
  vsh_vec3_sub(bounds->min, camera->position, rmin);
  vsh_vec3_sub(bounds->max, camera->position, rmax);
  for (int i = 0; i < 8; ++i) {
    const double d = (i & 4) ? clip_far : clip_near;
    const double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
    int inside = 1;
    for (int k = 0; k < 3; ++k) {
      const double p = d * (f[k] + sx * t * aspect * r[k] + sy * t * u[k]);
      inside &= p >= rmin[k] && p <= rmax[k];
    }
    if (inside) {
      lo = fmin(lo, d);
      hi = fmax(hi, d);
    }
  }
  if (!(lo <= hi))
    return VSH_CSM_EMPTY;
  out_near_far[0] = fmax(lo, clip_near);
  out_near_far[1] = fmin(fmax(hi, out_near_far[0]), clip_far);
  return VSH_CSM_OK;
}

int vsh_csm_default_count(double near_depth, double far_depth, double ratio_per_cascade)
{
  if (!(near_depth > 0.0) || !(far_depth > near_depth) || !isfinite(far_depth) ||
      !(ratio_per_cascade > 1.0))
    return 1;
  const double k = ceil(log(far_depth / near_depth) / log(ratio_per_cascade) - 1e-9);
  if (k < 1.0)
    return 1;
  return k > VSH_CSM_MAX_CASCADES ? VSH_CSM_MAX_CASCADES : (int)k;
}

vsh_csm_status vsh_csm_splits(const vsh_csm_split_params *p, double *out)
{
  if (!p)
    return VSH_CSM_BAD_INPUT;
  const vsh_split_scheme scheme = p->scheme;
  const int count = p->count;
  const double near_depth = p->near_depth, far_depth = p->far_depth, lambda = p->lambda;
  const double *fractions = p->fractions;
  if (!out || count < 1 || count > VSH_CSM_MAX_CASCADES || !(near_depth > 0.0) ||
      !(far_depth > near_depth) || !isfinite(far_depth))
    return VSH_CSM_BAD_INPUT;
  if (scheme == VSH_SPLIT_PRACTICAL && !(lambda >= 0.0 && lambda <= 1.0))
    return VSH_CSM_BAD_INPUT;
  if (!(p->max_ratio == 0.0 || (p->max_ratio > 1.0 && isfinite(p->max_ratio))))
    return VSH_CSM_BAD_INPUT;
  /* The cap only where every cascade can keep it (see vsh_csm.h). */
  const int capped = p->max_ratio > 1.0 &&
                     count * log(p->max_ratio) >= log(far_depth / near_depth) * (1.0 - 1e-12);
  double s[VSH_CSM_MAX_CASCADES + 1];
  s[0] = near_depth;
  s[count] = far_depth;
  for (int i = 1; i < count; ++i) {
    const double x = (double)i / count;
    const double uniform = near_depth + (far_depth - near_depth) * x;
    const double logarithmic = near_depth * pow(far_depth / near_depth, x);
    switch (scheme) {
    case VSH_SPLIT_UNIFORM:
      s[i] = uniform;
      break;
    case VSH_SPLIT_LOG:
      s[i] = logarithmic;
      break;
    case VSH_SPLIT_PRACTICAL:
      s[i] = lambda * logarithmic + (1.0 - lambda) * uniform;
      if (capped)
        s[i] = fmin(s[i], s[i - 1] * p->max_ratio);
      break;
    case VSH_SPLIT_EXPLICIT:
      if (!fractions || !(fractions[i - 1] > 0.0 && fractions[i - 1] < 1.0))
        return VSH_CSM_BAD_INPUT;
      s[i] = near_depth + (far_depth - near_depth) * fractions[i - 1];
      break;
    default:
      return VSH_CSM_BAD_INPUT;
    }
  }
  for (int i = 0; i < count; ++i)
    if (!(s[i + 1] > s[i]))
      return VSH_CSM_BAD_INPUT;
  memcpy(out, s, sizeof(double) * (size_t)(count + 1));
  return VSH_CSM_OK;
}
