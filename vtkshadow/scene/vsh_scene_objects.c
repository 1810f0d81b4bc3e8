/* vsh_scene_objects.c - one entry of "objects": shape, transform, flags, mesh path.
 *
 * Geometry is validated here rather than at tessellation time so that a bad
 * primitive (zero radius, flat box, parallel plane edges, singular transform)
 * is reported against its place in the file, and every renderer downstream can
 * assume well-formed input.
 */
#include "vsh_scene_internal.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define VSH_PARALLEL_SIN 1e-9
/* Transforms whose rows are this close to linearly dependent are singular for
 * all practical purposes (normals would come out as noise). */
#define VSH_SINGULAR_RELATIVE_DET 1e-12
#define VSH_SINGULAR_ABSOLUTE_DET 1e-300

static const char *const object_keys[] = {
    "sphere", "plane",     "box",    "cylinder", "mesh",    "points",  "polyline", "volume",
    "receiver", "casts", "color", "name", "transform", "mirror", "opacity", "filter", NULL};
static const char *const shape_keys[] = {"sphere", "plane",    "box",    "cylinder",
                                         "mesh",   "points", "polyline", "volume", NULL};
static const char *const sphere_keys[] = {"center", "radius", "resolution", NULL};
static const char *const plane_keys[] = {"origin", "point1", "point2", NULL};
static const char *const box_keys[] = {"min", "max", NULL};
static const char *const cylinder_keys[] = {"base", "top", "radius", "resolution", NULL};

static const cJSON *need(const vsh_ctx *ctx, const cJSON *obj, const char *parent,
                         const char *key, char *field) {
  const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
  vsh__field(field, parent, key);
  if (vsh__require(ctx, item, field)) return NULL;
  return item;
}

int vsh__need_vec3(const vsh_ctx *ctx, const cJSON *obj, const char *parent, const char *key,
                   double out[3]) {
  char field[VSH_FIELD_MAX];
  const cJSON *item = need(ctx, obj, parent, key, field);
  return !item || vsh__vector(ctx, item, field, 3, out) ? -1 : 0;
}

int vsh__positive(const vsh_ctx *ctx, const cJSON *obj, const char *parent, const char *key,
                  double *out) {
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item = need(ctx, obj, parent, key, field);
  if (!item || vsh__number(ctx, item, field, out)) return -1;
  if (!(*out > 0.0)) {
    vsh__fmt_number(*out, got, sizeof got);
    return vsh__fail(ctx, field, got, "must be > 0");
  }
  return 0;
}

int vsh__resolution(const vsh_ctx *ctx, const cJSON *obj, const char *parent, int fallback,
                    int most, int *out) {
  char field[VSH_FIELD_MAX];
  const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "resolution");
  *out = fallback;
  if (!item) return 0;
  vsh__field(field, parent, "resolution");
  return vsh__integer(ctx, item, field, 3, most, out);
}

static int parse_sphere(const vsh_ctx *ctx, const cJSON *shape, const char *f, vsh_object *o) {
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, sphere_keys, NULL)) return -1;
  if (vsh__need_vec3(ctx, shape, f, "center", o->center)) return -1;
  if (vsh__positive(ctx, shape, f, "radius", &o->radius)) return -1;
  return vsh__resolution(ctx, shape, f, 64, 4096, &o->resolution);
}

static int parse_plane(const vsh_ctx *ctx, const cJSON *shape, const char *f, vsh_object *o) {
  double e1[3], e2[3], s;
  int i;
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, plane_keys, NULL)) return -1;
  if (vsh__need_vec3(ctx, shape, f, "origin", o->origin) ||
      vsh__need_vec3(ctx, shape, f, "point1", o->point1) ||
      vsh__need_vec3(ctx, shape, f, "point2", o->point2))
    return -1;
  for (i = 0; i < 3; ++i) {
    e1[i] = o->point1[i] - o->origin[i];
    e2[i] = o->point2[i] - o->origin[i];
  }
  s = vsh__sin_between(e1, e2);
  if (!(s >= VSH_PARALLEL_SIN)) { /* also catches zero edges (-1) and overflow (NaN) */
    char got[VSH_GOT_MAX];
    vsh__fmt_json(shape, got, sizeof got);
    return vsh__fail(ctx, f, got,
                     "zero area: point1 - origin and point2 - origin are parallel or zero");
  }
  return 0;
}

