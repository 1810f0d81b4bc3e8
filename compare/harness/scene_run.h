// scene_run.h - one scene of a run: load, export, every renderer, every row.
#ifndef VTKSHADOW_SCENE_RUN_H
#define VTKSHADOW_SCENE_RUN_H

#include "compare_options.h"
#include "harness_results.h"
#include "reference_renderer.h"

#include <memory>
#include <vector>

namespace vsh_harness
{

// Never throws: every failure is recorded in the result's errors and the
// other renderers of the scene still run.
SceneResult RunScene(const Options& opt,
  const std::vector<std::unique_ptr<ReferenceRenderer>>& references, const SceneEntry& e);

// RunScene for every scene, opt.jobs at a time; results in scene order.
std::vector<SceneResult> RunScenes(const Options& opt,
  const std::vector<std::unique_ptr<ReferenceRenderer>>& references,
  const std::vector<SceneEntry>& scenes);

} // namespace vsh_harness

#endif
