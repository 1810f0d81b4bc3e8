// vtkshadow-compare: render scenes with the VTK techniques, POV-Ray, Blender
// Cycles and (on request) Blender EEVEE, extract per-light visibility from
// each, compute the metrics (C, compare/metrics), check them against the
// limits and write results.csv, results.json and index.html.
// See docs/harness.md. The jobs live in their own files:
//   compare_options   command line
//   scene_list        which scenes, their ids and thresholds files
//   scene_run         one scene: load, export, renderers, rows
//   reference_*       the reference-renderer interface and its cached driver;
//   povray_/cycles_/eevee_renderer (blender_renderer: what the last two share)
//   vtk_runner        the VTK techniques through vtkshadow-render
//   scene_export      the loaded scene as numbers (harness_export: file formats)
//   scene_compare     one row's metrics and heat map
//   check             --check: limits and known failures
//   report_data / report_html   results.csv / .json, index.html and the plot
#include "check.h"
#include "compare_options.h"
#include "harness_progress.h"
#include "reference_renderer.h"
#include "report.h"
#include "scene_list.h"
#include "scene_run.h"

#include <cstdio>
#include <cstdlib>

using namespace vsh_harness;

namespace
{
// Exit status: 1 render or metric failures, 3 check failures, else 0.
int Summarize(
  const Options& opt, const std::vector<SceneResult>& results, const CheckOutcome& check)
{
  int failed_scenes = 0;
  for (const SceneResult& sr : results)
    if (!sr.errors.empty())
    {
      ++failed_scenes;
      for (const auto& m : sr.errors)
        fprintf(stderr, "vtkshadow-compare: ERROR %s: %s\n", sr.entry.id.c_str(), m.c_str());
    }
  if (opt.check)
  {
    for (const auto& f : check.failures)
      fprintf(stderr, "vtkshadow-compare: CHECK FAILED %s\n", f.c_str());
    int known = 0;
    for (const KnownFailure& k : check.known)
      known += k.seen && k.still_failing && k.worse.empty();
    fprintf(stderr,
      "vtkshadow-compare: --check: %d comparisons, %zu failure(s), %d known "
      "failure(s) still failing\n",
      check.comparisons, check.failures.size(), known);
  }
  fprintf(
    stderr, "vtkshadow-compare: %zu scene(s), %d with errors\n", results.size(), failed_scenes);
  if (opt.report)
    printf("%s/index.html\n", opt.out.c_str());
  if (failed_scenes)
    return 1;
  return opt.check && !check.failures.empty() ? 3 : 0;
}
} // namespace

int main(int argc, char* argv[])
{
  Options opt;
  std::string error;
  switch (ParseOptions(argc, argv, opt, error))
  {
    case ParseStatus::Help:
      fputs(Usage(), stdout);
      return 0;
    case ParseStatus::Error:
      fprintf(stderr, "vtkshadow-compare: %s\n%s", error.c_str(), Usage());
      return 2;
    case ParseStatus::Run:
      break;
  }
  std::vector<SceneEntry> scenes;
  if (!ListScenes(opt.inputs, opt.thresholds, scenes, error) || !FinishOptions(opt, error))
  {
    fprintf(stderr, "vtkshadow-compare: %s\n", error.c_str());
    return 2;
  }
  const auto references = MakeReferenceRenderers(opt);
  if ((opt.Has("vtk") || opt.Has("eevee") || opt.Has("eevee-best")) && !getenv("DISPLAY"))
    Progress("WARNING: DISPLAY is not set; vtkshadow-render and EEVEE need an X server (run "
             "under xvfb-run -a or tests/gl-run.sh)");
  std::vector<SceneResult> results = RunScenes(opt, references, scenes);
  const CheckOutcome check = RunCheck(opt, results);
  bool written = WriteResults(opt, results);
  if (opt.report)
  {
    std::vector<std::string> tests;
    for (const auto& t : opt.techniques)
      if (opt.Has("vtk"))
        tests.push_back("vtk/" + t);
    for (const std::string& b : BlenderRenderers())
      if (opt.Has(b))
        tests.push_back(b);
    const bool plot = WritePlot(opt, results, tests);
    written = WriteHtml(opt, results, plot, check) && written;
  }
  const int status = Summarize(opt, results, check);
  return status == 0 && !written ? 1 : status;
}
