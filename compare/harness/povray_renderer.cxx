// povray_renderer.cxx - POV-Ray 3.7, the reference of every comparison
// (settings and why: docs/harness.md, "Renderer settings").
#include "reference_renderer.h"

#include "harness_png.h"
#include "harness_process.h"

namespace vsh_harness
{

namespace
{

class PovrayRenderer : public ReferenceRenderer
{
public:
  using ReferenceRenderer::ReferenceRenderer;

  std::string Name() const override { return "povray"; }
  std::string ExportFileName() const override { return "scene.pov"; }
  std::string LogName() const override { return "povray.log"; }

  void Prepare() override
  {
    this->Version = CommandVersion({ this->Opt.povray, "--version" }, "POV-Ray", 60);
    if (this->Version.empty())
      this->Unusable = "POV-Ray not usable: '" + this->Opt.povray +
        " --version' failed (is povray installed? apt-get install povray)";
  }

  std::string ExportBytes(const ExportScene& ex) const override
  {
    return PovScene(ex, this->Opt.povray_grid, this->Opt.seed);
  }

  std::string KeySettings(const ExportScene& ex) const override
  {
    return "settings povray -D -A +FN16 File_Gamma=1.0 Display_Gamma=1.0 +W" +
      std::to_string(ex.width) + " +H" + std::to_string(ex.height) + " eps=1e-3\n";
  }

  bool Render(const RenderJob& job, RenderOutput& out, std::string& err) const override
  {
    const int L = static_cast<int>(job.ex.lights.size());
    out.lights.resize(L);
    for (int k = 0; k < L; ++k)
    {
      // Light k alone, shadows on (1) and off (0): v = on / off.
      for (int shadows = 1; shadows >= 0; --shadows)
        if (!this->RenderOne(job, k, shadows, out, err))
          return false;
      out.lights[k].eps = 1e-3; // POV-Ray's intensity is N.L: the definition of the mask
    }
    return true;
  }

private:
  bool RenderOne(
    const RenderJob& job, int k, int shadows, RenderOutput& out, std::string& err) const
  {
    const std::string name = std::string(shadows ? "on" : "off") + std::to_string(k) + ".png";
    std::vector<std::string> argv{ this->Opt.povray, "-D", "-P", "-V", "-A", "+FN16",
      "File_Gamma=1.0", "Display_Gamma=1.0", "+W" + std::to_string(job.ex.width),
      "+H" + std::to_string(job.ex.height), "+WT" + std::to_string(this->Opt.threads),
      "Declare=VSH_LIGHT=" + std::to_string(k), "Declare=VSH_SHADOWS=" + std::to_string(shadows),
      "+Iscene.pov", "+O" + name };
    RunResult r = RunLogged(
      job.entry.id + ": povray light " + std::to_string(k) + " shadows " + (shadows ? "on" : "off"),
      argv, job.work, job.log, this->Opt.timeout);
    out.seconds += r.seconds;
    if (!r.ok())
    {
      err = "light " + std::to_string(k) + ": " + r.error;
      return false;
    }
    // The red channel; a tinted scene's green and blue too (POV-Ray's PNG is RGB).
    LightPair& p = out.lights[k];
    std::vector<float>* img[3] = { shadows ? &p.on : &p.off, shadows ? &p.on_g : &p.off_g,
      shadows ? &p.on_b : &p.off_b };
    for (int c = 0; c < (job.ex.tinted ? 3 : 1); ++c)
    {
      int w = 0, h = 0;
      if (!ReadPNGChannel(job.work + "/" + name, *img[c], w, h, err, c) || w != job.ex.width ||
        h != job.ex.height)
      {
        err = "light " + std::to_string(k) + ": bad output " + (err.empty() ? "size" : err);
        return false;
      }
    }
    return true;
  }
};

} // namespace

std::unique_ptr<ReferenceRenderer> MakePovrayRenderer(const Options& opt)
{
  return std::unique_ptr<ReferenceRenderer>(new PovrayRenderer(opt));
}

} // namespace vsh_harness
