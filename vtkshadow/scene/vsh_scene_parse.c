/* vsh_scene_parse.c - JSON text -> vsh_scene, with validation.
 *
 * Walks the top level, the camera and the lights; objects are in
 * vsh_scene_objects.c. Every check fails fast with one message naming the
 * file, the field path and the offending value: a scene file is written by
 * hand, and the first error is the one worth fixing.
 */
#include "vsh_scene_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Tolerance for "view_up parallel to the view direction": the sine of the
 * angle between them, so it does not depend on the vectors' lengths. */
#define VSH_PARALLEL_SIN 1e-9

static const char *const top_keys[] = {"description", "size",   "camera", "background",
                                       "lights",      "objects", NULL};
static const char *const camera_keys[] = {"position", "focal_point", "view_up", "view_angle",
                                          NULL};
static const char *const directional_keys[] = {"type",      "direction", "color",
                                               "intensity", "angle",     NULL};
static const char *const point_keys[] = {"type", "position", "color", "intensity", "radius", NULL};
static const char *const spot_keys[] = {"type",  "position",  "focal_point", "cone_angle",
                                        "color", "intensity", "radius",      NULL};

/* Required member: missing -> "missing required field". */
static const cJSON *need(const vsh_ctx *ctx, const cJSON *obj, const char *parent,
                         const char *key, char *field) {
  const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
  vsh__field(field, parent, key);
  if (vsh__require(ctx, item, field)) return NULL;
  return item;
}

/* b - a, rejecting the (absurd) case where the difference overflows. */
static int difference(const vsh_ctx *ctx, const double a[3], const double b[3],
                      const char *field, const char *other, double d[3]) {
  char got[VSH_GOT_MAX];
  int i;
  for (i = 0; i < 3; ++i) d[i] = b[i] - a[i];
  if (!isfinite(d[0]) || !isfinite(d[1]) || !isfinite(d[2])) {
    vsh__fmt_vec(b, 3, got, sizeof got);
    return vsh__fail(ctx, field, got, "too far from %s (difference overflows)", other);
  }
  if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0) {
    vsh__fmt_vec(b, 3, got, sizeof got);
    return vsh__fail(ctx, field, got, "equal to %s", other);
  }
  return 0;
}

static int parse_size(const vsh_ctx *ctx, const cJSON *item, vsh_scene *scene) {
  char got[VSH_GOT_MAX], field[VSH_FIELD_MAX];
  if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != 2) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, "size", got, "expected [width, height]");
  }
  vsh__field_index(field, "size", 0);
  if (vsh__integer(ctx, cJSON_GetArrayItem(item, 0), field, 1, 16384, &scene->width)) return -1;
  vsh__field_index(field, "size", 1);
  return vsh__integer(ctx, cJSON_GetArrayItem(item, 1), field, 1, 16384, &scene->height);
}

static int parse_camera(const vsh_ctx *ctx, const cJSON *obj, vsh_camera *cam) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item;
  double dir[3];
  if (vsh__object(ctx, obj, "camera") ||
      vsh__check_keys(ctx, obj, "camera", camera_keys, NULL))
    return -1;
  if (!(item = need(ctx, obj, "camera", "position", field)) ||
      vsh__vector(ctx, item, field, 3, cam->position))
    return -1;
  if (!(item = need(ctx, obj, "camera", "focal_point", field)) ||
      vsh__vector(ctx, item, field, 3, cam->focal_point))
    return -1;
  if (difference(ctx, cam->position, cam->focal_point, field, "camera.position", dir)) return -1;
  if (!(item = need(ctx, obj, "camera", "view_up", field)) ||
      vsh__vector(ctx, item, field, 3, cam->view_up))
    return -1;
  vsh__fmt_vec(cam->view_up, 3, got, sizeof got);
  {
    double s = vsh__sin_between(dir, cam->view_up);
    if (s < 0.0) return vsh__fail(ctx, field, got, "zero length");
    if (s < VSH_PARALLEL_SIN) return vsh__fail(ctx, field, got, "parallel to the view direction");
  }
  if (!(item = need(ctx, obj, "camera", "view_angle", field)) ||
      vsh__number(ctx, item, field, &cam->view_angle))
    return -1;
  if (!(cam->view_angle > 0.0 && cam->view_angle < 180.0)) {
    vsh__fmt_number(cam->view_angle, got, sizeof got);
    return vsh__fail(ctx, field, got, "must be in (0, 180) degrees");
  }
  return 0;
}

/* The light's size (optional, default 0 = hard): "radius" of a point or spot
 * light's disk, "angle" (angular diameter, degrees) of a directional light.
 * The key for the other kind was already refused by the key check. An angle
 * of 180 degrees or more has no finite tangent (a light filling the sky). */
