/* vsh_volume_cost.c - the shadow-volume cost model (see vsh_volume_cost.h). */
#include "vsh_volume_cost.h"

#include <math.h>

/* Fitted by
 *   tests/gl-run.sh build/bin/vtkshadow-python bench/bench_volume_cost.py \
 *       --bin build/bin --out DIR --rounds 8 --frames 8
 * (3 runs of its 15 scenes refitted together with --refit: 45 rows), on the
 * project's VM (2 cores of an AMD EPYC, Mesa llvmpipe under Xvfb, Release
 * build) at a load average of about 5: each row is
 * the median over interleaved rounds of volume's round median minus none's,
 * and single rows moved by 2-10x between runs. Residuals of the fit: within
 * a factor of 2 on most rows, 5x on the worst. The triangle term is large
 * (the pre-pass alone should cost about what a `none` frame's geometry
 * does): a cost the pass pays per scene triangle beyond its depth pre-pass,
 * or the interleaved timing's switching; re-fit on a quiet machine. */
const double VSH_VOLUME_MS_PER_PIXEL = 8.021e-06;
const double VSH_VOLUME_MS_PER_TRIANGLE = 1.217e-03;
const double VSH_VOLUME_MS_PER_EDGE = 1.167e-02;
const double VSH_VOLUME_MS_PER_FILL_PX = 5.808e-06;

static int usable(double x)
{
  return !isnan(x) && x >= 0.0;
}

double vsh_volume_cost_ms(const vsh_volume_ms_input *in)
{
  if (!in || !usable(in->pixels) || !usable(in->scene_triangles) ||
      !usable(in->silhouette_edges) || !usable(in->fill_px))
    return INFINITY;
  const double ms = VSH_VOLUME_MS_PER_PIXEL * in->pixels +
                    VSH_VOLUME_MS_PER_TRIANGLE * in->scene_triangles +
                    VSH_VOLUME_MS_PER_EDGE * in->silhouette_edges +
                    VSH_VOLUME_MS_PER_FILL_PX * in->fill_px;
  return isfinite(ms) ? ms : INFINITY;
}

double vsh_volume_predicted_error(int unsupported_casters, int soft_light)
{
  return unsupported_casters > 0 || soft_light ? INFINITY : 0.0;
}
