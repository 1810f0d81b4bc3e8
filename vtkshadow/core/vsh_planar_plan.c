/* vsh_planar_plan.c - see vsh_planar_plan.h. */
#include "vsh_planar_plan.h"

#include "vsh_mat4.h"
#include "vsh_planar.h"

#include <math.h>

/* Corner k (0..7) of a box in VTK order, minus origin. */
static void corner(const double b[6], int k, const double origin[3], double out[3])
{
  out[0] = b[k & 1] - origin[0];
  out[1] = b[2 + ((k >> 1) & 1)] - origin[1];
  out[2] = b[4 + ((k >> 2) & 1)] - origin[2];
}

int vsh_planar_receiver_fits(int receivers, int lights)
{
  const long long per_receiver = lights > 1 ? lights : 1;
  return ((long long)receivers + 1) * per_receiver <= VSH_PLANAR_MAX_PAIRS;
}

int vsh_planar_mask_channels(int receivers, int lights)
{
  return (long long)receivers * lights <= 32 ? 1 : 4;
}

void vsh_planar_pair_bits(int bit, unsigned int bits[4])
{
  bits[0] = bits[1] = bits[2] = bits[3] = 0u;
  if (bit >= 0 && bit < VSH_PLANAR_MAX_PAIRS)
    bits[bit / 32] = 1u << (bit % 32);
}

/* The pair (plane, light) oriented and its matrices; 0 when it casts nothing. */
static int plan_pair(const double receiver_plane[4], const double light[4], const double eye[3],
                     vsh_planar_pair *pair)
{
  /* Orient the plane towards the light: its lit side is the light's side. */
  const double side = receiver_plane[0] * light[0] + receiver_plane[1] * light[1] +
                      receiver_plane[2] * light[2] + receiver_plane[3] * light[3];
  for (int k = 0; k < 4; ++k)
    pair->plane[k] = side < 0 ? -receiver_plane[k] : receiver_plane[k];
  return vsh_planar_shadow_matrix_relative(pair->plane, light, eye, pair->shadow) ==
             VSH_PLANAR_OK &&
         vsh_planar_caster_clip_planes_relative(pair->plane, light, eye, pair->clip) ==
             VSH_PLANAR_OK;
}

int vsh_planar_plan_pairs(const double *planes, int receiver_count,
                          const vsh_planar_light *lights, int light_count, const double eye[3],
                          vsh_planar_pair *out, int capacity)
{
  if (receiver_count < 0 || light_count < 0 || capacity < 0 || !eye ||
      (receiver_count > 0 && light_count > 0 && (!planes || !lights)) || (capacity > 0 && !out))
    return -1;
  int count = 0;
  for (int r = 0; r < receiver_count; ++r) {
    for (int l = 0; l < light_count; ++l) {
      const long long bit = (long long)r * light_count + l;
      if (!lights[l].casts || bit >= VSH_PLANAR_MAX_PAIRS || count >= capacity)
        continue;
      vsh_planar_pair *pair = &out[count];
      if (!plan_pair(planes + 4 * r, lights[l].homogeneous, eye, pair))
        continue; /* light on, behind or parallel to the plane: no shadow */
      pair->receiver = r;
      pair->light = l;
      pair->bit = (int)bit;
      ++count;
    }
  }
  return count;
}

int vsh_planar_bounds_in_plane(const double bounds[6], const double plane[4])
{
  const double zero[3] = {0, 0, 0};
  double size = 1e-300;
  for (int a = 0; a < 3; ++a)
    size = fmax(size, bounds[2 * a + 1] - bounds[2 * a]);
  for (int k = 0; k < 8; ++k) {
    double p[3];
    corner(bounds, k, zero, p);
    if (fabs(plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3]) > 1e-6 * size)
      return 0;
  }
  return 1;
}

int vsh_planar_bounds_clipped(const double clip[2][4], const double bounds[6],
                              const double eye[3])
{
  for (int k = 0; k < 8; ++k) {
    double p[3];
    corner(bounds, k, eye, p);
    for (int c = 0; c < 2; ++c) {
      const double *plane = clip[c];
      if (plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3] <= 0.0)
        return 1;
    }
  }
  return 0;
}

int vsh_planar_bounds_culled(const double clip[2][4], const double bounds[6],
                             const double eye[3])
{
  for (int c = 0; c < 2; ++c) {
    const double *plane = clip[c];
    int cut = 0;
    for (int k = 0; k < 8; ++k) {
      double p[3];
      corner(bounds, k, eye, p);
      cut += plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3] <= 0.0;
    }
    if (cut == 8) return 1;
  }
  return 0;
}

void vsh_planar_rect_init(vsh_planar_rect *rect)
{
  rect->ndc[0] = rect->ndc[1] = 1e300;
  rect->ndc[2] = rect->ndc[3] = -1e300;
  rect->full = 0;
}

void vsh_planar_rect_add_bounds(vsh_planar_rect *rect, const double shadow_dc[16],
                                const double bounds[6], const double eye[3])
{
  for (int k = 0; k < 8; ++k) {
    double p[4], q[4];
    corner(bounds, k, eye, p);
    p[3] = 1.0;
    vsh_mat4_transform_point4(shadow_dc, p, q);
    if (!(q[3] > 0.0)) {
      rect->full = 1; /* at or behind the camera: anywhere on screen */
      continue;
    }
    const double x = q[0] / q[3], y = q[1] / q[3];
    rect->ndc[0] = fmin(rect->ndc[0], x);
    rect->ndc[1] = fmin(rect->ndc[1], y);
    rect->ndc[2] = fmax(rect->ndc[2], x);
    rect->ndc[3] = fmax(rect->ndc[3], y);
  }
}

/* A pixel coordinate, clamped to 0..limit in double before it becomes an int
 * (a corner just in front of the camera projects arbitrarily far). */
static int clamp_pixel(double v, int limit)
{
  v = fmax(0.0, fmin(v, (double)limit));
  return (int)v;
}

int vsh_planar_rect_pixels(const vsh_planar_rect *rect, const int size[2], int box[4])
{
  if (rect->full) {
    box[0] = box[1] = 0;
    box[2] = size[0];
    box[3] = size[1];
  } else {
    for (int a = 0; a < 2; ++a) {
      box[a] = clamp_pixel(floor((rect->ndc[a] * 0.5 + 0.5) * size[a]) - 1.0, size[a]);
      box[2 + a] = clamp_pixel(ceil((rect->ndc[2 + a] * 0.5 + 0.5) * size[a]) + 1.0, size[a]);
    }
  }
  return box[2] > box[0] && box[3] > box[1];
}

void vsh_planar_plane_to_view(const double plane[4], const double view[16], const double eye[3],
                              double out[4])
{
  vsh_mat4_transform_direction(view, plane, out);
  out[3] = plane[3] + plane[0] * eye[0] + plane[1] * eye[1] + plane[2] * eye[2];
}
