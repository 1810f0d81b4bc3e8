/* vsh_soft_adaptive.c - the batch of adaptive sample counts for the
 * sampled area light; see vsh_soft_adaptive.h. */
#include "vsh_soft_adaptive.h"

#include "vsh_rt_adaptive.h"

#include <math.h>

#define VSH_SA_PI 3.14159265358979323846
/* pi (3 - sqrt 5): vsh_soft_disk_sample's turn per index. */
#define VSH_SA_GOLDEN 2.39996322972865332

int vsh_soft_levels(int sample, int samples)
{
  if (samples < 1 || samples > 255 || sample < 0 || sample >= samples) {
    return 0;
  }
  return (255 * (sample + 1)) / samples - (255 * sample) / samples;
}

/* Distance between two angles on the circle, in [0, pi]. */
static double angle_gap(double a, double b)
{
  double d = fmod(fabs(a - b), 2.0 * VSH_SA_PI);
  return d > VSH_SA_PI ? 2.0 * VSH_SA_PI - d : d;
}

/* The largest cap missed by `count` spiral indices idx[] of an n-point
 * spiral, at `directions` directions. */
static double cap_of(const int *idx, int count, int n, int directions)
{
  double worst = 0.0;
  for (int a = 0; a < directions; ++a) {
    const double phi = 2.0 * VSH_SA_PI * a / directions;
    const double u[2] = { cos(phi), sin(phi) };
    double p = -1.0;
    for (int j = 0; j < count; ++j) {
      const double rho = sqrt((idx[j] + 0.5) / n), t = idx[j] * VSH_SA_GOLDEN;
      const double d = rho * (cos(t) * u[0] + sin(t) * u[1]);
      p = d > p ? d : p;
    }
    p = p < -1.0 ? -1.0 : (p > 1.0 ? 1.0 : p);
    const double cap = (acos(p) - p * sqrt(1.0 - p * p)) / VSH_SA_PI;
    worst = cap > worst ? cap : worst;
  }
  return worst;
}

/* Index 0, then per rim point j the unchosen index of [lo, n) whose angle
 * is nearest offset + 2 pi j / (first - 1). Writes first indices. */
static void rim_batch(int n, int first, int lo, double offset, int *chosen)
{
  chosen[0] = 0;
  for (int j = 1; j < first; ++j) {
    const double target = offset + 2.0 * VSH_SA_PI * (j - 1) / (first - 1);
    int best = -1;
    for (int k = lo; k < n; ++k) {
      int used = 0;
      for (int m = 0; m < j; ++m) used |= chosen[m] == k;
      if (!used && (best < 0 ||
            angle_gap(k * VSH_SA_GOLDEN, target) < angle_gap(best * VSH_SA_GOLDEN, target))) {
        best = k;
      }
    }
    chosen[j] = best;
  }
}

int vsh_soft_batch_order(int samples, int first, int *order)
{
  if (samples < 1 || !order) {
    return -1;
  }
  for (int k = 0; k < samples; ++k) {
    order[k] = k;
  }
  if (first < 2 || first >= samples || first > VSH_SOFT_ADAPTIVE_MAX_BATCH) {
    return 0;
  }
  /* The rim points come from the outermost indices (a pool of at least one
   * per rim point). Of the sets nearest to equal angles turned by 32
   * offsets, with pools of 1.5, 2 and 3 indices per rim point, the one
   * missing the smallest cap (at 1024 directions) wins. */
  int best[VSH_SOFT_ADAPTIVE_MAX_BATCH], trial[VSH_SOFT_ADAPTIVE_MAX_BATCH];
  double best_cap = 2.0;
  const int pools[3] = { 3 * (first - 1) / 2, 2 * (first - 1), 3 * (first - 1) };
  for (int p = 0; p < 3; ++p) {
    const int pool = pools[p] < samples - 1 ? pools[p] : samples - 1;
    for (int o = 0; o < 32; ++o) {
      rim_batch(samples, first, samples - pool, 2.0 * VSH_SA_PI * o / (32.0 * (first - 1)),
        trial);
      const double cap = cap_of(trial, first, samples, 1024);
      if (cap < best_cap) {
        best_cap = cap;
        for (int j = 0; j < first; ++j) best[j] = trial[j];
      }
    }
  }
  /* The others to the end in increasing order (backwards, so writes never
   * overtake reads), then the batch in front. */
  for (int j = 0; j < first; ++j) {
    order[best[j]] = -1;
  }
  int write = samples - 1;
  for (int k = samples - 1; k >= 0; --k) {
    if (order[k] >= 0) {
      order[write--] = order[k];
    }
  }
  for (int j = 0; j < first; ++j) {
    order[j] = best[j];
  }
  return 0;
}

