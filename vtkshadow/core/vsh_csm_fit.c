/* vsh_csm_fit.c - where each shadow map looks: directional cascades fitted
 * to view slices, perspective maps for spot lights and cube faces. */
#include "vsh_csm.h"

#include "vsh_mat4.h"
#include "vsh_vec3.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define VSH_PI 3.14159265358979323846

/* A right-handed basis whose z points towards the light (against
 * `travel`), chosen from the world axes only, so it never depends on the
 * camera: the texel grid stays put while the camera turns. */
static int light_basis(const double travel[3], double x[3], double y[3], double z[3])
{
  double t[3];
  if (!travel || !vsh_vec3_is_finite(travel) || vsh_vec3_normalize(travel, t) == 0.0)
    return 1;
  vsh_vec3_scale(t, -1.0, z);
  /* Reference axis: the world axis least aligned with z. */
  double ref[3] = {0, 0, 0};
  const double ax = fabs(z[0]), ay = fabs(z[1]), az = fabs(z[2]);
  ref[(ax <= ay && ax <= az) ? 0 : (ay <= az ? 1 : 2)] = 1.0;
  double c[3];
  vsh_vec3_cross(ref, z, c);
  vsh_vec3_normalize(c, x);
  vsh_vec3_cross(z, x, y);
  return 0;
}

/* Light-space coordinates (x, y, height towards the light) of the 8 corners
 * of a box given relative to the origin. */
static void box_in_light(const vsh_bounds *b, const double origin[3], const double x[3],
                         const double y[3], const double z[3], double out[8][3])
{
  double corners[8][3];
  vsh_bounds_corners(b, corners);
  for (int i = 0; i < 8; ++i) {
    double rel[3];
    vsh_vec3_sub(corners[i], origin, rel);
    out[i][0] = vsh_vec3_dot(rel, x);
    out[i][1] = vsh_vec3_dot(rel, y);
    out[i][2] = vsh_vec3_dot(rel, z);
  }
}

/* Orthographic world_to_clip for the light-space box [x0,x1] x [y0,y1] and
 * heights [h_far, h_near] (h_near nearest the light maps to depth -1). */
static void ortho(const double x[3], const double y[3], const double z[3], double x0, double x1,
                  double y0, double y1, double h_far, double h_near, double out[16])
{
  const double sx = 2.0 / (x1 - x0), sy = 2.0 / (y1 - y0), sz = 2.0 / (h_near - h_far);
  memset(out, 0, sizeof(double) * 16);
  for (int k = 0; k < 3; ++k) {
    out[0 + k] = sx * x[k];
    out[4 + k] = sy * y[k];
    out[8 + k] = -sz * z[k];
  }
  out[3] = -sx * 0.5 * (x0 + x1);
  out[7] = -sy * 0.5 * (y0 + y1);
  out[11] = sz * 0.5 * (h_near + h_far);
  out[15] = 1.0;
}

/* The radius, rounded up to a geometric grid of 2^(1/8) steps, so that
 * small changes of the split depths do not resize the map (which would
 * make every shadow edge swim). */
static double quantize_up(double v)
{
  return exp2(ceil(8.0 * log2(v) - 1e-9) / 8.0);
}

/* A directional map's box in light space: x and y ranges, and the heights
 * (towards the light) of what it must hold. */
typedef struct light_box {
  double x0, x1, y0, y1;
  double h_lo, h_hi;
} light_box;

/* The light-space box around the view slice's 8 corners (camera-relative;
 * r, u, f the camera basis, t the tangent of its half angle). */
static light_box slice_box(const vsh_csm_directional_params *p, const double r[3],
                           const double u[3], const double f[3], double t,
                           const double lx[3], const double ly[3], const double lz[3])
{
  double pts[8][3];
  for (int i = 0; i < 8; ++i) {
    const double d = (i & 4) ? p->slice_far : p->slice_near;
    const double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
    double q[3];
    for (int k = 0; k < 3; ++k)
      q[k] = d * (f[k] + sx * t * p->aspect * r[k] + sy * t * u[k]);
    pts[i][0] = vsh_vec3_dot(q, lx);
    pts[i][1] = vsh_vec3_dot(q, ly);
    pts[i][2] = vsh_vec3_dot(q, lz);
  }
  light_box b = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (int i = 0; i < 8; ++i) {
    b.x0 = fmin(b.x0, pts[i][0]);
    b.x1 = fmax(b.x1, pts[i][0]);
    b.y0 = fmin(b.y0, pts[i][1]);
    b.y1 = fmax(b.y1, pts[i][1]);
    b.h_lo = fmin(b.h_lo, pts[i][2]);
    b.h_hi = fmax(b.h_hi, pts[i][2]);
  }
  return b;
}

