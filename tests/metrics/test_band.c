/* test_band.c - vshm_boundary_band against its definition. */
#include "vsh_check.h"
#include "vshm_metrics.h"

#include <stdlib.h>

#define W 12
#define H 9
static float r[W * H];
static unsigned char valid[W * H], band[W * H];

/* brute force: a valid pixel of the opposite state within Chebyshev radius */
static int expected(int x, int y, int rad) {
  int i = y * W + x;
  if (!valid[i]) return 0;
  int lit = r[i] >= 0.5f;
  for (int dy = -rad; dy <= rad; ++dy)
    for (int dx = -rad; dx <= rad; ++dx) {
      int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
      int j = yy * W + xx;
      if (valid[j] && (r[j] >= 0.5f) != lit) return 1;
    }
  return 0;
}

static int count(void) {
  int n = 0;
  for (int i = 0; i < W * H; ++i) n += band[i] != 0;
  return n;
}

int main(void) {
  /* straight vertical edge between columns 4 and 5 */
  for (int i = 0; i < W * H; ++i) {
    r[i] = (i % W) < 5 ? 0.0f : 1.0f;
    valid[i] = 1;
  }
  CHECK(vshm_boundary_band(r, valid, W, H, 0, band) == VSHM_METRICS_OK);
  CHECK(count() == 0); /* radius 0: no band */
  CHECK(vshm_boundary_band(r, valid, W, H, 1, band) == VSHM_METRICS_OK);
  CHECK(count() == 2 * H); /* columns 4 and 5 */
  for (int y = 0; y < H; ++y) CHECK(band[y * W + 4] && band[y * W + 5]);
  CHECK(vshm_boundary_band(r, valid, W, H, 2, band) == VSHM_METRICS_OK);
  CHECK(count() == 4 * H); /* columns 3..6 */
  CHECK(vshm_boundary_band(r, valid, W, H, 1000, band) == VSHM_METRICS_OK);
  CHECK(count() == W * H); /* a huge radius is clamped, covers everything */

  /* no boundary: empty band */
  for (int i = 0; i < W * H; ++i) r[i] = 0.3f;
  CHECK(vshm_boundary_band(r, valid, W, H, 3, band) == VSHM_METRICS_OK);
  CHECK(count() == 0);

  /* random references and masks against the brute force, radii 1..4 */
  unsigned long s = 99;
  for (int t = 0; t < 30; ++t) {
    for (int i = 0; i < W * H; ++i) {
      s = s * 6364136223846793005UL + 1442695040888963407UL;
      unsigned u = (unsigned)(s >> 33);
      r[i] = (u % 7 < 2) ? 0.1f : 0.9f;
      valid[i] = (u / 7) % 10 != 0;
    }
    int rad = 1 + t % 4;
    CHECK(vshm_boundary_band(r, valid, W, H, rad, band) == VSHM_METRICS_OK);
    int bad = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) bad += (band[y * W + x] != 0) != expected(x, y, rad);
    CHECK(bad == 0);
  }

  CHECK(vshm_boundary_band(r, valid, W, H, -1, band) == VSHM_METRICS_EINVAL);
  CHECK(vshm_boundary_band(NULL, valid, W, H, 1, band) == VSHM_METRICS_EINVAL);
  return vsh_check_report("metrics.band");
}
