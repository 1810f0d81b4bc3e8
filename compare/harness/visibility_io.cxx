// visibility_io.cxx - visibility and mask files.
#include "visibility_io.h"

#include "vshm_png.h"

#include <algorithm>
#include <unistd.h>

namespace vsh_harness
{

std::vector<std::string> LightFileNames(int k)
{
  const std::string lk = "light" + std::to_string(k);
  return { lk + "_visibility.png", lk + "_mask.png" };
}

bool WriteVisibility(const std::string& dir, int k, const std::vector<float>& v,
  const std::vector<unsigned char>& mask, int w, int h, std::string& err)
{
  char e[1024] = "";
  const std::vector<std::string> names = LightFileNames(k);
  if (vshm_png_write_gray16_float((dir + "/" + names[0]).c_str(), v.data(), w, h, e, sizeof e) !=
      0 ||
    vshm_png_write_gray8((dir + "/" + names[1]).c_str(), mask.data(), w, h, e, sizeof e) != 0)
  {
    err = e;
    return false;
  }
  return true;
}

void RemoveLightFiles(const std::string& dir, int lights)
{
  for (int k = 0; k < lights; ++k)
    for (const std::string& n : LightFileNames(k))
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
