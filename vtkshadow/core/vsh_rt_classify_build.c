/* vsh_rt_classify_build.c - the light-space map of vsh_rt_classify.h: the
 * faces a light needs, and the order of its stages: plane groups and
 * contour edges (vsh_rt_classify_cover.c), then per face near, full and
 * union cover, then rest, which depends on each texel's final full
 * (vsh_rt_classify_raster.c), then the sheets (vsh_rt_classify_sheet.c). */
#include "vsh_rt_classify.h"
#include "vsh_rt_classify_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void basis(const double axis[3], double e1[3], double e2[3])
{
  const double helper[3] = { fabs(axis[0]) < 0.6 ? 1.0 : 0.0, fabs(axis[0]) < 0.6 ? 0.0 : 1.0,
                             0.0 };
  vsh_vec3_cross(axis, helper, e1);
  vsh_vec3_normalize(e1, e1);
  vsh_vec3_cross(axis, e1, e2);
}

/* Distance from point p to triangle t (9 doubles): the smallest over the
 * triangle's plane inside it, its edges and vertices. */
static double point_triangle_distance(const double p[3], const double *t)
{
  double e1[3], e2[3], n[3], d[3];
  vsh_vec3_sub(t + 3, t, e1);
  vsh_vec3_sub(t + 6, t, e2);
  vsh_vec3_cross(e1, e2, n);
  const double len = vsh_vec3_length(n);
  double best = HUGE_VAL;
  if (len > 0) {
    vsh_vec3_sub(p, t, d);
    const double h = vsh_vec3_dot(d, n) / len;
    int inside = 1;
    for (int k = 0; k < 3; ++k) {
      double e[3], w[3], c[3];
      vsh_vec3_sub(t + 3 * ((k + 1) % 3), t + 3 * k, e);
      vsh_vec3_sub(p, t + 3 * k, w);
      vsh_vec3_cross(e, w, c);
      inside = inside && vsh_vec3_dot(c, n) >= 0;
    }
    if (inside) {
      best = fabs(h);
    }
  }
  for (int k = 0; k < 3; ++k) {
    const double *a = t + 3 * k, *b = t + 3 * ((k + 1) % 3);
    double ab[3], ap[3];
    vsh_vec3_sub(b, a, ab);
    vsh_vec3_sub(p, a, ap);
    const double l2 = vsh_vec3_dot(ab, ab);
    double s = l2 > 0 ? vsh_vec3_dot(ap, ab) / l2 : 0;
    s = s < 0 ? 0 : (s > 1 ? 1 : s);
    for (int r = 0; r < 3; ++r) {
      d[r] = a[r] + s * ab[r] - p[r];
    }
    best = fmin(best, vsh_vec3_length(d));
  }
  return best;
}

/* The faces the light needs, and each face's extent. */
static void place_faces(vsh_rt_classify_map *map)
{
  const vsh_rt_light *light = &map->light;
  if (light->kind == VSH_RT_DIRECTIONAL) {
    vsh_rt_classify_face *f = &map->face[0];
    map->faces = 1;
    vsh_vec3_scale(light->direction, -1.0, f->axis);
    basis(f->axis, f->e1, f->e2);
    double umin = HUGE_VAL, umax = -HUGE_VAL, vmin = HUGE_VAL, vmax = -HUGE_VAL;
    for (size_t t = 0; t < map->count; ++t) {
      for (int k = 0; k < 3; ++k) {
        const double *p = map->triangles + 9 * t + 3 * k;
        umin = fmin(umin, vsh_vec3_dot(p, f->e1));
        umax = fmax(umax, vsh_vec3_dot(p, f->e1));
        vmin = fmin(vmin, vsh_vec3_dot(p, f->e2));
        vmax = fmax(vmax, vsh_vec3_dot(p, f->e2));
      }
    }
    const double side = fmax(umax - umin, vmax - vmin), pad = 1e-3 * side + 1e-12 * map->scale;
    f->u0 = umin - pad;
    f->v0 = vmin - pad;
    f->texel = (side + 2 * pad) / f->n;
    return;
  }
  const double cone = light->kind == VSH_RT_SPOT ? acos(fmax(-1.0, fmin(1.0, light->cos_cone))) : M_PI;
  if (cone < 75.0 * M_PI / 180.0) {
    vsh_rt_classify_face *f = &map->face[0];
    map->faces = 1;
    f->perspective = 1;
    memcpy(f->axis, light->direction, sizeof f->axis);
    basis(f->axis, f->e1, f->e2);
    const double extent = 1.01 * tan(cone) + 1e-3;
    f->u0 = f->v0 = -extent;
    f->texel = 2 * extent / f->n;
    return;
  }
  map->faces = 6;
  for (int k = 0; k < 6; ++k) {
    vsh_rt_classify_face *f = &map->face[k];
    f->perspective = 1;
    memset(f->axis, 0, sizeof f->axis);
    f->axis[k / 2] = k % 2 ? -1.0 : 1.0;
    basis(f->axis, f->e1, f->e2);
    f->u0 = f->v0 = -1.001;
    f->texel = 2 * 1.001 / f->n;
  }
}

