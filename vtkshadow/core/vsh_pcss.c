/* vsh_pcss.c - PCSS penumbra sizes (vsh_pcss.h). */
#include "vsh_pcss.h"

#include <math.h>

#define VSH_PCSS_PI 3.14159265358979323846

double vsh_pcss_light_term(int positional, double radius, double angle_deg) {
  if (positional) {
    return (isfinite(radius) && radius > 0.0) ? radius : 0.0;
  }
  if (!isfinite(angle_deg) || !(angle_deg > 0.0) || angle_deg >= 180.0) {
    return 0.0;
  }
  return tan(0.5 * angle_deg * VSH_PCSS_PI / 180.0);
}

double vsh_pcss_sun_halfwidth(double t, double d_receiver, double d_blocker) {
  if (!isfinite(t) || !isfinite(d_receiver) || !isfinite(d_blocker) || t < 0.0) {
    return -1.0;
  }
  if (t == 0.0 || d_blocker >= d_receiver) {
    return 0.0;
  }
  return t * (d_receiver - d_blocker);
}

double vsh_pcss_disk_halfwidth(double r, double d_receiver, double d_blocker) {
  if (!isfinite(r) || !isfinite(d_receiver) || !isfinite(d_blocker) || r < 0.0) {
    return -1.0;
  }
  if (r == 0.0 || d_receiver <= 0.0 || d_blocker <= 0.0 || d_blocker >= d_receiver) {
    return 0.0;
  }
  /* r (1 / d_blocker - 1 / d_receiver): the same value, without the
   * product d_receiver d_blocker that underflows at 1e-200 scales. */
  return r * (1.0 / d_blocker - 1.0 / d_receiver);
}

double vsh_pcss_kernel_texels(double halfwidth, double texel, double max_texels) {
  if (isnan(halfwidth) || !(halfwidth > 0.0) || !isfinite(texel) || !(texel > 0.0) ||
      !isfinite(max_texels) || !(max_texels > 0.0)) {
    return 0.0;
  }
  {
    const double texels = halfwidth / texel; /* +inf for an overflowing ratio */
    return texels < max_texels ? texels : max_texels;
  }
}
