// blender_renderer.cxx - running Blender (Cycles or EEVEE) on the export.
#include "blender_renderer.h"

#include "harness_files.h"
#include "harness_process.h"
#include "harness_progress.h"
#include "harness_text.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace vsh_harness
{

void BlenderRenderer::Prepare()
{
  this->Version = CommandVersion({ this->Opt.blender, "--version" }, "Blender", 120);
  if (this->Version.empty())
    this->Unusable = "Blender not usable: '" + this->Opt.blender +
      " --version' failed (is blender installed? apt-get install blender)";
  if (!ReadFile(this->Opt.cycles_script, this->ScriptBytes))
    this->Unusable = "cannot read the Blender script " + this->Opt.cycles_script;
}

std::string BlenderRenderer::ExportBytes(const ExportScene& ex) const
{
  return CyclesData(ex, this->Opt.cycles_samples, this->Opt.soft_samples, this->Opt.seed);
}

std::string BlenderRenderer::KeySettings(const ExportScene&) const
{
  return "settings " + this->Settings() + "\nscript " + MD5Hex(this->ScriptBytes) + "\n";
}

namespace
{
// Mean seconds of one bpy.ops.render.render (the script's frame_seconds.txt:
// "light state seconds" per frame), or -1 when absent.
double MeanFrameSeconds(const std::string& work)
{
  std::string frames;
  if (!ReadFile(work + "/frame_seconds.txt", frames))
    return -1;
  std::stringstream fs(frames);
  int light = 0, count = 0;
  std::string state;
  double sec = 0, sum = 0;
  while (fs >> light >> state >> sec)
  {
    sum += sec;
    ++count;
  }
  return count ? sum / count : -1;
}
} // namespace

bool BlenderRenderer::ReadLight(const RenderJob& job, int k, LightPair& p, std::string& err) const
{
  const size_t n = static_cast<size_t>(job.ex.width) * job.ex.height;
  // light<K>_on.f32 / _off.f32 (red); a tinted scene's _on_g, _on_b, ... too.
  static const char* const kChannel[] = { "", "_g", "_b" };
  std::vector<float>* imgs[2][3] = { { &p.off, &p.off_g, &p.off_b }, { &p.on, &p.on_g, &p.on_b } };
  for (int i = 0; i < 2 * (job.ex.tinted ? 3 : 1); ++i)
  {
    const int shadows = i % 2, c = i / 2;
    std::string raw;
    const std::string f =
      job.work + "/light" + std::to_string(k) + (shadows ? "_on" : "_off") + kChannel[c] + ".f32";
    if (!ReadFile(f, raw) || raw.size() != 4 * n)
    {
      err = "missing or short output " + f + "; log: " + job.log;
      return false;
    }
    std::vector<float>& img = *imgs[shadows][c];
    img.resize(n);
    // Blender's rows are bottom-up: flip to row 0 on top.
    for (int y = 0; y < job.ex.height; ++y)
      std::memcpy(&img[static_cast<size_t>(y) * job.ex.width],
        raw.data() + 4 * static_cast<size_t>(job.ex.height - 1 - y) * job.ex.width,
        4 * static_cast<size_t>(job.ex.width));
  }
  // Blender's intensities are not N.L: valid where off > 1e-6 of the brightest.
  float mx = 0;
  for (float x : p.off)
    if (std::isfinite(x))
      mx = std::max(mx, x);
  p.eps = 1e-6 * mx;
  return true;
}

bool BlenderRenderer::Render(const RenderJob& job, RenderOutput& out, std::string& err) const
{
  const int L = static_cast<int>(job.ex.lights.size());
  std::vector<std::string> argv{ this->Opt.blender, "-b", "--factory-startup", "--python-exit-code",
    "1", "-t", std::to_string(this->Opt.threads), "--python", this->Opt.cycles_script, "--",
    job.work + "/scene.bin", job.work, this->Preset };
  Progress(job.entry.id + ": " + this->Preset + " " + std::to_string(L) +
    " light(s) x shadows on/off ...");
  // All lights in one process (start-up ~0.7 s): the limit grows with them.
  RunResult r = RunProcess(argv, job.work, job.log, this->Opt.timeout * 2 * L + 60);
  Progress(job.entry.id + ": " + this->Preset + (r.ok() ? " done" : " FAILED") + " (" +
    Fmt(r.seconds, "%.1f") + " s)");
  out.seconds = r.seconds;
  if (!r.ok())
  {
    err = r.error;
    return false;
  }
  out.lights.resize(L);
  for (int k = 0; k < L; ++k)
    if (!this->ReadLight(job, k, out.lights[k], err))
      return false;
  out.frame_seconds = MeanFrameSeconds(job.work);
  return true;
}

} // namespace vsh_harness
