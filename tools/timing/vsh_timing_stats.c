/* vsh_timing_stats.c - medians, quartiles, ratios and the noise verdict of
 * an interleaved timing run (see vsh_timing.h). */
#include "vsh_timing.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int compare_doubles(const void* a, const void* b)
{
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

/* A sorted copy of `values` (caller frees), or NULL when count < 1, a value
 * is not finite or memory runs out. */
static double* sorted_copy(const double* values, int count)
{
  if (!values || count < 1)
  {
    return NULL;
  }
  for (int i = 0; i < count; ++i)
  {
    if (!isfinite(values[i]))
    {
      return NULL;
    }
  }
  double* copy = malloc((size_t)count * sizeof *copy);
  if (!copy)
  {
    return NULL;
  }
  memcpy(copy, values, (size_t)count * sizeof *copy);
  qsort(copy, (size_t)count, sizeof *copy, compare_doubles);
  return copy;
}

/* The value at fractional rank q * (count - 1) of sorted values. */
static double rank_value(const double* sorted, int count, double q)
{
  const double rank = q * (count - 1);
  const int low = (int)floor(rank);
  const int high = low + 1 < count ? low + 1 : low;
  return sorted[low] + (rank - low) * (sorted[high] - sorted[low]);
}

double vsh_timing_median(const double* values, int count)
{
  double* sorted = sorted_copy(values, count);
  if (!sorted)
  {
    return NAN;
  }
  const double median = count % 2 ? sorted[count / 2]
                                  : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
  free(sorted);
  return median;
}

int vsh_timing_quartiles(const double* values, int count, double* q1, double* q2, double* q3)
{
  double* sorted = sorted_copy(values, count);
  double out[3] = { NAN, NAN, NAN };
  if (sorted)
  {
    out[0] = rank_value(sorted, count, 0.25);
    out[1] = rank_value(sorted, count, 0.5);
    out[2] = rank_value(sorted, count, 0.75);
    free(sorted);
  }
  if (q1)
  {
    *q1 = out[0];
  }
  if (q2)
  {
    *q2 = out[1];
  }
  if (q3)
  {
    *q3 = out[2];
  }
  return sorted ? 0 : -1;
}

/* min and max of count finite values. */
static void min_max(const double* values, int count, double* lo, double* hi)
{
  *lo = *hi = values[0];
  for (int i = 1; i < count; ++i)
  {
    *lo = values[i] < *lo ? values[i] : *lo;
    *hi = values[i] > *hi ? values[i] : *hi;
  }
}

static int valid_times(const double* times, long long count)
{
  for (long long i = 0; i < count; ++i)
  {
    if (!isfinite(times[i]) || !(times[i] > 0.0))
    {
      return 0;
    }
  }
  return 1;
}

/* Figures of entry e from the block medians (entries x rounds). */
static void summarize_entry(const double* blocks, int rounds, int e, int reference,
  double* ratios, vsh_timing_stats* out)
{
  const double* mine = blocks + (long long)e * rounds;
  const double* ref = blocks + (long long)reference * rounds;
  for (int r = 0; r < rounds; ++r)
  {
    ratios[r] = mine[r] / ref[r];
  }
  vsh_timing_stats s;
  vsh_timing_quartiles(mine, rounds, &s.q1, &s.median, &s.q3);
  min_max(mine, rounds, &s.min, &s.max);
  s.ratio = vsh_timing_median(ratios, rounds);
  min_max(ratios, rounds, &s.ratio_min, &s.ratio_max);
  *out = s;
}

int vsh_timing_summarize(const double* times, int entries, int rounds, int frames, int reference,
  vsh_timing_stats* out)
{
  if (!times || !out || entries < 1 || entries > VSH_TIMING_MAX_ENTRIES || rounds < 1 ||
    rounds > VSH_TIMING_MAX_ROUNDS || frames < 1 || frames > VSH_TIMING_MAX_FRAMES ||
    reference < 0 || reference >= entries)
  {
    return -1;
  }
  const long long blocks_count = (long long)entries * rounds;
  if (!valid_times(times, blocks_count * frames))
  {
    return -1;
  }
  double* blocks = malloc((size_t)blocks_count * sizeof *blocks);
  double* ratios = malloc((size_t)rounds * sizeof *ratios);
  if (!blocks || !ratios)
  {
    free(blocks);
    free(ratios);
    return -1;
  }
  for (long long b = 0; b < blocks_count; ++b)
  {
    blocks[b] = vsh_timing_median(times + b * frames, frames);
  }
  for (int e = 0; e < entries; ++e)
  {
    summarize_entry(blocks, rounds, e, reference, ratios, &out[e]);
  }
  free(blocks);
  free(ratios);
  return 0;
}

int vsh_timing_too_noisy(double ratio, double tolerance)
{
  /* The slack keeps a ratio that prints as the bound (0.97 at 0.03) inside:
   * 1 - 0.97 is 0.030000000000000027 in binary. */
  return !(isfinite(ratio) && fabs(ratio - 1.0) <= tolerance + 1e-9);
}