static int parse_box(const vsh_ctx *ctx, const cJSON *shape, const char *f, vsh_object *o) {
  int i;
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, box_keys, NULL)) return -1;
  if (vsh__need_vec3(ctx, shape, f, "min", o->min) || vsh__need_vec3(ctx, shape, f, "max", o->max))
    return -1;
  for (i = 0; i < 3; ++i) {
    if (!(o->min[i] < o->max[i])) {
      char field[VSH_FIELD_MAX], sub[VSH_FIELD_MAX], got[VSH_GOT_MAX], lo[64];
      vsh__field(sub, f, "max");
      vsh__field_index(field, sub, (size_t)i);
      vsh__fmt_number(o->max[i], got, sizeof got);
      vsh__fmt_number(o->min[i], lo, sizeof lo);
      return vsh__fail(ctx, field, got, "must be greater than min[%d] = %s", i, lo);
    }
  }
  return 0;
}

static int parse_cylinder(const vsh_ctx *ctx, const cJSON *shape, const char *f, vsh_object *o) {
  double axis[3];
  char field[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  int i;
  if (vsh__object(ctx, shape, f) || vsh__check_keys(ctx, shape, f, cylinder_keys, NULL))
    return -1;
  if (vsh__need_vec3(ctx, shape, f, "base", o->base) || vsh__need_vec3(ctx, shape, f, "top", o->top))
    return -1;
  for (i = 0; i < 3; ++i) axis[i] = o->top[i] - o->base[i];
  vsh__field(field, f, "top");
  vsh__fmt_vec(o->top, 3, got, sizeof got);
  if (axis[0] == 0.0 && axis[1] == 0.0 && axis[2] == 0.0)
    return vsh__fail(ctx, field, got, "equal to base");
  if (!isfinite(vsh__norm3(axis)))
    return vsh__fail(ctx, field, got, "too far from base (length overflows)");
  if (vsh__positive(ctx, shape, f, "radius", &o->radius)) return -1;
  return vsh__resolution(ctx, shape, f, 64, 4096, &o->resolution);
}

static int parse_transform(const vsh_ctx *ctx, const cJSON *item, const char *f, double m[16]) {
  char got[VSH_GOT_MAX];
  double det;
  if (vsh__vector(ctx, item, f, 16, m)) return -1;
  if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0) {
    vsh__fmt_vec(m + 12, 4, got, sizeof got);
    return vsh__fail(ctx, f, got, "must be affine (row-major, last row 0 0 0 1)");
  }
  det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
        m[2] * (m[4] * m[9] - m[5] * m[8]);
  /* Two tests: scale-free (rows nearly dependent), and absolute, so that a
   * consumer inverting the matrix the naive way never divides by ~0 or inf. */
  if (!(fabs(vsh__relative_det(m)) >= VSH_SINGULAR_RELATIVE_DET) ||
      !(fabs(det) > VSH_SINGULAR_ABSOLUTE_DET) || !isfinite(det)) {
    vsh__fmt_vec(m, 12, got, sizeof got);
    return vsh__fail(ctx, f, got, "linear part is singular or degenerate (determinant %g)", det);
  }
  return 0;
}

static int has_mesh_extension(const char *p) {
  static const char *const exts[] = {"ply", "obj", "stl", "vtp"};
  const char *slash = strrchr(p, '/'), *dot = strrchr(p, '.');
  size_t i, k;
  if (!dot || (slash && dot < slash)) return 0;
  ++dot;
  if (strlen(dot) != 3) return 0;
  for (i = 0; i < 4; ++i) {
    for (k = 0; k < 3; ++k)
      if (tolower((unsigned char)dot[k]) != exts[i][k]) break;
    if (k == 3) return 1;
  }
  return 0;
}

/* Mesh paths are relative to the folder holding the scene file, so a scene and
 * its meshes can be moved together. */
static char *resolve(const char *scene_path, const char *mesh) {
  const char *slash = scene_path ? strrchr(scene_path, '/') : NULL;
  size_t dir_len = (mesh[0] == '/' || !slash) ? 0 : (size_t)(slash - scene_path) + 1;
  size_t n = strlen(mesh);
  char *out = (char *)malloc(dir_len + n + 1);
  if (!out) return NULL;
  if (dir_len) memcpy(out, scene_path, dir_len);
  memcpy(out + dir_len, mesh, n + 1);
  return out;
}

