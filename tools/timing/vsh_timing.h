/* vsh_timing.h - interleaved frame timing: the schedule and the statistics.
 *
 * A timing run renders several entries (shadow techniques with settings) in
 * one window. It does not time them one after the other, because the state
 * of a shared machine drifts and the order would become part of the result.
 * It runs `rounds` rounds instead. Each round runs a block of `frames`
 * frames per entry, in an order that changes from round to round. Each
 * entry is then compared with the reference entry (`none`) of the same
 * round.
 *
 * Schedule: a Williams design, the rows of a balanced Latin square. For an
 * even number n of entries the square's n rows are the cycle (row k + n/2
 * is row k reversed); for odd n its rows are followed by the same rows
 * reversed, a cycle of 2n rounds. Over a whole cycle every entry runs in
 * every position equally often (once, or twice for odd n), and every entry
 * directly follows every other entry equally often, so neither position nor
 * predecessor favours one entry. A run shorter than a cycle takes rows
 * spread evenly over it; with an even number of rounds, round r and round
 * r + rounds/2 run a row and its reverse, so every entry's mean position is
 * the middle.
 *
 * Statistics: the median of each block (entry, round) is the round's
 * figure, which ignores single slow frames such as the first frame after a
 * switch. Per entry we report the median of its round figures and their
 * spread (min, max, quartiles). The ratio to the reference is the median
 * over rounds of (entry / reference of the same round), with its min and
 * max. A second copy of the reference (`none#2`) measured the same way
 * gives the noise floor: a run whose floor is not within 1 +- tolerance is
 * too noisy to resolve differences of that size.
 *
 * Plain C11, no VTK: vtkshadow-render links it, and tests/timing checks
 * it. */
#ifndef VSH_TIMING_H
#define VSH_TIMING_H

#ifdef __cplusplus
extern "C" {
#endif

/* Limits that keep every array small and every index in an int. */
#define VSH_TIMING_MAX_ENTRIES 256
#define VSH_TIMING_MAX_ROUNDS 1000
#define VSH_TIMING_MAX_FRAMES 100000

/* Rounds in one full cycle of the schedule for n entries: n for even n, 2n
 * for odd n, 0 for n out of range. */
int vsh_timing_cycle_length(int n);

/* Row `row` of the cycle (0 <= row < cycle length): order[p] = the entry
 * run at position p. Rows 0..n-1 are the Williams square (row k: entry
 * (f[p] + k) mod n at position p, f = 0, 1, n-1, 2, n-2, ...); for odd n,
 * rows n..2n-1 are rows 0..n-1 reversed. Returns 0, or -1 for arguments
 * out of range. */
int vsh_timing_cycle_row(int n, int row, int* order);

/* The order of round `round` (0-based) of a run of `rounds` rounds: cycle
 * row floor(round * cycle length / rounds). A short run takes rows spread evenly over
 * the cycle; a run of k whole cycles takes every row k times. For an even
 * number of rounds, rounds r and r + rounds/2 take a row and its reverse.
 * Returns 0, or -1 for arguments out of range. */
int vsh_timing_round_order(int n, int rounds, int round, int* order);

/* How balanced a run of `rounds` rounds is for n entries:
 *   2  every entry in every position equally often and after every other
 *      entry equally often (rounds is a multiple of the cycle length);
 *   1  every entry's mean position is the middle (an even number of rounds);
 *   0  neither (an odd number of rounds that is not a whole cycle);
 *  -1  arguments out of range. */
int vsh_timing_balance(int n, int rounds);

/* The median of `count` values (the mean of the middle two for an even
 * count). NaN when count < 1 or a value is not finite. */
double vsh_timing_median(const double* values, int count);

/* The quartiles of `count` values by linear interpolation between order
 * statistics (q at rank q * (count - 1), Hyndman-Fan type 7). Returns 0, or
 * -1 (outputs NaN) when count < 1 or a value is not finite. */
int vsh_timing_quartiles(const double* values, int count, double* q1, double* q2, double* q3);

/* One entry's figures. Times in the unit of the input (milliseconds). */
typedef struct vsh_timing_stats
{
  double median;    /* median over rounds of the block medians */
  double min, max;  /* smallest and largest block median */
  double q1, q3;    /* quartiles of the block medians */
  double ratio;     /* median over rounds of block / reference block */
  double ratio_min; /* smallest and largest per-round ratio */
  double ratio_max;
} vsh_timing_stats;

/* Summaries of a whole run. `times` holds entries x rounds x frames frame
 * times, entry-major: times[(e * rounds + r) * frames + f]. `reference` is
 * the entry the ratios are against. out[e] for every entry. Returns 0, or
 * -1 when a size is out of range, the reference is not an entry, or a time
 * is not finite and positive (outputs untouched then). */
int vsh_timing_summarize(const double* times, int entries, int rounds, int frames, int reference,
  vsh_timing_stats* out);

/* Whether a noise-floor ratio (the reference against its own copy) says the
 * run is too noisy: 1 when |ratio - 1| > tolerance (+ 1e-9 for rounding)
 * or the ratio is not finite, else 0. */
int vsh_timing_too_noisy(double ratio, double tolerance);

#ifdef __cplusplus
}
#endif

#endif
