/* vsh_rt_classify_sheet.c - LIT (c) of vsh_rt_classify.h: over each
 * texel, the LAYER of one placement's opaque triangles that a pixel's
 * surface may lie on, and the smallest key of every other surface there
 * (the texel's sheet). The nearest layer also covers the texel whole, so
 * its largest key there is a union cover (cover_far) for SHADOWED: the
 * side of a blob away from the light, under its side towards it.
 *
 * One sheet: no contour edge of any placement crosses the texel (grown by
 * the margin; vsh_rt_classify_cover.c), so across it the number of a
 * placement's triangles over a point cannot change (crossing an unfolded
 * edge leaves one triangle for its neighbour on the other side). The
 * placement's triangles over the texel therefore split into layers, each
 * over the whole texel and connected through its unfolded edges. Taken
 * from the nearest triangle over the texel's centre, the triangles
 * connected to it through unfolded edges (among those over the texel) are
 * whole layers, one triangle over the centre per layer: holding no other
 * triangle over the centre, they are ONE layer. A centre within 1e-6 of a
 * texel of an edge is not counted: that texel gets no sheet.
 *
 * The ray leaves it: the tracer's origin is its landing on a triangle T
 * of the layer moved a small offset along T's normal towards the camera,
 * which (the blocks' normal boxes) is the side facing the light; or a
 * missed landing's point before the surface on the camera's ray, on the
 * same side. No edge across the texel bends the layer towards the light
 * (VSH_RTC_CONCAVE), so near T the layer lies on the far side of T's
 * plane, and the origin is on the light's side of the layer. The shadow
 * ray is one point of the light's image plane, where the layer has one
 * point, behind the origin: the ray does not meet the layer, and every
 * other surface over the texel is behind the tube. */
#include "vsh_rt_classify.h"
#include "vsh_rt_classify_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* More triangles than this over one texel: no sheet there. */
#define MAX_TEXEL_TRIANGLES 64
/* More triangle-texel overlaps than this in one face: no sheets (their
 * lists, 12 bytes each, would pass 200 MB; the scivis scenes have 0.7-1.7
 * million at 1024 texels a side). Also keeps the indices in 32 bits. */
#define MAX_OVERLAPS ((size_t)1 << 24)

void vsh_rtc_light_normals(const vsh_rt_classify_map *map, double *normals,
                           unsigned char *facing)
{
  const vsh_rt_light *light = &map->light;
  for (size_t t = 0; t < map->count; ++t) {
    const double *v = map->triangles + 9 * t;
    double *out = normals + 3 * t;
    facing[t] = 0;
    if (!(vsh_rtc_unit_normal(map, t, out) > 0)) {
      continue;
    }
    if (light->kind == VSH_RT_DIRECTIONAL) {
      const double c = vsh_vec3_dot(out, light->direction);
      vsh_vec3_scale(out, c < 0 ? -1.0 : 1.0, out);
      facing[t] = fabs(c) >= VSH_RT_CLASSIFY_MIN_COS;
      continue;
    }
    /* n.(L - x) is linear over the triangle and |L - x| convex: their
     * extremes are at the vertices. */
    double lowest = HUGE_VAL, highest = -HUGE_VAL, farthest = 0;
    for (int k = 0; k < 3; ++k) {
      double to[3];
      vsh_vec3_sub(light->position, v + 3 * k, to);
      const double s = vsh_vec3_dot(out, to);
      lowest = fmin(lowest, s);
      highest = fmax(highest, s);
      farthest = fmax(farthest, vsh_vec3_length(to));
    }
    if (highest <= 0) {
      vsh_vec3_scale(out, -1.0, out);
      const double flipped = -highest;
      highest = -lowest;
      lowest = flipped;
    }
    facing[t] = lowest >= VSH_RT_CLASSIFY_MIN_COS * farthest;
  }
}

/* Whether point (u, v) is inside the projected polygon (1), outside (0),
 * or within `tol` of one of its edges with no edge clearly outside (-1). */
