/* test_edt.c - the Felzenszwalb-Huttenlocher transform against brute force. */
#include "vsh_check.h"
#include "vshm_edt.h"

#include <math.h>
#include <stdlib.h>

/* Own LCG: the same "random" grids on every platform and libc. */
static unsigned long rng_state = 12345;
static unsigned rng(void) {
  rng_state = rng_state * 6364136223846793005UL + 1442695040888963407UL;
  return (unsigned)(rng_state >> 33);
}

static double brute(const unsigned char *f, int w, int h, int x, int y) {
  double best = INFINITY;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      if (f[j * w + i]) {
        double d = (double)(i - x) * (i - x) + (double)(j - y) * (j - y);
        if (d < best) best = d;
      }
  return best;
}

static void check_random(int w, int h, unsigned density_per_mille) {
  unsigned char *f = malloc((size_t)w * h);
  double *d2 = malloc(sizeof(double) * w * h);
  long count = 0;
  for (int i = 0; i < w * h; ++i) {
    f[i] = rng() % 1000 < density_per_mille;
    count += f[i];
  }
  CHECK(vshm_edt_sq(f, w, h, d2) == count);
  int bad = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double e = brute(f, w, h, x, y);
      /* squared distances are integers: exact equality is expected */
      if (!(d2[y * w + x] == e)) ++bad;
    }
  if (bad) fprintf(stderr, "%dx%d density %u: %d cells differ\n", w, h, density_per_mille, bad);
  CHECK(bad == 0);
  free(f);
  free(d2);
}

int main(void) {
  /* many shapes, including 1-wide, and sparse to dense */
  for (int t = 0; t < 60; ++t) {
    int w = 1 + (int)(rng() % 40), h = 1 + (int)(rng() % 40);
    unsigned dens[] = {2, 10, 50, 300, 900};
    check_random(w, h, dens[t % 5]);
  }

  /* a single feature: exact squared distances */
  unsigned char f[5 * 4] = {0};
  double d2[5 * 4];
  f[1 * 5 + 2] = 1;
  CHECK(vshm_edt_sq(f, 5, 4, d2) == 1);
  CHECK(d2[1 * 5 + 2] == 0.0);
  CHECK(d2[0] == 5.0);          /* (0,0): dx 2, dy 1 */
  CHECK(d2[3 * 5 + 4] == 8.0);  /* (4,3): dx 2, dy 2 */

  /* no feature: +INFINITY everywhere, count 0 */
  unsigned char none[6] = {0};
  double dn[6];
  CHECK(vshm_edt_sq(none, 3, 2, dn) == 0);
  for (int i = 0; i < 6; ++i) CHECK(isinf(dn[i]) && dn[i] > 0);

  /* bad arguments */
  CHECK(vshm_edt_sq(NULL, 3, 2, dn) == -1);
  CHECK(vshm_edt_sq(none, 0, 2, dn) == -1);
  return vsh_check_report("metrics.edt");
}
