/* Unit tests of the interleaved-timing schedule (tools/timing): every
 * round is a permutation; over a whole cycle every entry runs in every
 * position equally often and directly after every other entry equally
 * often; an even number of rounds puts every entry's mean position in the
 * middle; bad arguments are refused. */
#include "vsh_check.h"
#include "vsh_timing.h"

#include <stdlib.h>

/* order is a permutation of 0..n-1. */
static int is_permutation(const int* order, int n)
{
  int seen[VSH_TIMING_MAX_ENTRIES] = { 0 };
  for (int p = 0; p < n; ++p)
  {
    if (order[p] < 0 || order[p] >= n || seen[order[p]]++)
    {
      return 0;
    }
  }
  return 1;
}

/* Counts of a run: position[e * n + p] = rounds in which entry e ran at
 * position p; follows[a * n + b] = times b ran directly after a within a
 * round; sum_position[e]. Returns 0 when some round is not a permutation. */
static int count_run(int n, int rounds, int* position, int* follows, long* sum_position)
{
  int order[VSH_TIMING_MAX_ENTRIES];
  for (int i = 0; i < n * n; ++i)
  {
    position[i] = follows[i] = 0;
  }
  for (int e = 0; e < n; ++e)
  {
    sum_position[e] = 0;
  }
  for (int r = 0; r < rounds; ++r)
  {
    if (vsh_timing_round_order(n, rounds, r, order) != 0 || !is_permutation(order, n))
    {
      return 0;
    }
    for (int p = 0; p < n; ++p)
    {
      ++position[order[p] * n + p];
      sum_position[order[p]] += p;
      if (p + 1 < n)
      {
        ++follows[order[p] * n + order[p + 1]];
      }
    }
  }
  return 1;
}

/* Whole cycles (k = 1, 2) of c = n (even n) or 2n (odd n) rounds: each
 * entry k*c/n times per position, each ordered pair of distinct entries
 * k*c/n times as neighbours. */
static void test_whole_cycles(void)
{
  for (int n = 1; n <= 24; ++n)
  {
    int* position = calloc((size_t)(n * n), sizeof *position);
    int* follows = calloc((size_t)(n * n), sizeof *follows);
    long sum[VSH_TIMING_MAX_ENTRIES];
    for (int k = 1; k <= 2; ++k)
    {
      const int rounds = k * vsh_timing_cycle_length(n);
      const int per = rounds / n;
      CHECK(rounds == k * (n % 2 ? 2 * n : n));
      CHECK(vsh_timing_balance(n, rounds) == 2);
      CHECK(count_run(n, rounds, position, follows, sum));
      int positions_ok = 1, follows_ok = 1;
      for (int a = 0; a < n; ++a)
      {
        for (int b = 0; b < n; ++b)
        {
          positions_ok &= position[a * n + b] == per;
          follows_ok &= follows[a * n + b] == (a == b ? 0 : per);
        }
      }
      CHECK(positions_ok);
      CHECK(follows_ok);
      if (!positions_ok || !follows_ok)
      {
        fprintf(stderr, "  n = %d, rounds = %d\n", n, rounds);
      }
    }
    free(position);
    free(follows);
  }
}

/* Even round counts (also shorter than a cycle): every entry's summed
 * position is rounds * (n - 1) / 2, the middle. Odd counts that are not
 * whole cycles are reported as 0 and, for n >= 3 and one round, really are
 * unbalanced. */