/* Receivers clip the slice: shadows fall nowhere else. Returns 1 when they
 * do not overlap it. In stable mode only the floor of the heights moves
 * (the size must not depend on where the receivers are). */
static int clip_to_receivers(const vsh_bounds *receivers, const double origin[3],
                             const double lx[3], const double ly[3], const double lz[3],
                             int stable, int resolution, light_box *b)
{
  double rb[8][3];
  box_in_light(receivers, origin, lx, ly, lz, rb);
  double rx0 = INFINITY, rx1 = -INFINITY, ry0 = INFINITY, ry1 = -INFINITY, rh0 = INFINITY;
  double rh1 = -INFINITY;
  for (int i = 0; i < 8; ++i) {
    rx0 = fmin(rx0, rb[i][0]);
    rx1 = fmax(rx1, rb[i][0]);
    ry0 = fmin(ry0, rb[i][1]);
    ry1 = fmax(ry1, rb[i][1]);
    rh0 = fmin(rh0, rb[i][2]);
    rh1 = fmax(rh1, rb[i][2]);
  }
  if (rx0 > b->x1 || rx1 < b->x0 || ry0 > b->y1 || ry1 < b->y0 || rh0 > b->h_hi ||
      rh1 < b->h_lo)
    return 1;
  if (!stable) {
    /* Zero-volume receivers (a point, a segment along a light-space axis)
     * leave a zero-width range: keep at least one texel of the unclipped
     * fit around it so the map stays valid. */
    const double min_width = fmax(b->x1 - b->x0, b->y1 - b->y0) / resolution;
    b->x0 = fmax(b->x0, rx0);
    b->x1 = fmin(b->x1, rx1);
    b->y0 = fmax(b->y0, ry0);
    b->y1 = fmin(b->y1, ry1);
    if (b->x1 - b->x0 < min_width) {
      const double c = 0.5 * (b->x0 + b->x1);
      b->x0 = c - 0.5 * min_width;
      b->x1 = c + 0.5 * min_width;
    }
    if (b->y1 - b->y0 < min_width) {
      const double c = 0.5 * (b->y0 + b->y1);
      b->y0 = c - 0.5 * min_width;
      b->y1 = c + 0.5 * min_width;
    }
  }
  b->h_lo = fmax(b->h_lo, rh0);
  return 0;
}

/* The map's near plane: the highest caster (casters outside the view still
 * cast into it), not the slice's top, which may reach far into empty sky
 * and waste depth precision. */
static double caster_top(const vsh_bounds *casters, const double origin[3], const double lx[3],
                         const double ly[3], const double lz[3], const light_box *b)
{
  if (!casters || vsh_bounds_is_empty(casters))
    return b->h_hi;
  double cb[8][3];
  box_in_light(casters, origin, lx, ly, lz, cb);
  double h_near = -INFINITY;
  for (int i = 0; i < 8; ++i)
    h_near = fmax(h_near, cb[i][2]);
  return fmax(h_near, b->h_lo);
}

/* Stable mode: a rotation-invariant size - the sphere around the slice's
 * corners, with its centre on the view axis, depends only on depths, angle
 * and aspect - and a centre snapped to whole texels of a grid anchored at
 * the world origin. Returns the texel size. */
