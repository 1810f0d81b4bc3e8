// reflection_run.cxx - see reflection_run.h. The colour renders are not
// cached: a library has few mirror scenes and POV-Ray renders them in
// seconds.
#include "reflection_run.h"

#include "harness_files.h"
#include "harness_process.h"
#include "harness_progress.h"
#include "harness_text.h"
#include "technique_variant.h"

#include "vshm_metrics.h"
#include "vshm_png.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vsh_harness
{

namespace
{
struct Colour
{
  std::vector<float> rgb; // 3 per pixel, linear, row 0 on top
};

bool ReadRgb(const std::string& path, int w, int h, Colour& c, std::string& err)
{
  float* px = nullptr;
  int pw = 0, ph = 0;
  char e2[1024] = "";
  if (vshm_png_read_rgb(path.c_str(), &px, &pw, &ph, nullptr, e2, sizeof e2) != 0)
  {
    err = e2;
    return false;
  }
  c.rgb.assign(px, px + 3 * static_cast<size_t>(pw) * ph);
  free(px);
  if (pw != w || ph != h)
  {
    err = path + " is " + std::to_string(pw) + "x" + std::to_string(ph) + ", expected " +
      std::to_string(w) + "x" + std::to_string(h);
    return false;
  }
  return true;
}

// POV-Ray: colour (16-bit linear) and mirror mask, from PovColourScene.
bool PovrayColour(const Options& opt, const SceneEntry& e, const ExportScene& ex, Colour& colour,
  std::vector<unsigned char>& mirror, std::string& err)
{
  const std::string dir = AbsPath(opt.out + "/" + e.dir_id + "/povray");
  const std::string work = dir + "/.colourwork";
  if (!MakeWorkDir(work, "colour.pov", PovColourScene(ex, opt.povray_grid, opt.seed), err))
    return false;
  const std::string log = dir + "/povray-colour.log";
  for (int mask = 0; mask < 2; ++mask)
  {
    std::vector<std::string> argv{ opt.povray, "-D", "-P", "-V", "-A", "+FN16", "File_Gamma=1.0",
      "Display_Gamma=1.0", "+W" + std::to_string(ex.width), "+H" + std::to_string(ex.height),
      "+WT" + std::to_string(opt.threads), "Declare=VSH_MIRROR_MASK=" + std::to_string(mask),
      "+Icolour.pov", mask ? "+Omirror.png" : "+Ocolor.png" };
    RunResult r = RunLogged(
      e.id + ": povray " + (mask ? "mirror mask" : "colour"), argv, work, log, opt.timeout);
    if (!r.ok())
    {
      err = "povray colour: " + r.error;
      return false;
    }
  }
  Colour m;
  if (!ReadRgb(work + "/color.png", ex.width, ex.height, colour, err) ||
    !ReadRgb(work + "/mirror.png", ex.width, ex.height, m, err))
    return false;
  const size_t n = static_cast<size_t>(ex.width) * ex.height;
  mirror.assign(n, 0);
  for (size_t i = 0; i < n; ++i)
    mirror[i] = m.rgb[3 * i] > 0.5f ? 255 : 0;
  char e2[1024] = "";
  const bool ok = std::rename((work + "/color.png").c_str(), (dir + "/color.png").c_str()) == 0 &&
    vshm_png_write_gray8(
      (dir + "/mirror.png").c_str(), mirror.data(), ex.width, ex.height, e2, sizeof e2) == 0;
  if (!opt.keep_work)
    RemoveTree(work);
  if (!ok)
    err = "cannot store the POV-Ray colour images in " + dir + (*e2 ? ": " : "") + e2;
  return ok;
}

// Cycles: the colour image (render_cycles.py cycles-color), floats.
bool CyclesColour(
  const Options& opt, const SceneEntry& e, const ExportScene& ex, Colour& colour, std::string& err)
{
  const std::string dir = AbsPath(opt.out + "/" + e.dir_id + "/cycles");
  const std::string work = dir + "/.colourwork";
  if (!MakeWorkDir(work, "scene.bin", CyclesData(ex, 1, opt.soft_samples, opt.seed), err))
    return false;
  std::vector<std::string> argv{ opt.blender, "-b", "--factory-startup", "--python-exit-code", "1",
    "-t", std::to_string(opt.threads), "--python", opt.cycles_script, "--", work + "/scene.bin",
    work, "cycles-color" };
  RunResult r = RunLogged(
    e.id + ": cycles colour", argv, work, dir + "/cycles-colour.log", opt.timeout * 4 + 60);
  std::string raw;
  const size_t n = static_cast<size_t>(ex.width) * ex.height;
  if (!r.ok() || !ReadFile(work + "/color.f32", raw) || raw.size() != 12 * n)
  {
    err = "cycles colour: " + (r.ok() ? "missing or short color.f32" : r.error);
    return false;
  }
  colour.rgb.resize(3 * n);
  for (int y = 0; y < ex.height; ++y) // Blender's rows are bottom-up
    std::memcpy(&colour.rgb[3 * static_cast<size_t>(y) * ex.width],
      raw.data() + 12 * static_cast<size_t>(ex.height - 1 - y) * ex.width,
      12 * static_cast<size_t>(ex.width));
  // An 8-bit picture for the report; the metric reads the floats.
  std::vector<unsigned char> rgb8(3 * n);
  for (size_t i = 0; i < 3 * n; ++i)
    rgb8[i] = static_cast<unsigned char>(std::lround(
      255.0 * std::min(1.0f, std::max(0.0f, std::isfinite(colour.rgb[i]) ? colour.rgb[i] : 0.0f))));
  char e2[1024] = "";
  if (!opt.keep_work)
    RemoveTree(work);
  if (vshm_png_write_rgb8(
        (dir + "/color.png").c_str(), rgb8.data(), ex.width, ex.height, e2, sizeof e2) != 0)
    Progress("WARNING " + e.id + ": " + e2);
  return true;
}

// One VTK technique's colour image with its reflections, shaded as the ray
// tracers do (--matte).
bool VtkColour(const Options& opt, const SceneEntry& e, const ExportScene& ex, const std::string& t,
  Colour& colour, std::string& err)
{
  const std::string dir = opt.out + "/" + e.dir_id + "/vtk/" + t;
  const std::string image = AbsPath(dir + "/color.png");
  std::remove(image.c_str());
  std::vector<std::string> argv{ opt.render_bin, AbsPath(e.path), "--image", image, "--matte",
    "--reflections", "on", "--size", std::to_string(ex.width) + "x" + std::to_string(ex.height),
    "--quiet" };
  const std::vector<std::string> tech = RenderArguments(t); // a variant's --set too
  argv.insert(argv.begin() + 2, tech.begin(), tech.end());
  RunResult r = RunLogged(
    e.id + ": vtk/" + t + " colour", argv, "", AbsPath(dir + "/render-colour.log"), opt.timeout);
  if (!r.ok())
  {
    err = "vtk/" + t + " colour: " + r.error;
    return false;
  }
  return ReadRgb(image, ex.width, ex.height, colour, err);
}

// reflection_mae of one test on its rows, and its heat map.
void Attach(const Options& opt, const SceneEntry& e, const std::string& test, const Colour& c,
  const Colour& ref, const std::vector<unsigned char>& mirror, int w, int h, SceneResult& res)
{
  double mae = 0;
  long px = 0;
  const int rc =
    vshm_reflection_mae(c.rgb.data(), ref.rgb.data(), mirror.data(), nullptr, w, h, &mae, &px);
  if (rc != VSHM_METRICS_OK)
  {
    res.errors.push_back("reflection_mae " + test + ": " +
      (rc == VSHM_METRICS_EMPTY ? "no mirror pixel in view" : "metric failed"));
    return;
  }
  std::string tname = test;
  std::replace(tname.begin(), tname.end(), '/', '-');
  std::string heat = e.dir_id + "/heatmap/" + tname + "-mirror.png";
  std::vector<unsigned char> rgb(3 * static_cast<size_t>(w) * h);
  vshm_reflection_heatmap_rgb(c.rgb.data(), ref.rgb.data(), mirror.data(), w, h, rgb.data());
  char e2[1024] = "";
  if (!MakeDirs(opt.out + "/" + e.dir_id + "/heatmap") ||
    vshm_png_write_rgb8((opt.out + "/" + heat).c_str(), rgb.data(), w, h, e2, sizeof e2) != 0)
    heat.clear();
  Progress(e.id + ": " + test + " reflection_mae " + Fmt(mae, "%.4f") + " over " +
    std::to_string(px) + " mirror pixels");
  for (Row& r : res.rows)
    if (r.test == test)
    {
      r.reflection_mae = mae;
      r.mirror_heatmap = heat;
    }
}
} // namespace

void RunReflections(const Options& opt, const SceneEntry& e, const ExportScene& ex,
  const std::set<std::string>& ok_techniques, SceneResult& res)
{
  if (!ex.has_mirror || !opt.Has("povray"))
    return;
  Colour ref;
  std::vector<unsigned char> mirror;
  std::string err;
  if (!PovrayColour(opt, e, ex, ref, mirror, err))
  {
    res.errors.push_back(err);
    return;
  }
  res.mirror_image = e.dir_id + "/povray/mirror.png";
  for (const std::string& t : opt.techniques)
  {
    Colour c;
    if (!ok_techniques.count(t))
      continue;
    if (VtkColour(opt, e, ex, t, c, err))
      Attach(opt, e, "vtk/" + t, c, ref, mirror, ex.width, ex.height, res);
    else
      res.errors.push_back(err);
  }
  Colour cy;
  if (opt.Has("cycles"))
  {
    if (CyclesColour(opt, e, ex, cy, err))
      Attach(opt, e, "cycles", cy, ref, mirror, ex.width, ex.height, res);
    else
      res.errors.push_back(err);
  }
}

} // namespace vsh_harness
