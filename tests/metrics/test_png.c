/* test_png.c - PNG round trips (8/16-bit gray, RGB), the reader's error
 * messages, and that writes are atomic (no temp file, old file kept).
 * argv[1]: a scratch directory under the build tree; argv[2]: data dir. */
/* getpid: the writer names its temporary file <path>.tmp<pid> */
#define _POSIX_C_SOURCE 200809L

#include "vsh_check.h"
#include "vshm_png.h"

#include <unistd.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char dir[2048], data[2048];

static const char *path(const char *name) {
  static char buf[4][4096];
  static int k = 0;
  k = (k + 1) % 4;
  snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
  return buf[k];
}

static const char *data_path(const char *name) {
  static char buf[4096];
  snprintf(buf, sizeof buf, "%s/%s", data, name);
  return buf;
}

static int exists(const char *p) {
  FILE *f = fopen(p, "rb");
  if (f) fclose(f);
  return f != NULL;
}

/* No temporary file left behind: the only one this process could have
 * made for p is <p>.tmp<pid>. */
static int tmp_left(const char *p) {
  char t[4200];
  snprintf(t, sizeof t, "%s.tmp%ld", p, (long)getpid());
  return exists(t);
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: test_png SCRATCH_DIR DATA_DIR\n");
    return 2;
  }
  snprintf(dir, sizeof dir, "%s", argv[1]);
  snprintf(data, sizeof data, "%s", argv[2]);
  char err[1024];
  float *px = NULL;
  int w = 0, h = 0, depth = 0;

  /* 16-bit: every interesting value, exact back */
  enum { W16 = 7, H16 = 3 };
  uint16_t s16[W16 * H16];
  for (int i = 0; i < W16 * H16; ++i) s16[i] = (uint16_t)(i * 3121u);
  s16[0] = 0;
  s16[1] = 65535;
  s16[2] = 32768;
  s16[3] = 1;
  s16[4] = 256; /* a byte-order mistake would swap this with 1 */
  CHECK(vshm_png_write_gray16(path("g16.png"), s16, W16, H16, err, sizeof err) == 0);
  CHECK(!tmp_left(path("g16.png")));
  CHECK(vshm_png_read_gray(path("g16.png"), &px, &w, &h, &depth, err, sizeof err) == 0);
  CHECK(w == W16 && h == H16 && depth == 16);
  if (px) {
    for (int i = 0; i < W16 * H16; ++i) {
      CHECK(lrintf(px[i] * 65535.0f) == s16[i]);
      CHECK(px[i] == (float)s16[i] / 65535.0f);
    }
    CHECK(px[0] == 0.0f && px[1] == 1.0f);
  }
  free(px);

  /* 8-bit: all 256 values, rows in order (row 0 = top) */
  enum { W8 = 32, H8 = 8 };
  unsigned char s8[W8 * H8];
  for (int i = 0; i < W8 * H8; ++i) s8[i] = (unsigned char)i;
  CHECK(vshm_png_write_gray8(path("g8.png"), s8, W8, H8, err, sizeof err) == 0);
  CHECK(vshm_png_read_gray(path("g8.png"), &px, &w, &h, &depth, err, sizeof err) == 0);
  CHECK(w == W8 && h == H8 && depth == 8);
  if (px)
    for (int i = 0; i < W8 * H8; ++i) CHECK(px[i] == (float)s8[i] / 255.0f);
  free(px);

  /* float -> 16-bit: clamped and rounded */
  float fv[5] = {-0.5f, 0.25f, 1.5f, 0.5f, NAN};
  CHECK(vshm_png_write_gray16_float(path("f16.png"), fv, 5, 1, err, sizeof err) == 0);
  CHECK(vshm_png_read_gray(path("f16.png"), &px, &w, &h, NULL, err, sizeof err) == 0);
  if (px) {
    CHECK(px[0] == 0.0f && px[2] == 1.0f && px[4] == 0.0f);
    CHECK(lrintf(px[1] * 65535.0f) == 16384); /* 16383.75 rounds up */
    CHECK(lrintf(px[3] * 65535.0f) == 32768); /* 32767.5, half to even */
  }
  free(px);

  /* RGB writes, but the reader refuses it and says what it got */
  unsigned char rgb[2 * 2 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9};
  CHECK(vshm_png_write_rgb8(path("rgb.png"), rgb, 2, 2, err, sizeof err) == 0);
  px = (float *)1;
  CHECK(vshm_png_read_gray(path("rgb.png"), &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK(px == NULL);
  CHECK_STR_CONTAINS(err, "rgb.png: expected grayscale, got RGB");

  /* files written by another encoder (tests/metrics/data/make_data.py) */
  CHECK(vshm_png_read_gray(data_path("ref16.png"), &px, &w, &h, &depth, err, sizeof err) == 0);
  CHECK(w == 8 && h == 8 && depth == 16);
  if (px) CHECK(px[3] == 0.0f && px[4] == 1.0f && px[63] == 1.0f);
  free(px);
  CHECK(vshm_png_read_gray(data_path("gray_alpha8.png"), &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "gray_alpha8.png: expected grayscale, got gray+alpha");
  CHECK(vshm_png_read_gray(data_path("not_png.png"), &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "not_png.png: not a PNG file");
  CHECK(vshm_png_read_gray(data_path("truncated.png"), &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "truncated.png: corrupt");
  CHECK(vshm_png_read_gray(path("missing.png"), &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "missing.png: cannot open (No such file or directory)");
  /* an empty file is not a PNG either */
  FILE *f = fopen(path("empty.png"), "wb");
  if (f) fclose(f);
  CHECK(vshm_png_read_gray(path("empty.png"), &px, &w, &h, NULL, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "empty.png: not a PNG file");

  /* a failed write leaves nothing: directory missing */
  CHECK(vshm_png_write_gray8(path("no/such/dir/x.png"), s8, W8, H8, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "x.png: cannot create temporary file");
  CHECK(!exists(path("no/such/dir/x.png")));
  /* bad arguments: message, and the existing file is untouched */
  CHECK(vshm_png_write_gray8(path("g8.png"), s8, 0, H8, err, sizeof err) == -1);
  CHECK_STR_CONTAINS(err, "g8.png: invalid image (0x8)");
  CHECK(vshm_png_write_gray16(path("g8.png"), NULL, W8, H8, err, sizeof err) == -1);
  CHECK(vshm_png_read_gray(path("g8.png"), &px, &w, &h, &depth, err, sizeof err) == 0);
  CHECK(w == W8 && h == H8 && depth == 8);
  free(px);
  CHECK(!tmp_left(path("g8.png")));

  /* overwriting replaces the file */
  unsigned char one[1] = {7};
  CHECK(vshm_png_write_gray8(path("g8.png"), one, 1, 1, err, sizeof err) == 0);
  CHECK(vshm_png_read_gray(path("g8.png"), &px, &w, &h, NULL, err, sizeof err) == 0);
  CHECK(w == 1 && h == 1 && px && px[0] == 7.0f / 255.0f);
  free(px);

  /* err may be NULL */
  CHECK(vshm_png_read_gray(path("missing.png"), &px, &w, &h, NULL, NULL, 0) == -1);
  return vsh_check_report("metrics.png");
}
