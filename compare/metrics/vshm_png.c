/* vshm_png.c - see vshm_png.h. libpng reports errors with longjmp; each
 * libpng call sequence lives in its own function (read_body, write_body)
 * whose caller owns every resource, so nothing modified after setjmp is a
 * local of the function that called setjmp (C11 7.13.2.1: such locals are
 * indeterminate after longjmp unless volatile). */
#include "vshm_png.h"

#include "vshm_atomic.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <png.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Shared by the libpng callbacks and the code around them. */
typedef struct png_job {
  const char *path;
  char *err;
  size_t errlen;
  FILE *fp;
  /* read side */
  unsigned char *data;  /* decoded rows, rowbytes * height */
  png_bytep *rows;
  int width, height, depth;
  int channels; /* wanted: 1 (grayscale) or 3 (RGB; an alpha channel is dropped) */
} png_job;

static void set_err(char *err, size_t errlen, const char *fmt, ...) {
  if (!err || errlen == 0) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

/* libpng's default error handler prints to stderr; a library must not. */
static void on_png_error(png_structp png, png_const_charp msg) {
  png_job *job = (png_job *)png_get_error_ptr(png);
  set_err(job->err, job->errlen, "%s: corrupt or unsupported PNG (%s)", job->path, msg);
  png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg) {
  (void)png;
  (void)msg; /* warnings (e.g. a bad gAMA chunk) do not affect the samples */
}

static const char *color_type_name(int ct) {
  switch (ct) {
    case PNG_COLOR_TYPE_GRAY: return "grayscale";
    case PNG_COLOR_TYPE_GRAY_ALPHA: return "gray+alpha";
    case PNG_COLOR_TYPE_RGB: return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
    case PNG_COLOR_TYPE_PALETTE: return "palette";
    default: return "unknown colour type";
  }
}

/* Largest image accepted: keeps width * height * sizeof(float) and the
 * doubled grid of the edge metric far from overflow, and stops a forged
 * header from making us allocate gigabytes. 16384^2 is plenty for renders. */
#define VSHM_PNG_MAX_PIXELS (16384L * 16384L)

/* Returns 0, or -1 with job->err set. Allocates job->data and job->rows. */
static int read_body(png_job *job, png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png))) return -1;
  png_init_io(png, job->fp);
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);

  png_uint_32 w = png_get_image_width(png, info);
  png_uint_32 h = png_get_image_height(png, info);
  int ct = png_get_color_type(png, info);
  int depth = png_get_bit_depth(png, info);
  int rgb = ct == PNG_COLOR_TYPE_RGB || ct == PNG_COLOR_TYPE_RGB_ALPHA;
  if (job->channels == 1 ? ct != PNG_COLOR_TYPE_GRAY : !rgb) {
    set_err(job->err, job->errlen, "%s: expected %s, got %s", job->path,
            job->channels == 1 ? "grayscale" : "RGB or RGBA", color_type_name(ct));
    return -1;
  }
  if (w == 0 || h == 0 || w > INT_MAX || h > INT_MAX ||
      (double)w * (double)h > (double)VSHM_PNG_MAX_PIXELS) {
    set_err(job->err, job->errlen, "%s: unsupported size %lux%lu", job->path,
            (unsigned long)w, (unsigned long)h);
    return -1;
  }
  if (depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  /* Colour renders may carry alpha (VTK's PNG writer); the colour is what
   * is compared, so it is dropped. */
  if (ct == PNG_COLOR_TYPE_RGB_ALPHA) png_set_strip_alpha(png);
  /* A tRNS chunk would turn into an alpha channel only with png_set_expand
   * or png_set_tRNS_to_alpha, neither of which is called: it is ignored. */
  png_set_interlace_handling(png);
  png_read_update_info(png, info);

  size_t rowbytes = png_get_rowbytes(png, info);
  size_t bps = depth == 16 ? 2 : 1;
  if (rowbytes != (size_t)w * bps * (size_t)job->channels) {
    set_err(job->err, job->errlen, "%s: unexpected row layout", job->path);
    return -1;
  }
  job->data = malloc(rowbytes * h);
  job->rows = malloc(sizeof(png_bytep) * h);
  if (!job->data || !job->rows) {
    set_err(job->err, job->errlen, "%s: out of memory for %lux%lu image", job->path,
            (unsigned long)w, (unsigned long)h);
    return -1;
  }
  for (png_uint_32 y = 0; y < h; ++y) job->rows[y] = job->data + (size_t)y * rowbytes;
  png_read_image(png, job->rows);
  /* Reads up to IEND, so a file cut after the pixel data is still caught. */
  png_read_end(png, NULL);
  job->width = (int)w;
  job->height = (int)h;
  job->depth = depth;
  return 0;
}

