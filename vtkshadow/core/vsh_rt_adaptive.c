/* vsh_rt_adaptive.c - the decisions of adaptive ray counts for soft
 * shadows; see vsh_rt_adaptive.h. */
#include "vsh_rt_adaptive.h"

#include <math.h>

int vsh_rt_adaptive_first(int samples, int adaptive, int batch)
{
  if (samples < 1) {
    return 1;
  }
  if (!adaptive || batch < 1 || samples <= batch) {
    return samples;
  }
  return batch;
}

/* Distance between two angles on the circle, in [0, pi]. */
static double angle_gap(double a, double b)
{
  const double two_pi = 2.0 * 3.14159265358979323846;
  double d = fmod(fabs(a - b), two_pi);
  return d > 0.5 * two_pi ? two_pi - d : d;
}

/* The index of ring j (of `first` rings of equal area) of a `samples`-point
 * spiral whose angle is nearest point j of a `first`-point spiral: the
 * batch is then spread like a spiral of its own, in radius and angle. */
static int ring_choice(int j, int first, int samples)
{
  /* The golden angle, as vsh_rt_disk_sample turns its spiral. */
  const double golden = 3.14159265358979323846 * (3.0 - sqrt(5.0));
  /* Radii sqrt((k + 1/2) / samples) of indices [lo, hi) lie in ring j. */
  const int lo = (int)((long long)j * samples / first);
  const int hi = (int)((long long)(j + 1) * samples / first);
  const double target = j * golden;
  int best = lo;
  for (int k = lo + 1; k < hi; ++k) {
    if (angle_gap(k * golden, target) < angle_gap(best * golden, target)) {
      best = k;
    }
  }
  return best;
}

int vsh_rt_adaptive_order(int samples, int first, int *order)
{
  if (samples < 1 || !order) {
    return -1;
  }
  for (int k = 0; k < samples; ++k) {
    order[k] = k;
  }
  if (first < 1 || first >= samples) {
    return 0;
  }
  /* samples > first: every ring holds at least one index, so the choices
   * are distinct. Mark them, move the others to the end keeping their
   * order (backwards, so writes never overtake reads), then put the
   * choices in front, ring by ring. */
  for (int j = 0; j < first; ++j) {
    order[ring_choice(j, first, samples)] = -1;
  }
  int write = samples - 1;
  for (int k = samples - 1; k >= 0; --k) {
    if (order[k] >= 0) {
      order[write--] = order[k];
    }
  }
  for (int j = 0; j < first; ++j) {
    order[j] = ring_choice(j, first, samples);
  }
  return 0;
}

int vsh_rt_adaptive_rest(int samples, int first, int blocked)
{
  if (first >= samples || blocked <= 0 || blocked >= first) {
    return 0;
  }
  return samples - first;
}

int vsh_rt_adaptive_state(int traced, int blocked)
{
  if (traced <= 0) {
    return VSH_RT_BATCH_NONE;
  }
  if (blocked <= 0) {
    return VSH_RT_BATCH_FREE;
  }
  return blocked >= traced ? VSH_RT_BATCH_BLOCKED : VSH_RT_BATCH_MIXED;
}

int vsh_rt_adaptive_rest_near(int samples, int first, const unsigned char *states, int n)
{
  int free = 0, blocked = 0;
  if (first >= samples || !states) {
    return 0;
  }
  for (int k = 0; k < n; ++k) {
    if (states[k] == VSH_RT_BATCH_MIXED) {
      return samples - first;
    }
    free += states[k] == VSH_RT_BATCH_FREE;
    blocked += states[k] == VSH_RT_BATCH_BLOCKED;
  }
  return free && blocked ? samples - first : 0;
}

double vsh_rt_adaptive_expected_rays(int samples, int first, double penumbra)
{
  if (samples < 1) {
    return 0.0;
  }
  if (first < 1 || first >= samples) {
    return samples;
  }
  const double f = penumbra > 0.0 ? (penumbra < 1.0 ? penumbra : 1.0) : 0.0;
  return first + f * (samples - first);
}
