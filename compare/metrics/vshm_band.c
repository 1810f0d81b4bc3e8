/* vshm_band.c - vshm_boundary_band: the pixels near v_ref's shadow boundary.
 * A pixel is in the band when a valid pixel of the opposite state lies in
 * the (2r+1)^2 square around it, i.e. when it is inside the square
 * dilation of the other state's pixels. Square dilation separates into a
 * row pass and a column pass; each uses a running count, so the cost does
 * not grow with the radius. */
#include "vshm_boundary.h"
#include "vshm_metrics.h"
#include "vshm_metrics_size.h"

#include <stdlib.h>
#include <string.h>

/* out[i] = 1 when some in[j] != 0 with j in the window [i-r, i+r] of the
 * n elements in[0], in[stride], ...; prefix is scratch of n + 1 ints. */
static void dilate_1d(const unsigned char *in, unsigned char *out, int n, size_t stride,
                      int r, int *prefix) {
  prefix[0] = 0;
  for (int i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + (in[(size_t)i * stride] != 0);
  for (int i = 0; i < n; ++i) {
    int lo = i - r < 0 ? 0 : i - r;
    int hi = i + r >= n ? n - 1 : i + r;
    out[(size_t)i * stride] = prefix[hi + 1] - prefix[lo] > 0;
  }
}

/* Square dilation of a width * height mask by radius r, in place. */
static void dilate_square(unsigned char *mask, unsigned char *tmp, int width, int height,
                          int r, int *prefix) {
  for (int y = 0; y < height; ++y)
    dilate_1d(mask + (size_t)y * width, tmp + (size_t)y * width, width, 1, r, prefix);
  for (int x = 0; x < width; ++x) dilate_1d(tmp + x, mask + x, height, width, r, prefix);
}

int vshm_boundary_band(const float *v_ref, const unsigned char *valid, int width,
                       int height, int radius, unsigned char *band) {
  if (!v_ref || !valid || !band || radius < 0 || !vshm_metrics_size_ok(width, height))
    return VSHM_METRICS_EINVAL;
  size_t n = (size_t)width * (size_t)height;
  memset(band, 0, n);
  if (radius == 0) return VSHM_METRICS_OK;
  /* Beyond the image size a larger radius changes nothing. */
  int m = width > height ? width : height;
  if (radius > m) radius = m;

  /* one block: lit, shadow (both dilated in place), the original lit
   * state, and scratch */
  unsigned char *buf = malloc(4 * n);
  int *prefix = malloc(sizeof(int) * ((size_t)m + 1));
  if (!buf || !prefix) {
    free(buf);
    free(prefix);
    return VSHM_METRICS_ENOMEM;
  }
  unsigned char *lit = buf, *shadow = buf + n, *state = buf + 2 * n, *tmp = buf + 3 * n;
  for (size_t i = 0; i < n; ++i) {
    state[i] = (unsigned char)vshm_is_lit(v_ref[i]);
    lit[i] = valid[i] && state[i];
    shadow[i] = valid[i] && !state[i];
  }
  dilate_square(lit, tmp, width, height, radius, prefix);    /* near a lit pixel */
  dilate_square(shadow, tmp, width, height, radius, prefix); /* near a shadowed one */
  for (size_t i = 0; i < n; ++i)
    if (valid[i]) band[i] = state[i] ? shadow[i] : lit[i];
  free(buf);
  free(prefix);
  return VSHM_METRICS_OK;
}
