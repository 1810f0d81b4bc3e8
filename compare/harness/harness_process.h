// harness_process.h - running the renderers and tools of vtkshadow-compare
// as child processes: a time-out that kills the whole process group, output
// to a log, one progress line per run.
#ifndef VTKSHADOW_HARNESS_PROCESS_H
#define VTKSHADOW_HARNESS_PROCESS_H

#include <string>
#include <vector>

namespace vsh_harness
{

struct RunResult
{
  bool started = false; // exec succeeded
  bool timed_out = false;
  int exit_code = -1; // when exited normally
  int signal = 0;     // when killed by a signal
  double seconds = 0;
  std::string error; // human-readable failure, empty on success
  bool ok() const { return error.empty(); }
};

// Runs argv[0] (looked up on PATH when it has no '/') in `cwd` with stdout and
// stderr appended to `log`. Kills the whole process group after
// `timeout_s` seconds (<= 0: no limit).
RunResult RunProcess(const std::vector<std::string>& argv, const std::string& cwd,
  const std::string& log, double timeout_s);

// RunProcess, then one progress line "LABEL (1.2 s)", or "LABEL FAILED (1.2 s)"
// when the run failed (the reason is in the result's error).
RunResult RunLogged(const std::string& label, const std::vector<std::string>& argv,
  const std::string& cwd, const std::string& log, double timeout_s);

// Reads stdout of a short command (e.g. "povray --version"), first line
// matching `contains` (or the first non-empty line). Empty on failure.
std::string CommandVersion(
  const std::vector<std::string>& argv, const std::string& contains, double timeout_s);

} // namespace vsh_harness

#endif
