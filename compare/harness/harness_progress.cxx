// harness_progress.cxx - progress lines, one at a time (harness_progress.h).
#include "harness_progress.h"

#include <cstdio>
#include <mutex>

namespace vsh_harness
{

namespace
{
std::mutex g_progress_mutex;
}

void Progress(const std::string& msg)
{
  std::lock_guard<std::mutex> lock(g_progress_mutex);
  fprintf(stderr, "vtkshadow-compare: %s\n", msg.c_str());
  fflush(stderr);
}

} // namespace vsh_harness