static double stable_square(const vsh_csm_directional_params *p, const double f[3], double t,
                            const double lx[3], const double ly[3], light_box *b)
{
  const double *origin = p->camera->position;
  const int resolution = p->resolution;
  const double mid = 0.5 * (p->slice_near + p->slice_far);
  const double half = 0.5 * (p->slice_far - p->slice_near);
  const double radius = quantize_up(
      sqrt(half * half + p->slice_far * p->slice_far * t * t * (1.0 + p->aspect * p->aspect)));
  double c[3], center[3];
  vsh_vec3_scale(f, mid, c);
  center[0] = vsh_vec3_dot(c, lx);
  center[1] = vsh_vec3_dot(c, ly);
  /* Absolute light coordinates in double, snapped, then back. Snapping
   * moves the centre by up to half a texel, so the map is half a texel
   * wider than the sphere on each side: res texels of 2 radius / (res - 1).
   * (A one-texel map cannot be snapped and still cover the slice.) */
  const double texel = resolution > 1 ? 2.0 * radius / (resolution - 1) : 2.0 * radius;
  const double half_width = 0.5 * texel * resolution;
  for (int k = 0; k < 2 && resolution > 1; ++k) {
    const double *axis = k == 0 ? lx : ly;
    const double anchor = vsh_vec3_dot(origin, axis);
    const double absolute = center[k] + anchor;
    center[k] = floor(absolute / texel + 0.5) * texel - anchor;
  }
  b->x0 = center[0] - half_width;
  b->x1 = center[0] + half_width;
  b->y0 = center[1] - half_width;
  b->y1 = center[1] + half_width;
  return texel;
}

/* The orthographic view of box b with heights [h_lo, h_near]. */
static void write_directional(const double lx[3], const double ly[3], const double lz[3],
                              const light_box *b, double h_near, double texel_world,
                              vsh_shadow_view *out)
{
  /* The depth range's floor (casters all below the receivers leave h_near
   * == h_lo) is relative to the map's width too: a range of 1e-12 would let
   * rounding of the heights alone push receivers outside [-1, 1]. */
  const double extent = fmax(h_near - b->h_lo, fmax(1e-12 * fmax(fabs(h_near), 1.0),
                                                    1e-6 * fmax(b->x1 - b->x0, b->y1 - b->y0)));
  /* A little depth margin so geometry exactly on the range is kept. */
  const double margin = 1e-3 * extent;
  ortho(lx, ly, lz, b->x0, b->x1, b->y0, b->y1, b->h_lo - margin, b->h_lo + extent + margin,
        out->world_to_clip);
  out->texel_world = texel_world;
  out->perspective = 0;
  out->depth_extent = extent + 2.0 * margin;
  out->near_far[0] = 0.0;
  out->near_far[1] = out->depth_extent;
}

static int directional_input_ok(const vsh_csm_directional_params *p, const vsh_shadow_view *out)
{
  const vsh_camera *camera = p->camera;
  const vsh_bounds *receivers = p->receivers, *casters = p->casters;
  return camera && out && p->aspect > 0.0 && p->slice_near > 0.0 &&
         p->slice_far > p->slice_near && isfinite(p->slice_far) && p->resolution >= 1 &&
         camera->view_angle > 0.0 && camera->view_angle < 180.0 && isfinite(p->aspect) &&
         !(receivers && !vsh_bounds_is_empty(receivers) && !vsh_bounds_is_finite(receivers)) &&
         !(casters && !vsh_bounds_is_empty(casters) && !vsh_bounds_is_finite(casters));
}

vsh_csm_status vsh_csm_fit_directional(const vsh_csm_directional_params *p,
                                       vsh_shadow_view *out)
{
  double r[3], u[3], f[3], lx[3], ly[3], lz[3];
  if (!p || !directional_input_ok(p, out) || vsh_camera_basis(p->camera, r, u, f) != 0 ||
      light_basis(p->light_direction, lx, ly, lz) != 0)
    return VSH_CSM_BAD_INPUT;
  const double *origin = p->camera->position;
  const double t = tan(p->camera->view_angle * 0.5 * VSH_PI / 180.0);
  light_box b = slice_box(p, r, u, f, t, lx, ly, lz);
  if (p->receivers && !vsh_bounds_is_empty(p->receivers) &&
      clip_to_receivers(p->receivers, origin, lx, ly, lz, p->stable, p->resolution, &b) != 0)
    return VSH_CSM_EMPTY;
  const double h_near = caster_top(p->casters, origin, lx, ly, lz, &b);
  /* Stable: exactly the texel the centre was snapped to (x1 - x0 carries the
   * rounding of the centre's coordinate). */
  const double stable_texel = p->stable ? stable_square(p, f, t, lx, ly, &b) : 0.0;
  if (!(b.x1 > b.x0) || !(b.y1 > b.y0))
    return VSH_CSM_EMPTY;
  write_directional(lx, ly, lz, &b, h_near,
                    p->stable ? stable_texel : fmax(b.x1 - b.x0, b.y1 - b.y0) / p->resolution,
                    out);
  return VSH_CSM_OK;
}

