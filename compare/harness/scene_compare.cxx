// scene_compare.cxx - metrics and heat map of one row.
#include "scene_compare.h"

#include "harness_files.h"
#include "harness_png.h"
#include "visibility_io.h"

#include "vshm_metrics.h"
#include "vshm_penumbra.h"
#include "vshm_png.h"

#include <algorithm>
#include <cmath>

namespace vsh_harness
{

double RowMetric(const vshm_metrics& m, const std::string& name, bool& known)
{
  struct Named
  {
    const char* name;
    double vshm_metrics::*field;
  };
  static const Named kMetrics[] = { { "vis_mae", &vshm_metrics::vis_mae },
    { "wrong_pct", &vshm_metrics::wrong_pct }, { "edge_px", &vshm_metrics::edge_px },
    { "false_shadow_pct", &vshm_metrics::false_shadow_pct },
    { "false_light_pct", &vshm_metrics::false_light_pct },
    { "wrong_of_shadow_pct", &vshm_metrics::wrong_of_shadow_pct },
    { "wrong_of_test_shadow_pct", &vshm_metrics::wrong_of_test_shadow_pct } };
  for (const Named& n : kMetrics)
    if (name == n.name)
    {
      known = true;
      return m.*n.field;
    }
  known = false;
  return 0;
}

namespace
{
// The penumbra figures and, where the reference has a penumbra, its heat map
// (DIR/<scene>/heatmap/<test>-light<K>-penumbra.png).
void ComparePenumbra(const Options& opt, const std::string& dir_id, const std::string& stem,
  const std::vector<float>& tv, const std::vector<float>& ref,
  const std::vector<unsigned char>& valid, int w, int h, Row& row)
{
  if (vshm_penumbra_compute(tv.data(), ref.data(), valid.data(), nullptr, w, h, &row.pen) < 0 ||
    row.pen.penumbra_pixels == 0)
    return;
  std::vector<unsigned char> rgb(3 * static_cast<size_t>(w) * h);
  char e2[1024] = "";
  row.pen_heatmap = dir_id + "/heatmap/" + stem + "-penumbra.png";
  if (vshm_penumbra_heatmap_rgb(tv.data(), ref.data(), valid.data(), w, h, rgb.data()) != 0 ||
    vshm_png_write_rgb8(
      (opt.out + "/" + row.pen_heatmap).c_str(), rgb.data(), w, h, e2, sizeof e2) != 0)
    row.pen_heatmap.clear();
}

// wrong_pct over the valid pixels outside the one-pixel band along the
// reference's shadow boundary: a boundary one pixel off is a sampling
// difference between two exact renderers, not a wrong shadow.
double WrongOutsideBand(const std::vector<float>& tv, const std::vector<float>& ref,
  const std::vector<unsigned char>& valid, int w, int h)
{
  std::vector<unsigned char> band(valid.size());
  vshm_metrics banded{};
  if (vshm_boundary_band(ref.data(), valid.data(), w, h, 1, band.data()) != VSHM_METRICS_OK ||
    vshm_metrics_compute(tv.data(), ref.data(), valid.data(), band.data(), w, h, &banded) < 0)
    return std::nan("");
  return banded.wrong_pct;
}

// colour_mae of a tinted scene: the mean over the green and blue channels
// of the mean |v_test - v_ref| over the reference's valid pixels. NaN with
// `err` set when a channel file cannot be read; NaN when nothing is valid.
double ColourMae(const std::string& base, const std::string& testdir, int k,
  const std::vector<unsigned char>& valid, int w, int h, std::string& err)
{
  double sum = 0;
  long n = 0;
  for (int c = 1; c < 3; ++c)
  {
    const std::string name = "/" + ChannelFileName(k, c);
    std::vector<float> ref, tv;
    int w1 = 0, h1 = 0, w2 = 0, h2 = 0;
    if (!ReadPNGChannel(base + "/povray" + name, ref, w1, h1, err) ||
      !ReadPNGChannel(base + "/" + testdir + name, tv, w2, h2, err))
      return std::nan("");
    if (w1 != w || w2 != w || h1 != h || h2 != h)
    {
      err = "colour: image sizes differ";
      return std::nan("");
    }
    for (size_t i = 0; i < valid.size(); ++i)
      if (valid[i])
      {
        sum += std::fabs(double(tv[i]) - ref[i]);
        ++n;
      }
  }
  return n ? sum / n : std::nan("");
}
} // namespace

double RowMetric(const Row& r, const std::string& name, bool& known)
{
  if (name == "reflection_mae")
  {
    known = true;
    return r.reflection_mae;
  }
  if (name == "colour_mae")
  {
    known = true;
    return r.colour_mae;
  }
  if (name == "wrong_band_pct")
  {
    known = true;
    return r.wrong_band_pct;
  }
  // The penumbra figures under their results.json names: they bound the
  // rows of lights with a size, so that a hard shadow fails them.
  const char* const contour_names[] = { "pen_contour_01_px", "pen_contour_05_px",
    "pen_contour_09_px" };
  for (int i = 0; i < 3; ++i)
    if (name == contour_names[i])
    {
      known = true;
      return r.pen.contour_px[i];
    }
  if (name == "pen_mae")
  {
    known = true;
    return r.pen.pen_mae;
  }
  return RowMetric(r.m, name, known);
}

Row CompareWithReference(const Options& opt, const SceneEntry& e, int k, const std::string& test,
  const std::string& testdir, const std::string& light_type, bool tinted)
{
  Row row;
  row.scene = e.id;
  row.light = k;
  row.light_type = light_type;
  row.test = test;
  const std::string base = opt.out + "/" + e.dir_id;
  const std::string lk = "/light" + std::to_string(k);
  std::vector<float> ref, mask, tv;
  int w = 0, h = 0, w2 = 0, h2 = 0, w3 = 0, h3 = 0;
  std::string err;
  if (!ReadPNGChannel(base + "/povray" + lk + "_visibility.png", ref, w, h, err) ||
    !ReadPNGChannel(base + "/povray" + lk + "_mask.png", mask, w2, h2, err) ||
    !ReadPNGChannel(base + "/" + testdir + lk + "_visibility.png", tv, w3, h3, err))
    err = err.empty() ? "cannot read an image" : err;
  else if (w != w2 || w != w3 || h != h2 || h != h3)
    err = "image sizes differ";
  std::vector<unsigned char> valid(mask.size());
  for (size_t i = 0; err.empty() && i < mask.size(); ++i)
    valid[i] = mask[i] > 0.5f;
  const int rc = err.empty()
    ? vshm_metrics_compute(tv.data(), ref.data(), valid.data(), nullptr, w, h, &row.m)
    : -1;
  if (rc < 0)
  {
    row.status = "error";
    row.error = err.empty() ? "metrics failed" : err;
    return row;
  }
  row.width = w;
  row.height = h;
  row.wrong_band_pct = WrongOutsideBand(tv, ref, valid, w, h);
  row.status = rc == VSHM_METRICS_EMPTY ? "empty" : "ok";
  if (tinted)
  {
    row.colour_mae = ColourMae(base, testdir, k, valid, w, h, err);
    if (!err.empty())
      row.error = "colour_mae: " + err; // the other metrics stand
  }
  std::vector<unsigned char> rgb(3 * static_cast<size_t>(w) * h);
  vshm_error_heatmap_rgb(tv.data(), ref.data(), valid.data(), w, h, rgb.data());
  std::string tname = test;
  std::replace(tname.begin(), tname.end(), '/', '-');
  row.heatmap = e.dir_id + "/heatmap/" + tname + lk.substr(1) + ".png";
  char e2[1024] = "";
  std::string why;
  if (!MakeDirs(base + "/heatmap", why) ||
    vshm_png_write_rgb8((opt.out + "/" + row.heatmap).c_str(), rgb.data(), w, h, e2, sizeof e2) !=
      0)
  {
    // The metrics stand; the report shows no picture rather than a broken one.
    row.error = "heat map not written: " + (why.empty() ? std::string(e2) : why);
    row.heatmap.clear();
    return row;
  }
  ComparePenumbra(opt, e.dir_id, tname + lk.substr(1), tv, ref, valid, w, h, row);
  return row;
}

} // namespace vsh_harness
