/* test_png_rgb_fuzz.c - the colour PNG reader (vshm_png_read_rgb) on valid
 * files and on deterministic byte mutations of them (flips, erasures,
 * insertions; every other mutant with its chunk CRCs repaired so that it
 * reaches the decoder): it must either refuse the file with a message
 * naming it, or return an image of the size the header claims with every
 * sample in [0,1]; never crash (the sanitizer build runs this too).
 * argv[1]: a scratch directory. */
#include "vsh_check.h"
#include "vsh_mutate.h"
#include "vshm_png.h"

#include <zlib.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char dir[2048];

static int write_bytes(const char *path, const char *data, size_t len) {
  FILE *f = fopen(path, "wb");
  if (!f) return -1;
  size_t got = fwrite(data, 1, len, f);
  return fclose(f) == 0 && got == len ? 0 : -1;
}

/* Recomputes the CRC of every chunk whose length fits in the buffer, so
 * that a mutant gets past libpng's CRC check and reaches the decoder (the
 * header checks, the inflater, the row filters). */
static void fix_crcs(mm_buf *b) {
  size_t at = 8;
  const unsigned char *d = (const unsigned char *)b->data;
  while (at + 12 <= b->len) {
    size_t n = ((size_t)d[at] << 24) | ((size_t)d[at + 1] << 16) | ((size_t)d[at + 2] << 8) | d[at + 3];
    if (n > b->len - at - 12) return;
    uLong crc = crc32(0L, d + at + 4, (uInt)(n + 4));
    for (int i = 0; i < 4; ++i) b->data[at + 8 + n + i] = (char)(crc >> (24 - 8 * i));
    at += n + 12;
  }
}

/* Round trip of an 8-bit RGB file, then gray refused by the colour reader. */
static void valid_files(const char *rgb_path, const char *gray_path) {
  enum { W = 5, H = 3 };
  unsigned char rgb[3 * W * H], gray[W * H];
  for (int i = 0; i < 3 * W * H; ++i) rgb[i] = (unsigned char)(i * 17);
  for (int i = 0; i < W * H; ++i) gray[i] = (unsigned char)i;
  char err[1024];
  CHECK(vshm_png_write_rgb8(rgb_path, rgb, W, H, err, sizeof err) == 0);
  CHECK(vshm_png_write_gray8(gray_path, gray, W, H, err, sizeof err) == 0);
  float *px = NULL;
  int w = 0, h = 0, depth = 0;
  CHECK(vshm_png_read_rgb(rgb_path, &px, &w, &h, &depth, err, sizeof err) == 0);
  CHECK(w == W && h == H && depth == 8);
  for (int i = 0; px && i < 3 * W * H; ++i) CHECK(px[i] == (float)rgb[i] / 255.0f);
  free(px);
  px = (float *)1;
  CHECK(vshm_png_read_rgb(gray_path, &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK(px == NULL);
  CHECK_STR_CONTAINS(err, "expected RGB or RGBA, got grayscale");
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_png_rgb_fuzz SCRATCH_DIR\n");
    return 2;
  }
  (void)mm_num_char; /* the header's; these mutations are not about numbers */
  snprintf(dir, sizeof dir, "%s", argv[1]);
  char seed_path[2100], gray_path[2100], mut_path[2100], err[1024];
  snprintf(seed_path, sizeof seed_path, "%s/seed_rgb8.png", dir);
  snprintf(gray_path, sizeof gray_path, "%s/seed_gray8.png", dir);
  snprintf(mut_path, sizeof mut_path, "%s/mutant.png", dir);
  valid_files(seed_path, gray_path);

  size_t len = 0;
  char *seed = mm_read_file(seed_path, &len);
  CHECK(seed != NULL && len > 8);
  if (!seed) return vsh_check_report("metrics.png_rgb_fuzz");
  mm_state = 20261123;
  long accepted = 0, refused = 0;
  mm_buf b = {NULL, 0, 0};
  for (int iter = 0; iter < 3000; ++iter) {
    b.len = 0;
    mm_insert(&b, 0, seed, len);
    for (int k = 1 + (int)mm_below(4); k > 0; --k) {
      size_t at = mm_below(b.len);
      switch (mm_below(4)) {
        case 0: b.data[at] = (char)(b.data[at] ^ (1 << mm_below(8))); break;
        case 1: b.data[at] = (char)mm_next(); break;
        case 2: mm_erase(&b, at, 1 + mm_below(16)); break;
        default: {
          char junk[8];
          for (int j = 0; j < 8; ++j) junk[j] = (char)mm_next();
          mm_insert(&b, at, junk, 1 + mm_below(8));
        }
      }
    }
    if (iter % 2) fix_crcs(&b);
    if (write_bytes(mut_path, b.data, b.len) != 0) {
      CHECK(!"cannot write the mutant");
      break;
    }
    float *px = NULL;
    int w = 0, h = 0;
    err[0] = '\0';
    if (vshm_png_read_rgb(mut_path, &px, &w, &h, NULL, err, sizeof err) == 0) {
      ++accepted;
      CHECK(px != NULL && w > 0 && h > 0);
      for (long i = 0; px && i < 3L * w * h; ++i) CHECK(px[i] >= 0.0f && px[i] <= 1.0f);
    } else {
      ++refused;
      CHECK(px == NULL);
      CHECK_STR_CONTAINS(err, "mutant.png: ");
    }
    free(px);
  }
  free(b.data);
  free(seed);
  printf("png_rgb_fuzz: %ld mutants accepted, %ld refused\n", accepted, refused);
  CHECK(refused > 0);
  CHECK(accepted > 0); /* the repaired CRCs let some through to the decoder */
  return vsh_check_report("metrics.png_rgb_fuzz");
}
