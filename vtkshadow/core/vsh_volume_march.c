/* vsh_volume_march.c - a shadow ray's transmittance through a volume
 * (vsh_volume_march.h). */
#include "vsh_volume_march.h"

#include <math.h>
#include <stddef.h>

/* More steps than this per crossing and the steps grow instead: a bound
 * on one ray's cost whatever the matrix scales (a 4096^3 grid's diagonal
 * at half its spacing is about 14,200 steps). */
#define VSH_VOLUME_MAX_STEPS 65536

int vsh_volume_grid_valid(const vsh_volume_grid *g)
{
  if (!g) {
    return 0;
  }
  for (int a = 0; a < 3; ++a) {
    if (!isfinite(g->origin[a]) || !isfinite(g->spacing[a]) || !(g->spacing[a] > 0.0) ||
        g->dims[a] < 2) {
      return 0;
    }
  }
  return 1;
}

void vsh_volume_grid_box(const vsh_volume_grid *g, double lo[3], double hi[3])
{
  for (int a = 0; a < 3; ++a) {
    lo[a] = g->origin[a];
    hi[a] = g->origin[a] + (g->dims[a] - 1) * g->spacing[a];
  }
}

double vsh_volume_grid_step(const vsh_volume_grid *g)
{
  if (!vsh_volume_grid_valid(g)) {
    return 0.0;
  }
  double smallest = g->spacing[0];
  for (int a = 1; a < 3; ++a) {
    smallest = g->spacing[a] < smallest ? g->spacing[a] : smallest;
  }
  return 0.5 * smallest;
}

int vsh_volume_clip_ray(const double lo[3], const double hi[3], const double origin[3],
                        const double dir[3], double *t0, double *t1)
{
  double a = *t0, b = *t1;
  if (a != a || b != b) {
    return 0;
  }
  for (int k = 0; k < 3; ++k) {
    if (lo[k] != lo[k] || hi[k] != hi[k] || origin[k] != origin[k] || dir[k] != dir[k]) {
      return 0;
    }
    if (dir[k] == 0.0) {
      /* Parallel to this slab pair: inside it for every t, or never. */
      if (origin[k] < lo[k] || origin[k] > hi[k]) {
        return 0;
      }
      continue;
    }
    double near = (lo[k] - origin[k]) / dir[k], far = (hi[k] - origin[k]) / dir[k];
    if (near > far) {
      const double swap = near;
      near = far;
      far = swap;
    }
    a = near > a ? near : a;
    b = far < b ? far : b;
  }
  if (!(b > a)) {
    return 0;
  }
  *t0 = a;
  *t1 = b;
  return 1;
}

/* The cell holding fractional index f on an axis of n >= 2 points, and
 * the weight of its upper point. */
static size_t cell(double f, int n, double *w)
{
  f = f < 0.0 ? 0.0 : (f > n - 1 ? n - 1 : f);
  size_t i = (size_t)f;
  if (i >= (size_t)(n - 1)) {
    i = (size_t)(n - 2);
  }
  *w = f - (double)i;
  return i;
}

double vsh_volume_trilinear(const vsh_volume_grid *g, const float *values, const double p[3])
{
  if (!vsh_volume_grid_valid(g) || !values || !isfinite(p[0]) || !isfinite(p[1]) ||
      !isfinite(p[2])) {
    return NAN;
  }
  double w[3];
  size_t i[3];
  for (int a = 0; a < 3; ++a) {
    i[a] = cell((p[a] - g->origin[a]) / g->spacing[a], g->dims[a], &w[a]);
  }
  const size_t nx = (size_t)g->dims[0], nxy = nx * (size_t)g->dims[1];
  const float *c = values + i[0] + nx * i[1] + nxy * i[2];
  /* Along x on the cell's four x edges, then y, then z. */
  const double x00 = c[0] + w[0] * (c[1] - c[0]);
  const double x10 = c[nx] + w[0] * (c[nx + 1] - c[nx]);
  const double x01 = c[nxy] + w[0] * (c[nxy + 1] - c[nxy]);
  const double x11 = c[nxy + nx] + w[0] * (c[nxy + nx + 1] - c[nxy + nx]);
  const double y0 = x00 + w[1] * (x10 - x00), y1 = x01 + w[1] * (x11 - x01);
  return y0 + w[2] * (y1 - y0);
}

