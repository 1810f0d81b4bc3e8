/* The C API, compiled as C: load a scene, reject bad input, render, and
 * measure visibility with and without shadows. */
#include "vtkshadow.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "../vsh_check.h"

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: test_capi SCENE OUTDIR\n");
    return 2;
  }
  char error[1024] = "";
  char path[4096];
  /* mkdir -p: the output folder's parents may not exist in a fresh build. */
  snprintf(path, sizeof path, "%s", argv[2]);
  for (char *p = path + 1; *p; ++p) {
    if (*p == '/') {
      *p = '\0';
      mkdir(path, 0755);
      *p = '/';
    }
  }
  mkdir(path, 0755);

  CHECK(strcmp(vtkshadow_version(), "0.1.0") == 0);
  CHECK(vtkshadow_scene_load("/nonexistent/scene.json", error, sizeof error) == NULL);
  CHECK_STR_CONTAINS(error, "/nonexistent/scene.json");
  CHECK(vtkshadow_technique_new("bogus", error, sizeof error) == NULL);
  CHECK_STR_CONTAINS(error, "bogus");
  /* The registry, read through the C API: every name makes a technique. */
  CHECK(vtkshadow_technique_count() >= 5);
  for (int i = 0; i < vtkshadow_technique_count(); ++i) {
    const char *name = vtkshadow_technique_name_at(i);
    CHECK(name != NULL && vtkshadow_technique_description_at(i) != NULL);
    vtkshadow_technique *made = name ? vtkshadow_technique_new(name, error, sizeof error) : NULL;
    CHECK(made != NULL);
    vtkshadow_technique_free(made);
  }
  CHECK(vtkshadow_technique_name_at(vtkshadow_technique_count()) == NULL);
  CHECK(vtkshadow_technique_name_at(-1) == NULL);
  CHECK(vtkshadow_technique_description_at(-1) == NULL);

  vtkshadow_scene *scene = vtkshadow_scene_load(argv[1], error, sizeof error);
  CHECK(scene != NULL);
  if (!scene) {
    fprintf(stderr, "%s\n", error);
    return vsh_check_report("capi.c");
  }
  int w = 0, h = 0;
  vtkshadow_scene_size(scene, &w, &h);
  CHECK(w == 800 && h == 600);
  CHECK(vtkshadow_scene_light_count(scene) == 3);
  CHECK(vtkshadow_scene_object_count(scene) == 2);

  vtkshadow_technique *none = vtkshadow_technique_new("none", error, sizeof error);
  vtkshadow_technique *vtk = vtkshadow_technique_new("vtk", error, sizeof error);
  CHECK(none && vtk);
  CHECK(strcmp(vtkshadow_technique_name(vtk), "vtk") == 0);
  CHECK(vtkshadow_technique_set_map_resolution(vtk, 8) != 0);
  CHECK(vtkshadow_technique_set_map_resolution(vtk, 1024) == 0);
  CHECK(vtkshadow_technique_install(vtk, NULL, error, sizeof error) != 0);
  /* enable_shadows: no renderer or an unknown name is an error with a
   * message (the success path: tests/python/test_enable_shadows.py). */
  error[0] = '\0';
  CHECK(vtkshadow_enable_shadows(NULL, "auto", -1.0, error, sizeof error) == NULL);
  CHECK(strstr(error, "vtkOpenGLRenderer") != NULL);
  CHECK(vtkshadow_enable_shadows(NULL, "bogus", -1.0, error, sizeof error) == NULL);
  CHECK(strstr(error, "bogus") != NULL);
  CHECK(vtkshadow_technique_enable(vtk, NULL, error, sizeof error) != 0);
  CHECK(vtkshadow_technique_set_key_light(NULL, 1) != 0);
  CHECK(vtkshadow_technique_set_key_light(vtk, 0) == 0);
  CHECK(strcmp(vtkshadow_technique_light_message(vtk), "") == 0);
  CHECK(vtkshadow_technique_detected_receiver_count(vtk) == 0);

  snprintf(path, sizeof path, "%s/capi.png", argv[2]);
  remove(path);
  CHECK(vtkshadow_render_png(scene, vtk, path, error, sizeof error) == 0);
  struct stat st;
  CHECK(stat(path, &st) == 0 && st.st_size > 1000);

  double mean_none = 0.0, mean_vtk = 0.0;
  long valid_none = 0, valid_vtk = 0;
  CHECK(vtkshadow_visibility(scene, none, 0, NULL, &mean_none, &valid_none, error,
                             sizeof error) == 0);
  snprintf(path, sizeof path, "%s/capi-visibility.png", argv[2]);
  CHECK(vtkshadow_visibility(scene, vtk, 0, path, &mean_vtk, &valid_vtk, error,
                             sizeof error) == 0);
  /* Without shadows every valid pixel is fully lit; the sphere's shadow on the
   * floor covers a few percent of the lit pixels. */
  CHECK_NEAR(mean_none, 1.0, 1e-6);
  CHECK(valid_none == valid_vtk);
  CHECK(valid_none > 100000);
  CHECK(mean_vtk < 0.99 && mean_vtk > 0.5);
  CHECK(vtkshadow_visibility(scene, vtk, 3, NULL, NULL, NULL, error, sizeof error) != 0);
  CHECK_STR_CONTAINS(error, "out of range");
  printf("mean visibility: none %.6f, vtk %.6f over %ld valid pixels\n", mean_none, mean_vtk,
         valid_vtk);

  /* Settings by name: auto's error target, with bad keys and values refused. */
  vtkshadow_technique *automatic = vtkshadow_technique_new("auto", error, sizeof error);
  CHECK(automatic != NULL);
  CHECK(vtkshadow_technique_set_option(automatic, "max_error", 1.0, error, sizeof error) == 0);
  CHECK(vtkshadow_technique_set_option(automatic, "max_error", -1.0, error, sizeof error) != 0);
  CHECK_STR_CONTAINS(error, "max_error");
  CHECK(vtkshadow_technique_set_option(automatic, "no_such_key", 1.0, error, sizeof error) != 0);
  CHECK_STR_CONTAINS(error, "no_such_key");
  CHECK(vtkshadow_technique_set_option(NULL, "max_error", 1.0, error, sizeof error) != 0);
  CHECK(vtkshadow_technique_set_option(automatic, NULL, 1.0, error, sizeof error) != 0);
  double mean_auto = 0.0;
  CHECK(vtkshadow_visibility(scene, automatic, 0, NULL, &mean_auto, NULL, error,
                             sizeof error) == 0);
  /* Light 0's shadow falls on the floor only: auto draws it (planar). */
  CHECK(mean_auto < 0.99 && mean_auto > 0.5);

  vtkshadow_technique_free(automatic);
  vtkshadow_technique_free(none);
  vtkshadow_technique_free(vtk);
  vtkshadow_scene_free(scene);
  return vsh_check_report("capi.c");
}
