#include "render_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace
{
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

// A number as JSON: non-finite values (a ratio to a zero time) as null.
std::string Number(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

std::string NumberList(const std::vector<double>& values)
{
  std::string out = "[";
  for (size_t i = 0; i < values.size(); ++i)
  {
    out += (i ? ", " : "") + Number(values[i]);
  }
  return out + "]";
}

std::string Times(const vsh_timing_stats& s)
{
  return "{\"median\": " + Number(s.median) + ", \"min\": " + Number(s.min) +
    ", \"max\": " + Number(s.max) + ", \"q1\": " + Number(s.q1) + ", \"q3\": " + Number(s.q3) + "}";
}

const char* BalanceName(int balance)
{
  return balance == 2 ? "whole cycles: every technique in every position and after every other "
                        "equally often"
    : balance == 1    ? "mirrored: every technique's mean position is the middle"
                      : "unbalanced: an odd number of rounds shorter than a cycle";
}

std::string StagesJson(const std::vector<std::pair<std::string, double>>& stages)
{
  std::string out = "{";
  for (size_t i = 0; i < stages.size(); ++i)
  {
    out += (i ? ", " : "") + Quoted(stages[i].first) + ": " + Number(stages[i].second);
  }
  return out + "}";
}

std::string EntryJson(const TimedEntry& entry)
{
  std::ostringstream out;
  out << "      {\"label\": " << Quoted(entry.Label)
      << ", \"technique\": " << Quoted(entry.Technique) << ", \"settings\": {";
  for (size_t i = 0; i < entry.Settings.size(); ++i)
  {
    out << (i ? ", " : "") << Quoted(entry.Settings[i].first) << ": "
        << Number(entry.Settings[i].second);
  }
  const vsh_timing_stats& s = entry.Stats;
  out << "},\n       \"ms\": " << Times(s)
      << ",\n       \"ratio_to_none\": {\"median\": " << Number(s.ratio)
      << ", \"min\": " << Number(s.ratio_min) << ", \"max\": " << Number(s.ratio_max)
      << "},\n       \"round_medians_ms\": " << NumberList(entry.RoundMedians)
      << ",\n       \"shadow_map_bytes\": " << entry.MemoryBytes
      << ", \"pixels_changed_after_timing\": " << entry.ChangedPixels
      << ",\n       \"technique_stats\": " << entry.Details;
  if (!entry.Stages.empty())
  {
    // Medians of the profiled frames (vtkShadowStageProfile.h): proportions,
    // not the timed frame (each stage ends with a glFinish).
    out << ",\n       \"profiled_frame_ms\": " << Number(entry.ProfiledFrameMs)
        << ", \"stages_ms\": " << StagesJson(entry.Stages)
        << ",\n       \"stages_cpu_ms\": " << StagesJson(entry.CPUStages)
        << ",\n       \"profiled_frames_ms\": " << NumberList(entry.ProfiledFramesMs)
        << ", \"profiled_stage_sums_ms\": " << NumberList(entry.ProfiledStageSumsMs);
  }
  out << "}";
  return out.str();
}

std::string ScheduleJson(const TimingRun& run)
{
  std::ostringstream out;
  out << "[";
  for (size_t r = 0; r < run.Schedule.size(); ++r)
  {
    out << (r ? ",\n      [" : "\n      [");
    for (size_t p = 0; p < run.Schedule[r].size(); ++p)
    {
      out << (p ? ", " : "") << Quoted(run.Entries[run.Schedule[r][p]].Label);
    }
    out << "]";
  }
  return out.str() + "]";
}

std::string NoiseJson(const TimingRun& run)
{
  const TimedEntry& floor = run.Entries[run.NoiseFloor];
  return "{\"label\": " + Quoted(floor.Label + " / none") +
    ", \"ratio\": " + Number(floor.Stats.ratio) + ", \"min\": " + Number(floor.Stats.ratio_min) +
    ", \"max\": " + Number(floor.Stats.ratio_max) +
    ", \"tolerance\": " + Number(run.NoiseTolerance) +
    ", \"too_noisy\": " + (run.TooNoisy ? "true" : "false") + "}";
}
}

std::string StatsJson(const StatsHeader& header, const TimingRun& run)
{
  const TimedEntry& main = run.Entries[header.Main];
  const TimedEntry& none = run.Entries[run.Reference];
  std::ostringstream out;
  out << "{\n"
      << "  \"scene\": " << Quoted(header.Scene) << ",\n"
      << "  \"technique\": " << Quoted(header.Technique) << ",\n"
      << "  \"size\": [" << header.Width << ", " << header.Height << "],\n"
      << "  \"frames\": " << run.Frames << ",\n"
      << "  \"rounds\": " << run.Rounds << ",\n"
      << "  \"warmup_frames\": " << run.Warmup << ",\n"
      << "  \"shadowed_ms\": " << Times(main.Stats) << ",\n"
      << "  \"unshadowed_ms\": " << Times(none.Stats) << ",\n"
      << "  \"overhead_ms\": " << Number(main.Stats.median - none.Stats.median) << ",\n"
      << "  \"ratio\": " << Number(main.Stats.ratio) << ",\n"
      << "  \"noise_floor\": " << NoiseJson(run) << ",\n"
      << "  \"shadow_map_bytes\": " << main.MemoryBytes << ",\n"
      << "  \"technique_stats\": " << main.Details << ",\n"
      << "  \"timing\": {\n"
      << "    \"method\": \"interleaved blocks in one window\",\n"
      << "    \"reference\": " << Quoted(none.Label) << ",\n"
      << "    \"main\": " << Quoted(main.Label) << ",\n"
      << "    \"balance\": " << Quoted(BalanceName(run.Balance)) << ",\n"
      << "    \"schedule\": " << ScheduleJson(run) << ",\n"
      << "    \"entries\": [\n";
  for (size_t e = 0; e < run.Entries.size(); ++e)
  {
    out << EntryJson(run.Entries[e]) << (e + 1 < run.Entries.size() ? ",\n" : "\n");
  }
  out << "    ]\n  }\n}\n";
  return out.str();
}

std::string TimingSummary(const StatsHeader& header, const TimingRun& run)
{
  std::ostringstream out;
  char line[1024];
  std::snprintf(line, sizeof line,
    "timing: %d rounds x %d frames per technique after %d warm-up frames each, %dx%d, "
    "order rotated per round (%s)\n",
    run.Rounds, run.Frames, run.Warmup, header.Width, header.Height,
    run.Balance == 2     ? "whole cycles"
      : run.Balance == 1 ? "mirrored"
                         : "unbalanced");
  out << line;
  int width = 9; // "technique"; labels of --time-also can be long
  for (const auto& entry : run.Entries)
  {
    width = std::max(width, static_cast<int>(std::min<size_t>(entry.Label.size(), 200)));
  }
  std::snprintf(line, sizeof line, "  %-*s %10s %21s %8s %17s\n", width, "technique", "median ms",
    "rounds min-max ms", "x none", "rounds min-max");
  out << line;
  for (const auto& entry : run.Entries)
  {
    const vsh_timing_stats& s = entry.Stats;
    std::snprintf(line, sizeof line, "  %-*s %10.2f %10.2f-%-10.2f %8.3f %8.3f-%-8.3f\n", width,
      entry.Label.c_str(), s.median, s.min, s.max, s.ratio, s.ratio_min, s.ratio_max);
    out << line;
  }
  if (run.ProfileFrames > 0)
  {
    out << "stage profile (" << run.ProfileFrames
        << " frames each, glFinish after every stage; medians, wall/CPU ms):\n";
    for (const auto& entry : run.Entries)
    {
      std::snprintf(
        line, sizeof line, "  %-*s %8.2f =", width, entry.Label.c_str(), entry.ProfiledFrameMs);
      out << line;
      for (size_t i = 0; i < entry.Stages.size(); ++i)
      {
        // wall / CPU ms (CPU: every thread of the process)
        const double cpu = i < entry.CPUStages.size() ? entry.CPUStages[i].second : 0.0;
        std::snprintf(line, sizeof line, " %s %.2f/%.2f", entry.Stages[i].first.c_str(),
          entry.Stages[i].second, cpu);
        out << line;
      }
      out << "\n";
    }
  }
  const TimedEntry& floor = run.Entries[run.NoiseFloor];
  std::snprintf(line, sizeof line,
    "noise floor %s / none = %.3f (rounds %.3f-%.3f): %s 1.00 +- %.2f\n", floor.Label.c_str(),
    floor.Stats.ratio, floor.Stats.ratio_min, floor.Stats.ratio_max,
    run.TooNoisy ? "TOO NOISY, outside" : "within", run.NoiseTolerance);
  out << line;
  return out.str();
}

std::string NoiseWarning(const TimingRun& run)
{
  if (!run.TooNoisy)
  {
    return "";
  }
  const TimedEntry& floor = run.Entries[run.NoiseFloor];
  char line[400];
  std::snprintf(line, sizeof line,
    "warning: timing too noisy: %s / none = %.3f (rounds %.3f-%.3f), outside 1.00 +- %.2f; "
    "ratios are not reliable to better than that (more --rounds, a quieter machine)",
    floor.Label.c_str(), floor.Stats.ratio, floor.Stats.ratio_min, floor.Stats.ratio_max,
    run.NoiseTolerance);
  return line;
}