vsh_csm_status vsh_csm_fit_perspective(const vsh_csm_perspective_params *p,
                                       vsh_shadow_view *out)
{
  if (!p)
    return VSH_CSM_BAD_INPUT;
  const double *position = p->position, *direction = p->direction, *origin = p->origin;
  const double half_angle_deg = p->half_angle_deg;
  const vsh_bounds *bounds = p->bounds;
  const int resolution = p->resolution;
  double z[3], x[3], y[3], d[3];
  if (!position || !direction || !bounds || !origin || !out || resolution < 1 ||
      !(half_angle_deg > 0.0 && half_angle_deg < 90.0) || !vsh_vec3_is_finite(position) ||
      !vsh_vec3_is_finite(origin) ||
      vsh_bounds_is_empty(bounds) || !vsh_bounds_is_finite(bounds) ||
      !vsh_vec3_is_finite(direction) || vsh_vec3_normalize(direction, d) == 0.0)
    return VSH_CSM_BAD_INPUT;
  /* View basis looking along d (z towards the viewer, as OpenGL). */
  if (light_basis(d, x, y, z) != 0)
    return VSH_CSM_BAD_INPUT;
  /* Depth range along d of the bounds, relative to the light. */
  double corners[8][3], dmin = INFINITY, dmax = -INFINITY;
  vsh_bounds_corners(bounds, corners);
  for (int i = 0; i < 8; ++i) {
    double rel[3];
    vsh_vec3_sub(corners[i], position, rel);
    const double depth = vsh_vec3_dot(rel, d);
    dmin = fmin(dmin, depth);
    dmax = fmax(dmax, depth);
  }
  if (!(dmax > 0.0))
    return VSH_CSM_EMPTY;
  /* Near: the nearest bounds depth, but never so close that depth precision
   * collapses (a 24-bit map keeps far/near <= 1e4 usable). */
  const double far_d = dmax * 1.001;
  const double near_d = fmax(dmin * 0.999, far_d * 1e-4);
  const double cot = 1.0 / tan(half_angle_deg * VSH_PI / 180.0);
  /* view (camera-relative world -> light view): rows x, y, z; eye at
   * position - origin. */
  double view[16], proj[16], eye[3];
  vsh_vec3_sub(position, origin, eye);
  memset(view, 0, sizeof view);
  for (int k = 0; k < 3; ++k) {
    view[0 + k] = x[k];
    view[4 + k] = y[k];
    view[8 + k] = z[k];
  }
  view[3] = -vsh_vec3_dot(x, eye);
  view[7] = -vsh_vec3_dot(y, eye);
  view[11] = -vsh_vec3_dot(z, eye);
  view[15] = 1.0;
  memset(proj, 0, sizeof proj);
  proj[0] = cot;
  proj[5] = cot;
  out->perspective = 1;
  out->near_far[0] = near_d;
  out->near_far[1] = far_d;
  double terms[2];
  vsh_csm_perspective_depth_terms(out, terms);
  proj[10] = terms[0];
  proj[11] = terms[1];
  proj[14] = -1.0;
  vsh_mat4_multiply(proj, view, out->world_to_clip);
  out->texel_world = 2.0 / (cot * resolution); /* at distance 1 */
  out->depth_extent = far_d - near_d;
  return VSH_CSM_OK;
}

void vsh_csm_perspective_depth_terms(const vsh_shadow_view *view, double out[2])
{
  out[0] = out[1] = 0.0;
  if (!view || !view->perspective)
    return;
  const double n = view->near_far[0], f = view->near_far[1];
  if (!(f > n) || !isfinite(n) || !isfinite(f))
    return;
  out[0] = -(f + n) / (f - n);
  out[1] = -2.0 * f * n / (f - n);
}

void vsh_csm_cube_face_direction(int face, double out[3])
{
  out[0] = out[1] = out[2] = 0.0;
  if (face < 0 || face > 5)
    face = 0;
  out[face / 2] = (face % 2) ? -1.0 : 1.0;
}
