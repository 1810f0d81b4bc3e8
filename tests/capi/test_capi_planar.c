/* The C API with technique "planar", compiled as C: the actor marks reject
 * what is not a vtkActor, and a scene whose floor is "receiver": true gets
 * planar shadows (mean visibility < 1 for every light) while "none" has none
 * (mean visibility 1 on the same valid pixels).
 *
 *   test_capi_planar SCENE OUTDIR     (scenes/basic/sphere-plane.json) */
#include "vtkshadow.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "../vsh_check.h"

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: test_capi_planar SCENE OUTDIR\n");
    return 2;
  }
  char error[1024] = "";
  char path[4096];
  mkdir(argv[2], 0755);

  /* Marks: only vtkActors (passed as void*) are accepted. */
  CHECK(vtkshadow_actor_set_receiver(NULL, 1) != 0);
  CHECK(vtkshadow_actor_set_casts(NULL, 0) != 0);

  vtkshadow_scene *scene = vtkshadow_scene_load(argv[1], error, sizeof error);
  CHECK(scene != NULL);
  if (!scene) {
    fprintf(stderr, "%s\n", error);
    return vsh_check_report("capi.c.planar");
  }
  vtkshadow_technique *planar = vtkshadow_technique_new("planar", error, sizeof error);
  vtkshadow_technique *none = vtkshadow_technique_new("none", error, sizeof error);
  CHECK(planar != NULL && none != NULL);
  if (!planar || !none) {
    fprintf(stderr, "%s\n", error);
    return vsh_check_report("capi.c.planar");
  }
  CHECK(strcmp(vtkshadow_technique_name(planar), "planar") == 0);
  /* Planar shadows have no map: installing on nothing is still an error. */
  CHECK(vtkshadow_technique_install(planar, NULL, error, sizeof error) != 0);

  snprintf(path, sizeof path, "%s/capi-planar.png", argv[2]);
  remove(path);
  CHECK(vtkshadow_render_png(scene, planar, path, error, sizeof error) == 0);
  struct stat st;
  CHECK(stat(path, &st) == 0 && st.st_size > 1000);

  const int lights = vtkshadow_scene_light_count(scene);
  CHECK(lights == 3);
  for (int light = 0; light < lights; ++light) {
    double mean_none = 0.0, mean_planar = 0.0;
    long valid_none = 0, valid_planar = 0;
    CHECK(vtkshadow_visibility(scene, none, light, NULL, &mean_none, &valid_none, error,
                               sizeof error) == 0);
    snprintf(path, sizeof path, "%s/capi-planar-visibility-%d.png", argv[2], light);
    CHECK(vtkshadow_visibility(scene, planar, light, path, &mean_planar, &valid_planar, error,
                               sizeof error) == 0);
    CHECK(stat(path, &st) == 0 && st.st_size > 100);
    /* No shadows: every valid pixel fully lit. Planar: the sphere's shadow on
     * the receiver floor takes a few percent of the valid pixels. */
    CHECK_NEAR(mean_none, 1.0, 1e-6);
    CHECK(valid_none == valid_planar);
    CHECK(valid_planar > 10000);
    CHECK(mean_planar < 0.995 && mean_planar > 0.5);
    printf("light %d: mean visibility none %.6f, planar %.6f over %ld valid pixels\n", light,
           mean_none, mean_planar, valid_planar);
  }

  vtkshadow_technique_free(planar);
  vtkshadow_technique_free(none);
  vtkshadow_scene_free(scene);
  return vsh_check_report("capi.c.planar");
}
