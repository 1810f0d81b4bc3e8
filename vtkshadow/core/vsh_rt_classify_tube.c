/* vsh_rt_classify_tube.c - a pixel's tube, or a block of pixels' hull,
 * against the light-space map (vsh_rt_classify.h: why each decided class
 * is right). Both are the convex hull of a few points grown by a radius,
 * seen along a few view directions. */
#include "vsh_rt_classify.h"
#include "vsh_rt_classify_internal.h"

#include <math.h>
#include <string.h>

void vsh_rt_classify_tube_init(const vsh_rt_pixel_ray *ray, const double eye_to_anchor[3],
                               double magnitude, vsh_rt_classify_tube *out)
{
  /* vtkShadowRayTracer keeps a landing within vsh_rt_landing_slack of the
   * interval, or Embree's float hit within vsh_rt_refine_reach of its near
   * end; a miss starts at its near end, moved one offset towards the
   * camera. */
  const double slack = vsh_rt_landing_slack(ray);
  for (int r = 0; r < 3; ++r) {
    out->origin[r] = ray->origin[r] + eye_to_anchor[r];
    out->dir[r] = ray->direction[r];
  }
  out->t0 = ray->lo - slack;
  out->t1 = fmax(ray->hi, ray->lo + vsh_rt_refine_reach(ray)) + slack;
  /* The origin's offset off the surface, and four more for the float
   * rounding of the ray's origin and of Embree's triangles. */
  out->radius = 5.0 * vsh_rt_offset_distance(magnitude);
  out->reland = 0;
}

/* What is classified: the hull of `count` points grown by `radius`, seen
 * along `views` unit directions (the pixels' rays: their range). */
typedef struct hull {
  const double (*points)[3];
  int count;
  const double (*dirs)[3];
  int views;
  double radius;
  double reland; /* a landing may move this far along the views (vsh_rt_classify_tube) */
} hull;

/* Whether a spot light's cone holds none of the hull (1), all of it (0),
 * or cannot say (-1), from the hull's bounding sphere. */
static int outside_cone(const vsh_rt_light *light, const hull *h)
{
  double centre[3] = { 0, 0, 0 }, to[3];
  for (int k = 0; k < h->count; ++k) {
    vsh_vec3_add(centre, h->points[k], centre);
  }
  vsh_vec3_scale(centre, 1.0 / h->count, centre);
  double half = 0;
  for (int k = 0; k < h->count; ++k) {
    double d[3];
    vsh_vec3_sub(h->points[k], centre, d);
    half = fmax(half, vsh_vec3_length(d));
  }
  half += h->radius;
  vsh_vec3_sub(centre, light->position, to);
  const double dist = vsh_vec3_length(to);
  if (!(dist > 2 * half)) {
    return -1;
  }
  const double c = vsh_vec3_dot(to, light->direction) / dist;
  const double angle = acos(fmax(-1.0, fmin(1.0, c))), spread = asin(half / dist);
  const double cone = acos(fmax(-1.0, fmin(1.0, light->cos_cone)));
  if (angle - spread > cone + 1e-9) {
    return 1;
  }
  return angle + spread < cone - 1e-9 ? 0 : -1;
}

static int choose_face(const vsh_rt_classify_map *map, const hull *h)
{
  if (map->faces == 1) {
    return 0;
  }
  double to[3] = { 0, 0, 0 };
  for (int k = 0; k < h->count; ++k) {
    for (int r = 0; r < 3; ++r) {
      to[r] += h->points[k][r] - map->light.position[r];
    }
  }
  int axis = 0;
  for (int r = 1; r < 3; ++r) {
    axis = fabs(to[r]) > fabs(to[axis]) ? r : axis;
  }
  return 2 * axis + (to[axis] < 0);
}

/* The hull in one face: its footprint in (u, v) and its key range. */
typedef struct footprint {
  double umin, umax, vmin, vmax;
  double key_lo, key_hi;
  /* A tube's (two points) projected ends, and how far its radius reaches
   * beyond the segment between them (a straight line stays straight
   * through the projection). */
  int segment;
  double end[2][2], grow;
} footprint;

