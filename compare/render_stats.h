// render_stats.h - frame timings along a fixed camera path.
#ifndef vtkshadow_render_stats_h
#define vtkshadow_render_stats_h

#include <string>
#include <vector>

class vtkRenderWindow;
class vtkRenderer;
class vtkShadowScene;

struct FrameTimes
{
  double Median = 0, Min = 0, Max = 0;
};

// Render `frames` frames after `warmup` frames, the camera orbiting a small
// fixed path around the scene camera (+-5 degrees azimuth, +-2 elevation), so
// that caching is measured honestly; each frame ends with glFinish.
FrameTimes TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, const vtkShadowScene* scene,
  int frames, int warmup);

// The stats JSON document.
std::string StatsJson(const std::string& scene, const std::string& technique, int width, int height,
  int frames, const FrameTimes& shadowed, const FrameTimes& unshadowed, long long shadowMapBytes,
  const std::string& techniqueJson);

#endif
