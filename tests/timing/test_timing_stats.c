/* Unit tests of the interleaved-timing statistics (tools/timing) on
 * known inputs: medians and quartiles, block medians per round, paired
 * ratios to the reference, the spread over rounds, and the noise verdict. */
#include "vsh_check.h"
#include "vsh_timing.h"

#include <math.h>

static void test_median_quartiles(void)
{
  const double odd[] = { 5, 1, 4, 2, 3 };
  const double even[] = { 4, 1, 3, 2 };
  CHECK_NEAR(vsh_timing_median(odd, 5), 3.0, 0);
  CHECK_NEAR(vsh_timing_median(even, 4), 2.5, 0);
  CHECK_NEAR(vsh_timing_median(odd, 1), 5.0, 0);
  CHECK(odd[0] == 5 && odd[1] == 1); /* the input is not reordered */
  double q1, q2, q3;
  CHECK(vsh_timing_quartiles(odd, 5, &q1, &q2, &q3) == 0);
  CHECK_NEAR(q1, 2.0, 1e-15);
  CHECK_NEAR(q2, 3.0, 1e-15);
  CHECK_NEAR(q3, 4.0, 1e-15);
  /* 1 2 3 4: ranks 0.75, 1.5, 2.25 (type 7). */
  CHECK(vsh_timing_quartiles(even, 4, &q1, &q2, &q3) == 0);
  CHECK_NEAR(q1, 1.75, 1e-15);
  CHECK_NEAR(q2, 2.5, 1e-15);
  CHECK_NEAR(q3, 3.25, 1e-15);
  CHECK(vsh_timing_quartiles(odd, 1, &q1, &q2, &q3) == 0);
  CHECK(q1 == 5 && q2 == 5 && q3 == 5);
  const double bad[] = { 1, NAN, 3 };
  CHECK(isnan(vsh_timing_median(bad, 3)));
  CHECK(isnan(vsh_timing_median(odd, 0)));
  CHECK(vsh_timing_quartiles(bad, 3, &q1, &q2, &q3) == -1);
  CHECK(isnan(q1) && isnan(q2) && isnan(q3));
  const double inf[] = { 1, INFINITY };
  CHECK(isnan(vsh_timing_median(inf, 2)));
}

/* Three entries (none, none#2, technique), four rounds, three frames. The
 * machine slows down by a factor per round (1, 2, 1, 1.5); the technique
 * costs exactly 2x none in every round; none#2 equals none. One slow frame
 * per block (the switch) must not move a median. */
static void test_summarize_known(void)
{
  enum { E = 3, R = 4, F = 3 };
  const double load[R] = { 1.0, 2.0, 1.0, 1.5 };
  const double cost[E] = { 10.0, 10.0, 20.0 };
  double times[E * R * F];
  for (int e = 0; e < E; ++e)
  {
    for (int r = 0; r < R; ++r)
    {
      double* block = times + (e * R + r) * F;
      block[0] = cost[e] * load[r] * 5.0; /* the slow first frame */
      block[1] = cost[e] * load[r] * 0.99;
      block[2] = cost[e] * load[r] * 1.01;
    }
  }
  vsh_timing_stats s[E];
  CHECK(vsh_timing_summarize(times, E, R, F, 0, s) == 0);
  /* Block medians of none: 10.1, 20.2, 10.1, 15.15 -> median 12.625. */
  CHECK_NEAR(s[0].median, 12.625, 1e-12);
  CHECK_NEAR(s[0].min, 10.1, 1e-12);
  CHECK_NEAR(s[0].max, 20.2, 1e-12);
  /* Sorted 10.1 10.1 15.15 20.2: q1 at rank 0.75, q3 at 2.25. */
  CHECK_NEAR(s[0].q1, 10.1, 1e-12);
  CHECK_NEAR(s[0].q3, 15.15 + 0.25 * (20.2 - 15.15), 1e-12);
  CHECK_NEAR(s[0].ratio, 1.0, 1e-15);
  CHECK_NEAR(s[1].ratio, 1.0, 1e-15);
  CHECK_NEAR(s[1].ratio_min, 1.0, 1e-15);
  CHECK_NEAR(s[1].ratio_max, 1.0, 1e-15);
  /* Paired ratios see through the load: exactly 2 in every round, though
   * the technique's own medians spread from 20.2 to 40.4. */
  CHECK_NEAR(s[2].ratio, 2.0, 1e-12);
  CHECK_NEAR(s[2].ratio_min, 2.0, 1e-12);
  CHECK_NEAR(s[2].ratio_max, 2.0, 1e-12);
  CHECK_NEAR(s[2].min, 20.2, 1e-12);
  CHECK_NEAR(s[2].max, 40.4, 1e-12);
  CHECK(vsh_timing_too_noisy(s[1].ratio, 0.03) == 0);
}

