// scene_run.cxx - running the renderers of one scene and comparing them.
#include "scene_run.h"

#include "harness_progress.h"
#include "harness_text.h"
#include "reflection_run.h"
#include "scene_compare.h"
#include "scene_export.h"
#include "vtk_runner.h"

#include "vsh_scene.h"
#include "vtkShadowScene.h"

#include <vtkNew.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <set>
#include <thread>

namespace vsh_harness
{

namespace
{
// Loads the scene and builds the export; false when the scene cannot be
// loaded (then nothing can run). `have_export` is false when only the
// export failed (the VTK techniques can still run). The file is parsed once:
// vtkShadowScene takes the parsed vsh_scene (LoadParsed), and the fields
// read here come from that same scene.
bool LoadScene(const Options& opt, const SceneEntry& e, SceneResult& res, ExportScene& ex,
  std::string& content_key, bool& have_export)
{
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene* parsed = nullptr;
  if (vsh_scene_load(e.path.c_str(), &parsed, err, sizeof err) != 0)
  {
    res.errors.push_back(std::string("scene: ") + err);
    return false;
  }
  vtkNew<vtkShadowScene> vs;
  if (!vs->LoadParsed(parsed, e.path.c_str())) // takes `parsed`, also on failure
  {
    res.errors.push_back(std::string("scene: ") + vs->GetErrorMessage());
    return false;
  }
  const vsh_scene* s = vs->GetParsedScene();
  res.width = std::max(1, static_cast<int>(std::lround(s->width * opt.scale)));
  res.height = std::max(1, static_cast<int>(std::lround(s->height * opt.scale)));
  res.lights = static_cast<int>(s->light_count);
  res.description = s->description ? s->description : "";
  for (int k = 0; k < res.lights; ++k)
    res.light_types.push_back(vsh_light_type_name(s->lights[k].type));
  std::string kerr;
  have_export =
    ContentKey(s, e.path, content_key, kerr) && BuildExport(vs, s, res.width, res.height, ex);
  res.tinted = ex.tinted;
  if (!have_export)
    res.errors.push_back(
      "export: " + (kerr.empty() ? std::string("cannot build the scene") : kerr));
  return true;
}
} // namespace

SceneResult RunScene(const Options& opt,
  const std::vector<std::unique_ptr<ReferenceRenderer>>& references, const SceneEntry& e)
{
  SceneResult res;
  res.entry = e;
  ExportScene ex;
  std::string content_key;
  bool have_export = false;
  if (!LoadScene(opt, e, res, ex, content_key, have_export))
    return res;
  Progress(e.id + ": " + std::to_string(res.width) + "x" + std::to_string(res.height) + ", " +
    std::to_string(res.lights) + " light(s)");
  bool pov_ok = false;
  std::vector<std::string> peers_ok; // every reference renderer but POV-Ray
  for (const auto& r : references)
    if (have_export && RunReference(*r, opt, e, ex, content_key, res))
    {
      if (r->Name() == "povray")
        pov_ok = true;
      else
        peers_ok.push_back(r->Name());
    }
  std::set<std::string> ok_t;
  if (opt.Has("vtk"))
    RenderVtk(opt, e, res.width, res.height, res.lights, res, ok_t);
  for (int k = 0; pov_ok && k < res.lights; ++k)
  {
    for (const std::string& t : opt.techniques)
      if (ok_t.count(t))
        res.rows.push_back(
          CompareWithReference(opt, e, k, "vtk/" + t, "vtk/" + t, res.light_types[k], res.tinted));
    for (const std::string& b : peers_ok)
      res.rows.push_back(CompareWithReference(opt, e, k, b, b, res.light_types[k], res.tinted));
  }
  if (have_export && pov_ok)
    RunReflections(opt, e, ex, ok_t, res);
  for (const Row& r : res.rows)
    if (!r.error.empty())
      res.errors.push_back(
        "metrics " + r.test + " light " + std::to_string(r.light) + ": " + r.error);
  for (const std::string& m : res.errors)
    Progress("ERROR " + e.id + ": " + m);
  return res;
}

namespace
{
// "scene 3/31 done (hard/needles); 41 s so far, about 380 s left": the
// estimate is the mean time of a finished scene times the scenes to go.
void ReportProgress(
  const std::string& id, size_t done, size_t total, std::chrono::steady_clock::time_point start)
{
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double left = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
  Progress("scene " + std::to_string(done) + "/" + std::to_string(total) + " done (" + id + "); " +
    Fmt(elapsed, "%.0f") + " s so far" +
    (done < total ? ", about " + Fmt(left, "%.0f") + " s left" : ""));
}
} // namespace

std::vector<SceneResult> RunScenes(const Options& opt,
  const std::vector<std::unique_ptr<ReferenceRenderer>>& references,
  const std::vector<SceneEntry>& scenes)
{
  std::vector<SceneResult> results(scenes.size());
  std::atomic<size_t> next{ 0 }, done{ 0 };
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&]()
  {
    for (size_t i; (i = next++) < scenes.size();)
    {
      results[i] = RunScene(opt, references, scenes[i]);
      ReportProgress(scenes[i].id, ++done, scenes.size(), start);
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::min<int>(opt.jobs, static_cast<int>(scenes.size())); ++j)
    pool.emplace_back(worker);
  for (auto& t : pool)
    t.join();
  return results;
}

} // namespace vsh_harness
