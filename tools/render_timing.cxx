#include "render_timing.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkShadowPassBase.h"
#include "vtkShadowScene.h"
#include "vtkShadowStageProfile.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace
{
// Put the camera on frame `i` of the path: always from the scene camera, so
// the path is the same for every technique and never drifts (+-5 degrees
// azimuth, +-2 elevation around the scene camera).
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

void SceneCamera(vtkRenderer* renderer, const vtkShadowScene* scene)
{
  scene->ConfigureCamera(renderer->GetActiveCamera());
  vtkShadowScene::ResetCameraClippingRange(renderer);
}

// One frame, finished: Render() + glFinish, in milliseconds.
double TimedFrame(vtkRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(stop - start).count();
}

// The RGB pixels of a frame at the scene camera with the renderer's pass.
void SceneImage(vtkRenderWindow* window, vtkRenderer* renderer, const vtkShadowScene* scene,
  vtkUnsignedCharArray* pixels)
{
  SceneCamera(renderer, scene);
  window->Render();
  window->WaitForCompletion();
  const int* size = window->GetSize();
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels, 0);
}

long long ChangedPixels(vtkUnsignedCharArray* before, vtkUnsignedCharArray* after)
{
  const vtkIdType n = std::min(before->GetNumberOfTuples(), after->GetNumberOfTuples());
  const int c = before->GetNumberOfComponents();
  long long changed = std::llabs(static_cast<long long>(before->GetNumberOfTuples()) -
    static_cast<long long>(after->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < c; ++k)
    {
      if (before->GetValue(i * c + k) != after->GetValue(i * c + k))
      {
        ++changed;
        break;
      }
    }
  }
  return changed;
}

// Each entry once at the scene camera (the image kept for the state check),
// then its warm-up frames on the orbit: shaders compiled, maps built, caches
// filled before anything is timed.
void WarmUp(vtkRenderWindow* window, vtkOpenGLRenderer* renderer, const vtkShadowScene* scene,
  TimingRun& run, std::vector<vtkSmartPointer<vtkUnsignedCharArray>>& before)
{
  for (auto& entry : run.Entries)
  {
    renderer->SetPass(entry.Pass);
    before.push_back(vtkSmartPointer<vtkUnsignedCharArray>::New());
    SceneImage(window, renderer, scene, before.back());
    for (int i = 0; i < run.Warmup; ++i)
    {
      PlaceCamera(renderer, scene, i, run.Frames);
      window->Render();
      window->WaitForCompletion();
    }
  }
}

// After the rounds: each entry's scene-camera image against the one from
// before (a pass that picked up another's state draws differently), its
// memory and its details.
void CheckAfter(vtkRenderWindow* window, vtkOpenGLRenderer* renderer, const vtkShadowScene* scene,
  TimingRun& run, const std::vector<vtkSmartPointer<vtkUnsignedCharArray>>& before)
{
  vtkNew<vtkUnsignedCharArray> after;
  for (size_t e = 0; e < run.Entries.size(); ++e)
  {
    TimedEntry& entry = run.Entries[e];
    renderer->SetPass(entry.Pass);
    SceneImage(window, renderer, scene, after);
    entry.ChangedPixels = ChangedPixels(before[e], after);
    entry.MemoryBytes = entry.Pass->GetMemoryBytes();
    entry.Details = "{" + entry.Pass->GetStatsJSON(renderer) + "}";
  }
}

using StageList = std::vector<std::pair<std::string, double>>;

// Each stage's median over the frames, in the order first marked; a stage
// missing from a frame counts 0 there.
StageList StageMedians(const std::vector<StageList>& frames)
{
  StageList out;
  for (const auto& frame : frames)
  {
    for (const auto& stage : frame)
    {
      const bool known = std::any_of(out.begin(), out.end(),
        [&](const std::pair<std::string, double>& s) { return s.first == stage.first; });
      if (!known)
      {
        out.emplace_back(stage.first, 0.0);
      }
    }
  }
  for (auto& stage : out)
  {
    std::vector<double> values;
    for (const auto& frame : frames)
    {
      double v = 0.0;
      for (const auto& s : frame)
      {
        v += s.first == stage.first ? s.second : 0.0;
      }
      values.push_back(v);
    }
    stage.second = vsh_timing_median(values.data(), static_cast<int>(values.size()));
  }
  return out;
}