static int allocate(vsh_rt_classify_face *f)
{
  const size_t n = (size_t)f->n * (size_t)f->n;
  f->texels = malloc(n * sizeof *f->texels);
  f->coarse = malloc((n / 64 + 1) * sizeof *f->coarse);
  f->normal_box = malloc((n / 64 + 1) * 6 * sizeof *f->normal_box);
  f->bent = calloc(n, 1);
  if (!f->texels || !f->coarse || !f->normal_box || !f->bent) {
    return 1;
  }
  const vsh_rt_classify_texel empty = { INFINITY, INFINITY, INFINITY, INFINITY, -INFINITY, -1 };
  for (size_t x = 0; x < n; ++x) {
    f->texels[x] = empty;
  }
  for (size_t b = 0; b < n / 64 + 1; ++b) {
    for (int r = 0; r < 3; ++r) {
      f->normal_box[6 * b + (size_t)r] = INFINITY;
      f->normal_box[6 * b + 3 + (size_t)r] = -INFINITY;
    }
  }
  return 0;
}

/* The coarse level: each 8 x 8 block's texels (together in memory). */
static void summarize(vsh_rt_classify_face *f)
{
  const size_t blocks = (size_t)(f->n / 8) * (size_t)(f->n / 8);
  for (size_t b = 0; b < blocks; ++b) {
    const vsh_rt_classify_texel *t = f->texels + 64 * b;
    vsh_rt_classify_texel c = { INFINITY, -INFINITY, INFINITY, 0, INFINITY, t[0].full };
    for (int k = 0; k < 64; ++k) {
      c.near_key = fminf(c.near_key, t[k].near_key);
      /* A bent texel's sheet needs its footprint: not at this level. */
      c.sheet = fminf(c.sheet, fmaxf(t[k].near_key, f->bent[64 * b + (size_t)k] ? -INFINITY
                                                                                 : t[k].sheet));
      c.rest = fminf(c.rest, t[k].rest);
      c.full_far = fmaxf(c.full_far, fminf(t[k].full >= 0 ? t[k].full_far : INFINITY, t[k].cover_far));
      c.full = t[k].full == c.full ? c.full : -1;
    }
    c.cover_far = c.full_far; /* the shadow rule reads either */
    f->coarse[b] = c;
  }
}

/* The stages after the faces are placed: per triangle its light-facing
 * normal, plane group and edges; per face near, full and union cover,
 * rest (which reads the final full), and LIT (c)'s sheets. */
