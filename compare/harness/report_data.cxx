// report_data.cxx - results.csv and results.json.
#include "report.h"

#include "harness_files.h"
#include "harness_progress.h"
#include "harness_text.h"

#include <cmath>
#include <cstdio>

namespace vsh_harness
{

namespace
{
// A metric that may be absent (NaN): empty in CSV, null in JSON.
std::string Num(double v, bool json)
{
  return std::isfinite(v) ? Fmt(v, "%.9g") : (json ? "null" : "");
}

// The penumbra columns (docs/metrics.md, "Penumbra metrics"), after status
// so readers by position keep working.
std::string PenumbraFields(const vshm_penumbra& p, const char* sep, bool json)
{
  const char* names[] = { "pen_pixels", "pen_mae", "pen_bias", "pen_leak_pct",
    "pen_false_shadow_pct", "pen_width_ratio", "pen_contour_01_px", "pen_contour_05_px",
    "pen_contour_09_px" };
  const double values[] = { static_cast<double>(p.penumbra_pixels), p.pen_mae, p.pen_bias,
    p.leak_pct, p.false_shadow_pct, p.width_ratio, p.contour_px[0], p.contour_px[1],
    p.contour_px[2] };
  std::string o;
  for (int i = 0; i < 9; ++i)
    o += std::string(sep) + (json ? std::string("\"") + names[i] + "\": " : std::string()) +
      Fmt(values[i], "%.9g");
  return o;
}

std::string CsvRow(const Row& r)
{
  char buf[2048];
  snprintf(buf, sizeof buf, "%s,%d,%s,%s,%s,%d,%d,%ld,%ld,%.9g,%.9g,%.9g,%.9g,%.9g,%s,%s",
    r.scene.c_str(), r.light, r.light_type.c_str(), r.test.c_str(), r.reference.c_str(), r.width,
    r.height, r.m.valid_pixels, r.m.compared_pixels, r.m.vis_mae, r.m.wrong_pct, r.m.edge_px,
    r.m.false_shadow_pct, r.m.false_light_pct, Fmt(r.m.wrong_of_shadow_pct, "%.9g").c_str(),
    r.status.c_str());
  // Columns added later go last, so every earlier column keeps its place.
  return buf + PenumbraFields(r.pen, ",", false) + "," + Num(r.reflection_mae, false) + "," +
    Num(r.wrong_band_pct, false) + "," + Num(r.colour_mae, false) + "\n";
}

std::string JsonRow(const Row& r)
{
  char buf[2048];
  snprintf(buf, sizeof buf,
    "{\"light\": %d, \"light_type\": \"%s\", \"test\": \"%s\", "
    "\"reference\": \"%s\", \"valid_pixels\": %ld, \"compared_pixels\": %ld, "
    "\"vis_mae\": %.9g, \"wrong_pct\": %.9g, \"edge_px\": %.9g, "
    "\"false_shadow_pct\": %.9g, \"false_light_pct\": %.9g, \"wrong_of_shadow_pct\": %.9g, "
    "\"wrong_of_test_shadow_pct\": %.9g, \"ref_shadow_pixels\": %ld, \"test_shadow_pixels\": %ld, "
    "\"reflection_mae\": %s, \"status\": \"%s\", \"check\": \"%s\", \"heatmap\": \"%s\", "
    "\"mirror_heatmap\": \"%s\"",
    r.light, r.light_type.c_str(), JsonEscape(r.test).c_str(), r.reference.c_str(),
    r.m.valid_pixels, r.m.compared_pixels, r.m.vis_mae, r.m.wrong_pct, r.m.edge_px,
    r.m.false_shadow_pct, r.m.false_light_pct, r.m.wrong_of_shadow_pct,
    r.m.wrong_of_test_shadow_pct, r.m.ref_shadow_pixels, r.m.test_shadow_pixels,
    Num(r.reflection_mae, true).c_str(), r.status.c_str(), JsonEscape(r.check).c_str(),
    JsonEscape(r.heatmap).c_str(), JsonEscape(r.mirror_heatmap).c_str());
  return buf + PenumbraFields(r.pen, ", ", true) +
    ", \"wrong_band_pct\": " + Num(r.wrong_band_pct, true) +
    ", \"colour_mae\": " + Num(r.colour_mae, true) + ", \"pen_heatmap\": \"" +
    JsonEscape(r.pen_heatmap) + "\"}";
}

template <typename Map>
std::string JsonSeconds(const Map& m)
{
  std::string s;
  for (const auto& kv : m)
    s += std::string(s.empty() ? "" : ", ") + "\"" + JsonEscape(kv.first) +
      "\": " + Fmt(kv.second, "%.3f");
  return "{" + s + "}";
}

std::string JsonScene(const SceneResult& sr)
{
  std::string json = "    {\"scene\": \"" + JsonEscape(sr.entry.id) + "\", \"file\": \"" +
    JsonEscape(sr.entry.path) + "\", \"width\": " + std::to_string(sr.width) +
    ", \"height\": " + std::to_string(sr.height) + ", \"lights\": " + std::to_string(sr.lights) +
    ",\n     \"render_seconds\": " + JsonSeconds(sr.seconds) +
    ",\n     \"frame_seconds\": " + JsonSeconds(sr.frame_seconds) + ",\n     \"cached\": [";
  bool first = true;
  for (const auto& kv : sr.cached)
  {
    json += std::string(first ? "" : ", ") + "\"" + JsonEscape(kv.first) + "\"";
    first = false;
  }
  json += "],\n     \"reference_keys\": {";
  first = true;
  for (const auto& kv : sr.reference_keys)
  {
    json += std::string(first ? "" : ", ") + "\"" + JsonEscape(kv.first) + "\": \"" +
      JsonEscape(kv.second) + "\"";
    first = false;
  }
  json += "},\n     \"errors\": [";
  for (size_t i = 0; i < sr.errors.size(); ++i)
    json += std::string(i ? ", " : "") + "\"" + JsonEscape(sr.errors[i]) + "\"";
  json += "],\n     \"results\": [";
  for (size_t i = 0; i < sr.rows.size(); ++i)
    json += std::string(i ? "," : "") + "\n       " + JsonRow(sr.rows[i]);
  return json + "]}";
}
} // namespace

bool WriteResults(const Options& opt, const std::vector<SceneResult>& all)
{
  std::string csv = "scene,light,light_type,test,reference,width,height,valid_pixels,"
                    "compared_pixels,vis_mae,wrong_pct,edge_px,false_shadow_pct,false_light_pct,"
                    "wrong_of_shadow_pct,status,pen_pixels,pen_mae,pen_bias,pen_leak_pct,"
                    "pen_false_shadow_pct,pen_width_ratio,pen_contour_01_px,pen_contour_05_px,"
                    "pen_contour_09_px,reflection_mae,wrong_band_pct,colour_mae\n";
  std::string json = "{\n  \"scenes\": [\n";
  for (size_t si = 0; si < all.size(); ++si)
  {
    for (const Row& r : all[si].rows)
      csv += CsvRow(r);
    json += JsonScene(all[si]) + (si + 1 < all.size() ? ",\n" : "\n");
  }
  json += "  ]\n}\n";
  std::string err;
  if (!WriteFileAtomic(opt.out + "/results.csv", csv, err) ||
    !WriteFileAtomic(opt.out + "/results.json", json, err))
  {
    Progress("ERROR writing results: " + err);
    return false;
  }
  return true;
}

} // namespace vsh_harness
