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
 * a factor of 2 on most rows, 5x on the worst.
 *
 * The triangle term is from a run on the quiet machine (--rounds 4
 * --frames 8, load under 1), where the rows with a non-casting sphere of
 * 39,824 triangles (20 silhouette edges, little fill) isolate it: 8.7 and
 * 9.4 ms above none at 320x240 and 640x480, 1.5-2.0e-4 ms a triangle; that
 * run's fit gave 1.768e-4. The loaded fit's 1.217e-3 predicted 48 ms for
 * those rows and 79 ms of pre-pass for a 65,060-triangle sphere whose whole
 * volume frame measured 17.6 ms above none. The quiet run's edge and fill
 * terms (3.6e-3, 9.1e-7) are not taken: with them the model predicted
 * isosurface's volumes at 77 ms against 198 measured (the grids of spheres
 * do not exercise long self-overlapping silhouettes), and ranked them
 * below raytrace there. */
const double VSH_VOLUME_MS_PER_PIXEL = 8.021e-06;
const double VSH_VOLUME_MS_PER_TRIANGLE = 1.768e-04;
const double VSH_VOLUME_MS_PER_EDGE = 1.167e-02;
const double VSH_VOLUME_MS_PER_FILL_PX = 5.808e-06;

static int usable(double x)
{
  return !isnan(x) && x >= 0.0;
}

double vsh_volume_cost_ms(const vsh_volume_ms_input *in)
{
  if (!in || !usable(in->pixels) || !usable(in->scene_triangles) ||
      !usable(in->silhouette_edges) || !usable(in->fill_px) || !usable(in->cap_triangles))
    return INFINITY;
  const double ms = VSH_VOLUME_MS_PER_PIXEL * in->pixels +
                    VSH_VOLUME_MS_PER_TRIANGLE * (in->scene_triangles + in->cap_triangles) +
                    VSH_VOLUME_MS_PER_EDGE * in->silhouette_edges +
                    VSH_VOLUME_MS_PER_FILL_PX * in->fill_px;
  return isfinite(ms) ? ms : INFINITY;
}

double vsh_volume_predicted_error(int unsupported_casters, int soft_light)
{
  return unsupported_casters > 0 || soft_light ? INFINITY : 0.0;
}
