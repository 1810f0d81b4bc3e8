// visibility_io.cxx - visibility and mask files.
#include "visibility_io.h"

#include "vshm_png.h"

#include <algorithm>
#include <unistd.h>

namespace vsh_harness
{

std::string ChannelFileName(int k, int c)
{
  static const char* const kSuffix[] = { "", "_g", "_b" };
  return "light" + std::to_string(k) + "_visibility" + kSuffix[c] + ".png";
}

std::vector<std::string> LightFileNames(int k, bool tinted)
{
  std::vector<std::string> names{ ChannelFileName(k, 0),
    "light" + std::to_string(k) + "_mask.png" };
  if (tinted)
    for (int c = 1; c < 3; ++c)
      names.push_back(ChannelFileName(k, c));
  return names;
}

bool WriteVisibility(const std::string& dir, int k, const std::vector<float>& v,
  const std::vector<unsigned char>& mask, int w, int h, std::string& err,
  const std::vector<float>* gb)
{
  char e[1024] = "";
  const std::vector<std::string> names = LightFileNames(k, gb != nullptr);
  bool ok =
    vshm_png_write_gray16_float((dir + "/" + names[0]).c_str(), v.data(), w, h, e, sizeof e) == 0 &&
    vshm_png_write_gray8((dir + "/" + names[1]).c_str(), mask.data(), w, h, e, sizeof e) == 0;
  for (int c = 1; ok && gb && c < 3; ++c)
    ok = vshm_png_write_gray16_float(
           (dir + "/" + names[c + 1]).c_str(), gb[c - 1].data(), w, h, e, sizeof e) == 0;
  if (!ok)
    err = e;
  return ok;
}

void RemoveLightFiles(const std::string& dir, int lights)
{
  for (int k = 0; k < lights; ++k)
    for (const std::string& n : LightFileNames(k, true))
      unlink((dir + "/" + n).c_str());
}

void OnOff(const std::vector<float>& on, const std::vector<float>& off, double eps,
  std::vector<float>& v, std::vector<unsigned char>& mask)
{
  v.assign(on.size(), 0.0f);
  mask.assign(on.size(), 0);
  for (size_t i = 0; i < on.size(); ++i)
  {
    const bool valid = off[i] > eps;
    mask[i] = valid ? 255 : 0;
    if (off[i] > 0)
      v[i] = static_cast<float>(std::min(1.0, std::max(0.0, double(on[i]) / off[i])));
  }
}

} // namespace vsh_harness
