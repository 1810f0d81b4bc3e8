// vtkshadow-render: render a scene file with one shadow technique, and write
// the colour image, the per-light visibility and mask, and timing stats.
#include "render_options.h"
#include "render_stats.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
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
}

int main(int argc, char* argv[])
{
  RenderOptions options;
  std::string error;
  const int parsed = ParseRenderOptions(argc, argv, options, error);
  if (parsed < 0)
  {
    return 0;
  }
  if (parsed != 0)
  {
    return Fail(2, error + "\n" + RenderUsage());
  }

  vtkNew<vtkShadowScene> scene;
  if (!scene->Load(options.Scene.c_str()))
  {
    return Fail(2, scene->GetErrorMessage());
  }
  if (options.Light >= scene->GetNumberOfLights())
  {
    return Fail(2,
      "--light: light " + std::to_string(options.Light) + " out of range (" + options.Scene +
        " has " + std::to_string(scene->GetNumberOfLights()) + " lights)");
  }
  // Debian's VTK is built for X only and aborts without a display: open the
  // process's one connection now (every window below shares it, so Xvfb
  // never sees its last client leave mid-run) and say what to run if none.
  if (!vtkShadowDisplay::Open())
  {
    return Fail(2, vtkShadowDisplay::GetErrorMessage());
  }

  const int width = options.Width > 0 ? options.Width : scene->GetWidth();
  const int height = options.Height > 0 ? options.Height : scene->GetHeight();
  vtkNew<vtkShadowTechnique> technique;
  technique->SetName(options.Technique.c_str());
  technique->SetMapResolution(options.MapResolution);
  for (const auto& setting : options.Settings)
  {
    technique->SetOption(setting.first.c_str(), setting.second); // checked while parsing
  }
  auto progress = [&](const std::string& what) {
    if (!options.Quiet)
    {
      std::cerr << "vtkshadow-render: " << what << "\n";
    }
  };

  // Visibility and mask of light K, measured the same way for every technique.
  vtkNew<vtkShadowVisibility> visibility;
  if (!options.Visibility.empty() || !options.Mask.empty())
  {
    progress("visibility of light " + std::to_string(options.Light) + " with " +
      options.Technique + " at " + std::to_string(width) + "x" + std::to_string(height));
    visibility->SetScene(scene);
    visibility->SetTechnique(technique);
    visibility->SetLight(options.Light);
    visibility->SetSize(width, height);
    if (!visibility->Compute())
    {
      return Fail(1, std::string("visibility: ") + visibility->GetErrorMessage());
    }
  }

  // The colour image with every light, then (optionally) the timings.
  progress("colour image with " + options.Technique);
  vtkNew<vtkRenderWindow> window;
  vtkShadowDisplay::Attach(window); // opened above
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkOpenGLRenderer> renderer;
  window->AddRenderer(renderer);
  scene->Populate(renderer);
  technique->Install(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();

  std::string statsText;
  if (!options.Stats.empty())
  {
    progress("timing " + std::to_string(options.Frames) + " frames, shadowed and unshadowed");
    const FrameTimes shadowed = TimeFrames(window, renderer, scene, options.Frames, 3);
    // Memory and details of the technique's pass, before it is replaced.
    const long long bytes = technique->GetShadowMapMemory(renderer);
    window->Render(); // the scene camera again, for the details
    const std::string details = technique->GetStatsJSON(renderer);
    vtkNew<vtkShadowTechnique> none;
    none->Install(renderer);
    const FrameTimes unshadowed = TimeFrames(window, renderer, scene, options.Frames, 3);
    statsText = StatsJson(options.Scene, options.Technique, width, height, options.Frames,
      shadowed, unshadowed, bytes, details);
  }

  // Free the passes' GL objects while the context still exists.
  renderer->ReleaseGraphicsResources(window);
  renderer->SetPass(nullptr);

  WrittenFiles written;
  auto writePNG = [&](vtkImageData* image, const std::string& path) {
    if (path.empty())
    {
      return true;
    }
    if (!vtkshadow::WritePNGAtomically(image, path, error))
    {
      return false;
    }
    written.Paths.push_back(path);
    return true;
  };
  if (!writePNG(grab->GetOutput(), options.Image) ||
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
  progress("wrote " + options.Image);
  return 0;
}
