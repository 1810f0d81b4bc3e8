// render_stats.h - the --stats JSON document and the timing summary text of
// vtkshadow-render, from an interleaved timing run (render_timing.h).
#ifndef vtkshadow_render_stats_h
#define vtkshadow_render_stats_h

#include "render_timing.h"

#include <string>

// What the document says besides the timing run.
struct StatsHeader
{
  std::string Scene;
  std::string Technique; // the main technique's name
  int Width = 0;
  int Height = 0;
  int Main = 0; // the main technique's entry
};

// The stats JSON document. The top-level shadowed_ms / unshadowed_ms /
// ratio / shadow_map_bytes / technique_stats are those of the main entry
// and of none; "timing" holds every entry, the schedule and the noise floor.
std::string StatsJson(const StatsHeader& header, const TimingRun& run);

// A table of the entries for people: median ms, spread over rounds, ratio
// to none, and the noise-floor line.
std::string TimingSummary(const StatsHeader& header, const TimingRun& run);

// The warning when the run is too noisy (empty otherwise).
std::string NoiseWarning(const TimingRun& run);

#endif
