// vtkshadow-render: render a scene file with one shadow technique, and write
// the colour image, the per-light visibility and mask, and timing stats.
#include "render_options.h"
#include "render_stats.h"
#include "render_timing.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPlanarReflectionPass.h"
#include "vtkRenderWindow.h"
#include "vtkShadowDisplay.h"
#include "vtkShadowPNG.h"
#include "vtkShadowPassBase.h"
#include "vtkShadowScene.h"
#include "vtkShadowTechnique.h"
#include "vtkShadowVisibility.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
int Fail(int status, const std::string& message)
{
  std::cerr << "vtkshadow-render: " << message << "\n";
  return status;
}

// Outputs written so far; removed again if a later one fails, so a failed
// run leaves nothing behind.
struct WrittenFiles
{
  std::vector<std::string> Paths;
  bool Keep = false;
  ~WrittenFiles()
  {
    if (!this->Keep)
    {
      for (const auto& p : this->Paths)
      {
        std::remove(p.c_str());
      }
    }
  }
};

// The run's inputs once parsed and loaded.
struct Run
{
  RenderOptions Options;
  vtkNew<vtkShadowScene> Scene;
  vtkNew<vtkShadowTechnique> Technique;
  int Width = 0;
  int Height = 0;

  void Progress(const std::string& what) const
  {
    if (!this->Options.Quiet)
    {
      std::cerr << "vtkshadow-render: " << what << "\n";
    }
  }
};

// Scene, light index, display and technique: everything that can be bad
// input is checked here, before anything is rendered or written.
int Prepare(Run& run)
{
  const RenderOptions& options = run.Options;
  if (!run.Scene->Load(options.Scene.c_str()))
  {
    return Fail(2, run.Scene->GetErrorMessage());
  }
  if (options.Light >= run.Scene->GetNumberOfLights())
  {
    return Fail(2,
      "--light: light " + std::to_string(options.Light) + " out of range (" + options.Scene +
        " has " + std::to_string(run.Scene->GetNumberOfLights()) + " lights)");
  }
  if (options.ImageLight >= run.Scene->GetNumberOfLights())
  {
    return Fail(2,
      "--image-light: light " + std::to_string(options.ImageLight) + " out of range (" +
        options.Scene + " has " + std::to_string(run.Scene->GetNumberOfLights()) + " lights)");
  }
  // Debian's VTK is built for X only and aborts without a display: open the
  // process's one connection now (every window below shares it, so Xvfb
  // never sees its last client leave mid-run) and say what to run if none.
  if (!vtkShadowDisplay::Open())
  {
    return Fail(2, vtkShadowDisplay::GetErrorMessage());
  }
  run.Width = options.Width > 0 ? options.Width : run.Scene->GetWidth();
  run.Height = options.Height > 0 ? options.Height : run.Scene->GetHeight();
  run.Technique->SetName(options.Technique.c_str());
  run.Technique->SetMapResolution(options.MapResolution);
  for (const auto& setting : options.Settings)
  {
    run.Technique->SetOption(setting.first.c_str(), setting.second); // checked while parsing
  }
  return 0;
}

// Visibility and mask of light K, measured the same way for every technique.
int ComputeVisibility(const Run& run, vtkShadowVisibility* visibility)
{
  const RenderOptions& options = run.Options;
  if (options.Visibility.empty() && options.Mask.empty() && options.ChannelVisibility[0].empty() &&
    options.ChannelVisibility[1].empty() && options.ChannelVisibility[2].empty())
  {
    return 0;
  }
  run.Progress("visibility of light " + std::to_string(options.Light) + " with " +
    options.Technique + " at " + std::to_string(run.Width) + "x" + std::to_string(run.Height));
  visibility->SetScene(run.Scene);
  visibility->SetTechnique(run.Technique);
  visibility->SetLight(options.Light);
  visibility->SetSize(run.Width, run.Height);
  if (!visibility->Compute())
  {
    return Fail(1, std::string("visibility: ") + visibility->GetErrorMessage());
  }
  return 0;
}

