// check.cxx - limits, no-valid-pixel reasons and known failures per row.
#include "check.h"

#include "harness_files.h"
#include "harness_text.h"

#include <cjson/cJSON.h>

#include <memory>

namespace vsh_harness
{

namespace
{
const char* const kUpdateCommand =
  "sh scripts/library-run.sh OUT, then python3 scenes/update_thresholds.py OUT/*/results.json "
  "--write scenes/thresholds.json (docs/harness.md)";

// One thresholds file and the known failures beside it.
struct CheckFiles
{
  cJSON* root = nullptr;
  std::string path, error;
  std::vector<KnownFailure> known;
  ~CheckFiles() { cJSON_Delete(root); }
};

cJSON* ParseFile(const std::string& path, std::string& error)
{
  std::string text;
  cJSON* root = ReadFile(path, text) ? cJSON_ParseWithLength(text.data(), text.size()) : nullptr;
  if (!root)
    error = path + ": cannot read or not valid JSON";
  return root;
}

// {metric: number} of `obj` into `out`; false when `obj` is not such an
// object or is empty.
bool ReadBounds(const cJSON* obj, std::map<std::string, double>& out)
{
  const cJSON* m = nullptr;
  cJSON_ArrayForEach(m, obj)
  {
    if (!cJSON_IsNumber(m))
      return false;
    out[m->string] = m->valuedouble;
  }
  return cJSON_IsObject(obj) && !out.empty();
}

// known-failures.json: {"failures": [{"scene", "test", "light", "reason",
// "fails_while": {metric: value}, "at_most": {metric: value}}]}. A missing
// file means no known failure.
void LoadKnownFailures(const std::string& path, CheckFiles& f)
{
  if (!FileExists(path))
    return;
  cJSON* root = ParseFile(path, f.error);
  const cJSON* list = cJSON_GetObjectItemCaseSensitive(root, "failures");
  if (root && !cJSON_IsArray(list))
    f.error = path + ": no \"failures\" list";
  int i = 0;
  const cJSON* it = nullptr;
  cJSON_ArrayForEach(it, list)
  {
    KnownFailure k;
    k.file = path;
    const cJSON* scene = cJSON_GetObjectItemCaseSensitive(it, "scene");
    const cJSON* test = cJSON_GetObjectItemCaseSensitive(it, "test");
    const cJSON* light = cJSON_GetObjectItemCaseSensitive(it, "light");
    const cJSON* reason = cJSON_GetObjectItemCaseSensitive(it, "reason");
    const bool bounded =
      ReadBounds(cJSON_GetObjectItemCaseSensitive(it, "fails_while"), k.fails_while) &&
      ReadBounds(cJSON_GetObjectItemCaseSensitive(it, "at_most"), k.at_most);
    if (!cJSON_IsString(scene) || !cJSON_IsString(test) || !cJSON_IsNumber(light) ||
      !cJSON_IsString(reason) || !*reason->valuestring || !bounded)
      f.error = path + ": failures[" + std::to_string(i) +
        "] needs \"scene\", \"test\", \"light\", a non-empty \"reason\", \"fails_while\" "
        "{metric: value} (fixed once no metric is above) and \"at_most\" {metric: value} "
        "(worse once one is above)";
    else
    {
      k.scene = scene->valuestring;
      k.test = test->valuestring;
      k.light = light->valueint;
      k.reason = reason->valuestring;
      f.known.push_back(k);
    }
    ++i;
  }
  cJSON_Delete(root);
}

CheckFiles& FilesFor(const Options& opt, const std::string& thresholds,
  std::map<std::string, std::unique_ptr<CheckFiles>>& cache)
{
  auto& f = cache[thresholds];
  if (f)
    return *f;
  f.reset(new CheckFiles);
  f->path = thresholds;
  f->root = ParseFile(thresholds, f->error);
  LoadKnownFailures(
    opt.known_failures.empty() ? DirName(thresholds) + "/known-failures.json" : opt.known_failures,
    *f);
  return *f;
}

// Limits of a row: default[test], then scenes[scene][test] (null removes
// one). A number bounds every light; an array gives one value per light.
std::map<std::string, double> RowLimits(const cJSON* root, const Row& r)
{
  std::map<std::string, double> limits;
  const cJSON* def = cJSON_GetObjectItemCaseSensitive(root, "default");
  const cJSON* sc = cJSON_GetObjectItemCaseSensitive(
    cJSON_GetObjectItemCaseSensitive(root, "scenes"), r.scene.c_str());
  for (const cJSON* level : { def, sc })
  {
    const cJSON* it = nullptr;
    cJSON_ArrayForEach(it, cJSON_GetObjectItemCaseSensitive(level, r.test.c_str()))
    {
      const cJSON* v = cJSON_IsArray(it) ? cJSON_GetArrayItem(it, r.light) : it;
      if (cJSON_IsNumber(v))
        limits[it->string] = v->valuedouble;
      else if (cJSON_IsNull(it))
        limits.erase(it->string);
    }
  }
  return limits;
}

// The scene's reason for light k having no valid pixel, or "".
std::string NoValidReason(const cJSON* root, const Row& r)
{
  const cJSON* sc = cJSON_GetObjectItemCaseSensitive(
    cJSON_GetObjectItemCaseSensitive(root, "scenes"), r.scene.c_str());
  const cJSON* reason = cJSON_GetObjectItemCaseSensitive(
    cJSON_GetObjectItemCaseSensitive(sc, "no_valid_pixels"), std::to_string(r.light).c_str());
  return cJSON_IsString(reason) ? reason->valuestring : "";
}

std::string Where(const Row& r)
{
  return "scene " + r.scene + ", light " + std::to_string(r.light) + ", " + r.test;
}

// A listed row: still as bad as listed (fine) or better (the entry must go).
void CheckKnown(KnownFailure& k, Row& r, CheckOutcome& out)
{
  k.seen = true;
  for (const auto& fw : k.fails_while)
  {
    bool known = false;
    const double v = RowMetric(r, fw.first, known);
    k.measured += (k.measured.empty() ? "" : ", ") + fw.first + " = " + Fmt(v, "%.4g");
    if (!known)
      out.failures.push_back(k.file + ": unknown metric '" + fw.first + "'");
    else if (v > fw.second)
      k.still_failing = true;
  }
  ++out.comparisons;
  for (const auto& am : k.at_most)
  {
    bool known = false;
    const double v = RowMetric(r, am.first, known);
    ++out.comparisons;
    if (!known)
      out.failures.push_back(k.file + ": unknown metric '" + am.first + "'");
    else if (!(v <= am.second))
      k.worse += (k.worse.empty() ? "" : ", ") + am.first + " = " + Fmt(v, "%.6g") + " > " +
        Fmt(am.second, "%.6g");
  }
  if (!k.worse.empty())
  {
    r.check = "FAILED: known failure got worse";
    out.failures.push_back(Where(r) + ": known failure got worse (" + k.worse +
      ", the at_most of " + k.file + "; listed because: " + k.reason + ")");
  }
  else if (k.still_failing)
    r.check = "known failure: " + k.reason;
  else
  {
    r.check = "FAILED: known failure now passes";
    out.failures.push_back(Where(r) + ": known failure now passes (" + k.measured +
      ", listed as failing while above " + Fmt(k.fails_while.begin()->second, "%.6g") +
      "): remove it from " + k.file + " and write its limits with " + kUpdateCommand);
  }
}

// Every limit of a row.
void CheckLimits(
  const std::map<std::string, double>& limits, const CheckFiles& f, Row& r, CheckOutcome& out)
{
  const size_t before = out.failures.size();
  for (const auto& lim : limits)
  {
    bool known = false;
    const double value = RowMetric(r, lim.first, known);
    // A percentage of the frame; those of the shadow (wrong_of_*) may pass
    // 50 and still bound something: a lost shadow is 100.
    const bool pct = lim.first.size() > 4 &&
      lim.first.compare(lim.first.size() - 4, 4, "_pct") == 0 &&
      lim.first.rfind("wrong_of_", 0) != 0 && lim.first.rfind("pen_", 0) != 0;
    ++out.comparisons;
    if (!known)
      out.failures.push_back(f.path + ": unknown metric '" + lim.first + "'");
    else if (pct && lim.second >= kRefusedPctLimit)
      out.failures.push_back(Where(r) + ": the limit " + lim.first +
        " <= " + Fmt(lim.second, "%.6g") + " in " + f.path + " is " + Fmt(kRefusedPctLimit, "%g") +
        "% or more, which bounds nothing: list the row in known-failures.json with its reason");
    else if (!(value <= lim.second))
      out.failures.push_back(Where(r) + ": " + lim.first + " = " + Fmt(value, "%.6g") +
        " > threshold " + Fmt(lim.second, "%.6g"));
  }
  r.check = out.failures.size() == before ? "ok" : "FAILED: " + out.failures.back();
}

void CheckRow(CheckFiles& f, Row& r, CheckOutcome& out)
{
  for (KnownFailure& k : f.known)
    if (k.scene == r.scene && k.test == r.test && k.light == r.light && r.status == "ok")
    {
      CheckKnown(k, r, out);
      return;
    }
  if (r.status == "error")
  {
    r.check = "FAILED: not measured";
    out.failures.push_back(Where(r) + ": not measured (" + r.error + ")");
    return;
  }
  if (r.status == "empty")
  {
    const std::string why = NoValidReason(f.root, r);
    r.check = why.empty() ? "FAILED: no valid pixels" : "no valid pixels: " + why;
    if (why.empty())
      out.failures.push_back(Where(r) +
        ": no valid pixels (nothing lit in the reference), "
        "so nothing is compared; fix the scene or give the "
        "reason in " +
        f.path + " scenes[\"" + r.scene + "\"].no_valid_pixels[\"" + std::to_string(r.light) +
        "\"]");
    return;
  }
  const std::map<std::string, double> limits = RowLimits(f.root, r);
  if (limits.empty())
  {
    r.check = "FAILED: no limit";
    out.failures.push_back(Where(r) + ": no limit in " + f.path + "; write limits with " +
      kUpdateCommand + ", or list the row in known-failures.json with its reason");
    return;
  }
  CheckLimits(limits, f, r, out);
}

} // namespace

CheckOutcome RunCheck(const Options& opt, std::vector<SceneResult>& results)
{
  CheckOutcome out;
  std::map<std::string, std::unique_ptr<CheckFiles>> cache;
  for (SceneResult& sr : results)
  {
    if (sr.entry.thresholds.empty())
    {
      out.failures.push_back(sr.entry.id + ": no thresholds.json found for this scene");
      continue;
    }
    CheckFiles& f = FilesFor(opt, sr.entry.thresholds, cache);
    if (!f.error.empty())
    {
      out.failures.push_back(f.error);
      f.error.clear(); // once per file
    }
    if (!f.root)
      continue;
    for (Row& r : sr.rows)
      CheckRow(f, r, out);
    if (!sr.errors.empty())
      out.failures.push_back("scene " + sr.entry.id + ": " + std::to_string(sr.errors.size()) +
        " render error(s), not checked: " + sr.errors[0]);
  }
  for (auto& kv : cache)
    for (const KnownFailure& k : kv.second->known)
      out.known.push_back(k);
  return out;
}

} // namespace vsh_harness
