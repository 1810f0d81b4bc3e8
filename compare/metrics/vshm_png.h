/* vshm_png.h - the PNG files the metrics read and write.
 *
 * Visibility images are 16-bit grayscale (65535 = 1.0), masks 8-bit
 * grayscale (non-zero = set), heat maps 8-bit RGB; row 0 is the top row.
 * Sample values are taken as stored: gAMA/sRGB/iCCP chunks are ignored,
 * because the harness stores linear visibility, not display colours.
 *
 * Only grayscale is read. Taking "the first channel" of an RGB or
 * gray+alpha file would hide a pipeline mistake (a colour render passed
 * where a visibility image was expected), so such files are rejected.
 *
 * Every function reports problems as one line in err (may be NULL),
 * "<file>: <problem>", and never prints: the caller decides what to show.
 */
#ifndef VSHM_PNG_H
#define VSHM_PNG_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Reads a grayscale PNG (bit depth 1, 2, 4, 8 or 16; low depths are scaled
 * to the full range) into *pixels, width * height floats in [0,1], row
 * major, top row first: value / (2^depth - 1). *bit_depth (may be NULL)
 * gets the depth stored in the file. The caller free()s *pixels.
 * Returns 0, or -1 with err set and *pixels = NULL. */
int vshm_png_read_gray(const char *path, float **pixels, int *width, int *height,
                       int *bit_depth, char *err, size_t errlen);

/* Reads an RGB or RGBA PNG (bit depth 8 or 16; alpha is dropped) into
 * *rgb, 3 * width * height floats in [0,1] (R, G, B per pixel, row major,
 * top row first), for colour comparisons (vshm_reflection_mae). Grayscale
 * and palette files are refused, as the gray reader refuses colour.
 * Returns 0, or -1 with err set and *rgb = NULL. */
int vshm_png_read_rgb(const char *path, float **rgb, int *width, int *height, int *bit_depth,
                      char *err, size_t errlen);

/* Write width * height samples, row major, top row first, atomically
 * (see vshm_atomic.h). Return 0, or -1 with err set and nothing left on
 * disk (the destination, if it existed, is unchanged). */
int vshm_png_write_gray8(const char *path, const unsigned char *pixels, int width,
                         int height, char *err, size_t errlen);
int vshm_png_write_gray16(const char *path, const uint16_t *pixels, int width, int height,
                          char *err, size_t errlen);
/* rgb: 3 bytes per pixel, R G B. */
int vshm_png_write_rgb8(const char *path, const unsigned char *rgb, int width, int height,
                        char *err, size_t errlen);

/* Writes a visibility image as 16-bit grayscale: values are clamped to
 * [0,1] (NaN -> 0) and rounded to the nearest of 0..65535, so reading it
 * back returns the stored value within 0.5/65535. */
int vshm_png_write_gray16_float(const char *path, const float *v, int width, int height,
                                char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
