/* exact_field.h - the per-pixel exact values of exact_penumbra and
 * exact_terminator as a file, so that tests/harness/exact_cache.py can keep
 * them and later runs compare against them without integrating again.
 *
 * Layout: "VSHFIELD" (8 bytes), then width, height and the values per pixel
 * as three int32, then width * height * per-pixel doubles, row by row, all
 * in the machine's byte order. Doubles, not PNG levels: a run that reads a
 * field back computes from the very numbers it would have integrated, so its
 * output is byte for byte that of a run that integrates. */
#ifndef EXACT_FIELD_H
#define EXACT_FIELD_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const char exact_field_magic[8] = {'V', 'S', 'H', 'F', 'I', 'E', 'L', 'D'};

/* Takes a leading "--field-in F" or "--field-out F" off the command line:
 * *in or *out is set to F (the other stays NULL) and argc/argv move past
 * the pair. */
static void exact_field_options(int *argc, char ***argv, const char **in, const char **out) {
  *in = *out = NULL;
  if (*argc <= 2) return;
  if (strcmp((*argv)[1], "--field-in") == 0)
    *in = (*argv)[2];
  else if (strcmp((*argv)[1], "--field-out") == 0)
    *out = (*argv)[2];
  else
    return;
  (*argv)[2] = (*argv)[0]; /* the program name stays first */
  *argc -= 2, *argv += 2;
}

/* Writes the field to path. Returns 0, or -1 with err set. */
static int exact_field_write(const char *path, const double *v, int w, int h, int per_pixel,
                             char *err, size_t errlen) {
  const int32_t dims[3] = {w, h, per_pixel};
  const size_t n = (size_t)w * h * per_pixel;
  FILE *f = fopen(path, "wb");
  if (!f) return snprintf(err, errlen, "cannot write %s", path), -1;
  int bad = fwrite(exact_field_magic, 1, sizeof exact_field_magic, f) != sizeof exact_field_magic ||
            fwrite(dims, sizeof dims[0], 3, f) != 3 || fwrite(v, sizeof *v, n, f) != n;
  if (fclose(f) != 0 || bad) return snprintf(err, errlen, "cannot write %s", path), -1;
  return 0;
}

/* Reads a field of exactly w x h x per_pixel values from path into v.
 * Returns 0, or -1 with err set (unreadable, another size, short or long). */
static int exact_field_read(const char *path, double *v, int w, int h, int per_pixel, char *err,
                            size_t errlen) {
  char magic[sizeof exact_field_magic];
  int32_t dims[3];
  const size_t n = (size_t)w * h * per_pixel;
  FILE *f = fopen(path, "rb");
  if (!f) return snprintf(err, errlen, "cannot read %s", path), -1;
  int bad = fread(magic, 1, sizeof magic, f) != sizeof magic ||
            memcmp(magic, exact_field_magic, sizeof magic) != 0 ||
            fread(dims, sizeof dims[0], 3, f) != 3 || dims[0] != w || dims[1] != h ||
            dims[2] != per_pixel || fread(v, sizeof *v, n, f) != n || fgetc(f) != EOF;
  fclose(f);
  if (bad)
    return snprintf(err, errlen, "%s is not a %dx%d field of %d value(s) per pixel", path, w, h,
                    per_pixel),
           -1;
  return 0;
}

#endif
