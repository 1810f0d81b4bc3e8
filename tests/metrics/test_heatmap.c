/* test_heatmap.c - colours of the signed error heat map. */
#include "vsh_check.h"
#include "vshm_metrics.h"

int main(void) {
  float v[6] = {0.5f, 0.0f, 1.0f, 0.25f, 0.75f, 0.0f};
  float r[6] = {0.5f, 1.0f, 0.0f, 0.75f, 0.25f, 1.0f};
  unsigned char valid[6] = {1, 1, 1, 1, 1, 0};
  unsigned char rgb[18];
  CHECK(vshm_error_heatmap_rgb(v, r, valid, 3, 2, rgb) == VSHM_METRICS_OK);
  const unsigned char want[6][3] = {
      {255, 255, 255}, /* exact: white */
      {0, 0, 255},     /* v too dark by 1: blue */
      {255, 0, 0},     /* v too bright by 1: red */
      {128, 128, 255}, /* too dark by 0.5: half blue (lrint(127.5) = 128) */
      {255, 128, 128}, /* too bright by 0.5: half red */
      {128, 128, 128}, /* invalid: grey */
  };
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) CHECK(rgb[3 * i + c] == want[i][c]);
  CHECK(vshm_error_heatmap_rgb(v, r, valid, 3, 2, NULL) == VSHM_METRICS_EINVAL);
  return vsh_check_report("metrics.heatmap");
}
