// harness_util.h - small helpers of vtkshadow-compare: processes with a
// time-out, files, hashing, PNG reading of renderer output.
#ifndef VTKSHADOW_HARNESS_UTIL_H
#define VTKSHADOW_HARNESS_UTIL_H

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

// Reads stdout of a short command (e.g. "povray --version"), first line
// matching `contains` (or the first non-empty line). Empty on failure.
std::string CommandVersion(
  const std::vector<std::string>& argv, const std::string& contains, double timeout_s);

bool ReadFile(const std::string& path, std::string& out);
bool WriteFileAtomic(const std::string& path, const std::string& data, std::string& err);
bool CopyFileAtomic(const std::string& from, const std::string& to, std::string& err);
bool MakeDirs(const std::string& path);
// The same, with the reason of a failure (e.g. "Read-only file system").
bool MakeDirs(const std::string& path, std::string& why);
// Whether a file can be created in `dir` (writes and removes a probe file):
// finds a read-only or full folder before any work is done.
bool CanWriteIn(const std::string& dir, std::string& why);
void RemoveTree(const std::string& path);
bool FileExists(const std::string& path);
std::string DirName(const std::string& path);
std::string AbsPath(const std::string& path);

// Hex MD5 of a string (vtksys).
std::string MD5Hex(const std::string& data);

// A 16-bit (or 8-bit) PNG as floats in [0,1], first channel, row 0 on top.
bool ReadPNGChannel(
  const std::string& path, std::vector<float>& v, int& w, int& h, std::string& err);

std::string HtmlEscape(const std::string& s);
std::string JsonEscape(const std::string& s);
std::string Fmt(double v, const char* fmt = "%.17g");

// One progress line on stderr ("vtkshadow-compare: msg"), whole lines even
// when scenes run in parallel.
void Progress(const std::string& msg);

} // namespace vsh_harness

#endif
