/* test_edge.c - edge_px: known shifts, the no-boundary conventions, exclude,
 * and a brute-force crack-to-crack distance on random images. */
#include "vsh_check.h"
#include "vshm_metrics.h"

#include <math.h>
#include <stdlib.h>

static unsigned long rng_state = 777;
static unsigned rng(void) {
  rng_state = rng_state * 6364136223846793005UL + 1442695040888963407UL;
  return (unsigned)(rng_state >> 33);
}

/* Crack midpoints in pixel coordinates, found independently of the
 * library: between 4-adjacent valid pixels of different state (>= 0.5). */
typedef struct pt {
  double x, y;
  int a, b; /* the two pixels */
} pt;

static int cracks(const float *v, const unsigned char *valid, int w, int h, pt *out) {
  int n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int i = y * w + x;
      if (!valid[i]) continue;
      if (x + 1 < w && valid[i + 1] && (v[i] >= 0.5f) != (v[i + 1] >= 0.5f))
        out[n++] = (pt){x + 0.5, y, i, i + 1};
      if (y + 1 < h && valid[i + w] && (v[i] >= 0.5f) != (v[i + w] >= 0.5f))
        out[n++] = (pt){x, y + 0.5, i, i + w};
    }
  return n;
}

static double brute_edge(const float *v, const float *r, const unsigned char *valid,
                         const unsigned char *ex, int w, int h) {
  pt *ct = malloc(sizeof(pt) * 2 * w * h), *cr = malloc(sizeof(pt) * 2 * w * h);
  int nt = cracks(v, valid, w, h, ct), nr = cracks(r, valid, w, h, cr);
  double diag = sqrt((double)w * w + (double)h * h), sum = 0;
  long cnt = 0;
  for (int pass = 0; pass < 2; ++pass) {
    pt *from = pass ? cr : ct, *to = pass ? ct : cr;
    int nf = pass ? nr : nt, nto = pass ? nt : nr;
    for (int i = 0; i < nf; ++i) {
      if (ex && (ex[from[i].a] || ex[from[i].b])) continue;
      double best = diag;
      if (nto > 0) {
        best = INFINITY;
        for (int j = 0; j < nto; ++j) {
          double d = hypot(from[i].x - to[j].x, from[i].y - to[j].y);
          if (d < best) best = d;
        }
      }
      sum += best;
      ++cnt;
    }
  }
  free(ct);
  free(cr);
  return cnt ? sum / cnt : 0.0;
}

#define W 64
#define H 48
static float v[W * H], r[W * H];
static unsigned char valid[W * H], ex[W * H];

static void disc(float *a, double cx, double cy, double rad) {
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      a[y * W + x] = hypot(x - cx, y - cy) <= rad ? 0.0f : 1.0f;
}

static double edge(const unsigned char *exclude) {
  double e = -1;
  CHECK(vshm_edge_px(v, r, valid, exclude, W, H, &e) == VSHM_METRICS_OK);
  return e;
}

