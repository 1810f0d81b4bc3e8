// vtk_runner.h - the VTK techniques, each rendered by vtkshadow-render
// (one process per light) into OUT/<scene>/vtk/<technique>/.
#ifndef VTKSHADOW_VTK_RUNNER_H
#define VTKSHADOW_VTK_RUNNER_H

#include "compare_options.h"
#include "harness_results.h"

#include <set>
#include <string>

namespace vsh_harness
{

// Renders every technique of opt.techniques; the ones that succeeded for
// every light go into `ok_techniques`, failures into res.errors.
void RenderVtk(const Options& opt, const SceneEntry& e, int w, int h, int lights, SceneResult& res,
  std::set<std::string>& ok_techniques);

} // namespace vsh_harness

#endif
