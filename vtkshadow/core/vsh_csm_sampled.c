/* vsh_csm_sampled.c - see vsh_csm_sampled.h. */
#include "vsh_csm_sampled.h"

#include "vsh_mat4.h"
#include "vsh_soft.h"

#include <math.h>
#include <string.h>

#define VSH_SAMPLED_PI 3.14159265358979323846

vsh_csm_status vsh_csm_sample_frame_for(const vsh_csm_light *light, double size,
                                        const double toward[3], int n,
                                        vsh_csm_sample_frame *out) {
  double axis[3], scale;
  int i;
  if (!light || !out || n < 1 || n > VSH_CSM_MAX_SAMPLES || !(size >= 0.0) || !isfinite(size))
    return VSH_CSM_BAD_INPUT;
  if (!light->positional && !(size < 180.0)) return VSH_CSM_BAD_INPUT;
  memset(out, 0, sizeof *out);
  out->positional = light->positional;
  out->n = n;
  for (i = 0; i < 3; ++i) out->l[i] = light->position[i] - light->focal_point[i];
  if (!light->positional) {
    const double len = sqrt(out->l[0] * out->l[0] + out->l[1] * out->l[1] + out->l[2] * out->l[2]);
    if (!(len > 0.0) || !isfinite(len)) return VSH_CSM_BAD_INPUT;
    for (i = 0; i < 3; ++i) out->l[i] /= len;
  }
  if (size == 0.0 || n < 2 || !light->casts) return VSH_CSM_OK;
  if (light->positional) {
    if (!toward) return VSH_CSM_BAD_INPUT;
    for (i = 0; i < 3; ++i) axis[i] = toward[i] - light->position[i];
    scale = size;
  } else {
    for (i = 0; i < 3; ++i) axis[i] = out->l[i];
    scale = tan(size * VSH_SAMPLED_PI / 360.0);
  }
  /* The same axes vsh_soft_light_point / vsh_soft_sun_direction use. */
  if (vsh_soft_frame(axis, out->u, out->v)) return VSH_CSM_OK; /* toward at the light */
  for (i = 0; i < 3; ++i) {
    out->u[i] *= scale;
    out->v[i] *= scale;
  }
  out->sampled = 1;
  return VSH_CSM_OK;
}

vsh_csm_status vsh_csm_sample_disk(int i, int n, double out[2]) {
  if (!out || n < 1 || n > VSH_CSM_MAX_SAMPLES) return VSH_CSM_BAD_INPUT;
  return vsh_soft_disk_sample(i, n, 0.0, out) ? VSH_CSM_BAD_INPUT : VSH_CSM_OK;
}

/* Row r of a row-major matrix's linear part times d. */
static double row_dot(const double m[16], int r, const double d[3]) {
  return m[r * 4 + 0] * d[0] + m[r * 4 + 1] * d[1] + m[r * 4 + 2] * d[2];
}

vsh_csm_status vsh_csm_sample_shear(const vsh_shadow_view *view, const vsh_csm_sample_frame *f,
                                    double out[4]) {
  double c, scale;
  if (!view || !f || !out || view->perspective || f->positional) return VSH_CSM_BAD_INPUT;
  /* Along a sample's direction d = l + e (e = q0 u + q1 v, perpendicular to
   * l) clip moves by (M e).xy in x, y and c = (M l).z in z (the map looks
   * along l: (M l).xy = 0): x, y minus (M e).xy / c times clip z is then
   * constant along d, so each line of light lands on one texel. */
  c = row_dot(view->world_to_clip, 2, f->l);
  scale = fabs(row_dot(view->world_to_clip, 0, f->l)) + fabs(row_dot(view->world_to_clip, 1, f->l));
  if (!(fabs(c) > 0.0) || !isfinite(c) || scale > 1e-6 * fabs(c)) return VSH_CSM_BAD_INPUT;
  out[0] = row_dot(view->world_to_clip, 0, f->u) / c;
  out[1] = row_dot(view->world_to_clip, 1, f->u) / c;
  out[2] = row_dot(view->world_to_clip, 0, f->v) / c;
  out[3] = row_dot(view->world_to_clip, 1, f->v) / c;
  return VSH_CSM_OK;
}

