// reflection_run.h - the colour comparison of scenes with planar mirrors
// (docs/reflections.md, docs/harness.md "Mirrors"): POV-Ray renders the
// colour image and the mirror's pixels, Cycles and every VTK technique the
// colour image, and each test's reflection_mae against POV-Ray over those
// pixels goes on its rows, with the mirror region's heat map.
#ifndef VTKSHADOW_REFLECTION_RUN_H
#define VTKSHADOW_REFLECTION_RUN_H

#include "compare_options.h"
#include "harness_export.h"
#include "harness_results.h"

#include <set>
#include <string>

namespace vsh_harness
{

// Does nothing for a scene without a mirror. Failures go to res.errors;
// rows of a test whose colour image is missing keep reflection_mae NaN.
void RunReflections(const Options& opt, const SceneEntry& e, const ExportScene& ex,
  const std::set<std::string>& ok_techniques, SceneResult& res);

} // namespace vsh_harness

#endif