// After the rounds, ProfileFrames frames per entry with the stage profile on
// (a separate phase: its glFinish calls would distort the timed frames).
// "finish" is what follows the last pass (buffer swap, completion).
void ProfileStages(
  vtkRenderWindow* window, vtkOpenGLRenderer* renderer, const vtkShadowScene* scene, TimingRun& run)
{
  if (run.ProfileFrames <= 0)
  {
    return;
  }
  vtkshadow::SetStageProfiling(true);
  for (auto& entry : run.Entries)
  {
    renderer->SetPass(entry.Pass);
    std::vector<StageList> wall, cpu;
    std::vector<double> totals;
    entry.ProfiledStageSumsMs.clear();
    for (int f = 0; f < run.ProfileFrames; ++f)
    {
      PlaceCamera(renderer, scene, f, run.ProfileFrames);
      window->MakeCurrent();
      // The frame's clock starts before the stages' and stops after their
      // "finish": the stages never add up to more than the frame, even when
      // the process is descheduled between the two clocks.
      const auto start = std::chrono::steady_clock::now();
      vtkshadow::BeginStageFrame();
      window->Render();
      window->WaitForCompletion();
      vtkshadow::MarkStage("finish");
      totals.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
          .count());
      wall.push_back(vtkshadow::GetStageTimes());
      cpu.push_back(vtkshadow::GetStageCPUTimes());
      double sum = 0.0;
      for (const auto& stage : wall.back())
      {
        sum += stage.second;
      }
      entry.ProfiledStageSumsMs.push_back(sum);
    }
    entry.ProfiledFramesMs = totals;
    entry.Stages = StageMedians(wall);
    entry.CPUStages = StageMedians(cpu);
    entry.ProfiledFrameMs = vsh_timing_median(totals.data(), static_cast<int>(totals.size()));
  }
  vtkshadow::SetStageProfiling(false);
}
}

bool RunInterleavedTiming(vtkRenderWindow* window, vtkOpenGLRenderer* renderer,
  const vtkShadowScene* scene, TimingRun& run, std::string& error)
{
  const int n = static_cast<int>(run.Entries.size());
  std::vector<vtkSmartPointer<vtkUnsignedCharArray>> before;
  WarmUp(window, renderer, scene, run, before);
  for (auto& entry : run.Entries)
  {
    entry.Times.assign(static_cast<size_t>(run.Rounds) * run.Frames, 0.0);
  }
  run.Schedule.assign(run.Rounds, std::vector<int>(n));
  run.Balance = vsh_timing_balance(n, run.Rounds);
  for (int r = 0; r < run.Rounds; ++r)
  {
    vsh_timing_round_order(n, run.Rounds, r, run.Schedule[r].data());
    for (int e : run.Schedule[r])
    {
      TimedEntry& entry = run.Entries[e];
      renderer->SetPass(entry.Pass);
      for (int f = 0; f < run.Frames; ++f)
      {
        PlaceCamera(renderer, scene, f, run.Frames);
        entry.Times[static_cast<size_t>(r) * run.Frames + f] = TimedFrame(window);
      }
    }
  }
  CheckAfter(window, renderer, scene, run, before);
  ProfileStages(window, renderer, scene, run);
  renderer->SetPass(run.Entries.front().Pass);
  SceneCamera(renderer, scene);
  // The statistics: entry-major times, as vsh_timing_summarize takes them.
  std::vector<double> all;
  for (const auto& entry : run.Entries)
  {
    all.insert(all.end(), entry.Times.begin(), entry.Times.end());
  }
  std::vector<vsh_timing_stats> stats(n);
  if (vsh_timing_summarize(all.data(), n, run.Rounds, run.Frames, run.Reference, stats.data()) != 0)
  {
    error = "timing: a frame time was not a positive finite number (clock)";
    return false;
  }
  for (int e = 0; e < n; ++e)
  {
    TimedEntry& entry = run.Entries[e];
    entry.Stats = stats[e];
    entry.RoundMedians.clear();
    for (int r = 0; r < run.Rounds; ++r)
    {
      entry.RoundMedians.push_back(
        vsh_timing_median(entry.Times.data() + static_cast<size_t>(r) * run.Frames, run.Frames));
    }
  }
  run.TooNoisy =
    vsh_timing_too_noisy(run.Entries[run.NoiseFloor].Stats.ratio, run.NoiseTolerance) != 0;
  return true;
}

void ReleaseTimingPasses(vtkRenderWindow* window, TimingRun& run)
{
  for (auto& entry : run.Entries)
  {
    if (entry.Pass)
    {
      entry.Pass->ReleaseGraphicsResources(window);
    }
  }
}
