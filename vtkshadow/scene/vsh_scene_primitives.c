/* vsh_scene_primitives.c - the objects VTK draws without a surface mesh:
 * "points" (RenderPointsAsSpheres), "polyline" (RenderLinesAsTubes) and
 * "volume" (a volume-rendered blob).
 *
 * Points and lines have a size in pixels, not in world units: VTK's
 * impostors are `pixels` wide on screen at every depth. The ray tracers need
 * solids, so the loader turns the pixel size into a world radius per
 * position once, with the scene's own camera and size; a renderer drawing
 * the scene at another size scales the pixel size with it, and every
 * renderer then sees the same solids.
 */
#include "vsh_scene_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const points_keys[] = {"positions", "point_size", "resolution", NULL};
static const char *const polyline_keys[] = {"points", "line_width", "resolution", NULL};
static const char *const volume_keys[] = {"center", "radius", "density", "samples", NULL};

double vsh_impostor_world_radius(const vsh_scene *scene, double pixels, const double p[3]) {
  const vsh_camera *c = &scene->camera;
  double view[3], rel[3], d;
  int i;
  for (i = 0; i < 3; ++i) {
    view[i] = c->focal_point[i] - c->position[i];
    rel[i] = p[i] - c->position[i];
  }
  if (!vsh__normalize3(view, view)) return 0.0;
  d = vsh__dot3(rel, view);
  if (!(d > 0.0) || !(scene->height > 0) || !(pixels > 0.0)) return 0.0;
  return pixels * d * tan(c->view_angle * VSH_PI / 360.0) / (double)scene->height;
}

/* A positive number of pixels at the scene's size. */
static int pixel_size(const vsh_ctx *ctx, const cJSON *shape, const char *f, const char *key,
                      double *out) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item = cJSON_GetObjectItemCaseSensitive(shape, key);
  vsh__field(field, f, key);
  if (vsh__require(ctx, item, field) || vsh__number(ctx, item, field, out)) return -1;
  if (!(*out > 0.0 && *out <= 4096.0)) {
    vsh__fmt_number(*out, got, sizeof got);
    return vsh__fail(ctx, field, got, "must be in (0, 4096] pixels");
  }
  return 0;
}

/* `key`: an array of at least `least` [x, y, z] positions, each in front of
 * the camera, with the impostor radius there. */
static int positions(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *shape,
                     const char *f, const char *key, size_t least, vsh_object *o) {
  char field[VSH_FIELD_MAX], sub[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item = cJSON_GetObjectItemCaseSensitive(shape, key), *e;
  size_t n = 0, i;
  vsh__field(field, f, key);
  if (vsh__require(ctx, item, field)) return -1;
  if (!cJSON_IsArray(item)) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected an array of [x, y, z] positions");
  }
  for (e = item->child; e; e = e->next) ++n;
  if (n < least) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "needs at least %zu positions", least);
  }
  if (n > 1000000) return vsh__fail(ctx, field, NULL, "more than 1000000 positions (%zu)", n);
  o->positions = (double *)calloc(3 * n, sizeof(double));
  o->radii = (double *)calloc(n, sizeof(double));
  if (!o->positions || !o->radii) return vsh__fail(ctx, field, NULL, "out of memory");
  o->position_count = n;
  for (i = 0, e = item->child; e; e = e->next, ++i) {
    double *p = o->positions + 3 * i;
    vsh__field_index(sub, field, i);
    if (vsh__vector(ctx, e, sub, 3, p)) return -1;
    o->radii[i] = vsh_impostor_world_radius(scene, o->pixels, p);
    if (!(o->radii[i] > 0.0) || !isfinite(o->radii[i])) {
      vsh__fmt_vec(p, 3, got, sizeof got);
      return vsh__fail(ctx, sub, got,
                       "not in front of the camera (VTK draws no impostor there, so it "
                       "has no size)");
    }
  }
  return 0;
}

int vsh__parse_points(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *shape,
                      const char *f, vsh_object *o) {
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, points_keys, NULL)) return -1;
  if (pixel_size(ctx, shape, f, "point_size", &o->pixels)) return -1;
  /* 32 around: the inscribed UV sphere's radius is within 0.5 % of the
   * impostor's, well under a pixel of a point's shadow. */
  if (vsh__resolution(ctx, shape, f, 32, 256, &o->resolution)) return -1;
  return positions(ctx, scene, shape, f, "positions", 1, o);
}

int vsh__parse_polyline(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *shape,
                        const char *f, vsh_object *o) {
  char field[VSH_FIELD_MAX], sub[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  size_t i;
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, polyline_keys, NULL))
    return -1;
  if (pixel_size(ctx, shape, f, "line_width", &o->pixels)) return -1;
  if (vsh__resolution(ctx, shape, f, 24, 256, &o->resolution)) return -1;
  if (positions(ctx, scene, shape, f, "points", 2, o)) return -1;
  /* A zero-length segment has no axis for its frustum. */
  vsh__field(field, f, "points");
  for (i = 1; i < o->position_count; ++i) {
    const double *a = o->positions + 3 * (i - 1), *b = o->positions + 3 * i;
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {
      vsh__field_index(sub, field, i);
      vsh__fmt_vec(b, 3, got, sizeof got);
      return vsh__fail(ctx, sub, got, "equal to the point before it (a segment needs a length)");
    }
  }
  return 0;
}

int vsh__parse_volume(const vsh_ctx *ctx, const cJSON *shape, const char *f, vsh_object *o) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item;
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, volume_keys, NULL)) return -1;
  if (vsh__need_vec3(ctx, shape, f, "center", o->center) ||
      vsh__positive(ctx, shape, f, "radius", &o->radius))
    return -1;
  /* density * radius is the optical depth from the edge to the centre: past
   * ~50 nothing at all gets through and a float transfer function cannot say
   * more. */
  vsh__field(field, f, "density");
  item = cJSON_GetObjectItemCaseSensitive(shape, "density");
  if (vsh__require(ctx, item, field) || vsh__number(ctx, item, field, &o->density)) return -1;
  if (!(o->density > 0.0) || !(o->density * o->radius <= 50.0)) {
    vsh__fmt_number(o->density, got, sizeof got);
    return vsh__fail(ctx, field, got, "must be > 0 with density * radius <= 50");
  }
  o->samples = 64;
  if ((item = cJSON_GetObjectItemCaseSensitive(shape, "samples"))) {
    vsh__field(field, f, "samples");
    if (vsh__integer(ctx, item, field, 8, 512, &o->samples)) return -1;
  }
  return 0;
}