static int locate(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face, const hull *h,
                  footprint *out)
{
  double zlo = HUGE_VAL, zhi = -HUGE_VAL, ulo = HUGE_VAL, uhi = -HUGE_VAL, vlo = HUGE_VAL,
         vhi = -HUGE_VAL, spread = 0;
  for (int k = 0; k < h->count; ++k) {
    double f[3];
    vsh_rtc_face_point(map, face, h->points[k], f);
    double x = f[0], y = f[1];
    const double z = f[2];
    if (!isfinite(x + y + z)) {
      return 0; /* so that the plain comparisons below never meet a NaN */
    }
    zlo = z < zlo ? z : zlo;
    zhi = z > zhi ? z : zhi;
    if (face->perspective) {
      if (!(z - h->radius > 2 * map->near_z)) {
        return 0; /* at or behind the light's plane */
      }
      x /= z;
      y /= z;
      const double s = 1.0 + fabs(x) + fabs(y);
      spread = s > spread ? s : spread;
    }
    if (k < 2) {
      out->end[k][0] = x, out->end[k][1] = y;
    }
    ulo = x < ulo ? x : ulo;
    uhi = x > uhi ? x : uhi;
    vlo = y < vlo ? y : vlo;
    vhi = y > vhi ? y : vhi;
  }
  zlo -= h->radius;
  zhi += h->radius;
  /* A point moved by r moves its projection by at most r (1 + |u| + |v|) / z. */
  const double grow = face->perspective ? h->radius * spread / zlo : h->radius;
  out->segment = h->count == 2;
  out->grow = grow;
  out->umin = ulo - grow;
  out->umax = uhi + grow;
  out->vmin = vlo - grow;
  out->vmax = vhi + grow;
  out->key_lo = vsh_rt_classify_key(face, zlo);
  out->key_hi = vsh_rt_classify_key(face, zhi);
  return isfinite(out->umin + out->umax + out->vmin + out->vmax + out->key_lo + out->key_hi);
}

/* LIT (b)'s facing: P (the plane of triangle f) is seen from one side
 * along every view, not nearly edge-on (a missed landing's origin, the
 * interval's near end, would be barely off P), and that side faces the
 * light by at least VSH_RT_CLASSIFY_MIN_COS everywhere in the hull (n.(L -
 * x) is linear in x and |L - x| convex: their extremes are at the
 * points). */
static int faces_light(const vsh_rt_classify_map *map, const hull *h, int f)
{
  double n[3];
  if (!(vsh_rtc_unit_normal(map, (size_t)f, n) > 0)) {
    return 0;
  }
  double side = 0;
  for (int k = 0; k < h->views; ++k) {
    const double s = vsh_vec3_dot(n, h->dirs[k]);
    if (!(fabs(s) > 1e-3) || (side != 0 && (s > 0) != (side > 0))) {
      return 0;
    }
    side = s;
  }
  vsh_vec3_scale(n, side > 0 ? -1.0 : 1.0, n); /* towards the camera */
  if (map->light.kind == VSH_RT_DIRECTIONAL) {
    return vsh_vec3_dot(n, map->light.direction) >= VSH_RT_CLASSIFY_MIN_COS;
  }
  double lowest = HUGE_VAL, farthest = 0;
  for (int k = 0; k < h->count; ++k) {
    double to[3];
    vsh_vec3_sub(map->light.position, h->points[k], to);
    lowest = fmin(lowest, vsh_vec3_dot(n, to));
    farthest = fmax(farthest, vsh_vec3_length(to));
  }
  return lowest - h->radius >= VSH_RT_CLASSIFY_MIN_COS * (farthest + h->radius);
}

/* LIT (c)'s camera side: every normal in the block's box (turned towards
 * the light) against every view direction of the hull, not nearly
 * edge-on: the camera sees the layer's side that faces the light. */
static int sees_lit_side(const float box[6], const hull *h)
{
  if (!(box[0] <= box[3] && box[1] <= box[4] && box[2] <= box[5])) {
    return 0; /* no layer there */
  }
  for (int k = 0; k < h->views; ++k) {
    double most = 0; /* the largest n.d over the box */
    for (int r = 0; r < 3; ++r) {
      const double d = h->dirs[k][r];
      most += d * (d > 0 ? box[3 + r] : box[r]);
    }
    if (!(most < -1e-3)) {
      return 0;
    }
  }
  return 1;
}

/* LIT (c) on a bent texel: the footprint keeps clear of every concave
 * edge listed for its block (each grown by its margin), so the ray's
 * origin and the surface point it left lie on one side of them (a tube:
 * its projected segment, grown; a block: its box). */
static int clear_of_bends(const vsh_rt_classify_face *face, long block, const footprint *fp)
{
  for (int k = face->bend_start[block]; k < face->bend_start[block + 1]; ++k) {
    const double *e = face->bends + 5 * face->bend_list[k];
    const int near = fp->segment ? vsh_rtc_segments_within(fp->end[0], fp->end[1], e, e + 2,
                                                   2 * (fp->grow + e[4]))
                                 : vsh_rtc_segment_meets_box(e, e + 2, fp->umin - e[4], fp->umax + e[4],
                                                     fp->vmin - e[4], fp->vmax + e[4]);
    if (near) {
      return 0;
    }
  }
  return 1;
}

