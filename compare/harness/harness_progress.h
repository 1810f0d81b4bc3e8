// harness_progress.h - vtkshadow-compare's progress lines on stderr.
#ifndef VTKSHADOW_HARNESS_PROGRESS_H
#define VTKSHADOW_HARNESS_PROGRESS_H

#include <string>

namespace vsh_harness
{

// One progress line on stderr ("vtkshadow-compare: msg"), whole lines even
// when scenes run in parallel.
void Progress(const std::string& msg);

} // namespace vsh_harness

#endif