static int parse_mesh(const vsh_ctx *ctx, const cJSON *item, const char *f,
                      const char *scene_path, vsh_object *o) {
  char got[VSH_GOT_MAX * 2 + 32], written[VSH_GOT_MAX], looked[VSH_GOT_MAX];
  FILE *fp;
  cJSON tmp;
  if (vsh__string(ctx, item, f, &o->mesh_path)) return -1;
  vsh__fmt_json(item, written, sizeof written);
  if (!o->mesh_path[0]) return vsh__fail(ctx, f, written, "empty path");
  if (!has_mesh_extension(o->mesh_path))
    return vsh__fail(ctx, f, written, "unsupported file type, expected .ply, .obj, .stl or .vtp");
  o->mesh_resolved_path = resolve(scene_path, o->mesh_path);
  if (!o->mesh_resolved_path) return vsh__fail(ctx, f, NULL, "out of memory");

  memset(&tmp, 0, sizeof tmp);
  tmp.type = cJSON_String;
  tmp.valuestring = o->mesh_resolved_path;
  vsh__fmt_json(&tmp, looked, sizeof looked);
  if (strcmp(o->mesh_path, o->mesh_resolved_path) == 0)
    snprintf(got, sizeof got, "%s", written);
  else
    snprintf(got, sizeof got, "%s, looked for %s", written, looked);

  /* fopen succeeds on a directory on POSIX; reading one byte catches that. */
  errno = 0;
  fp = fopen(o->mesh_resolved_path, "rb");
  if (!fp) return vsh__fail(ctx, f, got, "unreadable: %s", strerror(errno));
  errno = 0;
  if (getc(fp) == EOF && ferror(fp)) {
    int e = errno;
    fclose(fp);
    return vsh__fail(ctx, f, got, "unreadable: %s", strerror(e ? e : EIO));
  }
  fclose(fp);
  return 0;
}

/* "mirror": R, the reflectance of a planar mirror. Only a plane has one
 * reflection plane, and R outside [0, 1] would create or destroy light. */
static int parse_mirror(const vsh_ctx *ctx, const cJSON *item, const char *field,
                        vsh_object *o) {
  char got[VSH_GOT_MAX];
  if (vsh__number(ctx, item, field, &o->mirror)) return -1;
  vsh__fmt_json(item, got, sizeof got);
  if (!(o->mirror >= 0.0 && o->mirror <= 1.0))
    return vsh__fail(ctx, field, got, "must be in [0, 1]");
  if (o->kind != VSH_OBJECT_PLANE)
    return vsh__fail(ctx, field, got, "only a plane can be a mirror, and a %s is not a plane",
                     vsh_object_kind_name(o->kind));
  o->has_mirror = 1;
  return 0;
}

/* A fraction in [0, 1] ("opacity", "filter"). */
static int parse_fraction(const vsh_ctx *ctx, const cJSON *item, const char *field,
                          double *out) {
  char got[VSH_GOT_MAX];
  if (vsh__number(ctx, item, field, out)) return -1;
  vsh__fmt_json(item, got, sizeof got);
  if (!(*out >= 0.0 && *out <= 1.0)) return vsh__fail(ctx, field, got, "must be in [0, 1]");
  return 0;
}

/* "opacity" and "filter": translucency. A mirror is opaque: the reflection
 * pass draws the mirrored scene into the mirror's pixels, which a
 * translucent mirror would also have to show through. */
static int parse_translucency(const vsh_ctx *ctx, const cJSON *obj, const char *f,
                              vsh_object *o) {
  char sub[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *item;
  o->opacity = 1.0;
  o->filter = 0.0;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "opacity"))) {
    vsh__field(sub, f, "opacity");
    if (parse_fraction(ctx, item, sub, &o->opacity)) return -1;
    if (o->has_mirror && o->opacity < 1.0) {
      vsh__fmt_json(item, got, sizeof got);
      return vsh__fail(ctx, sub, got, "a mirror must be opaque (opacity 1)");
    }
  }
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "filter"))) {
    vsh__field(sub, f, "filter");
    if (parse_fraction(ctx, item, sub, &o->filter)) return -1;
  }
  return 0;
}

/* Points, polylines and volumes are given in world coordinates: their
 * solids depend on the camera (impostors) or are sampled on an axis-aligned
 * grid (volumes), which a transform would skew; they are opaque. */
static int world_only(const vsh_ctx *ctx, const cJSON *obj, const char *f, const vsh_object *o) {
  static const char *const keys[] = {"transform", "opacity", "filter", NULL};
  char sub[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const char *const *k;
  for (k = keys; *k; ++k) {
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, *k);
    if (!item) continue;
    vsh__field(sub, f, *k);
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, sub, got, "not supported for a %s (give its positions in world "
                     "coordinates; it is opaque)", vsh_object_kind_name(o->kind));
  }
  return 0;
}

