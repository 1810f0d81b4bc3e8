// vtk_runner.cxx - running vtkshadow-render for each technique and light.
#include "vtk_runner.h"

#include "harness_files.h"
#include "harness_process.h"
#include "technique_variant.h"
#include "visibility_io.h"

#include <unistd.h>

namespace vsh_harness
{

namespace
{
// One technique, every light; false after the first failed light.
bool RenderTechnique(const Options& opt, const SceneEntry& e, const std::string& t, int w, int h,
  int lights, SceneResult& res)
{
  const std::string outdir = opt.out + "/" + e.dir_id + "/vtk/" + t;
  std::string why;
  if (!MakeDirs(outdir, why))
  {
    res.errors.push_back("vtk/" + t + ": cannot create " + outdir + ": " + why);
    return false;
  }
  RemoveLightFiles(outdir, lights);
  const std::string log = AbsPath(outdir + "/render.log");
  unlink(log.c_str());
  double total = 0;
  for (int k = 0; k < lights; ++k)
  {
    const std::vector<std::string> names = LightFileNames(k, res.tinted);
    std::vector<std::string> argv{ opt.render_bin, AbsPath(e.path), "--image",
      AbsPath(outdir + "/image.png"), "--light", std::to_string(k) };
    // A tinted scene: light<K>_visibility.png is the red channel, as the
    // references' (else the sum of R, G and B: the same for white light).
    const std::vector<std::string> vis = res.tinted
      ? std::vector<std::string>{ "--visibility-red", AbsPath(outdir + "/" + names[0]),
          "--visibility-green", AbsPath(outdir + "/" + names[2]), "--visibility-blue",
          AbsPath(outdir + "/" + names[3]) }
      : std::vector<std::string>{ "--visibility", AbsPath(outdir + "/" + names[0]) };
    argv.insert(argv.end(), vis.begin(), vis.end());
    for (const std::string& a :
      { std::string("--mask"), AbsPath(outdir + "/" + names[1]), std::string("--size"),
        std::to_string(w) + "x" + std::to_string(h), std::string("--quiet") })
      argv.push_back(a);
    // --technique NAME and a variant's --set KEY=VALUE (technique_variant.h).
    const std::vector<std::string> tech = RenderArguments(t);
    argv.insert(argv.begin() + 2, tech.begin(), tech.end());
    RunResult r =
      RunLogged(e.id + ": vtk/" + t + " light " + std::to_string(k), argv, "", log, opt.timeout);
    total += r.seconds;
    if (!r.ok())
    {
      res.errors.push_back("vtk/" + t + " light " + std::to_string(k) + ": " + r.error);
      RemoveLightFiles(outdir, lights);
      return false;
    }
  }
  res.seconds["vtk/" + t] = total;
  return true;
}
} // namespace

void RenderVtk(const Options& opt, const SceneEntry& e, int w, int h, int lights, SceneResult& res,
  std::set<std::string>& ok_techniques)
{
  for (const std::string& t : opt.techniques)
    if (RenderTechnique(opt, e, t, w, h, lights, res))
      ok_techniques.insert(t);
}

} // namespace vsh_harness