/* The rules over texels [i0, i1] x [j0, j1] of the face, or over its 8 x
 * 8 blocks' summaries (`coarse`: conservative, a block's summary is the
 * worst of its texels): SHADOWED, LIT (a), LIT (b)'s plane and LIT (c). */
static int scan(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face, const hull *h,
                const footprint *fp, const int range[4], int coarse, float key_lo, float key_hi)
{
  int shadowed = 1, lit = 1, plane = 1, sheet = 1, full = -1;
  long seen_box = -1; /* the last block whose normal box passed */
  const int n = coarse ? face->n >> 3 : face->n;
  for (int j = range[2]; j <= range[3] && (shadowed || lit || plane || sheet); ++j) {
    for (int i = range[0]; i <= range[1]; ++i) {
      if (i < 0 || j < 0 || i >= n || j >= n) {
        /* Beyond a perspective face: not this face's. Beyond the
         * directional map: no triangle projects there. */
        if (face->perspective) {
          return VSH_RT_CLASSIFY_UNDECIDED;
        }
        shadowed = plane = 0;
        continue;
      }
      const long block = coarse ? (long)j * n + i : (long)(j >> 3) * (n >> 3) + (i >> 3);
      const size_t x = coarse ? (size_t)j * (size_t)n + (size_t)i : vsh_rtc_texel_index(face, i, j);
      const vsh_rt_classify_texel *t = coarse ? &face->coarse[x] : &face->texels[x];
      shadowed = shadowed && ((t->full >= 0 && t->full_far < key_lo) || t->cover_far < key_lo);
      const int behind = t->near_key > key_hi;
      lit = lit && behind;
      if (sheet && !behind) {
        sheet = t->sheet > key_hi &&
                (block == seen_box || sees_lit_side(face->normal_box + 6 * block, h)) &&
                (coarse || !face->bent[x] || clear_of_bends(face, block, fp));
        seen_box = sheet ? block : seen_box;
      }
      plane = plane && t->full >= 0 && t->rest > key_hi && (full < 0 || t->full == full);
      full = full < 0 ? t->full : full;
      if (!(shadowed || lit || plane || sheet)) {
        return VSH_RT_CLASSIFY_UNDECIDED; /* every rule has failed */
      }
    }
  }
  if (shadowed) {
    return VSH_RT_CLASSIFY_SHADOWED;
  }
  if (lit || sheet || (plane && full >= 0 && faces_light(map, h, full))) {
    return VSH_RT_CLASSIFY_LIT;
  }
  return VSH_RT_CLASSIFY_UNDECIDED;
}

/* The triangles' class of the hull's footprint in face `face`. */
static int classify_footprint(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                              const hull *h, const footprint *fp, int max_texels)
{
  const int i0 = (int)floor((fp->umin - face->u0) / face->texel);
  const int i1 = (int)floor((fp->umax - face->u0) / face->texel);
  const int j0 = (int)floor((fp->vmin - face->v0) / face->texel);
  const int j1 = (int)floor((fp->vmax - face->v0) / face->texel);
  if (i1 < i0 || j1 < j0 || (double)(i1 - i0 + 1) * (j1 - j0 + 1) > max_texels) {
    return VSH_RT_CLASSIFY_UNDECIDED;
  }
  /* Rounded outwards, every comparison stays on the safe side. */
  const float key_lo = vsh_rtc_round_down(fp->key_lo), key_hi = vsh_rtc_round_up(fp->key_hi);
  const int range[4] = { i0, i1, j0, j1 };
  const int texels = (i1 - i0 + 1) * (j1 - j0 + 1);
  if (texels > 64) {
    /* A large footprint: the blocks' summaries first, and only them when
     * reading every texel would cost more than tracing. */
    const int blocks[4] = { i0 >> 3, i1 >> 3, j0 >> 3, j1 >> 3 };
    const int c = scan(map, face, h, fp, blocks, 1, key_lo, key_hi);
    if (c != VSH_RT_CLASSIFY_UNDECIDED || texels > VSH_RT_CLASSIFY_MAX_FINE_TEXELS) {
      return c;
    }
  }
  return scan(map, face, h, fp, range, 0, key_lo, key_hi);
}

/* The hull grown by its reland distance: the first half of its points (the
 * near ends) moved back along their views, the rest forward (a tube's two
 * ends on its one view; a block's corners k and k + 4 on view k). */
static hull grown(const hull *h, double (*points)[3])
{
  for (int k = 0; k < h->count; ++k) {
    const double *d = h->dirs[k % h->views];
    const double s = k < h->count / 2 ? -h->reland : h->reland;
    for (int r = 0; r < 3; ++r) {
      points[k][r] = h->points[k][r] + s * d[r];
    }
  }
  hull g = *h;
  g.points = (const double(*)[3])points;
  g.reland = 0;
  return g;
}

