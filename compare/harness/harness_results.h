// harness_results.h - what a vtkshadow-compare run measures: one Row per
// (scene, light, test) and one SceneResult per scene.
#ifndef VTKSHADOW_HARNESS_RESULTS_H
#define VTKSHADOW_HARNESS_RESULTS_H

#include "scene_list.h"

#include "vshm_metrics.h"
#include "vshm_penumbra.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace vsh_harness
{

struct Row
{
  std::string scene, test, reference = "povray", light_type, status, error, heatmap;
  int light = 0, width = 0, height = 0;
  vshm_metrics m{};
  // Penumbra metrics (docs/metrics.md): computed for every row; they read
  // "no penumbra" (pen.penumbra_pixels 0) on scenes with hard lights only.
  vshm_penumbra pen{};
  std::string pen_heatmap;
  // Scenes with mirrors: the colour error over the mirror's pixels against
  // POV-Ray (every light at once, so the same on each light's row), NaN
  // otherwise; and the mirror region's heat map.
  double reflection_mae = std::nan("");
  std::string mirror_heatmap;
  // wrong_pct outside the one-pixel band along the reference's shadow
  // boundary (vshm_boundary_band, radius 1): the measure issues 12 and 13
  // bound exact techniques by. NaN when not measured.
  double wrong_band_pct = std::nan("");
  // Tinted scenes: the mean over the green and blue channels of the mean
  // |v_test - v_ref| over the reference's valid pixels (docs/metrics.md).
  // NaN on other scenes.
  double colour_mae = std::nan("");
  // Set by --check: "" (not checked), "ok", "FAILED: why", "known failure: reason".
  std::string check;
};

struct SceneResult
{
  SceneEntry entry;
  std::string description;
  int lights = 0, width = 0, height = 0;
  std::vector<std::string> light_types;
  std::vector<std::string> errors; // render failures
  std::vector<Row> rows;
  std::map<std::string, double> seconds;       // renderer -> render time
  std::map<std::string, double> frame_seconds; // Blender renderer -> mean seconds per frame
  std::map<std::string, bool> cached;
  // Reference renderer -> the content key of its images (the cache's and the
  // shipped references' entry name), written to results.json so that
  // scripts/update-references.sh keeps exactly the entries a run used.
  std::map<std::string, std::string> reference_keys;
  std::string mirror_image; // POV-Ray's mirror pixels, when the scene has mirrors
  // Some object has a coloured filter (ExportScene::tinted): every renderer
  // also writes the green and blue visibility, and rows get colour_mae.
  bool tinted = false;
};

// A metric of a row by name (vis_mae, wrong_pct, edge_px, false_shadow_pct,
// false_light_pct, wrong_of_shadow_pct, wrong_of_test_shadow_pct).
// `known` is false for any other name.
double RowMetric(const vshm_metrics& m, const std::string& name, bool& known);

// RowMetric, and also reflection_mae (NaN on rows without mirrors, which
// then fails any limit on it), colour_mae (NaN on untinted scenes, the
// same), wrong_band_pct, pen_mae and pen_contour_{01,05,09}_px.
double RowMetric(const Row& r, const std::string& name, bool& known);

} // namespace vsh_harness

#endif
