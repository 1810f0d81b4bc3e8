/* test_transmit.c - unit tests of vsh_transmit: opaque and clear surfaces,
 * a closed sphere of opacity 0.5 (two crossings: 0.25), a red filter, a
 * half filter, nested shells, and out-of-range and NaN inputs. */
#include "vsh_check.h"
#include "vsh_transmit.h"

#include <math.h>

static void test_basic(void) {
  const double white[3] = {1, 1, 1}, red[3] = {1, 0, 0};
  double t[3];
  vsh_transmit_crossing(white, 1.0, 0.0, t);
  CHECK(t[0] == 0 && t[1] == 0 && t[2] == 0);
  vsh_transmit_crossing(white, 0.0, 0.0, t);
  CHECK(t[0] == 1 && t[1] == 1 && t[2] == 1);
  /* A closed sphere of opacity 0.5: in and out. */
  double v[3] = {1, 1, 1};
  vsh_transmit_accumulate(white, 0.5, 0.0, v);
  vsh_transmit_accumulate(white, 0.5, 0.0, v);
  CHECK_NEAR(v[0], 0.25, 1e-15);
  CHECK_NEAR(v[2], 0.25, 1e-15);
  /* A red filter at opacity 0.4: (1 - 0.4) of the light, all of it red. */
  vsh_transmit_crossing(red, 0.4, 1.0, t);
  CHECK_NEAR(t[0], 0.6, 1e-15);
  CHECK(t[1] == 0 && t[2] == 0);
  /* Half filtered: 0.6 (0.5 + 0.5 c). */
  vsh_transmit_crossing(red, 0.4, 0.5, t);
  CHECK_NEAR(t[0], 0.6, 1e-15);
  CHECK_NEAR(t[1], 0.3, 1e-15);
  /* Nested shells: 0.5 and 0.2 opacity, each crossed twice. */
  double n[3] = {1, 1, 1};
  for (int i = 0; i < 2; ++i) {
    vsh_transmit_accumulate(white, 0.5, 0.0, n);
    vsh_transmit_accumulate(white, 0.2, 0.0, n);
  }
  CHECK_NEAR(n[1], 0.25 * 0.64, 1e-15);
}

static void test_degenerate(void) {
  const double white[3] = {1, 1, 1}, odd[3] = {2.0, -1.0, NAN};
  double t[3];
  vsh_transmit_crossing(white, NAN, 0.0, t); /* NaN opacity: opaque */
  CHECK(t[0] == 0);
  vsh_transmit_crossing(white, -0.5, 0.0, t); /* clamped to clear */
  CHECK(t[0] == 1);
  vsh_transmit_crossing(white, 2.0, 0.0, t); /* clamped to opaque */
  CHECK(t[0] == 0);
  vsh_transmit_crossing(odd, 0.0, 1.0, t); /* colour clamped; NaN channel 0 */
  CHECK(t[0] == 1 && t[1] == 0 && t[2] == 0);
  vsh_transmit_crossing(white, 0.5, NAN, t); /* NaN filter: none */
  CHECK_NEAR(t[0], 0.5, 1e-15);
  CHECK(vsh_transmit_passes(0.5) && !vsh_transmit_passes(1.0) && !vsh_transmit_passes(NAN));
  CHECK(vsh_transmit_passes(0.0));
}

/* Crossings that matter to an 8-bit value: 0.5^9 = 1/512 is the first
 * power of 0.5 below 1/510. */
static void test_steps(void) {
  CHECK(vsh_transmit_steps(0.5) == 9);
  CHECK(vsh_transmit_steps(0.6) == 13); /* 0.6^12 = 0.0022 >= 1/510, 0.6^13 = 0.0013 */
  CHECK(vsh_transmit_steps(0.0) == 1);
  CHECK(vsh_transmit_steps(NAN) == 1);
  CHECK(vsh_transmit_steps(-1.0) == 1);
  CHECK(vsh_transmit_steps(1.0) == 255);
  CHECK(vsh_transmit_steps(0.999) == 255);
}

int main(void) {
  test_basic();
  test_degenerate();
  test_steps();
  return vsh_check_report("test_transmit");
}
