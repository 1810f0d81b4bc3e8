/* vsh_rt_classify_cover.c - what the classifier's maps know beyond single
 * triangles (vsh_rt_classify.h): which triangles share a plane, and where
 * the union of one placement's triangles covers a texel whole.
 *
 * Union cover: the boundary of the projected union of a set of triangles
 * lies on its CONTOUR edges, those on one triangle only, on more than two,
 * or folded (both neighbours on one side of the plane through the edge and
 * the light): across any other edge the two neighbours continue the union
 * on both sides, and around a vertex whose edges are all unfolded the fan
 * winds at least once. A texel (grown by the margin) that a triangle of
 * the set overlaps and no contour edge crosses therefore lies inside the
 * union (a path from inside to outside would cross a contour edge), so
 * every shadow ray through it meets one of the set's triangles, no farther
 * than their largest far key over it. */
#include "vsh_rt_classify.h"
#include "vsh_rt_classify_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct plane_key {
  long long q[4];
  size_t index;
} plane_key;

static int compare_planes(const void *pa, const void *pb)
{
  const plane_key *a = pa, *b = pb;
  for (int k = 0; k < 4; ++k) {
    if (a->q[k] != b->q[k]) {
      return a->q[k] < b->q[k] ? -1 : 1;
    }
  }
  return a->index < b->index ? -1 : (a->index > b->index);
}

int vsh_rtc_plane_groups(vsh_rt_classify_map *map)
{
  plane_key *keys = malloc((map->count ? map->count : 1) * sizeof *keys);
  if (!keys) {
    return 1;
  }
  size_t n = 0;
  for (size_t t = 0; t < map->count; ++t) {
    const double *v = map->triangles + 9 * t;
    double nrm[3];
    map->group[t] = (int)t;
    if (!(vsh_rtc_unit_normal(map, t, nrm) > 0)) {
      continue; /* degenerate: a group of its own */
    }
    /* One sign per plane: the first clearly non-zero component positive. */
    const int first = fabs(nrm[0]) > 0.5 ? 0 : (fabs(nrm[1]) > 0.5 ? 1 : 2);
    const double sign = nrm[first] < 0 ? -1.0 : 1.0;
    plane_key *k = &keys[n++];
    for (int r = 0; r < 3; ++r) {
      k->q[r] = llround(sign * nrm[r] / VSH_RT_CLASSIFY_NORMAL_QUANTUM);
    }
    k->q[3] =
      llround(sign * vsh_vec3_dot(nrm, v) / (VSH_RT_CLASSIFY_OFFSET_QUANTUM * map->scale));
    k->index = t;
  }
  qsort(keys, n, sizeof *keys, compare_planes);
  for (size_t a = 0; a < n;) {
    size_t b = a;
    while (b < n && memcmp(keys[b].q, keys[a].q, sizeof keys[a].q) == 0) {
      map->group[keys[b++].index] = (int)keys[a].index; /* sorted: the lowest index */
    }
    a = b;
  }
  free(keys);
  return 0;
}

/* One triangle edge with its endpoints in a canonical order. */
typedef struct edge {
  int run;
  double a[3], b[3], third[3];
  size_t slot; /* 3 * triangle + edge */
} edge;

static int compare_points(const double *a, const double *b)
{
  for (int k = 0; k < 3; ++k) {
    if (a[k] != b[k]) {
      return a[k] < b[k] ? -1 : 1;
    }
  }
  return 0;
}

static int compare_edges(const void *pa, const void *pb)
{
  const edge *a = pa, *b = pb;
  if (a->run != b->run) {
    return a->run < b->run ? -1 : 1;
  }
  const int c = compare_points(a->a, b->a);
  return c ? c : compare_points(a->b, b->b);
}

/* Whether the neighbours c1 and c2 of edge a-b lie on one side of the
 * plane through the edge and the light (or on it): a fold. */
