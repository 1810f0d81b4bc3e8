/* vsh_rt_classify_segments.c - the plane geometry LIT (c) keeps a
 * footprint clear of concave edges with (vsh_rt_classify_internal.h). */
#include "vsh_rt_classify_internal.h"

#include <math.h>

/* Whether segment (a, b) meets the box [u0, u1] x [v0, v1] (Liang-Barsky
 * clipping of the segment's parameter to each slab). */
int vsh_rtc_segment_meets_box(const double a[2], const double b[2], double u0, double u1,
                             double v0, double v1)
{
  double t0 = 0, t1 = 1;
  const double d[2] = { b[0] - a[0], b[1] - a[1] }, lo[2] = { u0, v0 }, hi[2] = { u1, v1 };
  for (int r = 0; r < 2; ++r) {
    if (d[r] == 0) {
      if (a[r] < lo[r] || a[r] > hi[r]) {
        return 0;
      }
      continue;
    }
    double ta = (lo[r] - a[r]) / d[r], tb = (hi[r] - a[r]) / d[r];
    if (ta > tb) {
      const double swap = ta;
      ta = tb, tb = swap;
    }
    t0 = ta > t0 ? ta : t0;
    t1 = tb < t1 ? tb : t1;
  }
  return t0 <= t1;
}

/* Distance from point p to segment (a, b) in the plane. */
static double point_segment_distance(const double p[2], const double a[2], const double b[2])
{
  const double du = b[0] - a[0], dv = b[1] - a[1], l2 = du * du + dv * dv;
  double t = l2 > 0 ? ((p[0] - a[0]) * du + (p[1] - a[1]) * dv) / l2 : 0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  const double x = a[0] + t * du - p[0], y = a[1] + t * dv - p[1];
  return sqrt(x * x + y * y);
}

/* Whether segments (a, b) and (c, d) come within `reach` of each other
 * (crossing, or an end within reach of the other segment). */
int vsh_rtc_segments_within(const double a[2], const double b[2], const double c[2],
                           const double d[2], double reach)
{
  const double d1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  const double d2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
  const double d3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
  const double d4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
  if (((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) &&
      ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0))) {
    return 1;
  }
  return !(point_segment_distance(a, c, d) > reach && point_segment_distance(b, c, d) > reach &&
           point_segment_distance(c, a, b) > reach && point_segment_distance(d, a, b) > reach);
}