static int parse_light_size(const vsh_ctx *ctx, const cJSON *obj, const char *parent,
                            vsh_light *light) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item;
  light->radius = 0.0;
  light->angle = 0.0;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "radius"))) {
    vsh__field(field, parent, "radius");
    if (vsh__number(ctx, item, field, &light->radius)) return -1;
    if (!(light->radius >= 0.0)) {
      vsh__fmt_number(light->radius, got, sizeof got);
      return vsh__fail(ctx, field, got, "must be >= 0 (0 is a hard point light)");
    }
  }
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "angle"))) {
    vsh__field(field, parent, "angle");
    if (vsh__number(ctx, item, field, &light->angle)) return -1;
    if (!(light->angle >= 0.0 && light->angle < 180.0)) {
      vsh__fmt_number(light->angle, got, sizeof got);
      return vsh__fail(ctx, field, got,
                       "must be in [0, 180) degrees (angular diameter; 0 is a hard sun)");
    }
  }
  return 0;
}

static int parse_light(const vsh_ctx *ctx, const cJSON *obj, const char *parent,
                       vsh_light *light) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item;
  const char *const *keys;
  const char *what;
  int i;
  if (vsh__object(ctx, obj, parent)) return -1;
  if (!(item = need(ctx, obj, parent, "type", field))) return -1;
  if (!cJSON_IsString(item)) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected \"directional\", \"point\" or \"spot\"");
  }
  if (strcmp(item->valuestring, "directional") == 0) {
    light->type = VSH_LIGHT_DIRECTIONAL;
    keys = directional_keys;
    what = "for a directional light";
  } else if (strcmp(item->valuestring, "point") == 0) {
    light->type = VSH_LIGHT_POINT;
    keys = point_keys;
    what = "for a point light";
  } else if (strcmp(item->valuestring, "spot") == 0) {
    light->type = VSH_LIGHT_SPOT;
    keys = spot_keys;
    what = "for a spot light";
  } else {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected \"directional\", \"point\" or \"spot\"");
  }
  if (vsh__check_keys(ctx, obj, parent, keys, what)) return -1;

  if (light->type == VSH_LIGHT_DIRECTIONAL) {
    double raw[3];
    if (!(item = need(ctx, obj, parent, "direction", field)) ||
        vsh__vector(ctx, item, field, 3, raw))
      return -1;
    if (!vsh__normalize3(raw, light->direction)) {
      vsh__fmt_vec(raw, 3, got, sizeof got);
      return vsh__fail(ctx, field, got, "zero length");
    }
  } else {
    if (!(item = need(ctx, obj, parent, "position", field)) ||
        vsh__vector(ctx, item, field, 3, light->position))
      return -1;
  }
  if (light->type == VSH_LIGHT_SPOT) {
    double axis[3];
    char other[VSH_FIELD_MAX];
    if (!(item = need(ctx, obj, parent, "focal_point", field)) ||
        vsh__vector(ctx, item, field, 3, light->focal_point))
      return -1;
    vsh__field(other, parent, "position");
    if (difference(ctx, light->position, light->focal_point, field, other, axis)) return -1;
    if (!(item = need(ctx, obj, parent, "cone_angle", field)) ||
        vsh__number(ctx, item, field, &light->cone_angle))
      return -1;
    if (!(light->cone_angle > 0.0 && light->cone_angle <= 90.0)) {
      vsh__fmt_number(light->cone_angle, got, sizeof got);
      return vsh__fail(ctx, field, got, "must be in (0, 90] degrees (a half-angle)");
    }
  }

  light->color[0] = light->color[1] = light->color[2] = 1.0;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "color"))) {
    vsh__field(field, parent, "color");
    if (vsh__vector(ctx, item, field, 3, light->color)) return -1;
    for (i = 0; i < 3; ++i) {
      if (light->color[i] < 0.0) {
        char sub[VSH_FIELD_MAX];
        vsh__field_index(sub, field, (size_t)i);
        vsh__fmt_number(light->color[i], got, sizeof got);
        return vsh__fail(ctx, sub, got, "must be >= 0");
      }
    }
  }
  light->intensity = 1.0;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "intensity"))) {
    vsh__field(field, parent, "intensity");
    if (vsh__number(ctx, item, field, &light->intensity)) return -1;
    if (light->intensity < 0.0) {
      vsh__fmt_number(light->intensity, got, sizeof got);
      return vsh__fail(ctx, field, got, "must be >= 0");
    }
  }
  return parse_light_size(ctx, obj, parent, light);
}

/* A non-empty JSON array, returned with its length. */
static int nonempty_array(const vsh_ctx *ctx, const cJSON *item, const char *field,
                          size_t *count) {
  char got[VSH_GOT_MAX];
  const cJSON *e;
  if (!cJSON_IsArray(item)) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected an array");
  }
  *count = 0;
  for (e = item->child; e; e = e->next) ++*count;
  if (*count == 0) return vsh__fail(ctx, field, "[]", "needs at least one entry");
  return 0;
}