static int folded(const vsh_rt_classify_map *map, const edge *e, const double c2[3])
{
  double ab[3], m[3], d1[3], d2[3];
  if (map->light.kind == VSH_RT_DIRECTIONAL) {
    vsh_vec3_sub(e->b, e->a, ab);
    vsh_vec3_cross(ab, map->light.direction, m);
  } else {
    double la[3], lb[3];
    vsh_vec3_sub(e->a, map->light.position, la);
    vsh_vec3_sub(e->b, map->light.position, lb);
    vsh_vec3_cross(la, lb, m);
  }
  vsh_vec3_sub(e->third, e->a, d1);
  vsh_vec3_sub(c2, e->a, d2);
  const double s1 = vsh_vec3_dot(m, d1), s2 = vsh_vec3_dot(m, d2);
  const double tiny = 1e-12 * vsh_vec3_length(m) * map->scale;
  return !(s1 * s2 < 0) || fabs(s1) <= tiny || fabs(s2) <= tiny;
}

/* How far a ray's origin, offset by eps along the unit normal n (turned
 * towards the light, direction l) off its plane, may see the neighbour
 * across a concave edge rise, in eps: the origin's column moves eps
 * sin(theta) sideways, where the neighbour's height (along l) rises over
 * n's plane by at most that times g = |grad h1 - grad h| (h: height along
 * l over the plane across l, grad h = -(n - (n.l) l) / (n.l)), while the
 * origin stands eps / cos(theta) above n's plane along l. Returns
 * sin(theta) cos(theta) g: below 1 the origin stays above the neighbour. */
static double rise_over_clearance(const double n[3], const double n1[3], const double l[3])
{
  const double c = vsh_vec3_dot(n, l), c1 = vsh_vec3_dot(n1, l);
  if (!(c > 0) || !(c1 > 0)) {
    return HUGE_VAL;
  }
  double across[3], g[3];
  for (int r = 0; r < 3; ++r) {
    across[r] = n[r] - c * l[r];
    g[r] = (n1[r] - c1 * l[r]) / c1 - across[r] / c;
  }
  return vsh_vec3_length(across) * c * vsh_vec3_length(g);
}

/* Whether the unfolded edge shared by e's and f's triangles bends towards
 * the light enough to matter: either neighbour's far vertex on the light's
 * side of the other's plane (by more than 1e-9 of the way), and the bend
 * sharp enough that an origin offset from one triangle could stand below
 * the other (rise_over_clearance above 1/4: a margin of 4 for the float
 * rounding of the origin and of Embree's triangles). A gently curved
 * surface's valleys are smooth. */
static int concave(const vsh_rt_classify_map *map, const double *normals, const edge *e,
                   const edge *f)
{
  const double *n0 = normals + 3 * (e->slot / 3), *n1 = normals + 3 * (f->slot / 3);
  double d0[3], d1[3];
  vsh_vec3_sub(f->third, e->a, d1);
  vsh_vec3_sub(e->third, e->a, d0);
  if (!(vsh_vec3_dot(n0, d1) > 1e-9 * vsh_vec3_length(d1) ||
        vsh_vec3_dot(n1, d0) > 1e-9 * vsh_vec3_length(d0))) {
    return 0;
  }
  double l[3];
  if (map->light.kind == VSH_RT_DIRECTIONAL) {
    memcpy(l, map->light.direction, sizeof l);
  } else {
    double middle[3];
    for (int r = 0; r < 3; ++r) {
      middle[r] = 0.5 * (e->a[r] + e->b[r]);
    }
    vsh_vec3_sub(map->light.position, middle, l);
    vsh_vec3_normalize(l, l);
  }
  return rise_over_clearance(n0, n1, l) > 0.25 || rise_over_clearance(n1, n0, l) > 0.25;
}