static void test_even_rounds(void)
{
  for (int n = 2; n <= 17; ++n)
  {
    int* position = calloc((size_t)(n * n), sizeof *position);
    int* follows = calloc((size_t)(n * n), sizeof *follows);
    long sum[VSH_TIMING_MAX_ENTRIES];
    const int cycle = vsh_timing_cycle_length(n);
    for (int rounds = 1; rounds <= 3 * 2 * n; ++rounds)
    {
      const int balance = vsh_timing_balance(n, rounds);
      CHECK(count_run(n, rounds, position, follows, sum));
      CHECK(balance == (rounds % cycle == 0 ? 2 : rounds % 2 == 0 ? 1 : 0));
      if (balance >= 1)
      {
        int middle = 1;
        for (int e = 0; e < n; ++e)
        {
          middle &= 2 * sum[e] == (long)rounds * (n - 1);
        }
        CHECK(middle);
      }
    }
    free(position);
    free(follows);
  }
  /* One round of three entries: positions 0, 1, 2, not all in the middle. */
  int order[3];
  CHECK(vsh_timing_round_order(3, 1, 0, order) == 0);
  CHECK(order[0] != 1 || order[2] != 1);
  CHECK(vsh_timing_balance(3, 1) == 0);
}

/* The default: 4 rounds of 3 entries (technique, none, none#2)
 * starts with the Williams row 0, 1, 2 and has its reverse two rounds
 * later; 4 rounds of 4 entries are the whole square, four distinct orders
 * (row 2 is row 0 reversed). */
static void test_known_rows(void)
{
  int order[4];
  CHECK(vsh_timing_cycle_row(3, 0, order) == 0);
  CHECK(order[0] == 0 && order[1] == 1 && order[2] == 2);
  CHECK(vsh_timing_cycle_row(3, 3, order) == 0);
  CHECK(order[0] == 2 && order[1] == 1 && order[2] == 0);
  CHECK(vsh_timing_cycle_row(4, 0, order) == 0);
  CHECK(order[0] == 0 && order[1] == 1 && order[2] == 3 && order[3] == 2);
  CHECK(vsh_timing_cycle_row(4, 1, order) == 0);
  CHECK(order[0] == 1 && order[1] == 2 && order[2] == 0 && order[3] == 3);
  CHECK(vsh_timing_round_order(3, 4, 2, order) == 0);
  CHECK(order[0] == 2 && order[1] == 1 && order[2] == 0);
  CHECK(vsh_timing_round_order(1, 3, 2, order) == 0 && order[0] == 0);
  int rows[4][4];
  for (int r = 0; r < 4; ++r)
  {
    CHECK(vsh_timing_round_order(4, 4, r, rows[r]) == 0);
  }
  for (int a = 0; a < 4; ++a)
  {
    for (int b = a + 1; b < 4; ++b)
    {
      CHECK(memcmp(rows[a], rows[b], sizeof rows[a]) != 0);
    }
  }
  CHECK(rows[2][0] == rows[0][3] && rows[2][1] == rows[0][2] && rows[2][3] == rows[0][0]);
  CHECK(vsh_timing_cycle_length(4) == 4 && vsh_timing_cycle_length(3) == 6);
}

static void test_bad_arguments(void)
{
  int order[4] = { 7, 7, 7, 7 };
  CHECK(vsh_timing_cycle_length(0) == 0);
  CHECK(vsh_timing_cycle_length(VSH_TIMING_MAX_ENTRIES + 1) == 0);
  CHECK(vsh_timing_cycle_row(3, -1, order) == -1);
  CHECK(vsh_timing_cycle_row(3, 6, order) == -1);
  CHECK(vsh_timing_cycle_row(4, 4, order) == -1);
  CHECK(vsh_timing_cycle_row(3, 0, NULL) == -1);
  CHECK(vsh_timing_round_order(3, 0, 0, order) == -1);
  CHECK(vsh_timing_round_order(3, 4, 4, order) == -1);
  CHECK(vsh_timing_round_order(3, 4, -1, order) == -1);
  CHECK(vsh_timing_round_order(0, 4, 0, order) == -1);
  CHECK(vsh_timing_round_order(3, VSH_TIMING_MAX_ROUNDS + 1, 0, order) == -1);
  CHECK(order[0] == 7 && order[3] == 7);
  CHECK(vsh_timing_balance(0, 4) == -1);
  CHECK(vsh_timing_balance(3, 0) == -1);
}

int main(void)
{
  test_whole_cycles();
  test_even_rounds();
  test_known_rows();
  test_bad_arguments();
  return vsh_check_report("timing.schedule");
}
