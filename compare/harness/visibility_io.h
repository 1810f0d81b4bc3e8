// visibility_io.h - per-light visibility and mask files of one renderer
// (light<K>_visibility.png 16-bit, light<K>_mask.png 8-bit, row 0 on top;
// tinted scenes also light<K>_visibility_g.png and light<K>_visibility_b.png,
// the green and blue channels, light<K>_visibility.png being the red one).
#ifndef VTKSHADOW_VISIBILITY_IO_H
#define VTKSHADOW_VISIBILITY_IO_H

#include <string>
#include <vector>

namespace vsh_harness
{

// The file names of light k: "light<k>_visibility.png", "light<k>_mask.png"
// and, when `tinted`, "light<k>_visibility_g.png", "light<k>_visibility_b.png".
std::vector<std::string> LightFileNames(int k, bool tinted = false);

// The visibility file of light k in colour channel c (0 red: the one every
// metric but colour_mae reads; 1 green; 2 blue).
std::string ChannelFileName(int k, int c);

// Writes the visibility (red channel) and mask of light k in `dir`, and the
// green and blue visibility when `gb` is given (gb[0] green, gb[1] blue;
// each file atomically).
bool WriteVisibility(const std::string& dir, int k, const std::vector<float>& v,
  const std::vector<unsigned char>& mask, int w, int h, std::string& err,
  const std::vector<float>* gb = nullptr);

// Deletes every file of lights 0..lights-1 in `dir` (the channel files
// too): before a render, so a failed one never leaves an old image looking
// valid.
void RemoveLightFiles(const std::string& dir, int lights);

// Visibility from a shadows-on/off pair: v = on / off clamped to [0,1],
// mask 255 where off > eps.
void OnOff(const std::vector<float>& on, const std::vector<float>& off, double eps,
  std::vector<float>& v, std::vector<unsigned char>& mask);

} // namespace vsh_harness

#endif
