/* vtkshadow.h - the C API of vtkshadow.
 *
 * Opaque handles over the VTK classes so that C programs can load scenes,
 * switch shadows on for a vtkRenderer* and measure per-light visibility.
 * Every function that can fail returns 0 on success (or a handle) and writes
 * a message into the caller's `error` buffer otherwise (it may be NULL).
 *
 *   char error[1024];
 *   vtkshadow_scene *scene = vtkshadow_scene_load("scene.json", error, sizeof error);
 *   if (!scene) { fprintf(stderr, "%s\n", error); return 2; }
 *   vtkshadow_technique *technique = vtkshadow_technique_new("vtk", error, sizeof error);
 *   vtkshadow_render_png(scene, technique, "out.png", error, sizeof error);
 *   vtkshadow_technique_free(technique);
 *   vtkshadow_scene_free(scene);
 */
#ifndef vtkshadow_h
#define vtkshadow_h

#include "vtkshadowModule.h" /* for export macro */

#include <stddef.h>

#ifdef __cplusplus
extern "C"
{
#endif

  typedef struct vtkshadow_scene vtkshadow_scene;
  typedef struct vtkshadow_technique vtkshadow_technique;

  /* "MAJOR.MINOR.PATCH" of this library. */
  VTKSHADOW_EXPORT const char* vtkshadow_version(void);

  /* Load and validate a scene file; NULL on failure with the message in error. */
  VTKSHADOW_EXPORT vtkshadow_scene* vtkshadow_scene_load(
    const char* path, char* error, size_t error_size);
  VTKSHADOW_EXPORT void vtkshadow_scene_free(vtkshadow_scene* scene);
  VTKSHADOW_EXPORT int vtkshadow_scene_light_count(const vtkshadow_scene* scene);
  VTKSHADOW_EXPORT int vtkshadow_scene_object_count(const vtkshadow_scene* scene);
  VTKSHADOW_EXPORT void vtkshadow_scene_size(const vtkshadow_scene* scene, int* width, int* height);
  /* Add the scene's actors, lights and camera to a vtkRenderer (passed as void*). */
  VTKSHADOW_EXPORT int vtkshadow_scene_populate(
    const vtkshadow_scene* scene, void* vtk_renderer, char* error, size_t error_size);

  /* The registered techniques (vtkShadowTechniqueRegistry): their number, and
   * the name and one-line description of technique i (NULL out of range). */
  VTKSHADOW_EXPORT int vtkshadow_technique_count(void);
  VTKSHADOW_EXPORT const char* vtkshadow_technique_name_at(int index);
  VTKSHADOW_EXPORT const char* vtkshadow_technique_description_at(int index);

  /* A technique by name ("none", "vtk", ...); NULL for an unknown name. */
  VTKSHADOW_EXPORT vtkshadow_technique* vtkshadow_technique_new(
    const char* name, char* error, size_t error_size);
  VTKSHADOW_EXPORT void vtkshadow_technique_free(vtkshadow_technique* technique);
  VTKSHADOW_EXPORT const char* vtkshadow_technique_name(const vtkshadow_technique* technique);
  /* Shadow-map edge length in texels (16..16384) for map-based techniques. */
  VTKSHADOW_EXPORT int vtkshadow_technique_set_map_resolution(
    vtkshadow_technique* technique, int resolution);
  /* A technique setting by name, as vtkShadowTechnique::SetOption: e.g.
   * "cascades", "filter" for csm, "max_error" (wrong_pct) or "max_texel_px"
   * for auto. Returns 0, or 1 for an unknown key or a value out of range
   * (nothing changed; the message names both). Set before install. */
  VTKSHADOW_EXPORT int vtkshadow_technique_set_option(
    vtkshadow_technique* technique, const char* key, double value, char* error, size_t error_size);
  /* Switch the technique on for a vtkOpenGLRenderer (passed as void*). */
  VTKSHADOW_EXPORT int vtkshadow_technique_install(
    vtkshadow_technique* technique, void* vtk_renderer, char* error, size_t error_size);

  /* Shadows in one call on an ordinary VTK scene: the technique `name` (NULL:
   * "auto") on a vtkOpenGLRenderer (passed as void*), with max_error
   * (wrong_pct, auto only; < 0: the default). At each frame in which the
   * renderer has only VTK's automatic headlight (or no light),
   * vtkLightKit's key light is there, removed again when the application
   * adds lights of its own (vtkshadow_technique_light_message says what is
   * done); flat actors become plane receivers when none is marked. Returns
   * the technique (free it with
   * vtkshadow_technique_free; the shadows stay on) or NULL with the message,
   * leaving the renderer unchanged. */
  VTKSHADOW_EXPORT vtkshadow_technique* vtkshadow_enable_shadows(
    void* vtk_renderer, const char* name, double max_error, char* error, size_t error_size);
  /* The same for a technique configured with vtkshadow_technique_set_option
   * (e.g. "residual_light"): install it and keep the key light when needed. */
  VTKSHADOW_EXPORT int vtkshadow_technique_enable(
    vtkshadow_technique* technique, void* vtk_renderer, char* error, size_t error_size);
  /* Whether enable keeps the key light (default 1); 0 adds none and removes
   * those an earlier enable added. */
  VTKSHADOW_EXPORT int vtkshadow_technique_set_key_light(vtkshadow_technique* technique, int on);
  /* What is done to the renderer's lights now ("" when nothing). */
  VTKSHADOW_EXPORT const char* vtkshadow_technique_light_message(
    const vtkshadow_technique* technique);
  /* Actors the technique found as plane receivers in its last frame. */
  VTKSHADOW_EXPORT int vtkshadow_technique_detected_receiver_count(
    const vtkshadow_technique* technique);

  /* Planar shadows: mark a vtkActor (passed as void*) as a receiver (its flat
   * geometry is the plane and the area shadows may cover), or opt it out of
   * casting. Technique "planar" uses these marks; vtkshadow_scene_populate sets
   * them from the scene's "receiver" and "casts" fields. */
  VTKSHADOW_EXPORT int vtkshadow_actor_set_receiver(void* vtk_actor, int receiver);
  VTKSHADOW_EXPORT int vtkshadow_actor_set_casts(void* vtk_actor, int casts);

  /* Render the scene in colour with the technique to a PNG file (offscreen;
   * needs an X display with Debian's VTK). */
  VTKSHADOW_EXPORT int vtkshadow_render_png(const vtkshadow_scene* scene,
    vtkshadow_technique* technique, const char* path, char* error, size_t error_size);

  /* Visibility of one light under the technique (see docs/metrics.md).
   * Reports the mean visibility and the count of valid pixels; writes the
   * 16-bit visibility PNG when png_path is not NULL. */
  VTKSHADOW_EXPORT int vtkshadow_visibility(const vtkshadow_scene* scene,
    vtkshadow_technique* technique, int light, const char* png_path, double* mean_visibility,
    long* valid_pixels, char* error, size_t error_size);

#ifdef __cplusplus
}
#endif

#endif
