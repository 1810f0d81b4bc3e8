/* vsh_scene_internal.h - helpers shared by the scene library's .c files.
 *
 * Not installed. The parser is split into small files (error formatting, typed
 * field readers, the scene walk); this header is the glue between them.
 */
#ifndef VSH_SCENE_INTERNAL_H
#define VSH_SCENE_INTERNAL_H

#include "vsh_scene.h"

#include <cjson/cJSON.h>
#include <stddef.h>

/* Field paths are built only from our own key names and array indices, so a
 * fixed buffer is plenty ("objects[4095].cylinder.resolution"). */
#define VSH_FIELD_MAX 128
/* How much of an offending value is quoted back in a message. */
#define VSH_GOT_MAX 160

/* Everything a validation error needs to describe itself. */
typedef struct vsh_ctx {
  const char *file;  /* display name: the path as given, or "(memory)" */
  char *err;         /* caller's buffer; may be NULL */
  size_t err_size;
} vsh_ctx;

/* ---- vsh_scene_errors.c ------------------------------------------------- */

/* Writes "FILE: FIELD: problem (got GOT)" into ctx->err and returns -1.
 * field == NULL or "" drops the "FIELD: " part; got == NULL drops "(got ...)". */
int vsh__fail(const vsh_ctx *ctx, const char *field, const char *got, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* Shortest "%.Ng" that reads back as the same double; "inf", "-inf", "nan" otherwise. */
void vsh__fmt_number(double v, char *buf, size_t size);
/* "[a, b, c]" for n numbers. */
void vsh__fmt_vec(const double *v, int n, char *buf, size_t size);
/* A compact, truncated JSON rendering of a parsed value (strings quoted). */
void vsh__fmt_json(const cJSON *item, char *buf, size_t size);

/* ---- vsh_scene_fields.c ------------------------------------------------- */

/* "parent.key", or "key" when parent is empty. */
void vsh__field(char *buf, const char *parent, const char *key);
/* "parent[index]". */
void vsh__field_index(char *buf, const char *parent, size_t index);

/* Rejects keys not in the NULL-terminated `allowed` list and duplicate keys.
 * `what` (may be NULL) is appended to the message, e.g. "for a point light". */
int vsh__check_keys(const vsh_ctx *ctx, const cJSON *object, const char *field,
                    const char *const *allowed, const char *what);
/* "missing required field" when item is NULL, else 0. */
int vsh__require(const vsh_ctx *ctx, const cJSON *item, const char *field);
int vsh__object(const vsh_ctx *ctx, const cJSON *item, const char *field);
int vsh__number(const vsh_ctx *ctx, const cJSON *item, const char *field, double *out);
int vsh__integer(const vsh_ctx *ctx, const cJSON *item, const char *field, int lo, int hi,
                 int *out);
int vsh__boolean(const vsh_ctx *ctx, const cJSON *item, const char *field, int *out);
/* Copies the string (malloc); *out stays NULL on error. */
int vsh__string(const vsh_ctx *ctx, const cJSON *item, const char *field, char **out);
/* An array of exactly n finite numbers. */
int vsh__vector(const vsh_ctx *ctx, const cJSON *item, const char *field, int n, double *out);
/* An [r, g, b] array with every component in [0, 1]. */
int vsh__color01(const vsh_ctx *ctx, const cJSON *item, const char *field, double out[3]);

char *vsh__strdup(const char *s);

/* ---- vsh_scene_objects.c ------------------------------------------------ */

/* Reads objects[index] into *out (which the caller zeroed). `scene_path` is
 * the scene file's path (may be NULL) used to resolve relative mesh paths. */
int vsh__parse_object(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *item,
                      size_t index, const char *scene_path, vsh_object *out);

/* Typed shape fields shared by the shapes: a required [x, y, z]; a
 * required number > 0; an optional "resolution" in 3..most (default
 * `fallback`). */
int vsh__need_vec3(const vsh_ctx *ctx, const cJSON *obj, const char *parent, const char *key,
                   double out[3]);
int vsh__positive(const vsh_ctx *ctx, const cJSON *obj, const char *parent, const char *key,
                  double *out);
int vsh__resolution(const vsh_ctx *ctx, const cJSON *obj, const char *parent, int fallback,
                    int most, int *out);

/* ---- vsh_scene_primitives.c --------------------------------------------- */

/* "points", "polyline" (radii from the scene's camera and size, which are
 * parsed first) and "volume". */
int vsh__parse_points(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *shape,
                      const char *field, vsh_object *o);
int vsh__parse_polyline(const vsh_ctx *ctx, const vsh_scene *scene, const cJSON *shape,
                        const char *field, vsh_object *o);
int vsh__parse_volume(const vsh_ctx *ctx, const cJSON *shape, const char *field, vsh_object *o);

/* ---- vsh_tessellate_impostors.c ----------------------------------------- */

/* points: a sphere per position; polyline: a sphere per vertex and a cone
 * frustum per segment. 0 on success. */
int vsh__tessellate_points(const vsh_object *o, vsh_mesh *out);
int vsh__tessellate_polyline(const vsh_object *o, vsh_mesh *out);
/* The UV sphere of vsh_tessellate.c around center. */
int vsh__sphere_mesh(const double center[3], double radius, int resolution, vsh_mesh *out);

/* ---- vsh_mesh.c ----------------------------------------------------------- */

/* Allocates the arrays of *mesh for the given counts (zeroed); 0 on success. */
int vsh__mesh_alloc(vsh_mesh *mesh, size_t point_count, size_t triangle_count);

/* ---- small vector maths (vsh_vec.c) ------------------------------------- */

/* Euclidean length computed with scaling, so 1e200-sized inputs do not
 * overflow and 1e-200-sized inputs do not underflow to zero. */
double vsh__norm3(const double v[3]);
/* out = v / |v| (out may alias v); returns 0 and zeroes out when v is zero or
 * not finite. */
int vsh__normalize3(const double v[3], double out[3]);
void vsh__cross3(const double a[3], const double b[3], double out[3]);
double vsh__dot3(const double a[3], const double b[3]);
/* |a x b| / (|a| |b|) computed on normalized copies: 0 for parallel vectors,
 * 1 for perpendicular ones. Returns -1 when either vector is zero. */
double vsh__sin_between(const double a[3], const double b[3]);
/* Determinant of the upper-left 3x3 of a row-major 4x4, divided by the product
 * of its row lengths: scale-free, |value| <= 1, 0 for singular matrices. */
double vsh__relative_det(const double m[16]);
/* A right-handed frame (u, v, a) around the unit axis a: u from the
 * coordinate axis least aligned with a, so for a = +z the seam of a
 * cylinder or tube starts at +x as in most tools. */
void vsh__frame_around(const double a[3], double u[3], double v[3]);

#define VSH_PI 3.14159265358979323846

#endif
