/* vsh_mutate.h - the byte-buffer primitives of the deterministic mutation
 * fuzz tests (scene files, mesh files): a seeded splitmix64 generator, a
 * growable buffer with insert and erase, what counts as part of a
 * number, and reading a seed file whole. Same seed, same sequence, on every machine. */
#ifndef VSH_MUTATE_H
#define VSH_MUTATE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct mm_buf {
  char *data;
  size_t len, cap;
} mm_buf;

static uint64_t mm_state;
static uint64_t mm_next(void) { /* splitmix64 */
  uint64_t z = (mm_state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
static size_t mm_below(size_t n) { return n ? (size_t)(mm_next() % n) : 0; }

static void mm_reserve(mm_buf *b, size_t extra) {
  if (b->len + extra + 1 > b->cap) {
    b->cap = (b->len + extra + 1) * 2;
    b->data = (char *)realloc(b->data, b->cap);
    if (!b->data) abort();
  }
}
static void mm_insert(mm_buf *b, size_t at, const char *s, size_t n) {
  mm_reserve(b, n);
  memmove(b->data + at + n, b->data + at, b->len - at);
  memcpy(b->data + at, s, n);
  b->len += n;
}
static void mm_erase(mm_buf *b, size_t at, size_t n) {
  if (at + n > b->len) n = b->len - at;
  memmove(b->data + at, b->data + at + n, b->len - at - n);
  b->len -= n;
}

static int mm_num_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

/* The whole file at `path` (caller frees), its size in *len; NULL when it
 * cannot be read. */
static char *mm_read_file(const char *path, size_t *len) {
  FILE *f = fopen(path, "rb");
  char *data;
  long size;
  if (!f) return NULL;
  if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
    fclose(f);
    return NULL;
  }
  data = (char *)malloc((size_t)size + 1);
  if (data && fread(data, 1, (size_t)size, f) != (size_t)size) {
    free(data);
    data = NULL;
  }
  fclose(f);
  *len = (size_t)size;
  return data;
}

#endif