// A pass of `technique` with `settings` (checked while parsing).
vtkSmartPointer<vtkShadowPassBase> MakePass(
  const std::string& technique, const std::vector<std::pair<std::string, double>>& settings)
{
  vtkNew<vtkShadowTechnique> maker;
  maker->SetName(technique.c_str());
  for (const auto& setting : settings)
  {
    maker->SetOption(setting.first.c_str(), setting.second);
  }
  vtkSmartPointer<vtkShadowPassBase> pass;
  pass.TakeReference(maker->CreatePass());
  return pass;
}

// The timed entries: the main technique (its installed pass, which drew the
// colour image), none, none#2 (the noise floor) and every --time-also.
void SetUpTiming(const Run& run, vtkOpenGLRenderer* renderer, TimingRun& timing, int& main)
{
  const RenderOptions& options = run.Options;
  auto* installed = vtkShadowPassBase::SafeDownCast(renderer->GetPass());
  // With mirrors the installed pass is the mirrors' pass around the
  // technique's (RenderColourAndStats).
  auto* mirrors = vtkPlanarReflectionPass::SafeDownCast(installed);
  timing.Rounds = options.Rounds;
  timing.Frames = options.Frames;
  timing.Warmup = options.Warmup;
  timing.ProfileFrames = options.ProfileFrames;
  timing.NoiseTolerance = options.NoiseTolerance;
  auto add = [&](const std::string& label, const std::string& technique,
               const std::vector<std::pair<std::string, double>>& settings, vtkShadowPassBase* pass)
  {
    TimedEntry entry;
    entry.Label = label;
    entry.Technique = technique;
    entry.Settings = settings;
    entry.Pass = pass ? vtkSmartPointer<vtkShadowPassBase>(pass) : MakePass(technique, settings);
    if (!pass && mirrors && entry.Pass)
    {
      // Every entry draws the mirrors as the installed pass does, each
      // through its own reflection pass (its worlds' caches are its own).
      vtkNew<vtkPlanarReflectionPass> reflections;
      reflections->SetDelegatePass(entry.Pass);
      reflections->SetReflectShadows(mirrors->GetReflectShadows());
      reflections->SetReflections(mirrors->GetReflections());
      entry.Pass = reflections.GetPointer();
    }
    timing.Entries.push_back(entry);
  };
  const bool mainIsNone = MainTimingLabel(options) == "none";
  if (!mainIsNone)
  {
    add(MainTimingLabel(options), options.Technique, options.Settings, installed);
  }
  timing.Reference = static_cast<int>(timing.Entries.size());
  add("none", "none", {}, mainIsNone ? installed : nullptr);
  timing.NoiseFloor = static_cast<int>(timing.Entries.size());
  add("none#2", "none", {}, nullptr);
  for (const auto& spec : options.TimeAlso)
  {
    add(spec.Label, spec.Technique, spec.Settings, nullptr);
  }
  main = mainIsNone ? timing.Reference : 0;
}

// The timing run as the stats JSON text; noisy set when the noise floor is
// outside the tolerance. Empty with an error message on failure.
std::string TimeTechniques(const Run& run, vtkRenderWindow* window, vtkOpenGLRenderer* renderer,
  bool& noisy, std::string& error)
{
  TimingRun timing;
  StatsHeader header;
  SetUpTiming(run, renderer, timing, header.Main);
  header.Scene = run.Options.Scene;
  header.Technique = run.Options.Technique;
  header.Width = run.Width;
  header.Height = run.Height;
  run.Progress("timing " + std::to_string(timing.Entries.size()) + " techniques interleaved: " +
    std::to_string(timing.Rounds) + " rounds x " + std::to_string(timing.Frames) + " frames");
  const bool ok = RunInterleavedTiming(window, renderer, run.Scene, timing, error);
  ReleaseTimingPasses(window, timing);
  if (!ok)
  {
    return "";
  }
  if (!run.Options.Quiet)
  {
    std::cerr << TimingSummary(header, timing);
  }
  const std::string warning = NoiseWarning(timing);
  if (!warning.empty())
  {
    std::cerr << "vtkshadow-render: " << warning << "\n"; // also with --quiet
  }
  noisy = timing.TooNoisy;
  return StatsJson(header, timing);
}

