/* vshm_boundary.c - see vshm_boundary.h. */
#include "vshm_boundary.h"

#include <string.h>

long vshm_boundary_cracks(const float *v, const unsigned char *valid, int width,
                          int height, unsigned char *cracks) {
  int w2 = 2 * width - 1;
  int h2 = 2 * height - 1;
  memset(cracks, 0, (size_t)w2 * (size_t)h2);
  long count = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      size_t i = (size_t)y * width + x;
      if (!valid[i]) continue;
      int lit = vshm_is_lit(v[i]);
      /* Look right and down only, so each crack is found once. */
      if (x + 1 < width && valid[i + 1] && vshm_is_lit(v[i + 1]) != lit) {
        cracks[(size_t)(2 * y) * w2 + (2 * x + 1)] = 1;
        ++count;
      }
      if (y + 1 < height && valid[i + width] && vshm_is_lit(v[i + width]) != lit) {
        cracks[(size_t)(2 * y + 1) * w2 + (2 * x)] = 1;
        ++count;
      }
    }
  }
  return count;
}

void vshm_crack_pixels(int cx, int cy, int width, long *a, long *b) {
  if (cx & 1) { /* between (cx-1)/2 and (cx+1)/2 on row cy/2 */
    long row = (long)(cy / 2) * width;
    *a = row + (cx - 1) / 2;
    *b = row + (cx + 1) / 2;
  } else { /* between rows (cy-1)/2 and (cy+1)/2 in column cx/2 */
    *a = (long)((cy - 1) / 2) * width + cx / 2;
    *b = (long)((cy + 1) / 2) * width + cx / 2;
  }
}
