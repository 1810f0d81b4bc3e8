/* vsh_random.h - a fixed-seed random generator for the unit tests, so a
 * failing random case is the same case on every run and machine
 * (xorshift64*, 53-bit uniform doubles). */
#ifndef VSH_RANDOM_H
#define VSH_RANDOM_H

#include "vsh_vec3.h"

#include <stdint.h>

static uint64_t vsh_test_rng_state = 0x9E3779B97F4A7C15ull;

/* Restart the sequence (a non-zero seed). */
static inline void vsh_test_seed(uint64_t seed) { vsh_test_rng_state = seed; }

/* Uniform in [lo, hi). */
static inline double vsh_test_rnd(double lo, double hi) {
  vsh_test_rng_state ^= vsh_test_rng_state >> 12;
  vsh_test_rng_state ^= vsh_test_rng_state << 25;
  vsh_test_rng_state ^= vsh_test_rng_state >> 27;
  const uint64_t r = vsh_test_rng_state * 0x2545F4914F6CDD1Dull;
  return lo + (hi - lo) * ((double)(r >> 11) * (1.0 / 9007199254740992.0));
}

/* A uniformly distributed unit vector (rejection from the unit ball). */
static inline void vsh_test_rnd_unit(double out[3]) {
  double v[3];
  do {
    v[0] = vsh_test_rnd(-1, 1);
    v[1] = vsh_test_rnd(-1, 1);
    v[2] = vsh_test_rnd(-1, 1);
  } while (vsh_vec3_length(v) < 0.1 || vsh_vec3_length(v) > 1);
  vsh_vec3_normalize(v, out);
}

#endif
