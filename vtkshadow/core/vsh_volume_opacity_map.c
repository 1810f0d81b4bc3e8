/* vsh_volume_opacity_map.c - the opacity shadow map of volumes
 * (vsh_volume_opacity_map.h). */
#include "vsh_volume_opacity_map.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <math.h>
#include <stddef.h>

/* A point light sees the boxes within this angle of its axis, or the map
 * is not planned (tan 80 degrees): wider, the texels at the rim stretch
 * over more of the boxes than the whole map does at the centre. */
#define VSH_VOLUME_MAP_MAX_TAN 5.671281819617709

/* The 4x4 (affine) of a 3x4 row-major matrix. */
static void affine4(const double m[12], double out[16])
{
  for (int i = 0; i < 12; ++i) {
    out[i] = m[i];
  }
  out[12] = out[13] = out[14] = 0.0;
  out[15] = 1.0;
}

/* The 8 corners of a volume's box in the caller's frame; 0 when it has no
 * box there (an invalid grid, a singular or non-finite matrix). */
static int box_corners(const vsh_volume_map_volume *v, double corners[8][3])
{
  double to_data[16], to_frame[16], lo[3], hi[3];
  if (!vsh_volume_grid_valid(&v->grid)) {
    return 0;
  }
  affine4(v->to_data, to_data);
  if (!vsh_mat4_is_finite(to_data) || !vsh_mat4_inverse(to_data, to_frame)) {
    return 0;
  }
  vsh_volume_grid_box(&v->grid, lo, hi);
  for (int c = 0; c < 8; ++c) {
    const double p[3] = {(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1],
                         (c & 4) ? hi[2] : lo[2]};
    vsh_mat4_transform_point(to_frame, p, corners[c]);
  }
  return 1;
}

/* u and v completing w (unit) into a right-handed orthonormal basis. */
static void basis(const double w[3], double axes[9])
{
  /* The world axis least aligned with w keeps the cross product well
   * conditioned, a light parallel to a face included. */
  const double a[3] = {fabs(w[0]), fabs(w[1]), fabs(w[2])};
  const int k = a[0] <= a[1] && a[0] <= a[2] ? 0 : (a[1] <= a[2] ? 1 : 2);
  double e[3] = {0, 0, 0}, u[3], v[3];
  e[k] = 1.0;
  vsh_vec3_cross(e, w, u);
  vsh_vec3_normalize(u, u);
  vsh_vec3_cross(w, u, v);
  for (int i = 0; i < 3; ++i) {
    axes[i] = u[i];
    axes[3 + i] = v[i];
    axes[6 + i] = w[i];
  }
}

/* Every usable volume's corners (up to count * 8) into `pts`; the number
 * of points. */
static int all_corners(const vsh_volume_map_volume *volumes, int count, double (*pts)[3])
{
  int n = 0;
  for (int i = 0; i < count; ++i) {
    if (box_corners(&volumes[i], (double (*)[3])pts[n])) {
      n += 8;
    }
  }
  return n;
}

/* The window of the projected points (s, t) with a texel of margin. */
static int window(vsh_volume_map_plan *out, const double lo[2], const double hi[2])
{
  for (int a = 0; a < 2; ++a) {
    const double extent = hi[a] - lo[a];
    if (!isfinite(extent) || !(extent > 0.0)) {
      return VSH_VOLUME_MAP_EMPTY;
    }
    const double pad = extent / (out->size[a] - 2);
    out->lo[a] = lo[a] - pad;
    out->hi[a] = hi[a] + pad;
  }
  return VSH_VOLUME_MAP_OK;
}

/* Directional: the plane through the nearest corner, perpendicular to the
 * light's travel, and the corners' (u, v) extent on it. */
static int plan_directional(const double (*pts)[3], int n, const double towards[3],
                            vsh_volume_map_plan *out)
{
  double w[3], lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, near = INFINITY;
  vsh_vec3_scale(towards, -1.0, w);
  if (vsh_vec3_normalize(w, w) == 0.0) {
    return VSH_VOLUME_MAP_BAD_LIGHT;
  }
  basis(w, out->axes);
  for (int c = 0; c < n; ++c) {
    for (int a = 0; a < 2; ++a) {
      const double s = vsh_vec3_dot(out->axes + 3 * a, pts[c]);
      lo[a] = s < lo[a] ? s : lo[a];
      hi[a] = s > hi[a] ? s : hi[a];
    }
    const double d = vsh_vec3_dot(w, pts[c]);
    near = d < near ? d : near;
  }
  vsh_vec3_scale(w, near, out->eye); /* (u, v) of the eye are 0 */
  return window(out, lo, hi);
}

