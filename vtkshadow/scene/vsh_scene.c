/* vsh_scene.c - reading a scene file from disk, freeing scenes, enum names.
 *
 * File I/O is kept apart from parsing so the parser can be tested (and
 * fuzzed) from memory; vsh_scene_load only adds "cannot open" / "cannot read".
 */
#include "vsh_scene_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Scene files are hand-written and small; anything this large is a mistake
 * (e.g. a mesh passed as the scene), better reported than slurped. */
#define VSH_SCENE_FILE_MAX ((size_t)64 * 1024 * 1024)

int vsh_scene_load(const char *path, vsh_scene **out, char *err, size_t err_size) {
  vsh_ctx ctx;
  FILE *fp;
  char *text = NULL;
  size_t length = 0, capacity = 0;
  int rc;

  ctx.file = path ? path : "(null)";
  ctx.err = err;
  ctx.err_size = err_size;
  if (out) *out = NULL;
  if (!path || !path[0]) return vsh__fail(&ctx, NULL, NULL, "no scene file given");
  if (!out) return vsh__fail(&ctx, NULL, NULL, "no output pointer given");

  errno = 0;
  fp = fopen(path, "rb");
  if (!fp) return vsh__fail(&ctx, NULL, NULL, "cannot open: %s", strerror(errno));
  for (;;) {
    size_t got;
    if (length == capacity) {
      char *bigger;
      if (capacity >= VSH_SCENE_FILE_MAX) {
        free(text);
        fclose(fp);
        return vsh__fail(&ctx, NULL, NULL, "file too large (more than %zu MiB)",
                         VSH_SCENE_FILE_MAX >> 20);
      }
      capacity = capacity ? capacity * 2 : 16384;
      bigger = (char *)realloc(text, capacity);
      if (!bigger) {
        free(text);
        fclose(fp);
        return vsh__fail(&ctx, NULL, NULL, "out of memory");
      }
      text = bigger;
    }
    errno = 0;
    got = fread(text + length, 1, capacity - length, fp);
    length += got;
    if (got == 0) break;
  }
  if (ferror(fp)) { /* e.g. the path is a directory: EISDIR */
    int e = errno;
    free(text);
    fclose(fp);
    return vsh__fail(&ctx, NULL, NULL, "cannot read: %s", strerror(e ? e : EIO));
  }
  fclose(fp);
  rc = vsh_scene_parse(text ? text : "", length, path, out, err, err_size);
  free(text);
  return rc;
}

static void free_object(vsh_object *o) {
  free(o->mesh_path);
  free(o->mesh_resolved_path);
  free(o->name);
  free(o->positions);
  free(o->radii);
}

void vsh_scene_free(vsh_scene *scene) {
  size_t i;
  if (!scene) return;
  /* Also called on half-built scenes after a validation error: calloc'd
   * storage means unset pointers are NULL. */
  if (scene->objects)
    for (i = 0; i < scene->object_count; ++i) free_object(&scene->objects[i]);
  free(scene->objects);
  free(scene->lights);
  free(scene->description);
  free(scene->path);
  free(scene);
}

const char *vsh_light_type_name(vsh_light_type type) {
  switch (type) {
  case VSH_LIGHT_DIRECTIONAL: return "directional";
  case VSH_LIGHT_POINT: return "point";
  case VSH_LIGHT_SPOT: return "spot";
  }
  return "unknown";
}

const char *vsh_object_kind_name(vsh_object_kind kind) {
  switch (kind) {
  case VSH_OBJECT_SPHERE: return "sphere";
  case VSH_OBJECT_PLANE: return "plane";
  case VSH_OBJECT_BOX: return "box";
  case VSH_OBJECT_CYLINDER: return "cylinder";
  case VSH_OBJECT_MESH: return "mesh";
  case VSH_OBJECT_POINTS: return "points";
  case VSH_OBJECT_POLYLINE: return "polyline";
  case VSH_OBJECT_VOLUME: return "volume";
  }
  return "unknown";
}