/* Reads `channels` (1: grayscale, 3: RGB) samples per pixel as floats. */
static int read_png(const char *path, int channels, float **pixels, int *width,
                    int *height, int *bit_depth, char *err, size_t errlen) {
  *pixels = NULL;
  png_job job;
  memset(&job, 0, sizeof job);
  job.path = path;
  job.err = err;
  job.errlen = errlen;
  job.channels = channels;

  job.fp = fopen(path, "rb");
  if (!job.fp) {
    set_err(err, errlen, "%s: cannot open (%s)", path, strerror(errno));
    return -1;
  }
  unsigned char sig[8];
  if (fread(sig, 1, 8, job.fp) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
    set_err(err, errlen, "%s: not a PNG file", path);
    fclose(job.fp);
    return -1;
  }
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : NULL;
  int rc = -1;
  if (!png || !info) {
    set_err(err, errlen, "%s: out of memory", path);
  } else {
    rc = read_body(&job, png, info);
  }
  png_destroy_read_struct(png ? &png : NULL, info ? &info : NULL, NULL);
  fclose(job.fp);

  float *out = NULL;
  if (rc == 0) {
    size_t n = (size_t)job.width * (size_t)job.height * (size_t)channels;
    out = malloc(n * sizeof *out);
    if (!out) {
      set_err(err, errlen, "%s: out of memory", path);
      rc = -1;
    } else if (job.depth == 16) {
      /* PNG stores 16-bit samples big-endian; no png_set_swap, so decode
       * by hand, which is right on any host byte order. */
      for (size_t i = 0; i < n; ++i) {
        unsigned s = ((unsigned)job.data[2 * i] << 8) | job.data[2 * i + 1];
        out[i] = (float)s / 65535.0f;
      }
    } else {
      for (size_t i = 0; i < n; ++i) out[i] = (float)job.data[i] / 255.0f;
    }
  }
  free(job.rows);
  free(job.data);
  if (rc != 0) {
    free(out);
    return -1;
  }
  *pixels = out;
  *width = job.width;
  *height = job.height;
  if (bit_depth) *bit_depth = job.depth;
  return 0;
}

int vshm_png_read_gray(const char *path, float **pixels, int *width, int *height,
                       int *bit_depth, char *err, size_t errlen) {
  return read_png(path, 1, pixels, width, height, bit_depth, err, errlen);
}

int vshm_png_read_rgb(const char *path, float **rgb, int *width, int *height, int *bit_depth,
                      char *err, size_t errlen) {
  return read_png(path, 3, rgb, width, height, bit_depth, err, errlen);
}

/* Encodes already-packed rows (PNG byte order) into job->fp. */
static int write_body(png_job *job, png_structp png, png_infop info,
                      const unsigned char *packed, int width, int height,
                      int color_type, int depth, size_t rowbytes) {
  if (setjmp(png_jmpbuf(png))) return -1;
  png_init_io(png, job->fp);
  png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, depth, color_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, (png_const_bytep)(packed + (size_t)y * rowbytes));
  png_write_end(png, NULL);
  return 0;
}

static int write_png(const char *path, const unsigned char *packed, int width, int height,
                     int color_type, int depth, int channels, char *err, size_t errlen) {
  if (!path || !packed || width <= 0 || height <= 0 ||
      (double)width * (double)height > (double)VSHM_PNG_MAX_PIXELS) {
    set_err(err, errlen, "%s: invalid image (%dx%d)", path ? path : "(null)", width,
            height);
    return -1;
  }
  vshm_atomic_file af;
  if (vshm_atomic_open(&af, path, err, errlen) != 0) return -1;

  png_job job;
  memset(&job, 0, sizeof job);
  job.path = path;
  job.err = err;
  job.errlen = errlen;
  job.fp = af.fp;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : NULL;
  int rc = -1;
  if (!png || !info) {
    set_err(err, errlen, "%s: out of memory", path);
  } else {
    size_t rowbytes = (size_t)width * (size_t)channels * (size_t)(depth / 8);
    rc = write_body(&job, png, info, packed, width, height, color_type, depth, rowbytes);
  }
  png_destroy_write_struct(png ? &png : NULL, info ? &info : NULL);
  if (rc != 0) {
    vshm_atomic_abort(&af);
    return -1;
  }
  return vshm_atomic_commit(&af, err, errlen);
}

int vshm_png_write_gray8(const char *path, const unsigned char *pixels, int width,
                         int height, char *err, size_t errlen) {
  return write_png(path, pixels, width, height, PNG_COLOR_TYPE_GRAY, 8, 1, err, errlen);
}

int vshm_png_write_rgb8(const char *path, const unsigned char *rgb, int width, int height,
                        char *err, size_t errlen) {
  return write_png(path, rgb, width, height, PNG_COLOR_TYPE_RGB, 8, 3, err, errlen);
}

int vshm_png_write_gray16(const char *path, const uint16_t *pixels, int width, int height,
                          char *err, size_t errlen) {
  if (!pixels || width <= 0 || height <= 0 ||
      (double)width * (double)height > (double)VSHM_PNG_MAX_PIXELS)
    return write_png(path, NULL, width, height, PNG_COLOR_TYPE_GRAY, 16, 1, err, errlen);
  size_t n = (size_t)width * (size_t)height;
  unsigned char *be = malloc(2 * n);
  if (!be) {
    set_err(err, errlen, "%s: out of memory", path ? path : "(null)");
    return -1;
  }
  for (size_t i = 0; i < n; ++i) { /* PNG wants big-endian samples */
    be[2 * i] = (unsigned char)(pixels[i] >> 8);
    be[2 * i + 1] = (unsigned char)(pixels[i] & 0xff);
  }
  int rc = write_png(path, be, width, height, PNG_COLOR_TYPE_GRAY, 16, 1, err, errlen);
  free(be);
  return rc;
}

int vshm_png_write_gray16_float(const char *path, const float *v, int width, int height,
                                char *err, size_t errlen) {
  if (!v || width <= 0 || height <= 0 ||
      (double)width * (double)height > (double)VSHM_PNG_MAX_PIXELS)
    return vshm_png_write_gray16(path, NULL, width, height, err, errlen);
  size_t n = (size_t)width * (size_t)height;
  uint16_t *s = malloc(n * sizeof *s);
  if (!s) {
    set_err(err, errlen, "%s: out of memory", path ? path : "(null)");
    return -1;
  }
  for (size_t i = 0; i < n; ++i) {
    float x = v[i];
    if (!(x > 0.0f)) x = 0.0f; /* also NaN */
    if (x > 1.0f) x = 1.0f;
    s[i] = (uint16_t)lrintf(x * 65535.0f);
  }
  int rc = vshm_png_write_gray16(path, s, width, height, err, errlen);
  free(s);
  return rc;
}