/* Point light: the axis towards the corners' centre, and the corners'
 * (u / w, v / w) extent. */
static int plan_perspective(const double (*pts)[3], int n, const double light[3],
                            vsh_volume_map_plan *out)
{
  double centre[3] = {0, 0, 0}, w[3], lo[2] = {INFINITY, INFINITY};
  double hi[2] = {-INFINITY, -INFINITY};
  for (int c = 0; c < n; ++c) {
    vsh_vec3_add(centre, pts[c], centre);
  }
  vsh_vec3_scale(centre, 1.0 / n, centre);
  vsh_vec3_sub(centre, light, w);
  if (vsh_vec3_normalize(w, w) == 0.0) {
    return VSH_VOLUME_MAP_INSIDE; /* the light at the boxes' centre */
  }
  basis(w, out->axes);
  for (int c = 0; c < n; ++c) {
    double d[3];
    vsh_vec3_sub(pts[c], light, d);
    const double along = vsh_vec3_dot(w, d);
    for (int a = 0; a < 2; ++a) {
      /* A corner at or behind the light, or too far aside: the light is
       * inside a box, on it, or about to be. */
      const double s = vsh_vec3_dot(out->axes + 3 * a, d) / along;
      if (!(along > 0.0) || !(fabs(s) <= VSH_VOLUME_MAP_MAX_TAN)) {
        return VSH_VOLUME_MAP_INSIDE;
      }
      lo[a] = s < lo[a] ? s : lo[a];
      hi[a] = s > hi[a] ? s : hi[a];
    }
  }
  for (int i = 0; i < 3; ++i) {
    out->eye[i] = light[i];
  }
  return window(out, lo, hi);
}

/* At most this many volumes are planned over (their corners on the stack). */
#define VSH_VOLUME_MAP_MAX_VOLUMES 64

int vsh_volume_opacity_map_plan(const vsh_volume_map_volume *volumes, int count,
                                const double light[4], int size, vsh_volume_map_plan *out)
{
  double pts[VSH_VOLUME_MAP_MAX_VOLUMES * 8][3];
  *out = (vsh_volume_map_plan){0};
  out->size[0] = out->size[1] = size < 3 ? 3 : size;
  out->perspective = light && light[3] != 0.0;
  count = count < VSH_VOLUME_MAP_MAX_VOLUMES ? count : VSH_VOLUME_MAP_MAX_VOLUMES;
  const int n = volumes && count > 0 ? all_corners(volumes, count, pts) : 0;
  if (!light || !vsh_vec3_is_finite(light) || !isfinite(light[3])) {
    out->status = VSH_VOLUME_MAP_BAD_LIGHT;
  } else if (n == 0) {
    out->status = VSH_VOLUME_MAP_EMPTY;
  } else if (out->perspective) {
    /* (x, y, z, w) with w != 1 is the point (x, y, z) / w. */
    const double p[3] = {light[0] / light[3], light[1] / light[3], light[2] / light[3]};
    out->status = plan_perspective((const double (*)[3])pts, n, p, out);
  } else {
    out->status = plan_directional((const double (*)[3])pts, n, light, out);
  }
  return out->status;
}

void vsh_volume_opacity_map_texel_ray(const vsh_volume_map_plan *plan, int i, int j, double o[3],
                                      double d[3])
{
  const double s = plan->lo[0] + (i + 0.5) * (plan->hi[0] - plan->lo[0]) / plan->size[0];
  const double t = plan->lo[1] + (j + 0.5) * (plan->hi[1] - plan->lo[1]) / plan->size[1];
  const double *u = plan->axes, *v = plan->axes + 3, *w = plan->axes + 6;
  for (int k = 0; k < 3; ++k) {
    o[k] = plan->perspective ? plan->eye[k] : plan->eye[k] + s * u[k] + t * v[k];
    d[k] = plan->perspective ? s * u[k] + t * v[k] + w[k] : w[k];
  }
  vsh_vec3_normalize(d, d);
}

/* One ray through every volume: (T, entry, exit, 0) into texel; the
 * samples taken. */
