/* vsh_check.h - the few assertion macros the C unit tests share.
 * Each failed check prints file, line and the values, and the test's main
 * returns vsh_check_report(), non-zero when anything failed. */
#ifndef VSH_CHECK_H
#define VSH_CHECK_H

#include <math.h>
#include <stdio.h>
#include <string.h>

static int vsh_check_failures = 0;
static int vsh_check_count = 0;

#define CHECK(cond)                                                              \
  do {                                                                           \
    ++vsh_check_count;                                                           \
    if (!(cond)) {                                                               \
      ++vsh_check_failures;                                                      \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);   \
    }                                                                            \
  } while (0)

#define CHECK_NEAR(a, b, tol)                                                    \
  do {                                                                           \
    double vsh_a_ = (a), vsh_b_ = (b);                                           \
    ++vsh_check_count;                                                           \
    if (!(fabs(vsh_a_ - vsh_b_) <= (tol))) {                                     \
      ++vsh_check_failures;                                                      \
      fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.17g, %s = %.17g, tol %g\n", \
              __FILE__, __LINE__, #a, vsh_a_, #b, vsh_b_, (double)(tol));        \
    }                                                                            \
  } while (0)

#define CHECK_STR_CONTAINS(haystack, needle)                                     \
  do {                                                                           \
    const char *vsh_h_ = (haystack), *vsh_n_ = (needle);                         \
    ++vsh_check_count;                                                           \
    if (!vsh_h_ || !strstr(vsh_h_, vsh_n_)) {                                    \
      ++vsh_check_failures;                                                      \
      fprintf(stderr, "%s:%d: expected \"%s\" in \"%s\"\n", __FILE__, __LINE__,  \
              vsh_n_, vsh_h_ ? vsh_h_ : "(null)");                               \
    }                                                                            \
  } while (0)

static inline int vsh_check_report(const char *name) {
  printf("%s: %d checks, %d failed\n", name, vsh_check_count, vsh_check_failures);
  return vsh_check_failures ? 1 : 0;
}

#endif