int vsh_rtc_contours(const vsh_rt_classify_map *map, const int *placements,
                     const double *normals, unsigned char *contour, int *partner)
{
  memset(contour, VSH_RTC_CONTOUR, 3 * map->count);
  for (size_t k = 0; k < 3 * map->count; ++k) {
    partner[k] = -1;
  }
  edge *edges = malloc((map->count ? 3 * map->count : 1) * sizeof *edges);
  if (!edges) {
    return 1;
  }
  size_t n = 0;
  for (size_t t = 0; t < map->count; ++t) {
    if (!(map->flags[t] & VSH_RT_CLASSIFY_CASTS)) {
      continue;
    }
    const double *v = map->triangles + 9 * t;
    for (int k = 0; k < 3; ++k) {
      edge *e = &edges[n++];
      const double *p = v + 3 * k, *q = v + 3 * ((k + 1) % 3);
      const int swap = compare_points(p, q) > 0;
      memcpy(e->a, swap ? q : p, sizeof e->a);
      memcpy(e->b, swap ? p : q, sizeof e->b);
      memcpy(e->third, v + 3 * ((k + 2) % 3), sizeof e->third);
      e->run = placements ? placements[t] : 0;
      e->slot = 3 * t + (size_t)k;
    }
  }
  qsort(edges, n, sizeof *edges, compare_edges);
  for (size_t a = 0; a < n;) {
    size_t b = a + 1;
    while (b < n && compare_edges(&edges[a], &edges[b]) == 0) {
      ++b;
    }
    if (b - a == 2 && !folded(map, &edges[a], edges[a + 1].third)) {
      const size_t s0 = edges[a].slot, s1 = edges[a + 1].slot;
      contour[s0] = contour[s1] =
        concave(map, normals, &edges[a], &edges[a + 1]) ? VSH_RTC_CONCAVE : VSH_RTC_SMOOTH;
      partner[s0] = (int)(s1 / 3);
      partner[s1] = (int)(s0 / 3);
    }
    a = b;
  }
  free(edges);
  return 0;
}

/* The run's covered texels into cover_far (overlapped, bit 1, and no
 * contour across, bit 2), the texels its contour or concave (bit 4) edges
 * cross into `crossed`, and the scratch cleared. */
static void flush(vsh_rt_classify_face *face, vsh_rtc_scratch *s, unsigned char *crossed)
{
  for (size_t k = 0; k < s->count; ++k) {
    const size_t x = s->touched[k];
    if ((s->mark[x] & 3) == 1) {
      face->texels[x].cover_far = fminf(face->texels[x].cover_far, s->hi[x]);
    }
    crossed[x] |= (unsigned char)(((s->mark[x] & 2) ? VSH_RTC_CROSSED_CONTOUR : 0) |
                                  ((s->mark[x] & 4) ? VSH_RTC_CROSSED_CONCAVE : 0));
    s->mark[x] = 0;
  }
  s->count = 0;
}

int vsh_rtc_cover_face(vsh_rt_classify_map *map, vsh_rt_classify_face *face,
                       const int *placements, const unsigned char *contour,
                       unsigned char *crossed)
{
  const size_t texels = (size_t)face->n * (size_t)face->n;
  vsh_rtc_scratch s;
  s.hi = malloc(texels * sizeof *s.hi);
  s.mark = calloc(texels, 1);
  s.touched = malloc(texels * sizeof *s.touched);
  s.count = 0;
  if (!s.hi || !s.mark || !s.touched) {
    free(s.hi);
    free(s.mark);
    free(s.touched);
    return 1;
  }
  for (size_t start = 0; start < map->count;) {
    size_t end = start + 1;
    while (end < map->count && (!placements || placements[end] == placements[start])) {
      ++end;
    }
    double margin = 0;
    for (size_t t = start; t < end; ++t) {
      vsh_rtc_rasterize(map, face, t, 0, &s);
      if (map->flags[t] & VSH_RT_CLASSIFY_CASTS) {
        margin = fmax(margin, vsh_rtc_margin(map, face, t));
      }
    }
    for (size_t t = start; t < end; ++t) {
      for (int k = 0; k < 3 && (map->flags[t] & VSH_RT_CLASSIFY_CASTS); ++k) {
        const unsigned char c = contour[3 * t + (size_t)k];
        if (c != VSH_RTC_SMOOTH) {
          const double *v = map->triangles + 9 * t;
          vsh_rtc_mark_segment(map, face, v + 3 * k, v + 3 * ((k + 1) % 3), margin,
                               c == VSH_RTC_CONTOUR ? 2 : 4, &s);
        }
      }
    }
    flush(face, &s, crossed);
    start = end;
  }
  free(s.hi);
  free(s.mark);
  free(s.touched);
  return 0;
}
