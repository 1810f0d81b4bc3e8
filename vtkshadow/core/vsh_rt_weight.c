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

void vsh_rt_visibility_add(vsh_rt_visibility *v, double weight, int blocked)
{
  const double w = isfinite(weight) && weight > 0.0 ? weight : 0.0;
  ++v->traced;
  v->weight += w;
  if (blocked) {
    ++v->blocked;
  } else {
    v->free_weight += w;
  }
}

void vsh_rt_visibility_add_transmitted(vsh_rt_visibility *v, double weight, double transmitted)
{
  const double t = transmitted == transmitted ? (transmitted < 0.0 ? 0.0 : (transmitted > 1.0 ? 1.0 : transmitted)) : 0.0;
  if (t <= 0.0 || t >= 1.0) {
    vsh_rt_visibility_add(v, weight, t <= 0.0);
    return;
  }
  const double w = isfinite(weight) && weight > 0.0 ? weight : 0.0;
  ++v->traced;
  ++v->partial;
  v->weight += w;
  v->free_weight += w * t;
  v->partial_loss += 1.0 - t;
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