/* Whether an impostor may meet the hull: over its footprint, one whose keys
 * reach into the hull's key range. */
static int may_meet_impostors(const vsh_rt_classify_map *map,
                              const vsh_rt_classify_occluders *occluders, const hull *h)
{
  const int f = choose_face(map, h);
  footprint fp;
  return !locate(map, &map->face[f], h, &fp) ||
         vsh_rtc_occluders_reach(occluders, &map->face[f], f, fp.umin, fp.umax, fp.vmin, fp.vmax,
                                 vsh_rtc_round_down(fp.key_lo), vsh_rtc_round_up(fp.key_hi));
}

/* The hull to classify: `given`, or, where an impostor may meet it grown
 * by its reland distance, that grown hull (into `points` and `wide`): a
 * landing on the impostor may be anywhere there. */
static const hull *landing_hull(const vsh_rt_classify_map *map,
                                const vsh_rt_classify_occluders *occluders, const hull *given,
                                double (*points)[3], hull *wide)
{
  if (map->count == 0 || !occluders || occluders->count == 0 || !(given->reland > 0) ||
      given->count > 8) {
    return given;
  }
  *wide = grown(given, points);
  return may_meet_impostors(map, occluders, wide) ? wide : given;
}

static int classify_hull(const vsh_rt_classify_map *map, const vsh_rt_classify_occluders *occluders,
                         const hull *given, int max_texels)
{
  if (!map || map->unusable) {
    return VSH_RT_CLASSIFY_UNDECIDED;
  }
  double points[8][3];
  hull wide;
  const hull *h = landing_hull(map, occluders, given, points, &wide);
  if (map->light.kind == VSH_RT_SPOT) {
    const int outside = outside_cone(&map->light, h);
    if (outside != 0) {
      return outside > 0 ? VSH_RT_CLASSIFY_OUTSIDE_CONE : VSH_RT_CLASSIFY_UNDECIDED;
    }
  }
  const int impostors = occluders && occluders->count > 0;
  if (map->count == 0) {
    /* Nothing in the map casts; impostors may, and the map has no faces
     * to place them in. */
    return impostors ? VSH_RT_CLASSIFY_UNDECIDED : VSH_RT_CLASSIFY_LIT;
  }
  const int f = choose_face(map, h);
  const vsh_rt_classify_face *face = &map->face[f];
  footprint fp;
  if (!locate(map, face, h, &fp)) {
    return VSH_RT_CLASSIFY_UNDECIDED;
  }
  const int c = classify_footprint(map, face, h, &fp, max_texels);
  if (c == VSH_RT_CLASSIFY_LIT && impostors &&
      !vsh_rtc_occluders_clear(occluders, face, f, fp.umin, fp.umax, fp.vmin, fp.vmax,
                               vsh_rtc_round_up(fp.key_hi))) {
    return VSH_RT_CLASSIFY_UNDECIDED; /* an impostor may be across the ray, or under it */
  }
  return c;
}

int vsh_rt_classify_pixel(const vsh_rt_classify_map *map, const vsh_rt_classify_tube *tube)
{
  return vsh_rt_classify_pixel_among(map, NULL, tube);
}

int vsh_rt_classify_pixel_among(const vsh_rt_classify_map *map,
                                const vsh_rt_classify_occluders *occluders,
                                const vsh_rt_classify_tube *tube)
{
  if (!tube || !(tube->t1 >= tube->t0)) {
    return VSH_RT_CLASSIFY_UNDECIDED;
  }
  double ends[2][3];
  for (int r = 0; r < 3; ++r) {
    ends[0][r] = tube->origin[r] + tube->t0 * tube->dir[r];
    ends[1][r] = tube->origin[r] + tube->t1 * tube->dir[r];
  }
  const hull h = { (const double(*)[3])ends, 2, (const double(*)[3])tube->dir, 1, tube->radius,
                   tube->reland };
  return classify_hull(map, occluders, &h, VSH_RT_CLASSIFY_MAX_TEXELS);
}

int vsh_rt_classify_block(const vsh_rt_classify_map *map, const vsh_rt_classify_region *region)
{
  return vsh_rt_classify_block_among(map, NULL, region);
}

int vsh_rt_classify_block_among(const vsh_rt_classify_map *map,
                                const vsh_rt_classify_occluders *occluders,
                                const vsh_rt_classify_region *region)
{
  if (!region) {
    return VSH_RT_CLASSIFY_UNDECIDED;
  }
  const hull h = { (const double(*)[3])region->corner, 8, (const double(*)[3])region->dir, 4,
                   region->radius, region->reland };
  return classify_hull(map, occluders, &h, VSH_RT_CLASSIFY_MAX_BLOCK_TEXELS);
}