/* Line and column (1-based, bytes) of a position in the text. */
static void line_column(const char *text, size_t pos, size_t *line, size_t *column) {
  size_t i;
  *line = 1;
  *column = 1;
  for (i = 0; i < pos; ++i) {
    if (text[i] == '\n') {
      ++*line;
      *column = 1;
    } else {
      ++*column;
    }
  }
}

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

static int parse_tree(const vsh_ctx *ctx, const cJSON *root, const char *path, vsh_scene *s) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item, *e;
  size_t i;
  if (!cJSON_IsObject(root)) {
    vsh__fmt_json(root, got, sizeof got);
    return vsh__fail(ctx, NULL, got, "expected a JSON object at the top level");
  }
  if (vsh__check_keys(ctx, root, "", top_keys, NULL)) return -1;

  if ((item = cJSON_GetObjectItemCaseSensitive(root, "description")) &&
      vsh__string(ctx, item, "description", &s->description))
    return -1;
  if (!(item = need(ctx, root, "", "size", field)) || parse_size(ctx, item, s)) return -1;
  if (!(item = need(ctx, root, "", "camera", field)) || parse_camera(ctx, item, &s->camera))
    return -1;
  if ((item = cJSON_GetObjectItemCaseSensitive(root, "background")) &&
      vsh__color01(ctx, item, "background", s->background))
    return -1;

  if (!(item = need(ctx, root, "", "lights", field)) ||
      nonempty_array(ctx, item, field, &s->light_count))
    return -1;
  s->lights = (vsh_light *)calloc(s->light_count, sizeof *s->lights);
  if (!s->lights) return vsh__fail(ctx, "lights", NULL, "out of memory");
  for (i = 0, e = item->child; e; e = e->next, ++i) {
    vsh__field_index(field, "lights", i);
    if (parse_light(ctx, e, field, &s->lights[i])) return -1;
  }

  if (!(item = need(ctx, root, "", "objects", field)) ||
      nonempty_array(ctx, item, field, &s->object_count))
    return -1;
  s->objects = (vsh_object *)calloc(s->object_count, sizeof *s->objects);
  if (!s->objects) return vsh__fail(ctx, "objects", NULL, "out of memory");
  for (i = 0, e = item->child; e; e = e->next, ++i)
    if (vsh__parse_object(ctx, s, e, i, path, &s->objects[i])) return -1;
  return 0;
}

int vsh_scene_parse(const char *text, size_t length, const char *path, vsh_scene **out,
                    char *err, size_t err_size) {
  vsh_ctx ctx;
  vsh_scene *scene;
  cJSON *root;
  char *copy;
  const char *end = NULL;
  size_t i;
  int rc;

  ctx.file = path ? path : "(memory)";
  ctx.err = err;
  ctx.err_size = err_size;
  if (err && err_size) err[0] = '\0';
  if (!out) return vsh__fail(&ctx, NULL, NULL, "no output pointer given");
  *out = NULL;
  if (!text) length = 0;

  for (i = 0; i < length && is_space(text[i]); ++i) {
  }
  if (i == length) return vsh__fail(&ctx, NULL, NULL, "empty file");

  /* A terminated private copy: cJSON's number parser and our line counting
   * then never depend on what lies beyond `length` in the caller's buffer. */
  copy = (char *)malloc(length + 1);
  if (!copy) return vsh__fail(&ctx, NULL, NULL, "out of memory");
  memcpy(copy, text, length);
  copy[length] = '\0';

  /* cJSON_ParseWithLengthOpts reports the error position through `end`
   * (unlike cJSON_GetErrorPtr it is not global state, so it is thread-safe). */
  root = cJSON_ParseWithLengthOpts(copy, length, &end, 0);
  if (!root) {
    size_t pos = (end && end >= copy && end <= copy + length) ? (size_t)(end - copy) : 0, line, col;
    line_column(copy, pos, &line, &col);
    free(copy);
    return vsh__fail(&ctx, NULL, NULL, "line %zu column %zu: invalid JSON", line, col);
  }
  if (end && end >= copy && end <= copy + length) {
    size_t pos = (size_t)(end - copy);
    while (pos < length && is_space(copy[pos])) ++pos;
    if (pos < length) {
      size_t line, col;
      line_column(copy, pos, &line, &col);
      cJSON_Delete(root);
      free(copy);
      return vsh__fail(&ctx, NULL, NULL, "line %zu column %zu: invalid JSON (text after the end)",
                       line, col);
    }
  }
  free(copy);

  scene = (vsh_scene *)calloc(1, sizeof *scene);
  if (!scene) {
    cJSON_Delete(root);
    return vsh__fail(&ctx, NULL, NULL, "out of memory");
  }
  rc = parse_tree(&ctx, root, path, scene);
  if (rc == 0 && path && !(scene->path = vsh__strdup(path)))
    rc = vsh__fail(&ctx, NULL, NULL, "out of memory");
  cJSON_Delete(root);
  if (rc) {
    vsh_scene_free(scene);
    return rc;
  }
  *out = scene;
  return 0;
}
