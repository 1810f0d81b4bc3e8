// harness_png.cxx - one channel of a PNG as floats (harness_png.h).
#include "harness_png.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace vsh_harness
{

bool ReadPNGChannel(
  const std::string& path, std::vector<float>& v, int& w, int& h, std::string& err, int channel)
{
  FILE* f = fopen(path.c_str(), "rb");
  if (!f)
  {
    err = path + ": cannot open (" + strerror(errno) + ")";
    return false;
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info)
  {
    fclose(f);
    err = path + ": out of memory";
    return false;
  }
  if (setjmp(png_jmpbuf(png)))
  {
    png_destroy_read_struct(&png, &info, nullptr);
    fclose(f);
    err = path + ": corrupt PNG";
    return false;
  }
  png_init_io(png, f);
  png_set_user_limits(png, 16384, 16384);
  png_read_png(png, info, PNG_TRANSFORM_PACKING | PNG_TRANSFORM_EXPAND, nullptr);
  w = png_get_image_width(png, info);
  h = png_get_image_height(png, info);
  int depth = png_get_bit_depth(png, info);
  int channels = png_get_channels(png, info);
  png_bytepp rows = png_get_rows(png, info);
  if (channel < 0 || channel >= channels)
  {
    png_destroy_read_struct(&png, &info, nullptr);
    fclose(f);
    err = path + ": no channel " + std::to_string(channel);
    return false;
  }
  v.assign(static_cast<size_t>(w) * h, 0.0f);
  const double maxv = depth == 16 ? 65535.0 : 255.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const size_t i = static_cast<size_t>(channels) * x + channel;
      unsigned s = depth == 16 ? (unsigned(rows[y][2 * i]) << 8) | rows[y][2 * i + 1] : rows[y][i];
      v[static_cast<size_t>(y) * w + x] = static_cast<float>(s / maxv);
    }
  png_destroy_read_struct(&png, &info, nullptr);
  fclose(f);
  return true;
}

} // namespace vsh_harness