/* Per-round ratios 1.0, 1.1, 0.9, 1.2 of none#2: median 1.05, min 0.9, max
 * 1.2; noisy at tolerance 0.03, not at 0.05. */
static void test_noise_floor(void)
{
  enum { E = 2, R = 4, F = 1 };
  const double times[E * R * F] = { 10, 10, 10, 10, 10, 11, 9, 12 };
  vsh_timing_stats s[E];
  CHECK(vsh_timing_summarize(times, E, R, F, 0, s) == 0);
  CHECK_NEAR(s[1].ratio, 1.05, 1e-12);
  CHECK_NEAR(s[1].ratio_min, 0.9, 1e-12);
  CHECK_NEAR(s[1].ratio_max, 1.2, 1e-12);
  CHECK_NEAR(s[1].median, 10.5, 1e-12);
  CHECK(vsh_timing_too_noisy(s[1].ratio, 0.03) == 1);
  CHECK(vsh_timing_too_noisy(s[1].ratio, 0.05) == 0);
  CHECK(vsh_timing_too_noisy(0.97, 0.03) == 0);
  CHECK(vsh_timing_too_noisy(0.969, 0.03) == 1);
  CHECK(vsh_timing_too_noisy(NAN, 0.03) == 1);
  CHECK(vsh_timing_too_noisy(INFINITY, 0.03) == 1);
  /* The reference need not be entry 0. */
  CHECK(vsh_timing_summarize(times, E, R, F, 1, s) == 0);
  CHECK_NEAR(s[1].ratio, 1.0, 1e-15);
  CHECK_NEAR(s[0].ratio, vsh_timing_median((const double[]){ 1.0, 10.0 / 11, 10.0 / 9, 10.0 / 12 }, 4),
    1e-12);
}

static void test_bad_input(void)
{
  double times[4] = { 1, 2, 3, 4 };
  vsh_timing_stats s[2] = { { 0 } };
  s[0].median = 42;
  CHECK(vsh_timing_summarize(times, 2, 2, 1, 2, s) == -1);  /* no such reference */
  CHECK(vsh_timing_summarize(times, 2, 2, 1, -1, s) == -1);
  CHECK(vsh_timing_summarize(times, 0, 2, 1, 0, s) == -1);
  CHECK(vsh_timing_summarize(times, 2, 0, 1, 0, s) == -1);
  CHECK(vsh_timing_summarize(times, 2, 2, 0, 0, s) == -1);
  CHECK(vsh_timing_summarize(NULL, 2, 2, 1, 0, s) == -1);
  times[2] = 0.0; /* a frame cannot take no time: a broken clock */
  CHECK(vsh_timing_summarize(times, 2, 2, 1, 0, s) == -1);
  times[2] = NAN;
  CHECK(vsh_timing_summarize(times, 2, 2, 1, 0, s) == -1);
  times[2] = -3.0;
  CHECK(vsh_timing_summarize(times, 2, 2, 1, 0, s) == -1);
  CHECK(s[0].median == 42); /* untouched */
}

int main(void)
{
  test_median_quartiles();
  test_summarize_known();
  test_noise_floor();
  test_bad_input();
  return vsh_check_report("timing.stats");
}
