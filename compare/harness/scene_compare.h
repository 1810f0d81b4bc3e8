// scene_compare.h - one result row: a test's visibility of one light
// against POV-Ray's (metrics of compare/metrics, heat map).
#ifndef VTKSHADOW_SCENE_COMPARE_H
#define VTKSHADOW_SCENE_COMPARE_H

#include "compare_options.h"
#include "harness_results.h"

#include <string>

namespace vsh_harness
{

// `testdir`: the test's folder under OUT/<scene>/ (e.g. "vtk/csm", "cycles").
// `tinted`: the scene has green and blue visibility files; colour_mae is
// measured from them.
Row CompareWithReference(const Options& opt, const SceneEntry& e, int k, const std::string& test,
  const std::string& testdir, const std::string& light_type, bool tinted = false);

} // namespace vsh_harness

#endif
