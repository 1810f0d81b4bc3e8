// report.h - what a run writes for people and programs: results.csv and
// results.json (one row per scene, light and test), the wrong_pct plot
// (gnuplot) and index.html.
#ifndef VTKSHADOW_REPORT_H
#define VTKSHADOW_REPORT_H

#include "check.h"
#include "compare_options.h"
#include "harness_results.h"

#include <string>
#include <vector>

namespace vsh_harness
{

// results.csv and results.json; false (and a message) when either cannot be written.
bool WriteResults(const Options& opt, const std::vector<SceneResult>& all);

// wrong_pct.png (worst light per test and scene); false when not made.
bool WritePlot(
  const Options& opt, const std::vector<SceneResult>& all, const std::vector<std::string>& tests);

// index.html: --check failures (when checked), known failures, and per scene
// and light the images, heat maps and the table of rows.
bool WriteHtml(
  const Options& opt, const std::vector<SceneResult>& all, bool plot, const CheckOutcome& check);

} // namespace vsh_harness

#endif
