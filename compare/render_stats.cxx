#include "render_stats.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShadowScene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace
{
// Put the camera on frame `i` of the path: always from the scene camera, so the
// path is the same for every technique and never drifts.
void PlaceCamera(vtkRenderer* renderer, const vtkShadowScene* scene, int i, int frames)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  scene->ConfigureCamera(camera);
  const double phase = 2.0 * 3.14159265358979323846 * i / std::max(frames, 2);
  camera->Azimuth(5.0 * std::sin(phase));
  camera->Elevation(2.0 * std::cos(phase) - 2.0);
  camera->OrthogonalizeViewUp();
  vtkShadowScene::ResetCameraClippingRange(renderer); // near from the visible geometry
}

std::string Json(const FrameTimes& t)
{
  std::ostringstream out;
  out.precision(6);
  out << "{\"median\": " << t.Median << ", \"min\": " << t.Min << ", \"max\": " << t.Max << "}";
  return out.str();
}

std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}
}

FrameTimes TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, const vtkShadowScene* scene,
  int frames, int warmup)
{
  for (int i = 0; i < warmup; ++i)
  {
    PlaceCamera(renderer, scene, i, frames);
    window->Render();
    window->WaitForCompletion();
  }
  std::vector<double> ms;
  ms.reserve(frames);
  for (int i = 0; i < frames; ++i)
  {
    PlaceCamera(renderer, scene, i, frames);
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    const auto stop = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  scene->ConfigureCamera(renderer->GetActiveCamera());
  vtkShadowScene::ResetCameraClippingRange(renderer); // near from the visible geometry
  FrameTimes t;
  std::sort(ms.begin(), ms.end());
  const size_t n = ms.size();
  t.Median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  t.Min = ms.front();
  t.Max = ms.back();
  return t;
}

std::string StatsJson(const std::string& scene, const std::string& technique, int width, int height,
  int frames, const FrameTimes& shadowed, const FrameTimes& unshadowed, long long shadowMapBytes,
  const std::string& techniqueJson)
{
  std::ostringstream out;
  out.precision(6);
  out << "{\n"
      << "  \"scene\": " << Quoted(scene) << ",\n"
      << "  \"technique\": " << Quoted(technique) << ",\n"
      << "  \"size\": [" << width << ", " << height << "],\n"
      << "  \"frames\": " << frames << ",\n"
      << "  \"shadowed_ms\": " << Json(shadowed) << ",\n"
      << "  \"unshadowed_ms\": " << Json(unshadowed) << ",\n"
      << "  \"overhead_ms\": " << (shadowed.Median - unshadowed.Median) << ",\n"
      << "  \"shadow_map_bytes\": " << shadowMapBytes << ",\n"
      << "  \"technique_stats\": " << techniqueJson << "\n"
      << "}\n";
  return out.str();
}
