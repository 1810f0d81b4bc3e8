#include "vtkShadowStageProfile.h"

#include "vtk_glew.h"

#include <chrono>
#include <ctime>

namespace
{
// Process-wide: a profile follows one frame through every pass that draws it
// (auto's chain, a mirror's worlds), which own no common object.
struct StageProfile
{
  bool On = false;
  std::chrono::steady_clock::time_point Last;
  double LastCPU = 0.0; // ms of process CPU time
  std::vector<std::pair<std::string, double>> Stages;
  std::vector<std::pair<std::string, double>> CPUStages;
};

// Process CPU time in ms (every thread).
double ProcessCPUMilliseconds()
{
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

void Add(std::vector<std::pair<std::string, double>>& stages, const char* stage, double ms)
{
  for (auto& entry : stages)
  {
    if (entry.first == stage)
    {
      entry.second += ms;
      return;
    }
  }
  stages.emplace_back(stage, ms);
}

StageProfile& Profile()
{
  static StageProfile profile;
  return profile;
}
}

namespace vtkshadow
{
void SetStageProfiling(bool on)
{
  Profile().On = on;
}

bool GetStageProfiling()
{
  return Profile().On;
}

void BeginStageFrame()
{
  StageProfile& p = Profile();
  if (p.On)
  {
    glFinish();
  }
  p.Stages.clear();
  p.CPUStages.clear();
  p.Last = std::chrono::steady_clock::now();
  p.LastCPU = ProcessCPUMilliseconds();
}

void MarkStage(const char* stage)
{
  StageProfile& p = Profile();
  if (!p.On || !stage)
  {
    return;
  }
  glFinish();
  const auto now = std::chrono::steady_clock::now();
  const double cpu = ProcessCPUMilliseconds();
  Add(p.Stages, stage, std::chrono::duration<double, std::milli>(now - p.Last).count());
  Add(p.CPUStages, stage, cpu - p.LastCPU);
  p.Last = now;
  p.LastCPU = cpu;
}

std::vector<std::pair<std::string, double>> GetStageTimes()
{
  return Profile().Stages;
}

std::vector<std::pair<std::string, double>> GetStageCPUTimes()
{
  return Profile().CPUStages;
}
}