static int texel_fill(const vsh_volume_map_volume *volumes, int count, double cutoff,
                      const double o[3], const double d[3], float texel[4])
{
  double kept = 1.0, entry = VSH_VOLUME_MAP_NONE, leave = -VSH_VOLUME_MAP_NONE;
  int samples = 0;
  for (int i = 0; i < count && kept > 0.0; ++i) {
    const vsh_volume_map_volume *v = &volumes[i];
    if (!vsh_volume_grid_valid(&v->grid)) {
      continue;
    }
    vsh_volume_ray ray = {{0, 0, 0}, {0, 0, 0}, 0.0, INFINITY};
    for (int r = 0; r < 3; ++r) {
      const double *row = v->to_data + 4 * r;
      ray.origin[r] = row[0] * o[0] + row[1] * o[1] + row[2] * o[2] + row[3];
      ray.direction[r] = row[0] * d[0] + row[1] * d[1] + row[2] * d[2];
    }
    double lo[3], hi[3], t0 = 0.0, t1 = INFINITY;
    vsh_volume_grid_box(&v->grid, lo, hi);
    if (!vsh_volume_clip_ray(lo, hi, ray.origin, ray.direction, &t0, &t1) || !isfinite(t1)) {
      continue;
    }
    entry = t0 < entry ? t0 : entry;
    leave = t1 > leave ? t1 : leave;
    /* The march stops where this volume takes the ray under the cutoff. */
    const vsh_volume_march_input in = {&v->grid, v->unit, cutoff > 0.0 ? cutoff / kept : 0.0};
    int taken = 0;
    kept *= vsh_volume_march(&in, &ray, v->sample, v->user, &taken);
    samples += taken;
  }
  texel[0] = (float)(kept < cutoff ? 0.0 : kept);
  texel[1] = (float)entry;
  texel[2] = (float)(leave < entry ? entry : leave);
  texel[3] = 0.0f;
  return samples;
}

long long vsh_volume_opacity_map_fill(const vsh_volume_map_plan *plan,
                                      const vsh_volume_map_volume *volumes, int count,
                                      double cutoff, int row0, int row1, float *texels)
{
  long long samples = 0;
  if (!plan || !texels || plan->status != VSH_VOLUME_MAP_OK) {
    return 0;
  }
  row0 = row0 < 0 ? 0 : row0;
  row1 = row1 > plan->size[1] ? plan->size[1] : row1;
  for (int j = row0; j < row1; ++j) {
    for (int i = 0; i < plan->size[0]; ++i) {
      double o[3], d[3];
      float *texel = texels + 4 * ((size_t)j * (size_t)plan->size[0] + (size_t)i);
      vsh_volume_opacity_map_texel_ray(plan, i, j, o, d);
      samples += texel_fill(volumes, volumes ? count : 0, cutoff, o, d, texel);
    }
  }
  return samples;
}

double vsh_volume_opacity_map_kept(const float texel[4], double d)
{
  if (!(d > texel[1])) {
    return 1.0; /* before the entry (or NaN) */
  }
  if (d >= texel[2]) {
    return texel[0];
  }
  return pow(texel[0], (d - texel[1]) / ((double)texel[2] - texel[1]));
}

int vsh_volume_opacity_map_view_matrix(const vsh_volume_map_plan *plan,
                                       const double view_rotation[16], const double eye[3],
                                       double out[16])
{
  vsh_mat4_identity(out);
  if (!plan || plan->status != VSH_VOLUME_MAP_OK) {
    return 0;
  }
  /* frame = R^T view + eye, then (u, v, w) = axes (frame - plan eye). */
  double offset[3];
  vsh_vec3_sub(eye, plan->eye, offset);
  for (int r = 0; r < 3; ++r) {
    const double *a = plan->axes + 3 * r;
    for (int c = 0; c < 3; ++c) {
      /* (A R^T)[r][c] = sum_k A[r][k] R[c][k] */
      out[4 * r + c] = a[0] * view_rotation[4 * c] + a[1] * view_rotation[4 * c + 1] +
                       a[2] * view_rotation[4 * c + 2];
    }
    out[4 * r + 3] = vsh_vec3_dot(a, offset);
  }
  return 1;
}

void vsh_volume_opacity_map_light(const double homogeneous[4], const double origin[3],
                                  double out[4]) {
  const int positional = homogeneous[3] != 0.0;
  for (int a = 0; a < 3; ++a)
    out[a] = positional ? homogeneous[a] / homogeneous[3] - origin[a] : homogeneous[a];
  out[3] = positional ? 1.0 : 0.0;
}
