/* vsh_rt_classify_occluders.c - the impostors a map does not hold, as a
 * per-frame grid of the smallest and largest key per 8 x 8 texel block of
 * each face (vsh_rt_classify.h, "OCCLUDERS": why a LIT class then stands,
 * and where a landing on an impostor may leave a tube). */
#include "vsh_rt_classify.h"
#include "vsh_rt_classify_internal.h"

#include <math.h>
#include <stdlib.h>

/* One ball's box and its nearest and farthest keys in a face; 0 when it
 * reaches a perspective face's plane (its projection has no bound), -1 when
 * it is wholly behind it. */
static int ball_box(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                    const double c[3], double r, double box[4], double key[2])
{
  double f[3];
  vsh_rtc_face_point(map, face, c, f);
  const double x = f[0], y = f[1], z = f[2];
  if (!isfinite(x + y + z + r)) {
    return 0;
  }
  if (!face->perspective) {
    box[0] = x - r, box[1] = x + r, box[2] = y - r, box[3] = y + r;
    key[0] = vsh_rt_classify_key(face, z - r);
    key[1] = vsh_rt_classify_key(face, z + r);
    return 1;
  }
  if (z + r <= 0) {
    return -1;
  }
  if (!(z - r > 2 * map->near_z)) {
    return 0;
  }
  /* The ball lies in the cube [x +- r] x [y +- r] x [z +- r], all in front:
   * x / z and y / z over it are extreme at its corners. */
  const double zs[2] = { z - r, z + r };
  box[0] = box[2] = HUGE_VAL;
  box[1] = box[3] = -HUGE_VAL;
  for (int k = 0; k < 2; ++k) {
    for (int s = -1; s <= 1; s += 2) {
      box[0] = fmin(box[0], (x + s * r) / zs[k]);
      box[1] = fmax(box[1], (x + s * r) / zs[k]);
      box[2] = fmin(box[2], (y + s * r) / zs[k]);
      box[3] = fmax(box[3], (y + s * r) / zs[k]);
    }
  }
  key[0] = vsh_rt_classify_key(face, z - r);
  key[1] = vsh_rt_classify_key(face, z + r);
  return 1;
}

/* The block range of [lo, hi] along one axis of a face: floor of the texel
 * index over 8, not clamped. */
static void block_range(const vsh_rt_classify_face *face, double origin, double lo, double hi,
                        long range[2])
{
  const double b0 = floor((lo - origin) / face->texel / 8.0);
  const double b1 = floor((hi - origin) / face->texel / 8.0);
  /* Far beyond the face: any value past its blocks says so. */
  range[0] = (long)fmax(fmin(b0, 1e9), -1e9);
  range[1] = (long)fmax(fmin(b1, 1e9), -1e9);
}

/* Capsule k's mark in face f: the union of its two balls' boxes (the hull
 * of two balls projects inside the hull of their projections). */
static void mark(const vsh_rt_classify_map *map, int f, const double *capsule, double margin,
                 vsh_rt_classify_occluder_face *out)
{
  const vsh_rt_classify_face *face = &map->face[f];
  double box[4] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL }, key = HUGE_VAL, far = -HUGE_VAL;
  int behind = 0;
  for (int ball = 0; ball < 2; ++ball) {
    double b[4], k[2];
    const int in = ball_box(map, face, capsule + 4 * ball, capsule[4 * ball + 3] + margin, b, k);
    if (in == 0) {
      out->everywhere = -HUGE_VALF;
      return;
    }
    if (in < 0) {
      ++behind;
      continue;
    }
    box[0] = fmin(box[0], b[0]), box[1] = fmax(box[1], b[1]);
    box[2] = fmin(box[2], b[2]), box[3] = fmax(box[3], b[3]);
    key = fmin(key, k[0]);
    far = fmax(far, k[1]);
  }
  if (behind == 2) {
    return;
  }
  if (behind == 1) {
    out->everywhere = -HUGE_VALF; /* the hull crosses the face's plane */
    return;
  }
  const float stored = vsh_rtc_round_down(key), stored_far = vsh_rtc_round_up(far);
  long bu[2], bv[2];
  block_range(face, face->u0, box[0], box[1], bu);
  block_range(face, face->v0, box[2], box[3], bv);
  const long n = out->blocks;
  if (bu[0] < 0 || bv[0] < 0 || bu[1] >= n || bv[1] >= n) {
    out->outside = fminf(out->outside, stored);
    out->outside_far = fmaxf(out->outside_far, stored_far);
  }
  for (long j = bv[0] < 0 ? 0 : bv[0]; j <= bv[1] && j < n; ++j) {
    for (long i = bu[0] < 0 ? 0 : bu[0]; i <= bu[1] && i < n; ++i) {
      out->keys[j * n + i] = fminf(out->keys[j * n + i], stored);
      out->far_keys[j * n + i] = fmaxf(out->far_keys[j * n + i], stored_far);
    }
  }
}

