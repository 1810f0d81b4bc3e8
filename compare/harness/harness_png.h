// harness_png.h - the reference renderers' own images read as numbers.
#ifndef VTKSHADOW_HARNESS_PNG_H
#define VTKSHADOW_HARNESS_PNG_H

#include <string>
#include <vector>

namespace vsh_harness
{

// A 16-bit (or 8-bit) PNG as floats in [0,1], channel `channel` (0 first),
// row 0 on top: POV-Ray's RGB output too (the metrics' reader, vshm_png.h,
// takes grayscale only, on purpose). A channel the image does not have is
// an error.
bool ReadPNGChannel(const std::string& path, std::vector<float>& v, int& w, int& h,
  std::string& err, int channel = 0);

} // namespace vsh_harness

#endif
