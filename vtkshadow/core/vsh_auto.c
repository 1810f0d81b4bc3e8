/* vsh_auto.c - the conservative "may A shadow B" test behind the automatic
 * choice of technique. */
#include "vsh_auto.h"

#include "vsh_vec3.h"

#include <math.h>

int vsh_auto_may_shadow(const double a[3], double ra, const double b[3], double rb,
                        const double light[4])
{
  if (!a || !b || !light || !vsh_vec3_is_finite(a) || !vsh_vec3_is_finite(b) ||
      !isfinite(light[0]) || !isfinite(light[1]) || !isfinite(light[2]) || !isfinite(light[3]) ||
      !(ra >= 0.0) || !(rb >= 0.0) || !isfinite(ra) || !isfinite(rb))
    return 1;
  const double reach = ra + rb;
  if (light[3] == 0.0) {
    /* Directional: A's shadow is the half-cylinder of radius ra swept away
     * from the light; B touches it when B's centre is within ra + rb of the
     * axis and not entirely on the light's side of A. */
    double towards[3], away[3], ab[3];
    if (vsh_vec3_normalize(light, towards) == 0.0)
      return 1;
    vsh_vec3_scale(towards, -1.0, away);
    vsh_vec3_sub(b, a, ab);
    const double along = vsh_vec3_dot(ab, away);
    if (along < -reach)
      return 0;
    double perp[3];
    for (int k = 0; k < 3; ++k)
      perp[k] = ab[k] - along * away[k];
    return vsh_vec3_length(perp) <= reach ? 1 : 0;
  }
  /* Positional: A's shadow is the cone from the light through A's sphere,
   * beyond A. */
  double l[3], la[3], lb[3];
  for (int k = 0; k < 3; ++k)
    l[k] = light[k] / light[3];
  vsh_vec3_sub(a, l, la);
  vsh_vec3_sub(b, l, lb);
  const double da = vsh_vec3_length(la), db = vsh_vec3_length(lb);
  if (da <= ra || db <= rb)
    return 1; /* the light is inside a sphere: anything may happen */
  if (db + rb < da - ra)
    return 0; /* B entirely nearer to the light than A */
  const double cone = asin(ra / da);
  const double spread = asin(rb / db);
  const double c = vsh_vec3_dot(la, lb) / (da * db);
  const double angle = acos(c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c));
  return angle <= cone + spread ? 1 : 0;
}

int vsh_auto_box_may_shadow(const double amin[3], const double amax[3], const double bmin[3],
                            const double bmax[3], const double towards_light[3])
{
  double away[3];
  if (!amin || !amax || !bmin || !bmax || !towards_light || !vsh_vec3_is_finite(amin) ||
      !vsh_vec3_is_finite(amax) || !vsh_vec3_is_finite(bmin) || !vsh_vec3_is_finite(bmax) ||
      !vsh_vec3_is_finite(towards_light) || vsh_vec3_normalize(towards_light, away) == 0.0)
    return 1;
  vsh_vec3_scale(away, -1.0, away);
  /* B meets A + t * away for some t > 0 iff the ray t * away (t > 0) meets
   * the Minkowski difference C = B - A = [bmin - amax, bmax - amin]. */
  double t0 = 0.0, t1 = INFINITY;
  int interior = 1;
  for (int k = 0; k < 3; ++k) {
    const double lo = bmin[k] - amax[k], hi = bmax[k] - amin[k];
    if (lo > hi)
      return 1;
    interior = interior && lo < 0.0 && hi > 0.0;
    if (away[k] == 0.0) {
      if (0.0 < lo || 0.0 > hi)
        return 0;
      continue;
    }
    double ta = lo / away[k], tb = hi / away[k];
    if (ta > tb) {
      const double swap = ta;
      ta = tb;
      tb = swap;
    }
    t0 = fmax(t0, ta);
    t1 = fmin(t1, tb);
  }
  if (interior)
    return 1; /* the boxes overlap in volume */
  /* Touching at t = 0 only (t1 == 0) is no shadow. */
  return (t0 <= t1 && t1 > 0.0) ? 1 : 0;
}

int vsh_auto_on_lit_side(const double plane[4], const double light[4], const double b[3],
                         double rb)
{
  if (!plane || !light || !b || !vsh_vec3_is_finite(b) || !(rb >= 0.0) || !isfinite(rb))
    return 0;
  const double n_len = vsh_vec3_length(plane);
  if (!(n_len > 0.0) || !isfinite(n_len) || !isfinite(plane[3]))
    return 0;
  /* Signed side of the light: positive means the normal points towards it. */
  const double side = plane[0] * light[0] + plane[1] * light[1] + plane[2] * light[2] +
                      plane[3] * light[3];
  if (side == 0.0 || !isfinite(side))
    return 0;
  const double sign = side > 0.0 ? 1.0 : -1.0;
  const double distance = sign * (vsh_vec3_dot(plane, b) + plane[3]) / n_len;
  return distance >= rb ? 1 : 0;
}

double vsh_auto_texel_target(double max_wrong_pct, double pixels, double edge_length_px,
                             double stretch, double band_px)
{
  if (!isfinite(max_wrong_pct) || !isfinite(pixels) || !isfinite(edge_length_px) ||
      !isfinite(band_px) || !isfinite(stretch) || max_wrong_pct < 0.0 || band_px < 0.0 ||
      !(pixels > 0.0) || !(edge_length_px > 0.0) || !(stretch >= 1.0))
    return 0.0;
  const double t =
      2.0 * (band_px + max_wrong_pct / 100.0 * pixels / (edge_length_px * stretch));
  return isfinite(t) ? t : 0.0;
}