int vsh_soft_batch_levels(int samples, int first, const int *order)
{
  if (samples < 1 || samples > 255 || !order) {
    return -1;
  }
  if (first >= samples || first < 1) {
    return 255;
  }
  int sum = 0;
  for (int j = 0; j < first; ++j) {
    if (order[j] < 0 || order[j] >= samples) {
      return -1;
    }
    sum += vsh_soft_levels(order[j], samples);
  }
  return sum;
}

int vsh_soft_batch_state(int level, int batch_levels)
{
  if (level < 0 || level > batch_levels) {
    return VSH_RT_BATCH_NONE;
  }
  if (level == 0) {
    return VSH_RT_BATCH_BLOCKED;
  }
  return level == batch_levels ? VSH_RT_BATCH_FREE : VSH_RT_BATCH_MIXED;
}

double vsh_soft_batch_missed_cap(const double *xy, int count)
{
  if (count < 1 || !xy) {
    return 1.0;
  }
  /* The cap beyond the chord at distance p in direction u holds no point
   * when p >= max_j (q_j . u), the batch's support in direction u; the
   * largest such cap is at the smallest support. */
  double worst = 0.0;
  for (int a = 0; a < 8192; ++a) {
    const double phi = 2.0 * VSH_SA_PI * a / 8192.0;
    const double u[2] = { cos(phi), sin(phi) };
    double p = -1.0;
    for (int j = 0; j < count; ++j) {
      const double d = xy[2 * j] * u[0] + xy[2 * j + 1] * u[1];
      p = d > p ? d : p;
    }
    p = p < -1.0 ? -1.0 : (p > 1.0 ? 1.0 : p);
    const double cap = (acos(p) - p * sqrt(1.0 - p * p)) / VSH_SA_PI;
    worst = cap > worst ? cap : worst;
  }
  return worst;
}

int vsh_soft_share_state(double share, int batch, int samples)
{
  if (batch < 1 || samples < batch || !isfinite(share)) {
    return VSH_RT_BATCH_NONE;
  }
  if (share < 0.5 / samples) {
    return VSH_RT_BATCH_FREE;
  }
  return share > (batch - 0.5) / samples ? VSH_RT_BATCH_BLOCKED : VSH_RT_BATCH_MIXED;
}

/* Bits of a pixel's mark while vsh_soft_mark_pixels works: the state
 * (VSH_RT_BATCH_*) in bits 0-1, refined in bit 2. */
#define VSH_SM_STATE 3
#define VSH_SM_REFINE 4

static int mark_near(const unsigned char *mark, int width, int height, int x, int y)
{
  int mixed = 0, lit = 0, blocked = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    const int yy = y + dy < 0 ? 0 : (y + dy >= height ? height - 1 : y + dy);
    for (int dx = -1; dx <= 1; ++dx) {
      const int xx = x + dx < 0 ? 0 : (x + dx >= width ? width - 1 : x + dx);
      const int s = mark[(long)yy * width + xx] & VSH_SM_STATE;
      mixed |= s == VSH_RT_BATCH_MIXED;
      lit |= s == VSH_RT_BATCH_FREE;
      blocked |= s == VSH_RT_BATCH_BLOCKED;
    }
  }
  return mixed || (lit && blocked);
}

long vsh_soft_mark_pixels(const float *share, int stride, int width, int height, int batch,
  int samples, unsigned char *mark, int box[4])
{
  if (!share || !mark || stride < 1 || width < 1 || height < 1 || batch < 1 || samples < batch) {
    return -1;
  }
  const long count = (long)width * height;
  for (long p = 0; p < count; ++p) {
    mark[p] = (unsigned char)vsh_soft_share_state(share[p * stride], batch, samples);
  }
  int b[4] = { width, height, 0, 0 };
  long refined = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (mark_near(mark, width, height, x, y)) {
        mark[(long)y * width + x] |= VSH_SM_REFINE;
        ++refined;
        b[0] = x < b[0] ? x : b[0];
        b[1] = y < b[1] ? y : b[1];
        b[2] = x + 1 > b[2] ? x + 1 : b[2];
        b[3] = y + 1 > b[3] ? y + 1 : b[3];
      }
    }
  }
  for (long p = 0; p < count; ++p) {
    const int s = mark[p] & VSH_SM_STATE;
    mark[p] = (mark[p] & VSH_SM_REFINE) ? VSH_SOFT_MARK_REFINE
                                         : (s == VSH_RT_BATCH_BLOCKED ? VSH_SOFT_MARK_BLOCKED
                                                                      : VSH_SOFT_MARK_LIT);
  }
  if (box) {
    for (int k = 0; k < 4; ++k) {
      box[k] = refined ? b[k] : 0;
    }
  }
  return refined;
}
