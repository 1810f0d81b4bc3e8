// visibility_io.h - per-light visibility and mask files of one renderer
// (light<K>_visibility.png 16-bit, light<K>_mask.png 8-bit, row 0 on top).
#ifndef VTKSHADOW_VISIBILITY_IO_H
#define VTKSHADOW_VISIBILITY_IO_H

#include <string>
#include <vector>

namespace vsh_harness
{

// The two file names of light k ("light<k>_visibility.png", "light<k>_mask.png").
std::vector<std::string> LightFileNames(int k);

// Writes both files of light k in `dir` (each atomically).
bool WriteVisibility(const std::string& dir, int k, const std::vector<float>& v,
  const std::vector<unsigned char>& mask, int w, int h, std::string& err);

// Deletes the files of lights 0..lights-1 in `dir`: before a render, so a
// failed one never leaves an old image looking valid.
void RemoveLightFiles(const std::string& dir, int lights);

// Visibility from a shadows-on/off pair: v = on / off clamped to [0,1],
// mask 255 where off > eps.
void OnOff(const std::vector<float>& on, const std::vector<float>& off, double eps,
  std::vector<float>& v, std::vector<unsigned char>& mask);

} // namespace vsh_harness

#endif
