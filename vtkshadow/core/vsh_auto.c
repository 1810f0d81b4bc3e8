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

/* ---- the per-light decision --------------------------------------------- */

/* std::max's rule (a NaN b keeps a), which the VTK layer used before. */
static double max_keep(double a, double b)
{
  return a < b ? b : a;
}

void vsh_auto_object_init(vsh_auto_object *o, const double bounds[6], int receiver, int casts,
                          const double frustum[24])
{
  double diagonal2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double extent = bounds[2 * k + 1] - bounds[2 * k];
    o->center[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    diagonal2 += extent * extent;
  }
  for (int k = 0; k < 6; ++k)
    o->bounds[k] = bounds[k];
  o->radius = 0.5 * sqrt(diagonal2);
  o->receiver = receiver != 0;
  o->casts = casts != 0;
  o->flat = 0;
  for (int k = 0; k < 4; ++k)
    o->plane[k] = 0.0;
  o->in_view = frustum ? vsh_auto_sphere_in_frustum(frustum, o->center, o->radius) : 1;
}

int vsh_auto_sphere_in_frustum(const double frustum[24], const double center[3], double radius)
{
  for (int p = 0; p < 6; ++p) {
    const double *plane = frustum + 4 * p;
    const double n = sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
    if (!(plane[0] * center[0] + plane[1] * center[1] + plane[2] * center[2] + plane[3] >=
          -radius * n))
      return 0;
  }
  return 1;
}

/* Whether object a may shadow object b under light (the light's kind picks
 * the test: boxes are exact for parallel light, spheres bound the cones). */
static int may_shadow(const vsh_auto_object *a, const vsh_auto_object *b, const double light[4])
{
  if (light[3] == 0.0) {
    const double amin[3] = {a->bounds[0], a->bounds[2], a->bounds[4]};
    const double amax[3] = {a->bounds[1], a->bounds[3], a->bounds[5]};
    const double bmin[3] = {b->bounds[0], b->bounds[2], b->bounds[4]};
    const double bmax[3] = {b->bounds[1], b->bounds[3], b->bounds[5]};
    return vsh_auto_box_may_shadow(amin, amax, bmin, bmax, light) != 0;
  }
  return vsh_auto_may_shadow(a->center, a->radius, b->center, b->radius, light) != 0;
}

static vsh_auto_light_choice choice(int technique, vsh_auto_reason reason, int a, int b)
{
  vsh_auto_light_choice c;
  c.technique = technique;
  c.reason = reason;
  c.a = a;
  c.b = b;
  return c;
}

vsh_auto_light_choice vsh_auto_choose_light(const vsh_auto_object *objects, int count,
                                            const double light[4], int headlight, int concave)
{
  if (headlight)
    return choice(VSH_AUTO_NONE, VSH_AUTO_REASON_HEADLIGHT, -1, -1);
  int any_caster = 0;
  for (int i = 0; i < count; ++i)
    any_caster = any_caster || objects[i].casts;
  if (!any_caster)
    return choice(VSH_AUTO_NONE, VSH_AUTO_REASON_NO_CASTER, -1, -1);
  if (concave >= 0 && concave < count)
    return choice(VSH_AUTO_CSM, VSH_AUTO_REASON_CONCAVE, concave, -1);
  int any_shadow = 0;
  for (int i = 0; i < count; ++i) {
    const vsh_auto_object *a = &objects[i];
    for (int j = 0; j < count; ++j) {
      const vsh_auto_object *b = &objects[j];
      if (!a->casts || i == j || !b->in_view ||
          (a->flat && vsh_auto_on_lit_side(a->plane, light, b->center, b->radius)))
        continue; /* a plane receiver only blocks light from what lies behind it */
      if (!may_shadow(a, b, light))
        continue;
      any_shadow = 1;
      if (!(b->receiver && b->flat))
        return choice(VSH_AUTO_CSM, VSH_AUTO_REASON_SHADOWS_OTHER, i, j);
    }
  }
  return any_shadow ? choice(VSH_AUTO_PLANAR, VSH_AUTO_REASON_PLANES_ONLY, -1, -1)
                    : choice(VSH_AUTO_NONE, VSH_AUTO_REASON_NO_SHADOW, -1, -1);
}

double vsh_auto_plane_stretch(const vsh_auto_object *objects, int count, const double light[4])
{
  double stretch = 1.0;
  for (int i = 0; i < count; ++i) {
    const vsh_auto_object *r = &objects[i];
    if (!r->flat || !r->in_view)
      continue;
    double towards[3];
    for (int k = 0; k < 3; ++k)
      towards[k] = light[k] - light[3] * r->center[k];
    const double len = sqrt(towards[0] * towards[0] + towards[1] * towards[1] +
                            towards[2] * towards[2]);
    const double n = sqrt(r->plane[0] * r->plane[0] + r->plane[1] * r->plane[1] +
                          r->plane[2] * r->plane[2]);
    if (len > 0.0 && n > 0.0) {
      const double c = fabs(towards[0] * r->plane[0] + towards[1] * r->plane[1] +
                            towards[2] * r->plane[2]) /
                       (len * n);
      stretch = max_keep(stretch, 1.0 / max_keep(c, 1.0 / 64.0));
    }
  }
  return stretch;
}

void vsh_auto_light_masks(const int *techniques, int count, unsigned int *planar,
                          unsigned int *csm)
{
  *planar = *csm = 0u;
  for (int l = 0; l < count && l < 32; ++l) {
    *planar |= (techniques[l] == VSH_AUTO_PLANAR ? 1u : 0u) << l;
    *csm |= (techniques[l] == VSH_AUTO_CSM ? 1u : 0u) << l;
  }
}

double vsh_auto_frame_texel_target(double max_texel_px, double max_wrong_pct, double pixels,
                                   double edge_length_px, double stretch)
{
  if (max_texel_px > 0.0)
    return max_texel_px;
  /* A shadow boundary at least a pixel long, a one-pixel band. */
  return vsh_auto_texel_target(max_wrong_pct, pixels, max_keep(edge_length_px, 1.0), stretch, 1.0);
}
