/* vsh_rt_light.c - directions to lights, spot cones and sample points on a
 * light's area for shadow rays (vsh_raytrace.h). */
#include "vsh_raytrace.h"

#include "vsh_vec3.h"

#include <math.h>
#include <string.h>

static const double Pi = 3.14159265358979323846;

int vsh_rt_light_init(const double homogeneous[4], const double focal[3], double cone_degrees,
                      double radius, double angle, vsh_rt_light *out)
{
  memset(out, 0, sizeof *out);
  out->cos_cone = -2.0;
  out->radius = isfinite(radius) && radius > 0.0 ? radius : 0.0;
  out->angle = isfinite(angle) && angle > 0.0 ? fmin(angle, Pi / 2) : 0.0;
  if (homogeneous[3] == 0.0) {
    out->kind = VSH_RT_DIRECTIONAL;
    if (vsh_vec3_normalize(homogeneous, out->direction) <= 0.0) {
      out->direction[2] = 1.0; /* a light straight above: something finite */
      return VSH_RT_DEGENERATE;
    }
    return VSH_RT_OK;
  }
  for (int k = 0; k < 3; ++k) {
    out->position[k] = homogeneous[k] / homogeneous[3];
  }
  out->kind = VSH_RT_POINT;
  /* VTK's shader treats a positional light with a cone of 90 degrees or
   * more as a point light. */
  if (!(cone_degrees < 90.0)) {
    return VSH_RT_OK;
  }
  double axis[3];
  vsh_vec3_sub(focal, out->position, axis);
  if (vsh_vec3_normalize(axis, out->direction) <= 0.0) {
    out->direction[2] = -1.0;
    return VSH_RT_DEGENERATE;
  }
  out->kind = VSH_RT_SPOT;
  out->cos_cone = cos(fmax(cone_degrees, 0.0) * Pi / 180.0);
  return VSH_RT_OK;
}

int vsh_rt_light_direction(const vsh_rt_light *light, const double point[3], double dir[3],
                           double *distance)
{
  if (light->kind == VSH_RT_DIRECTIONAL) {
    memcpy(dir, light->direction, 3 * sizeof(double));
    *distance = HUGE_VAL;
    return VSH_RT_OK;
  }
  double d[3];
  vsh_vec3_sub(light->position, point, d);
  *distance = vsh_vec3_normalize(d, dir);
  return *distance > 0.0 ? VSH_RT_OK : VSH_RT_DEGENERATE;
}

int vsh_rt_light_in_cone(const vsh_rt_light *light, const double to_light[3])
{
  if (light->kind != VSH_RT_SPOT) {
    return 1;
  }
  return -vsh_vec3_dot(to_light, light->direction) >= light->cos_cone;
}

void vsh_rt_disk_sample(int k, int n, double rotation, double out[2])
{
  if (n <= 1) {
    out[0] = out[1] = 0.0;
    return;
  }
  /* Vogel's spiral: radius sqrt((k + 1/2) / n) is area-uniform, the golden
   * angle spreads consecutive samples evenly. */
  const double golden = Pi * (3.0 - sqrt(5.0));
  const double r = sqrt((k + 0.5) / n);
  const double a = k * golden + rotation;
  out[0] = r * cos(a);
  out[1] = r * sin(a);
}

/* Two unit vectors perpendicular to unit `w` (and to each other). */
static void basis(const double w[3], double u[3], double v[3])
{
  /* Cross with the axis least aligned with w: never parallel. */
  const double ax = fabs(w[0]), ay = fabs(w[1]), az = fabs(w[2]);
  double e[3] = { 0.0, 0.0, 0.0 };
  e[ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2)] = 1.0;
  double c[3];
  vsh_vec3_cross(w, e, c);
  vsh_vec3_normalize(c, u);
  vsh_vec3_cross(w, u, v);
}

int vsh_rt_light_sample(const vsh_rt_light *light, const double point[3], int k, int n,
                        double rotation, double dir[3], double *distance)
{
  double centre[3];
  const int status = vsh_rt_light_direction(light, point, centre, distance);
  /* A hard light's one ray needs no size (no tan per ray). */
  const double size = status != VSH_RT_OK || n <= 1 ? 0.0
                      : light->kind == VSH_RT_DIRECTIONAL ? tan(0.5 * light->angle)
                                                          : light->radius;
  if (size <= 0.0) {
    memcpy(dir, centre, sizeof centre);
    return status;
  }
  double u[3], v[3], disk[2];
  basis(centre, u, v);
  vsh_rt_disk_sample(k, n, rotation, disk);
  if (light->kind == VSH_RT_DIRECTIONAL) {
    /* The sun's disk seen from the point: directions within angle / 2. */
    double d[3];
    for (int c = 0; c < 3; ++c) {
      d[c] = centre[c] + size * (disk[0] * u[c] + disk[1] * v[c]);
    }
    vsh_vec3_normalize(d, dir);
    return VSH_RT_OK;
  }
  /* A disk of `radius` around the light's centre, facing the point. */
  double target[3], d[3];
  for (int c = 0; c < 3; ++c) {
    target[c] = light->position[c] + size * (disk[0] * u[c] + disk[1] * v[c]);
  }
  vsh_vec3_sub(target, point, d);
  *distance = vsh_vec3_normalize(d, dir);
  return *distance > 0.0 ? VSH_RT_OK : VSH_RT_DEGENERATE;
}

double vsh_rt_pixel_rotation(unsigned int x, unsigned int y)
{
  /* A 32-bit integer hash (lowbias32) of the pixel's coordinates. */
  unsigned long h = ((unsigned long)x * 0x9E3779B1UL) ^ ((unsigned long)y * 0x85EBCA77UL);
  h &= 0xFFFFFFFFUL;
  h ^= h >> 16;
  h = (h * 0x7FEB352DUL) & 0xFFFFFFFFUL;
  h ^= h >> 15;
  h = (h * 0x846CA68BUL) & 0xFFFFFFFFUL;
  h ^= h >> 16;
  return 2.0 * Pi * ((double)h / 4294967296.0);
}
