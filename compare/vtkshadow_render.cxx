// vtkshadow-render: render a scene file with one shadow technique, and write
// the colour image, the per-light visibility and mask, and timing stats.
#include "render_options.h"
#include "render_stats.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPlanarReflectionPass.h"
#include "vtkRenderWindow.h"
#include "vtkShadowDisplay.h"
#include "vtkShadowPNG.h"
#include "vtkShadowScene.h"
#include "vtkShadowTechnique.h"
#include "vtkShadowVisibility.h"
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
  if (options.Visibility.empty() && options.Mask.empty())
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

// The colour image with every light into `grab`, then (optionally) the
// timings, shadowed and unshadowed, as the stats JSON text.
std::string RenderColourAndStats(const Run& run, vtkWindowToImageFilter* grab)
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

  std::string statsText;
  if (!options.Stats.empty())
  {
    run.Progress("timing " + std::to_string(options.Frames) + " frames, shadowed and unshadowed");
    const FrameTimes shadowed = TimeFrames(window, renderer, run.Scene, options.Frames, 3);
    // Memory and details of the technique's pass, before it is replaced.
    const long long bytes = run.Technique->GetShadowMapMemory(renderer);
    window->Render(); // the scene camera again, for the details
    const std::string details = run.Technique->GetStatsJSON(renderer);
    vtkNew<vtkShadowTechnique> none;
    none->Install(renderer);
    const FrameTimes unshadowed = TimeFrames(window, renderer, run.Scene, options.Frames, 3);
    statsText = StatsJson(options.Scene, options.Technique, run.Width, run.Height, options.Frames,
      shadowed, unshadowed, bytes, details);
  }
  // Free the passes' GL objects while the context still exists; the image
  // is kept by the filter.
  grab->SetInput(nullptr);
  renderer->ReleaseGraphicsResources(window);
  renderer->SetPass(nullptr);
  return statsText;
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
  if (!writePNG(image, options.Image) ||
    !writePNG(visibility->GetVisibility16(), options.Visibility) ||
    !writePNG(visibility->GetMask(), options.Mask))
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
  const std::string statsText = RenderColourAndStats(run, grab);
  return WriteOutputs(run, grab->GetOutput(), visibility, statsText);
}