// The colour image with every light into `grab`, then (optionally) the
// interleaved timings as the stats JSON text.
int RenderColourAndStats(
  const Run& run, vtkWindowToImageFilter* grab, std::string& statsText, bool& noisy)
{
  const RenderOptions& options = run.Options;
  run.Progress("colour image with " + options.Technique);
  vtkNew<vtkRenderWindow> window;
  vtkShadowDisplay::Attach(window); // opened in Prepare
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(run.Width, run.Height);
  const bool mirrors = options.Reflections == "on" || options.Reflections == "no-shadows" ||
    (options.Reflections == "auto" && run.Scene->HasMirrors());
  window->SetStencilCapable(mirrors ? 1 : 0); // the mirrors' mask
  vtkNew<vtkOpenGLRenderer> renderer;
  window->AddRenderer(renderer);
  if (options.Matte)
    run.Scene->PopulateMatte(renderer, options.ImageLight);
  else
    run.Scene->Populate(renderer, false, options.ImageLight);
  run.Technique->Install(renderer);
  if (mirrors)
  {
    // The technique's pass becomes the delegate of the mirrors' pass.
    vtkNew<vtkPlanarReflectionPass> reflections;
    reflections->SetDelegatePass(renderer->GetPass());
    reflections->SetReflectShadows(options.Reflections != "no-shadows");
    renderer->SetPass(reflections);
  }
  window->Render();
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  grab->SetInput(nullptr); // the image is kept by the filter

  std::string error;
  if (!options.Stats.empty())
  {
    statsText = TimeTechniques(run, window, renderer, noisy, error);
  }
  // Free the passes' GL objects while the context still exists.
  renderer->ReleaseGraphicsResources(window);
  renderer->SetPass(nullptr);
  return options.Stats.empty() || !statsText.empty() ? 0 : Fail(1, error);
}

// Every output, each written atomically; all removed again if one fails.
int WriteOutputs(const Run& run, vtkImageData* image, vtkShadowVisibility* visibility,
  const std::string& statsText)
{
  const RenderOptions& options = run.Options;
  std::string error;
  WrittenFiles written;
  auto writePNG = [&](vtkImageData* data, const std::string& path)
  {
    if (path.empty())
    {
      return true;
    }
    if (!vtkshadow::WritePNGAtomically(data, path, error))
    {
      return false;
    }
    written.Paths.push_back(path);
    return true;
  };
  bool ok = writePNG(image, options.Image) &&
    writePNG(visibility->GetVisibility16(), options.Visibility) &&
    writePNG(visibility->GetMask(), options.Mask);
  for (int c = 0; ok && c < 3; ++c)
  {
    ok = writePNG(visibility->GetChannelVisibility16(c), options.ChannelVisibility[c]);
  }
  if (!ok)
  {
    return Fail(1, error);
  }
  if (!options.Stats.empty())
  {
    if (!vtkshadow::WriteTextAtomically(statsText, options.Stats, error))
    {
      return Fail(1, error);
    }
    written.Paths.push_back(options.Stats);
  }
  written.Keep = true;
  run.Progress("wrote " + options.Image);
  return 0;
}
}

int main(int argc, char* argv[])
{
  Run run;
  std::string error;
  const int parsed = ParseRenderOptions(argc, argv, run.Options, error);
  if (parsed < 0)
  {
    return 0;
  }
  if (parsed != 0)
  {
    return Fail(2, error + "\n" + RenderUsage());
  }
  if (const int status = Prepare(run))
  {
    return status;
  }
  vtkNew<vtkShadowVisibility> visibility;
  if (const int status = ComputeVisibility(run, visibility))
  {
    return status;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  std::string statsText;
  bool noisy = false;
  if (const int status = RenderColourAndStats(run, grab, statsText, noisy))
  {
    return status;
  }
  if (const int status = WriteOutputs(run, grab->GetOutput(), visibility, statsText))
  {
    return status;
  }
  // Everything is written; a too-noisy timing fails only when asked to.
  return noisy && run.Options.FailIfNoisy ? 3 : 0;
}
