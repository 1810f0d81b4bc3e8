/* fuzz_scene_parse.c - libFuzzer entry point for vsh_scene_parse.
 *
 * Built only with Clang and -DVTKSHADOW_FUZZ=ON (see CMakeLists.txt). The
 * scene path is inside tests/scene/data/good so that mutated mesh paths can
 * resolve to the real sample meshes and the success path gets exercised.
 * Checks the same contract as the ctest mutation fuzzer: on failure no scene
 * and a one-line message starting with the file name; on success every
 * primitive tessellates with unit normals.
 */
#include "vsh_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef VSH_FUZZ_SCENE_PATH
#define VSH_FUZZ_SCENE_PATH "fuzz.json"
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const char path[] = VSH_FUZZ_SCENE_PATH;
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  size_t i, k;
  if (vsh_scene_parse((const char *)data, size, path, &s, err, sizeof err) != 0) {
    if (s != NULL || strncmp(err, path, sizeof path - 1) != 0 || strchr(err, '\n')) abort();
    return 0;
  }
  if (!s) abort();
  for (i = 0; i < s->object_count; ++i) {
    const vsh_object *o = &s->objects[i];
    vsh_mesh m;
    if (o->kind == VSH_OBJECT_MESH) continue;
    if (o->resolution > 512) continue; /* valid but slow */
    if (vsh_object_tessellate(o, &m) != 0) abort();
    for (k = 0; k < m.point_count; ++k) {
      const double *n = m.normals + 3 * k;
      if (!(fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) < 1e-9)) abort();
    }
    vsh_mesh_free(&m);
  }
  vsh_scene_free(s);
  return 0;
}
