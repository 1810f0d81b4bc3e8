/* mesh_mutate.h - seeded mutations of mesh files for the deterministic fuzz
 * tests (C and C++). Text formats get their numbers swapped for odd values
 * (0, -1, huge, nan, inf, past-the-end counts); binary ones get 1/2/4/8-byte
 * fields overwritten with odd integers and floats; all get bit flips,
 * deletions, duplications, insertions and truncation.
 * Same seed, same mutations: a failure reproduces from its printed iteration. */
#ifndef MESH_MUTATE_H
#define MESH_MUTATE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vsh_mutate.h"

static const char *const mm_values[] = {
    "0", "-1", "-2", "-9", "1", "2", "3", "4", "5", "9", "255", "256", "65536",
    "2147483647", "2147483648", "4294967295", "4294967296", "-2147483649", "99999999999999999999",
    "1e39", "-1e39", "1e308", "1e999", "nan", "-nan", "inf", "-inf", "0.5", "1.5", "-0", "0x10",
    "", " ", "x", "/", "//", "1/2/3/4", "50000001"};

/* Swap a number in the text for an odd value. */
static void mm_swap_number(mm_buf *b) {
  size_t i, start = mm_below(b->len);
  for (i = 0; i < b->len; ++i) {
    size_t p = (start + i) % b->len;
    if (b->data[p] >= '0' && b->data[p] <= '9') {
      size_t s = p, e = p;
      const char *v = mm_values[mm_below(sizeof mm_values / sizeof mm_values[0])];
      while (s > 0 && mm_num_char(b->data[s - 1])) --s;
      while (e < b->len && mm_num_char(b->data[e])) ++e;
      mm_erase(b, s, e - s);
      mm_insert(b, s, v, strlen(v));
      return;
    }
  }
}

/* Overwrite a 1/2/4/8-byte field with an odd integer or float. */
static void mm_poke(mm_buf *b) {
  static const uint32_t ints[] = {0, 1, 2, 3, 4, 5, 255, 256, 0x7FFFFFFFu, 0x80000000u,
                                  0xFFFFFFFFu, 0xFFFFFFFEu, 50000001u, 1000};
  static const uint32_t floats[] = {0x7FC00000u /* nan */, 0x7F800000u /* inf */,
                                    0xFF800000u /* -inf */, 0x7F7FFFFFu /* FLT_MAX */,
                                    0x00000001u /* denormal */};
  unsigned char bytes[8];
  size_t n = (size_t)1 << mm_below(4), at, k;
  uint64_t v = mm_below(2) ? ints[mm_below(sizeof ints / sizeof ints[0])]
                           : floats[mm_below(sizeof floats / sizeof floats[0])];
  if (n == 8 && mm_below(2)) v = 0x7FF8000000000000ull; /* double nan */
  if (b->len < n) return;
  at = mm_below(b->len - n + 1);
  if (mm_below(3) == 0) at &= ~(size_t)(n - 1); /* aligned, as fields usually are */
  for (k = 0; k < n; ++k) bytes[k] = (unsigned char)(v >> (8 * (mm_below(4) == 0 ? n - 1 - k : k)));
  memcpy(b->data + at, bytes, n);
}

static void mm_mutate(mm_buf *b) {
  static const char punct[] = "0123456789 \n/-.e<>\"=_";
  size_t at, n;
  switch (mm_below(9)) {
  case 0: /* flip a bit */
    if (b->len) b->data[mm_below(b->len)] ^= (char)(1u << mm_below(8));
    break;
  case 1: /* delete a span */
    if (b->len) mm_erase(b, mm_below(b->len), 1 + mm_below(16));
    break;
  case 2: { /* insert a character */
    char c = punct[mm_below(sizeof punct - 1)];
    mm_insert(b, mm_below(b->len + 1), &c, 1);
    break;
  }
  case 3:
  case 4:
    mm_swap_number(b);
    break;
  case 5:
  case 6:
    mm_poke(b);
    break;
  case 7: { /* duplicate a span elsewhere (extra lines, elements, records) */
    char tmp[128];
    if (!b->len) break;
    at = mm_below(b->len);
    n = 1 + mm_below(sizeof tmp);
    if (at + n > b->len) n = b->len - at;
    memcpy(tmp, b->data + at, n);
    mm_insert(b, mm_below(b->len + 1), tmp, n);
    break;
  }
  default: /* truncate */
    if (b->len) b->len = mm_below(b->len + 1);
    break;
  }
}

/* Seeds mutation `iteration` of seed `file`, applies 1 to 4 mutations. */
static void mm_make(mm_buf *b, const char *seed, size_t seed_len, int file, long iteration) {
  int m, count = 1 + (int)(iteration % 4);
  mm_state = 0x3e5d0000ull + (uint64_t)file * 1000003ull + (uint64_t)iteration;
  b->len = 0;
  mm_reserve(b, seed_len);
  memcpy(b->data, seed, seed_len);
  b->len = seed_len;
  for (m = 0; m < count; ++m) mm_mutate(b);
}

#endif