static int build_faces(vsh_rt_classify_map *map, const int *placements)
{
  const size_t count = map->count, texels = (size_t)map->face[0].n * (size_t)map->face[0].n;
  unsigned char *contour = malloc(count ? 3 * count : 1), *facing = malloc(count ? count : 1);
  unsigned char *crossed = malloc(texels);
  double *normals = malloc((count ? 3 * count : 1) * sizeof *normals);
  int *partner = malloc((count ? 3 * count : 1) * sizeof *partner);
  int failed = !contour || !facing || !crossed || !normals || !partner;
  if (!failed) {
    vsh_rtc_light_normals(map, normals, facing);
    failed = vsh_rtc_plane_groups(map) || vsh_rtc_contours(map, placements, normals, contour, partner);
  }
  const vsh_rtc_layer_input in = { placements, normals, facing, partner, contour, crossed };
  for (int k = 0; k < map->faces && !failed; ++k) {
    memset(crossed, 0, texels);
    failed = vsh_rtc_cover_face(map, &map->face[k], placements, contour, crossed);
    for (size_t t = 0; t < count && !failed; ++t) {
      vsh_rtc_rasterize(map, &map->face[k], t, 1, NULL);
    }
    failed = failed || vsh_rtc_sheet_face(map, &map->face[k], &in);
  }
  free(contour);
  free(facing);
  free(crossed);
  free(normals);
  free(partner);
  return failed;
}

int vsh_rt_classify_build(vsh_rt_classify_map *map, const vsh_rt_light *light,
                          const double *triangles, const unsigned char *flags,
                          const int *placements, size_t count, int resolution)
{
  const clock_t start = clock();
  memset(map, 0, sizeof *map);
  map->unusable = 1;
  if (!light || (count > 0 && (!triangles || !flags)) || resolution < 16 || resolution > 8192 ||
      resolution % 8 != 0) {
    return 1;
  }
  map->light = *light;
  map->count = count;
  map->triangles = malloc((count ? count : 1) * 9 * sizeof(double));
  map->flags = malloc(count ? count : 1);
  map->group = malloc((count ? count : 1) * sizeof(int));
  if (!map->triangles || !map->flags || !map->group) {
    return 1;
  }
  if (count > 0) { /* memcpy from NULL is undefined even for 0 bytes */
    memcpy(map->triangles, triangles, count * 9 * sizeof(double));
    memcpy(map->flags, flags, count);
  }
  double scale = light->kind == VSH_RT_DIRECTIONAL ? 0.0 : vsh_vec3_length(light->position);
  for (size_t k = 0; k < 9 * count; ++k) {
    if (!isfinite(triangles[k])) {
      return 1;
    }
    scale = fmax(scale, fabs(triangles[k]));
  }
  map->scale = scale > 0 ? scale : 1.0;
  map->near_z = 1e-4 * map->scale;
  for (int k = 0; k < 6; ++k) {
    map->face[k].n = resolution;
  }
  place_faces(map);
  for (int k = 0; k < map->faces; ++k) {
    if (allocate(&map->face[k])) {
      return 1;
    }
  }
  if (light->kind != VSH_RT_DIRECTIONAL) {
    for (size_t t = 0; t < count; ++t) {
      if (point_triangle_distance(light->position, triangles + 9 * t) < 4 * map->near_z) {
        map->build_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
        return 0; /* geometry at the light: nothing decided */
      }
    }
  }
  if (build_faces(map, placements)) {
    return 1;
  }
  for (int k = 0; k < map->faces; ++k) {
    summarize(&map->face[k]);
  }
  map->unusable = 0;
  map->build_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
  return 0;
}

void vsh_rt_classify_free(vsh_rt_classify_map *map)
{
  for (int k = 0; k < 6; ++k) {
    free(map->face[k].texels);
    free(map->face[k].coarse);
    free(map->face[k].normal_box);
    free(map->face[k].bent);
    free(map->face[k].bend_start);
    free(map->face[k].bend_list);
    free(map->face[k].bends);
  }
  free(map->triangles);
  free(map->flags);
  free(map->group);
  memset(map, 0, sizeof *map);
  map->unusable = 1;
}

size_t vsh_rt_classify_bytes(const vsh_rt_classify_map *map)
{
  size_t bytes = map->count * (9 * sizeof(double) + 1 + sizeof(int));
  for (int k = 0; k < map->faces; ++k) {
    const size_t texels = (size_t)map->face[k].n * (size_t)map->face[k].n;
    bytes += texels * sizeof(vsh_rt_classify_texel) * 65 / 64 + texels / 64 * 6 * sizeof(float);
  }
  return bytes;
}