int main(void) {
  for (int i = 0; i < W * H; ++i) valid[i] = 1;

  /* a straight shadow edge moved by k pixels: exactly k */
  for (int k = 0; k <= 6; ++k) {
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        r[y * W + x] = x < 20 ? 0.0f : 1.0f;
        v[y * W + x] = x < 20 + k ? 0.0f : 1.0f;
      }
    CHECK_NEAR(edge(NULL), (double)k, 1e-12);
    vshm_metrics m;
    CHECK(vshm_metrics_compute(v, r, valid, NULL, W, H, &m) == VSHM_METRICS_OK);
    CHECK_NEAR(m.edge_px, (double)k, 1e-12);
    CHECK_NEAR(m.wrong_pct, 100.0 * k / W, 1e-9);
  }

  /* a disc shadow grown by k pixels (radius 10 -> 10 + k): about k, the
   * rest is the staircase of the digital circle */
  for (int k = 1; k <= 5; ++k) {
    disc(r, 31.3, 23.7, 10.0);
    disc(v, 31.3, 23.7, 10.0 + k);
    CHECK_NEAR(edge(NULL), (double)k, 0.3);
  }

  /* a disc shadow moved sideways by k pixels: the sides move by k, the top
   * and bottom hardly at all, so edge_px is about (2/pi) k, not k; it must
   * match the brute force exactly */
  for (int k = 1; k <= 4; ++k) {
    disc(r, 25.3, 23.7, 12.0);
    disc(v, 25.3 + k, 23.7, 12.0);
    double e = edge(NULL);
    CHECK_NEAR(e, brute_edge(v, r, valid, NULL, W, H), 1e-9);
    CHECK_NEAR(e, 2.0 / 3.14159265358979323846 * k, 0.25 * k);
  }

  /* no boundary in either image: 0 */
  for (int i = 0; i < W * H; ++i) v[i] = r[i] = 1.0f;
  CHECK(edge(NULL) == 0.0);
  for (int i = 0; i < W * H; ++i) v[i] = 0.0f; /* all wrong, still no edge */
  CHECK(edge(NULL) == 0.0);

  /* only one has a boundary: the image diagonal, either way round */
  double diag = sqrt((double)W * W + (double)H * H);
  disc(r, 30, 20, 8);
  for (int i = 0; i < W * H; ++i) v[i] = 1.0f; /* shadow vanished */
  CHECK_NEAR(edge(NULL), diag, 1e-9);
  disc(v, 30, 20, 8);
  for (int i = 0; i < W * H; ++i) r[i] = 1.0f; /* shadow where none is */
  CHECK_NEAR(edge(NULL), diag, 1e-9);

  /* invalid pixels make no boundary: a shadow only outside the mask */
  for (int i = 0; i < W * H; ++i) {
    r[i] = 1.0f;
    v[i] = (i % W) < 10 ? 0.0f : 1.0f;
    valid[i] = (i % W) >= 10;
  }
  CHECK(edge(NULL) == 0.0);
  for (int i = 0; i < W * H; ++i) valid[i] = 1;

  /* exclude: cracks touching an excluded pixel do not contribute, but the
   * boundaries themselves do not move. Straight edges 3 apart, and the
   * left half of the rows excluded: still 3. */
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      r[y * W + x] = x < 20 ? 0.0f : 1.0f;
      v[y * W + x] = x < 23 ? 0.0f : 1.0f;
      ex[y * W + x] = y < H / 2;
    }
  CHECK_NEAR(edge(ex), 3.0, 1e-12);
  /* exclude the reference's edge columns only: the test's cracks are still
   * measured against it (distance 3), the reference's are not counted */
  for (int i = 0; i < W * H; ++i) ex[i] = (i % W) == 19 || (i % W) == 20;
  CHECK_NEAR(edge(ex), 3.0, 1e-12);
  /* everything excluded: no contribution, 0 */
  for (int i = 0; i < W * H; ++i) ex[i] = 1;
  CHECK(edge(ex) == 0.0);

  /* random images with random masks and exclusions against brute force */
  for (int t = 0; t < 40; ++t) {
    for (int i = 0; i < W * H; ++i) {
      /* blobs, not noise: threshold a coarse random pattern */
      int cx = (i % W) / 8, cy = (i / W) / 8;
      unsigned s = (unsigned)(cx * 73856093u ^ cy * 19349663u ^ (unsigned)t * 83492791u);
      r[i] = (s % 3 == 0) ? 0.2f : 0.8f;
      v[i] = (rng() % 100 < 8) ? 1.0f - r[i] : r[i]; /* 8% flipped */
      valid[i] = rng() % 100 < 95;
      ex[i] = rng() % 100 < 10;
    }
    double e = -1;
    CHECK(vshm_edge_px(v, r, valid, t % 2 ? ex : NULL, W, H, &e) == VSHM_METRICS_OK);
    CHECK_NEAR(e, brute_edge(v, r, valid, t % 2 ? ex : NULL, W, H), 1e-9);
  }

  /* 1-pixel-wide images work (the doubled grid is 1 wide) */
  {
    float a[5] = {0, 0, 1, 1, 1}, b[5] = {0, 0, 0, 1, 1};
    unsigned char m[5] = {1, 1, 1, 1, 1};
    double e = -1;
    CHECK(vshm_edge_px(a, b, m, NULL, 1, 5, &e) == VSHM_METRICS_OK);
    CHECK_NEAR(e, 1.0, 1e-12);
  }

  double e;
  CHECK(vshm_edge_px(NULL, r, valid, NULL, W, H, &e) == VSHM_METRICS_EINVAL);
  CHECK(vshm_edge_px(v, r, valid, NULL, W, H, NULL) == VSHM_METRICS_EINVAL);
  return vsh_check_report("metrics.edge");
}
