/* vsh_rt_weight.c - N.L-weighted visibility of a light with a size
 * (vsh_rt_weight.h). */
#include "vsh_rt_weight.h"

#include <math.h>

double vsh_rt_sample_weight(const double normal[3], const double dir[3])
{
  if (!normal || !dir) {
    return 1.0;
  }
  const double n2 = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
  const double d = normal[0] * dir[0] + normal[1] * dir[1] + normal[2] * dir[2];
  if (!(n2 > 0.0) || !isfinite(n2) || !isfinite(d)) {
    return 1.0;
  }
  return d > 0.0 ? d / sqrt(n2) : 0.0;
}

static double clamp01(double x)
{
  return x == x ? (x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x)) : 0.0;
}

static double usable_weight(double weight)
{
  return isfinite(weight) && weight > 0.0 ? weight : 0.0;
}

/* The scalar part of one ray that let `t` (clamped) of its light through. */
static void add_scalar(vsh_rt_visibility *v, double w, double t)
{
  ++v->traced;
  v->weight += w;
  if (t <= 0.0) {
    ++v->blocked;
  } else if (t >= 1.0) {
    v->free_weight += w;
  } else {
    ++v->partial;
    v->free_weight += w * t;
    v->partial_loss += 1.0 - t;
  }
}

void vsh_rt_visibility_add(vsh_rt_visibility *v, double weight, int blocked)
{
  vsh_rt_visibility_add_transmitted(v, weight, blocked ? 0.0 : 1.0);
}

void vsh_rt_visibility_add_transmitted(vsh_rt_visibility *v, double weight, double transmitted)
{
  const double grey[3] = { transmitted, transmitted, transmitted };
  vsh_rt_visibility_add_coloured(v, weight, grey);
}

void vsh_rt_visibility_add_coloured(vsh_rt_visibility *v, double weight,
                                    const double transmitted[3])
{
  const double w = usable_weight(weight);
  double largest = 0.0, smallest = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double t = clamp01(transmitted[k]);
    v->channel_weight[k] += w * t;
    largest = t > largest ? t : largest;
    smallest = t < smallest ? t : smallest;
  }
  add_scalar(v, w, largest);
  /* Free in its largest channel but tinted: still a partial ray for the
   * adaptive batches (its neighbours are not all alike). */
  if (largest >= 1.0 && smallest < 1.0) {
    ++v->partial;
  }
}

void vsh_rt_visibility_tint(const vsh_rt_visibility *v, double tint[3])
{
  for (int k = 0; k < 3; ++k) {
    const double ratio = v->free_weight > 0.0 && isfinite(v->free_weight)
                             ? v->channel_weight[k] / v->free_weight
                             : 1.0;
    tint[k] = clamp01(ratio == ratio ? ratio : 1.0);
  }
}

double vsh_rt_visibility_value(const vsh_rt_visibility *v)
{
  if (v->traced <= 0) {
    return 1.0;
  }
  if (v->weight > 0.0 && isfinite(v->weight)) {
    const double r = v->free_weight / v->weight;
    return r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
  }
  const double r = 1.0 - ((double)v->blocked + v->partial_loss) / v->traced;
  return r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
}