static int over_point(const polygon *p, double u, double v, double tol)
{
  if (u < p->umin - tol || u > p->umax + tol || v < p->vmin - tol || v > p->vmax + tol) {
    return 0;
  }
  if (p->area2 == 0 || !isfinite(p->area2)) {
    return -1; /* seen edge-on over the point */
  }
  const double s = p->area2 > 0 ? 1.0 : -1.0;
  int near_edge = 0;
  for (int k = 0; k < p->count; ++k) {
    const int j = (k + 1) % p->count;
    const double eu = p->u[j] - p->u[k], ev = p->v[j] - p->v[k];
    const double length = sqrt(eu * eu + ev * ev);
    const double side = s * (eu * (v - p->v[k]) - ev * (u - p->u[k]));
    if (side < -tol * length) {
      return 0;
    }
    near_edge = near_edge || side <= tol * length;
  }
  return near_edge ? -1 : 1;
}

static double key_at(const polygon *p, double u, double v)
{
  return p->has_plane ? p->a * u + p->b * v + p->c : p->key_min;
}

typedef struct overlap {
  int t;
  float lo, hi; /* the triangle's key range over the texel, rounded outwards */
} overlap;

/* Every triangle's texels in one face (projected again where needed, not
 * kept: a polygon per triangle would cost 272 bytes each). */
typedef struct sheet_lists {
  unsigned *start; /* per texel: its overlaps [start[x], start[x + 1]) */
  overlap *list;
} sheet_lists;

/* The nearest triangle over (u, v) among the texel's k overlaps, each
 * one's place (over[e]: 1 over the point, 0 not); -1 when none is, or
 * any is too near to tell. */
static int nearest_over(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                        const overlap *o, int k, double u, double v, double tol,
                        unsigned char *over)
{
  int best = -1;
  double best_key = HUGE_VAL;
  for (int e = 0; e < k; ++e) {
    polygon projected;
    const polygon *p = &projected;
    if (!vsh_rtc_project(map, face, map->triangles + 9 * (size_t)o[e].t, &projected)) {
      return -1; /* it overlapped the texel: cannot happen */
    }
    const int c = over_point(p, u, v, tol);
    if (c < 0) {
      return -1;
    }
    over[e] = (unsigned char)c;
    if (c && key_at(p, u, v) < best_key) {
      best_key = key_at(p, u, v);
      best = e;
    }
  }
  return best;
}

/* Marks (layer[e]) the overlaps connected to `seed` through unfolded
 * edges. */
static void connect_layer(const int *partner, const overlap *o, int k, int seed,
                          unsigned char *layer)
{
  int queue[MAX_TEXEL_TRIANGLES], head = 0, tail = 0;
  memset(layer, 0, (size_t)k);
  layer[seed] = 1;
  queue[tail++] = seed;
  while (head < tail) {
    const int t = o[queue[head++]].t;
    for (int m = 0; m < 3; ++m) {
      const int across = partner[3 * (size_t)t + (size_t)m];
      for (int e = 0; e < k && across >= 0; ++e) {
        if (!layer[e] && o[e].t == across) {
          layer[e] = 1;
          queue[tail++] = e;
        }
      }
    }
  }
}

/* The texel's sheet (-inf: none) from its k overlaps, and its layer's
 * normals into the block's box. One layer of opaque triangles, facing the
 * light or not, covers the whole texel (no contour edge crosses it):
 * `far`, its largest key there, is a union cover's far key (+inf: none). */