/* m <- S m with S the clip-space shear x -= sx z, y -= sy z. */
static void shear_rows(double m[16], double sx, double sy) {
  int c;
  for (c = 0; c < 4; ++c) {
    m[0 * 4 + c] -= sx * m[2 * 4 + c];
    m[1 * 4 + c] -= sy * m[2 * 4 + c];
  }
}

/* m <- m T(-o): the view moved by o. */
static void move_eye(double m[16], const double o[3]) {
  int r;
  for (r = 0; r < 4; ++r)
    m[r * 4 + 3] -= m[r * 4 + 0] * o[0] + m[r * 4 + 1] * o[1] + m[r * 4 + 2] * o[2];
}

vsh_csm_status vsh_csm_sample_tile(const vsh_csm_tile *base, const vsh_csm_sample_frame *f,
                                   int i, vsh_csm_tile *out) {
  double q[2];
  int k;
  if (!base || !f || !out || !f->sampled || vsh_csm_sample_disk(i, f->n, q) != VSH_CSM_OK)
    return VSH_CSM_BAD_INPUT;
  *out = *base;
  if (base->view.texel_world <= 0.0) return VSH_CSM_OK; /* an empty map stays empty */
  if (f->positional) {
    double o[3];
    if (!base->view.perspective) return VSH_CSM_BAD_INPUT;
    for (k = 0; k < 3; ++k) o[k] = q[0] * f->u[k] + q[1] * f->v[k];
    move_eye(out->view.world_to_clip, o);
    move_eye(out->absolute, o);
  } else {
    double s[4];
    if (vsh_csm_sample_shear(&base->view, f, s) != VSH_CSM_OK) return VSH_CSM_BAD_INPUT;
    shear_rows(out->view.world_to_clip, q[0] * s[0] + q[1] * s[2], q[0] * s[1] + q[1] * s[3]);
    shear_rows(out->absolute, q[0] * s[0] + q[1] * s[2], q[0] * s[1] + q[1] * s[3]);
  }
  return VSH_CSM_OK;
}

/* Row 2 of a perspective world -> clip matrix for depth range (n, f): a
 * times the view's z row plus b, where the w row is minus the view's z row. */
static void depth_row(double m[16], double a, double b) {
  int c;
  for (c = 0; c < 4; ++c) m[2 * 4 + c] = -a * m[3 * 4 + c] + (c == 3 ? b : 0.0);
}

vsh_csm_status vsh_csm_sample_widen(vsh_csm_tile *tile, const vsh_csm_sample_frame *f) {
  double r, n, fa, a, b;
  if (!tile || !f) return VSH_CSM_BAD_INPUT;
  if (!f->sampled || !f->positional || !tile->view.perspective || tile->view.texel_world <= 0.0)
    return VSH_CSM_OK;
  r = sqrt(f->u[0] * f->u[0] + f->u[1] * f->u[1] + f->u[2] * f->u[2]);
  n = tile->view.near_far[0] - r;
  if (n < 0.25 * tile->view.near_far[0]) n = 0.25 * tile->view.near_far[0];
  fa = tile->view.near_far[1] + r;
  if (!(fa > n) || !(n > 0.0) || !isfinite(fa)) return VSH_CSM_OK;
  a = -(fa + n) / (fa - n);
  b = -2.0 * fa * n / (fa - n);
  depth_row(tile->view.world_to_clip, a, b);
  depth_row(tile->absolute, a, b);
  tile->view.near_far[0] = n;
  tile->view.near_far[1] = fa;
  tile->view.depth_extent = fa - n;
  return VSH_CSM_OK;
}

int vsh_csm_sampled_resolution(int requested, int tiles, long long budget) {
  double fit;
  int r;
  if (requested < 16) return 16;
  if (tiles < 1 || budget <= 0) return requested;
  fit = floor(sqrt((double)budget / (4.0 * tiles)));
  r = fit < requested ? (int)fit : requested;
  r -= r % 16;
  return r < 16 ? 16 : r;
}
