/* vsh_timing_schedule.c - the order of the entries in each round (see
 * vsh_timing.h). */
#include "vsh_timing.h"

int vsh_timing_cycle_length(int n)
{
  if (n < 1 || n > VSH_TIMING_MAX_ENTRIES)
  {
    return 0;
  }
  return n % 2 ? 2 * n : n;
}

/* Position j of the Williams square's first row: 0, 1, n-1, 2, n-2, ...
 * Consecutive entries differ by +1, -2, +3, -4, ... (mod n), all distinct,
 * which is what makes every ordered pair appear once as neighbours (for
 * even n; odd n needs the reversed rows as well). */
static int williams_first(int n, int j)
{
  if (j == 0)
  {
    return 0;
  }
  return j % 2 ? (j + 1) / 2 : n - j / 2;
}

int vsh_timing_cycle_row(int n, int row, int* order)
{
  if (!order || row < 0 || row >= vsh_timing_cycle_length(n))
  {
    return -1;
  }
  /* Even n: the square itself holds the reverses (row k + n/2 is row k
   * reversed), so it is the whole cycle. Odd n: the reversed rows follow. */
  const int reversed = row >= n;
  const int shift = reversed ? row - n : row;
  for (int j = 0; j < n; ++j)
  {
    const int entry = (williams_first(n, j) + shift) % n;
    order[reversed ? n - 1 - j : j] = entry;
  }
  return 0;
}

int vsh_timing_round_order(int n, int rounds, int round, int* order)
{
  if (n < 1 || n > VSH_TIMING_MAX_ENTRIES || rounds < 1 || rounds > VSH_TIMING_MAX_ROUNDS ||
    round < 0 || round >= rounds)
  {
    return -1;
  }
  const long long cycle = vsh_timing_cycle_length(n);
  const int row = (int)((round * cycle) / rounds);
  return vsh_timing_cycle_row(n, row, order);
}

int vsh_timing_balance(int n, int rounds)
{
  if (n < 1 || n > VSH_TIMING_MAX_ENTRIES || rounds < 1 || rounds > VSH_TIMING_MAX_ROUNDS)
  {
    return -1;
  }
  if (rounds % vsh_timing_cycle_length(n) == 0)
  {
    return 2;
  }
  return rounds % 2 == 0 ? 1 : 0;
}
