// render_options.h - the command line of vtkshadow-render, parsed and checked
// before anything is rendered, so bad input never leaves partial output.
#ifndef vtkshadow_render_options_h
#define vtkshadow_render_options_h

#include <ostream>
#include <string>
#include <utility>
#include <vector>

// A technique timed next to the main one (--time-also TECH[:KEY=VALUE,...]).
struct TimedSpec
{
  std::string Label; // the text as given: how the stats name the entry
  std::string Technique;
  std::vector<std::pair<std::string, double>> Settings;
};

struct RenderOptions
{
  std::string Scene;
  std::string Technique = "none";
  std::string Image;
  std::string Visibility;
  // --visibility-red/-green/-blue: one colour channel's visibility each.
  std::string ChannelVisibility[3];
  std::string Mask;
  std::string Stats;
  int Light = 0;
  // Interleaved timing (--stats): rounds of one block of Frames frames per
  // timed technique, after Warmup frames each; see tools/timing/vsh_timing.h.
  int Frames = 15;
  int Rounds = 4;
  int Warmup = 5;
  // After the timing, this many frames per technique with the stage profile
  // on (vtkShadowStageProfile.h): each stage's median in the stats.
  int ProfileFrames = 0;
  double NoiseTolerance = 0.03;
  bool FailIfNoisy = false;
  std::vector<TimedSpec> TimeAlso;
  int MapResolution = 2048;
  int Width = 0; // 0: the scene's size
  int Height = 0;
  bool Quiet = false;
  // Planar mirrors: "auto" (on when the scene has mirrors), "on", "off",
  // "no-shadows" (mirrors on, the reflection drawn without shadows).
  std::string Reflections = "auto";
  // Colour image as the ray tracers shade it (diffuse 1, no ambient or
  // specular), and with only light ImageLight (-1: every light).
  bool Matte = false;
  int ImageLight = -1;
  // --set KEY=VALUE technique settings, in order.
  std::vector<std::pair<std::string, double>> Settings;
};

// Parse argv. Returns 0 when the program should go on, 2 on a usage error
// (message in `error`), and -1 after printing --help.
int ParseRenderOptions(int argc, char* argv[], RenderOptions& options, std::string& error);

// Each registered technique, "name<TAB>description" per line.
void PrintTechniques(std::ostream& out);

// The usage text.
const char* RenderUsage();

// The label of the main technique in the timing: its name, and its settings
// as in --time-also (csm:cascades=2,map_resolution=1024) when it has any.
std::string MainTimingLabel(const RenderOptions& options);

#endif