static float texel_sheet(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                         const vsh_rtc_layer_input *in, const overlap *o, int k, double u,
                         double v, double tol, float box[6], float *far)
{
  unsigned char over[MAX_TEXEL_TRIANGLES], layer[MAX_TEXEL_TRIANGLES];
  *far = INFINITY;
  const int seed = nearest_over(map, face, o, k, u, v, tol, over);
  if (seed < 0) {
    return -INFINITY;
  }
  connect_layer(in->partner, o, k, seed, layer);
  float rest = INFINITY, reach = -INFINITY;
  int facing = 1;
  for (int e = 0; e < k; ++e) {
    const int t = o[e].t;
    if (!layer[e]) {
      rest = fminf(rest, o[e].lo);
      continue;
    }
    if (!(map->flags[t] & VSH_RT_CLASSIFY_CASTS) || (over[e] && e != seed)) {
      return -INFINITY; /* not one layer of opaque triangles */
    }
    facing = facing && in->facing[t];
    reach = fmaxf(reach, o[e].hi);
  }
  *far = reach;
  if (!facing) {
    return -INFINITY;
  }
  for (int e = 0; e < k; ++e) {
    for (int r = 0; r < 3 && layer[e]; ++r) {
      const double n = in->normals[3 * (size_t)o[e].t + (size_t)r];
      box[r] = fminf(box[r], vsh_rtc_round_down(n));
      box[3 + r] = fmaxf(box[3 + r], vsh_rtc_round_up(n));
    }
  }
  return rest;
}

/* Every triangle's texels, listed per texel (0: too many, or out of
 * memory: no sheets, every pixel left to the other rules). */
static int list_overlaps(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                         sheet_lists *s)
{
  const size_t texels = (size_t)face->n * (size_t)face->n;
  unsigned *cursor = calloc(texels + 1, sizeof *cursor);
  int ok = cursor != NULL;
  for (int pass = 0; pass < 2 && ok; ++pass) {
    size_t total = 0;
    for (size_t t = 0; t < map->count && ok; ++t) {
      polygon projected;
      const polygon *p = &projected;
      int range[4];
      if (!vsh_rtc_project(map, face, map->triangles + 9 * t, &projected) ||
          !vsh_rtc_texel_range(face, p->umin, p->umax, p->vmin, p->vmax, p->margin, range)) {
        continue;
      }
      for (int j = range[2]; j <= range[3]; ++j) {
        const double v0 = face->v0 + j * face->texel, v1 = v0 + face->texel;
        for (int i = range[0]; i <= range[1]; ++i) {
          const double u0 = face->u0 + i * face->texel, u1 = u0 + face->texel;
          if (!vsh_rtc_overlaps(p, u0, u1, v0, v1)) {
            continue;
          }
          const size_t x = vsh_rtc_texel_index(face, i, j);
          if (pass == 0) {
            ++s->start[x + 1];
            ok = ++total <= MAX_OVERLAPS;
            continue;
          }
          double lo, hi;
          vsh_rtc_key_range(p, u0, u1, v0, v1, &lo, &hi);
          s->list[cursor[x]++] = (overlap){ (int)t, vsh_rtc_round_down(lo), vsh_rtc_round_up(hi) };
        }
      }
    }
    if (pass == 0 && ok) {
      for (size_t x = 0; x < texels; ++x) {
        s->start[x + 1] += s->start[x];
      }
      memcpy(cursor, s->start, texels * sizeof *cursor);
      s->list = malloc((total ? total : 1) * sizeof *s->list);
      ok = s->list != NULL;
    }
  }
  free(cursor);
  return ok;
}

/* Concave edge e (slot 3 t + m) projected: its ends and margin into
 * out[5]; 0 when it is not in the face. */
static int project_bend(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                        size_t slot, double out[5])
{
  const double *v = map->triangles + 9 * (slot / 3);
  const double *a = v + 3 * (slot % 3), *b = v + 3 * ((slot % 3 + 1) % 3);
  polygon p;
  int ends[2];
  if (!vsh_rtc_project_segment(map, face, a, b, &p, ends)) {
    return 0;
  }
  out[0] = p.u[ends[0]], out[1] = p.v[ends[0]], out[2] = p.u[ends[1]], out[3] = p.v[ends[1]];
  out[4] = p.margin;
  return 1;
}

/* The concave edges over each 8 x 8 block they cross (each edge once:
 * from its lower triangle), read where a texel is bent. */
