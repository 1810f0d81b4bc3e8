/* vsh_transmit.c - the transmittance of translucent crossings. */
#include "vsh_transmit.h"

static double clamp01(double v, double nan_value) {
  if (!(v == v)) return nan_value;
  return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
}

void vsh_transmit_crossing(const double color[3], double opacity, double filter,
                           double out[3]) {
  const double a = clamp01(opacity, 1.0), f = clamp01(filter, 0.0);
  for (int k = 0; k < 3; ++k) {
    out[k] = (1.0 - a) * ((1.0 - f) + f * clamp01(color[k], 0.0));
  }
}

void vsh_transmit_accumulate(const double color[3], double opacity, double filter,
                             double inout[3]) {
  double t[3];
  vsh_transmit_crossing(color, opacity, filter, t);
  for (int k = 0; k < 3; ++k) inout[k] *= t[k];
}

int vsh_transmit_passes(double opacity) { return clamp01(opacity, 1.0) < 1.0; }

int vsh_transmit_steps(double transmit) {
  const double t = clamp01(transmit, 0.0);
  double left = t;
  int k = 1;
  while (left >= 1.0 / 510.0 && k < 255) {
    left *= t;
    ++k;
  }
  return k;
}
