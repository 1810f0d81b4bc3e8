/* Downstream C program: load a scene through the installed C API and render
 * it with VTK's shadow maps. */
#include "vtkshadow.h"

#include <stdio.h>

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: downstream SCENE OUT.png\n");
    return 2;
  }
  char error[1024];
  vtkshadow_scene *scene = vtkshadow_scene_load(argv[1], error, sizeof error);
  if (!scene) {
    fprintf(stderr, "downstream: %s\n", error);
    return 2;
  }
  vtkshadow_technique *technique = vtkshadow_technique_new("vtk", error, sizeof error);
  const int status = technique ? vtkshadow_render_png(scene, technique, argv[2], error, sizeof error) : 1;
  if (status != 0)
    fprintf(stderr, "downstream: %s\n", error);
  printf("downstream: vtkshadow %s, %d lights, %s\n", vtkshadow_version(),
         vtkshadow_scene_light_count(scene), status == 0 ? argv[2] : "failed");
  vtkshadow_technique_free(technique);
  vtkshadow_scene_free(scene);
  return status;
}