int vsh_rt_classify_occluders_build(vsh_rt_classify_occluders *out,
                                    const vsh_rt_classify_map *map, const double *capsules,
                                    size_t count)
{
  if (!out) {
    return -1;
  }
  *out = (vsh_rt_classify_occluders){ 0 };
  if (!map || map->unusable || (count && !capsules)) {
    return -1;
  }
  out->faces = map->faces;
  out->count = count;
  /* Embree's float copy of a centre and radius: the maps' margin. */
  const double margin = VSH_RT_CLASSIFY_MARGIN * map->scale;
  for (int f = 0; f < map->faces; ++f) {
    vsh_rt_classify_occluder_face *o = &out->face[f];
    o->blocks = map->face[f].n >> 3;
    o->outside = o->everywhere = HUGE_VALF;
    o->outside_far = -HUGE_VALF;
    const size_t cells = (size_t)o->blocks * (size_t)o->blocks;
    o->keys = (float *)malloc((cells ? cells : 1) * sizeof(float));
    o->far_keys = (float *)malloc((cells ? cells : 1) * sizeof(float));
    if (!o->keys || !o->far_keys) {
      vsh_rt_classify_occluders_free(out);
      return -1;
    }
    for (size_t k = 0; k < cells; ++k) {
      o->keys[k] = HUGE_VALF;
      o->far_keys[k] = -HUGE_VALF;
    }
    for (size_t c = 0; c < count; ++c) {
      mark(map, f, capsules + 8 * c, margin, o);
    }
  }
  return 0;
}

void vsh_rt_classify_occluders_free(vsh_rt_classify_occluders *occluders)
{
  if (!occluders) {
    return;
  }
  for (int f = 0; f < 6; ++f) {
    free(occluders->face[f].keys);
    free(occluders->face[f].far_keys);
  }
  *occluders = (vsh_rt_classify_occluders){ 0 };
}

int vsh_rtc_occluders_reach(const vsh_rt_classify_occluders *occluders,
                            const vsh_rt_classify_face *face, int f, double umin, double umax,
                            double vmin, double vmax, float key_lo, float key_hi)
{
  if (!occluders || occluders->count == 0) {
    return 0;
  }
  if (f >= occluders->faces) {
    return 1;
  }
  const vsh_rt_classify_occluder_face *o = &occluders->face[f];
  if (!o->keys || !o->far_keys || o->everywhere <= key_hi) {
    return 1;
  }
  long bu[2], bv[2];
  block_range(face, face->u0, umin, umax, bu);
  block_range(face, face->v0, vmin, vmax, bv);
  const long n = o->blocks;
  if ((bu[0] < 0 || bv[0] < 0 || bu[1] >= n || bv[1] >= n) && o->outside <= key_hi &&
      o->outside_far >= key_lo) {
    return 1;
  }
  for (long j = bv[0] < 0 ? 0 : bv[0]; j <= bv[1] && j < n; ++j) {
    for (long i = bu[0] < 0 ? 0 : bu[0]; i <= bu[1] && i < n; ++i) {
      if (o->keys[j * n + i] <= key_hi && o->far_keys[j * n + i] >= key_lo) {
        return 1;
      }
    }
  }
  return 0;
}

int vsh_rtc_occluders_clear(const vsh_rt_classify_occluders *occluders,
                            const vsh_rt_classify_face *face, int f, double umin, double umax,
                            double vmin, double vmax, float key_hi)
{
  /* No block holds an impostor with any key up to key_hi (an impostor's
   * largest key is never below its smallest). */
  return !vsh_rtc_occluders_reach(occluders, face, f, umin, umax, vmin, vmax, -HUGE_VALF,
                                  key_hi);
}