static int parse_shape(const vsh_ctx *ctx, const vsh_scene *scene, const char *shape_key,
                       const cJSON *shape, const char *sub, const char *scene_path,
                       vsh_object *o) {
  if (strcmp(shape_key, "sphere") == 0) {
    o->kind = VSH_OBJECT_SPHERE;
    return parse_sphere(ctx, shape, sub, o);
  } else if (strcmp(shape_key, "plane") == 0) {
    o->kind = VSH_OBJECT_PLANE;
    return parse_plane(ctx, shape, sub, o);
  } else if (strcmp(shape_key, "box") == 0) {
    o->kind = VSH_OBJECT_BOX;
    return parse_box(ctx, shape, sub, o);
  } else if (strcmp(shape_key, "cylinder") == 0) {
    o->kind = VSH_OBJECT_CYLINDER;
    return parse_cylinder(ctx, shape, sub, o);
  } else if (strcmp(shape_key, "points") == 0) {
    o->kind = VSH_OBJECT_POINTS;
    return vsh__parse_points(ctx, scene, shape, sub, o);
  } else if (strcmp(shape_key, "polyline") == 0) {
    o->kind = VSH_OBJECT_POLYLINE;
    return vsh__parse_polyline(ctx, scene, shape, sub, o);
  } else if (strcmp(shape_key, "volume") == 0) {
    o->kind = VSH_OBJECT_VOLUME;
    return vsh__parse_volume(ctx, shape, sub, o);
  }
  o->kind = VSH_OBJECT_MESH;
  return parse_mesh(ctx, shape, sub, scene_path, o);
}

int vsh__parse_object(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *obj,
                      size_t index, const char *scene_path, vsh_object *o) {
  char f[VSH_FIELD_MAX], sub[VSH_FIELD_MAX], got[VSH_GOT_MAX];
  const cJSON *shape = NULL, *item;
  const char *shape_key = NULL;
  const char *const *k;
  int i;

  vsh__field_index(f, "objects", index);
  if (vsh__object(ctx, obj, f) || vsh__check_keys(ctx, obj, f, object_keys, NULL)) return -1;

  /* Exactly one shape key. */
  for (k = shape_keys; *k; ++k) {
    if ((item = cJSON_GetObjectItemCaseSensitive(obj, *k))) {
      if (shape)
        return vsh__fail(ctx, f, NULL, "more than one shape (\"%s\" and \"%s\")", shape_key, *k);
      shape = item;
      shape_key = *k;
    }
  }
  if (!shape)
    return vsh__fail(ctx, f, NULL,
                     "missing shape: needs one of sphere, plane, box, cylinder, mesh, "
                     "points, polyline, volume");
  vsh__field(sub, f, shape_key);
  if (parse_shape(ctx, scene, shape_key, shape, sub, scene_path, o)) return -1;
  if (o->kind >= VSH_OBJECT_POINTS && world_only(ctx, obj, f, o)) return -1;

  for (i = 0; i < 16; ++i) o->transform[i] = (i % 5 == 0) ? 1.0 : 0.0;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "transform"))) {
    vsh__field(sub, f, "transform");
    if (parse_transform(ctx, item, sub, o->transform)) return -1;
    o->has_transform = 1;
  }
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "receiver"))) {
    vsh__field(sub, f, "receiver");
    if (vsh__boolean(ctx, item, sub, &o->receiver)) return -1;
    /* Planar shadows are projected onto a plane, so only flat objects can
     * receive them; a mesh may happen to be flat but we cannot know here. */
    if (o->receiver && o->kind != VSH_OBJECT_PLANE) {
      vsh__fmt_json(item, got, sizeof got);
      return vsh__fail(ctx, sub, got,
                       "only flat objects (plane) can be receivers, and a %s is not flat",
                       vsh_object_kind_name(o->kind));
    }
  }
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "mirror"))) {
    vsh__field(sub, f, "mirror");
    if (parse_mirror(ctx, item, sub, o)) return -1;
  }
  o->casts = 1;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "casts"))) {
    vsh__field(sub, f, "casts");
    if (vsh__boolean(ctx, item, sub, &o->casts)) return -1;
  }
  o->color[0] = o->color[1] = o->color[2] = 1.0;
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "color"))) {
    vsh__field(sub, f, "color");
    if (vsh__color01(ctx, item, sub, o->color)) return -1;
  }
  if ((item = cJSON_GetObjectItemCaseSensitive(obj, "name"))) {
    vsh__field(sub, f, "name");
    if (vsh__string(ctx, item, sub, &o->name)) return -1;
  }
  return parse_translucency(ctx, obj, f, o);
}
