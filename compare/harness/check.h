// check.h - --check: every (scene, light, test) row bounded by the limits of
// thresholds.json or listed as a known failure (docs/harness.md, "--check,
// thresholds and known failures").
#ifndef VTKSHADOW_CHECK_H
#define VTKSHADOW_CHECK_H

#include "compare_options.h"
#include "harness_results.h"

#include <map>
#include <string>
#include <vector>

namespace vsh_harness
{

// One entry of known-failures.json: a row known to be wrong, with why, and
// bounded on both sides. It counts as still failing while any metric of
// `fails_while` is above its value; once none is, the entry must go (the
// check fails until it does). It must not get worse either: every metric of
// `at_most` is a limit like those of thresholds.json.
struct KnownFailure
{
  std::string file, scene, test, reason;
  int light = 0;
  std::map<std::string, double> fails_while, at_most;
  // Filled by the check:
  bool seen = false;          // a row of this run matched
  bool still_failing = false; // ... and is still that bad
  std::string measured;       // "wrong_pct = 95.8" of that row
  std::string worse;          // "wrong_pct = 1.6 > 1.28": the at_most it is above, if any
};

struct CheckOutcome
{
  std::vector<std::string> failures; // one line each: what, where, what to do
  int comparisons = 0;
  std::vector<KnownFailure> known; // every entry of the files read
};

// Evaluates every row of every scene against its thresholds file and known
// failures (setting Row::check) and returns what fails. The row notes are
// set even when --check is not given, so the report can show them.
CheckOutcome RunCheck(const Options& opt, std::vector<SceneResult>& results);

// The smallest limit update_thresholds.py refuses for a *_pct metric: a row
// this bad is a known failure, not a limit.
constexpr double kRefusedPctLimit = 50.0;

} // namespace vsh_harness

#endif
