// render_timing.h - interleaved frame timing of several techniques in one
// window (vtkshadow-render --stats): the schedule and the statistics are
// tools/timing/vsh_timing.h; this file renders the frames.
#ifndef vtkshadow_render_timing_h
#define vtkshadow_render_timing_h

#include "vsh_timing.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLRenderer;
class vtkRenderWindow;
class vtkShadowPassBase;
class vtkShadowScene;

// One timed technique. The pass lives for the whole run and is switched in
// and out of the renderer, so its caches behave as in an application that
// keeps it.
struct TimedEntry
{
  std::string Label;     // "none", "none#2", "csm:cascades=2", ...
  std::string Technique; // registry name
  std::vector<std::pair<std::string, double>> Settings;
  vtkSmartPointer<vtkShadowPassBase> Pass;
  // Filled by RunInterleavedTiming:
  std::vector<double> Times;        // rounds x frames, round-major, ms
  std::vector<double> RoundMedians; // per round, ms
  vsh_timing_stats Stats = {};
  long long MemoryBytes = 0;
  std::string Details; // the pass's GetStatsJSON after the run
  // With TimingRun::ProfileFrames > 0: each stage's median over the profiled
  // frames (ms, in the order first marked) and the profiled frames' median.
  std::vector<std::pair<std::string, double>> Stages;
  std::vector<std::pair<std::string, double>> CPUStages; // process CPU ms (all threads)
  double ProfiledFrameMs = 0.0;
  // Per profiled frame: its wall time and the sum of its stages. They agree
  // frame by frame; the medians above need not add up (a stall lands in a
  // different stage in each frame, and each stage's median drops it).
  std::vector<double> ProfiledFramesMs;
  std::vector<double> ProfiledStageSumsMs;
  long long ChangedPixels = 0; // scene-camera image after the run vs before
};

struct TimingRun
{
  int Rounds = 4;
  int Frames = 15;
  int Warmup = 5;
  int ProfileFrames = 0; // frames per entry with the stage profile, after the rounds
  double NoiseTolerance = 0.03;
  int Reference = 0;  // the index of "none"
  int NoiseFloor = 1; // the index of "none#2"
  std::vector<TimedEntry> Entries;
  std::vector<std::vector<int>> Schedule; // per round, the entry order
  int Balance = 0;                        // vsh_timing_balance
  bool TooNoisy = false;
};

// Render the schedule: each entry's warm-up frames, then per round one block
// of Frames frames per entry in the round's order, the camera on
// vtkShadowPassBase's orbit (the same frames for every entry). Fills the
// entries' times and statistics and the noise verdict. The renderer's pass
// is the first entry's afterwards. Returns false (with `error`) when the
// statistics cannot be computed (a broken clock).
bool RunInterleavedTiming(vtkRenderWindow* window, vtkOpenGLRenderer* renderer,
  const vtkShadowScene* scene, TimingRun& run, std::string& error);

// Free the GL objects of every entry's pass while the context exists.
void ReleaseTimingPasses(vtkRenderWindow* window, TimingRun& run);

#endif