double vsh_volume_table(const float *table, int n, double lo, double hi, int clamp, double s)
{
  if (!table || n < 1 || s != s) {
    return 0.0;
  }
  if (s < lo || s > hi || !(hi > lo)) {
    /* Outside the table (or a table of one scalar): its nearer end. */
    if (!clamp && (s < lo || s > hi)) {
      return 0.0;
    }
    return s <= lo ? table[0] : table[n - 1];
  }
  if (n == 1) {
    return table[0];
  }
  const double f = (s - lo) / (hi - lo) * (n - 1);
  size_t i = (size_t)f;
  if (i >= (size_t)(n - 1)) {
    i = (size_t)(n - 2);
  }
  const double w = f - (double)i;
  return table[i] + w * (table[i + 1] - table[i]);
}

/* -ln(1 - alpha), alpha clamped to [0, 1], NaN opaque: the optical depth
 * of one unit distance. */
static double unit_depth(double alpha)
{
  if (!(alpha < 1.0)) {
    return INFINITY; /* 1 and above, and NaN */
  }
  return alpha > 0.0 ? -log1p(-alpha) : 0.0;
}

static double usable_unit(double unit) { return isfinite(unit) && unit > 0.0 ? unit : 1.0; }

double vsh_volume_kept(double alpha, double length, double unit)
{
  if (!isfinite(length) || !(length >= 0.0)) {
    return 1.0;
  }
  const double depth = unit_depth(alpha) * (length / usable_unit(unit));
  return depth == depth ? exp(-depth) : 1.0; /* inf * 0: a step of no length */
}

/* The march's steps over [t0, t1]: their number, each of world length *ds,
 * as many as the data step asks (a data length of step per step), at
 * least 1 and at most VSH_VOLUME_MAX_STEPS. */
static int step_count(double t0, double t1, double data_per_t, double step, double *ds)
{
  const double n = ceil((t1 - t0) * data_per_t / step);
  const int steps = n < 1.0 ? 1 : (n > VSH_VOLUME_MAX_STEPS ? VSH_VOLUME_MAX_STEPS : (int)n);
  *ds = (t1 - t0) / steps;
  return steps;
}

double vsh_volume_march(const vsh_volume_march_input *in, const vsh_volume_ray *r,
                        vsh_volume_sampler sample, void *user, int *samples)
{
  if (samples) {
    *samples = 0;
  }
  const double step = in && r && sample ? vsh_volume_grid_step(in->grid) : 0.0;
  if (!(step > 0.0)) {
    return 1.0;
  }
  const double *d = r->direction;
  const double data_per_t = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  double lo[3], hi[3], t0 = r->t_min, t1 = r->t_max;
  vsh_volume_grid_box(in->grid, lo, hi);
  if (!(data_per_t > 0.0) || !isfinite(data_per_t) ||
      !vsh_volume_clip_ray(lo, hi, r->origin, d, &t0, &t1) || !isfinite(t1 - t0)) {
    return 1.0;
  }
  double ds;
  const int steps = step_count(t0, t1, data_per_t, step, &ds);
  /* The depth of every step summed in unit depths; the ray is blocked once
   * the depth's transmittance falls under the cutoff. */
  const double per_step = ds / usable_unit(in->unit);
  const double limit = in->cutoff > 0.0 ? -log(in->cutoff) : INFINITY;
  double depth = 0.0;
  for (int s = 0; s < steps; ++s) {
    const double t = t0 + (s + 0.5) * ds;
    double p[3];
    for (int a = 0; a < 3; ++a) {
      p[a] = r->origin[a] + t * d[a];
      p[a] = p[a] < lo[a] ? lo[a] : (p[a] > hi[a] ? hi[a] : p[a]); /* rounding */
    }
    depth += unit_depth(sample(user, p)) * per_step;
    if (samples) {
      ++*samples;
    }
    if (depth > limit) {
      return 0.0;
    }
  }
  return exp(-depth);
}