static int list_bends(const vsh_rt_classify_map *map, vsh_rt_classify_face *face,
                      const vsh_rtc_layer_input *in)
{
  const int blocks = face->n / 8;
  const size_t nb = (size_t)blocks * (size_t)blocks;
  face->bend_start = calloc(nb + 1, sizeof *face->bend_start);
  size_t edges = 0;
  for (size_t slot = 0; slot < 3 * map->count; ++slot) {
    edges += in->contour[slot] == VSH_RTC_CONCAVE && in->partner[slot] > (int)(slot / 3);
  }
  face->bends = malloc((edges ? edges : 1) * 5 * sizeof *face->bends);
  if (!face->bend_start || !face->bends) {
    return 1;
  }
  size_t total = 0, kept = 0;
  int *cursor = NULL;
  for (int pass = 0; pass < 2; ++pass) {
    kept = 0;
    for (size_t slot = 0; slot < 3 * map->count; ++slot) {
      double *e = face->bends + 5 * kept;
      int range[4];
      if (in->contour[slot] != VSH_RTC_CONCAVE || in->partner[slot] <= (int)(slot / 3) ||
          !project_bend(map, face, slot, e) ||
          !vsh_rtc_texel_range(face, fmin(e[0], e[2]), fmax(e[0], e[2]), fmin(e[1], e[3]),
                               fmax(e[1], e[3]), e[4], range)) {
        continue;
      }
      for (int bj = range[2] / 8; bj <= range[3] / 8; ++bj) {
        for (int bi = range[0] / 8; bi <= range[1] / 8; ++bi) {
          const size_t b = (size_t)bj * (size_t)blocks + (size_t)bi;
          if (pass == 0) {
            ++face->bend_start[b + 1];
            ++total;
          } else {
            face->bend_list[cursor[b]++] = (int)kept;
          }
        }
      }
      ++kept;
    }
    if (pass == 0) {
      for (size_t b = 0; b < nb; ++b) {
        face->bend_start[b + 1] += face->bend_start[b];
      }
      face->bend_list = malloc((total ? total : 1) * sizeof *face->bend_list);
      cursor = malloc((nb ? nb : 1) * sizeof *cursor);
      if (!face->bend_list || !cursor) {
        free(cursor);
        return 1;
      }
      for (size_t b = 0; b < nb; ++b) {
        cursor[b] = face->bend_start[b];
      }
    }
  }
  free(cursor);
  return 0;
}

int vsh_rtc_sheet_face(const vsh_rt_classify_map *map, vsh_rt_classify_face *face,
                       const vsh_rtc_layer_input *in)
{
  const size_t texels = (size_t)face->n * (size_t)face->n;
  sheet_lists s = { calloc(texels + 1, sizeof(unsigned)), NULL };
  const int failed = !s.start;
  if (!failed && list_overlaps(map, face, &s)) {
    const double tol = 1e-6 * face->texel;
    const int blocks = face->n / 8;
    for (int j = 0; j < face->n; ++j) {
      for (int i = 0; i < face->n; ++i) {
        const size_t x = vsh_rtc_texel_index(face, i, j);
        const size_t k = s.start[x + 1] - s.start[x];
        if ((in->crossed[x] & VSH_RTC_CROSSED_CONTOUR) || k == 0 || k > MAX_TEXEL_TRIANGLES) {
          continue;
        }
        float *box = face->normal_box + 6 * ((size_t)(j / 8) * (size_t)blocks + (size_t)(i / 8));
        float far;
        face->texels[x].sheet =
          texel_sheet(map, face, in, s.list + s.start[x], (int)k, face->u0 + (i + 0.5) * face->texel,
                      face->v0 + (j + 0.5) * face->texel, tol, box, &far);
        face->texels[x].cover_far = fminf(face->texels[x].cover_far, far);
        face->bent[x] = (in->crossed[x] & VSH_RTC_CROSSED_CONCAVE) && face->texels[x].sheet > -INFINITY;
      }
    }
  }
  free(s.start);
  free(s.list);
  return failed || list_bends(map, face, in);
}
