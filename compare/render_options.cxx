#include "render_options.h"

#include "vtkNew.h"
#include "vtkShadowTechnique.h"
#include "vtkShadowTechniqueRegistry.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace
{
// Strict integer parse: the whole string, in range.
bool ParseInt(const char* text, long low, long high, int& out)
{
  if (!text || !*text)
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (errno != 0 || *end != '\0' || value < low || value > high)
  {
    return false;
  }
  out = static_cast<int>(value);
  return true;
}
}

void PrintTechniques(std::ostream& out)
{
  for (int i = 0; i < vtkShadowTechniqueRegistry::GetNumberOfTechniques(); ++i)
  {
    out << vtkShadowTechniqueRegistry::GetName(i) << "\t"
        << vtkShadowTechniqueRegistry::GetDescription(i) << "\n";
  }
}

const char* RenderUsage()
{
  return "usage: vtkshadow-render SCENE --technique T --image OUT.png\n"
         "       vtkshadow-render --list-techniques\n"
         "         [--visibility V.png] [--mask M.png] [--light K] [--stats S.json]\n"
         "         [--frames N] [--map-resolution R] [--size WxH] [--set KEY=VALUE]...\n"
         "         [--max-error E | --max-error Npx] [--reflections auto|on|off|no-shadows]\n"
         "         [--matte] [--image-light K] [--quiet]\n"
         "\n"
         "Render SCENE (a vtkshadow scene file) with shadow technique T.\n"
         "  --technique T        one of the known techniques (required)\n"
         "  --image OUT.png      colour image with every light (required)\n"
         "  --visibility V.png   16-bit visibility of light K (65535 lit, 0 blocked)\n"
         "  --mask M.png         8-bit mask, 255 where light K reaches a visible surface\n"
         "  --light K            light index for --visibility and --mask (default 0)\n"
         "  --stats S.json       timings over --frames frames and shadow-map memory\n"
         "  --frames N           timed frames after warm-up (default 30)\n"
         "  --map-resolution R   shadow-map size for map techniques (default 2048)\n"
         "  --size WxH           override the scene's image size\n"
         "  --set KEY=VALUE      a technique setting, e.g. cascades=4, filter=1,\n"
         "                       bias_scale=0.5 (see docs/cascaded-shadow-maps.md)\n"
         "  --max-error E        auto only: the error target, wrong_pct E (percent of\n"
         "                       the pixels, default 0.5), or Npx: an on-screen\n"
         "                       shadow-map texel size of N pixels\n"
         "  --reflections R      planar mirrors (\"mirror\": R on planes): auto (default, on\n"
         "                       when the scene has mirrors), on, off, or no-shadows\n"
         "                       (reflections drawn without the technique's shadows)\n"
         "  --matte              colour image shaded as the ray tracers do (diffuse 1,\n"
         "                       no ambient, no specular)\n"
         "  --image-light K      colour image with light K only (default every light)\n"
         "  --quiet              no progress output\n"
         "  --list-techniques    print each technique with its description and exit\n"
         "Exit status: 0 success, 1 rendering failure, 2 bad input.\n";
}

namespace
{
// What the checks after parsing need to know about the command line.
struct ParseState
{
  bool TechniqueGiven = false;
  bool MaxErrorGiven = false;
};

// --size WxH.
int ParseSize(const char* v, RenderOptions& options, std::string& error)
{
  const char* x = std::strchr(v, 'x');
  const std::string w = x ? std::string(v, x) : "";
  if (!x || !ParseInt(w.c_str(), 1, 16384, options.Width) ||
    !ParseInt(x + 1, 1, 16384, options.Height))
  {
    error = std::string("--size: expected WxH with 1..16384 each (got \"") + v + "\")";
    return 2;
  }
  return 0;
}

// --set KEY=NUMBER (the key is checked against the technique later).
int ParseSetting(const char* v, RenderOptions& options, std::string& error)
{
  const char* eq = std::strchr(v, '=');
  char* end = nullptr;
  const double number = eq ? std::strtod(eq + 1, &end) : 0.0;
  if (!eq || eq == v || !end || end == eq + 1 || *end != '\0' || !std::isfinite(number))
  {
    error = std::string("--set: expected KEY=NUMBER (got \"") + v + "\")";
    return 2;
  }
  options.Settings.emplace_back(std::string(v, eq), number);
  return 0;
}

// --max-error E (a wrong_pct) or Npx (a texel size): auto's error target.
int ParseMaxError(const char* v, RenderOptions& options, std::string& error)
{
  char* end = nullptr;
  const double number = std::strtod(v, &end);
  const bool pixels = end && std::strcmp(end, "px") == 0;
  if (end == v || !end || (*end != '\0' && !pixels) || !std::isfinite(number) || number < 0.0 ||
    (!pixels && number > 100.0) || (pixels && number <= 0.0))
  {
    error = std::string("--max-error: expected a wrong_pct in [0, 100] or a texel size "
                        "such as 2px (got \"") +
      v + "\")";
    return 2;
  }
  options.Settings.emplace_back(pixels ? "max_texel_px" : "max_error", number);
  return 0;
}

// --light, --frames, --map-resolution: integers in their ranges.
int ParseIntegerOption(
  const std::string& arg, const char* v, RenderOptions& options, std::string& error)
{
  int* target = arg == "--light" ? &options.Light
    : arg == "--frames"          ? &options.Frames
                                 : &options.MapResolution;
  const long low = arg == "--light" ? 0 : arg == "--frames" ? 1 : 16;
  const long high = arg == "--light" ? 1000000 : arg == "--frames" ? 100000 : 16384;
  if (!ParseInt(v, low, high, *target))
  {
    error = arg + ": expected an integer in [" + std::to_string(low) + ", " + std::to_string(high) +
      "] (got \"" + v + "\")";
    return 2;
  }
  return 0;
}

// An option that takes a value `v`: 0, 2 on bad input, 1 when `arg` is not
// such an option.
int ParseValueOption(const std::string& arg, const char* v, RenderOptions& options,
  ParseState& state, std::string& error)
{
  if (arg == "--technique")
  {
    options.Technique = v;
    state.TechniqueGiven = true;
    return 0;
  }
  if (arg == "--image" || arg == "--visibility" || arg == "--mask" || arg == "--stats")
  {
    if (!*v)
    {
      error = arg + ": empty path";
      return 2;
    }
    std::string& target = arg == "--image" ? options.Image
      : arg == "--visibility"              ? options.Visibility
      : arg == "--mask"                    ? options.Mask
                                           : options.Stats;
    target = v;
    return 0;
  }
  if (arg == "--light" || arg == "--frames" || arg == "--map-resolution")
  {
    return ParseIntegerOption(arg, v, options, error);
  }
  if (arg == "--size")
  {
    return ParseSize(v, options, error);
  }
  if (arg == "--reflections")
  {
    const std::string r = v;
    if (r != "auto" && r != "on" && r != "off" && r != "no-shadows")
    {
      error = "--reflections: expected auto, on, off or no-shadows (got \"" + r + "\")";
      return 2;
    }
    options.Reflections = r;
    return 0;
  }
  if (arg == "--image-light")
  {
    char* end = nullptr;
    errno = 0;
    const long k = std::strtol(v, &end, 10);
    if (!*v || *end || errno || k < 0 || k > 1000000)
    {
      error = std::string("--image-light: expected a light index >= 0 (got \"") + v + "\")";
      return 2;
    }
    options.ImageLight = static_cast<int>(k);
    return 0;
  }
  if (arg == "--set")
  {
    return ParseSetting(v, options, error);
  }
  if (arg == "--max-error")
  {
    state.MaxErrorGiven = true;
    return ParseMaxError(v, options, error);
  }
  return 1;
}

bool TakesValue(const std::string& arg)
{
  static const char* const withValue[] = { "--technique", "--image", "--visibility", "--mask",
    "--stats", "--light", "--frames", "--map-resolution", "--size", "--set", "--max-error",
    "--reflections", "--image-light" };
  for (const char* name : withValue)
  {
    if (arg == name)
    {
      return true;
    }
  }
  return false;
}

// The whole command line is consistent: scene, technique and its settings,
// image.
int CheckRenderOptions(const RenderOptions& options, const ParseState& state, std::string& error)
{
  if (options.Scene.empty())
  {
    error = "missing SCENE";
    return 2;
  }
  if (!state.TechniqueGiven)
  {
    error =
      "missing --technique (known: " + std::string(vtkShadowTechnique::GetKnownTechniques()) + ")";
    return 2;
  }
  if (!vtkShadowTechnique::IsKnownTechnique(options.Technique.c_str()))
  {
    error = "--technique: unknown technique \"" + options.Technique +
      "\" (known: " + vtkShadowTechnique::GetKnownTechniques() + ")";
    return 2;
  }
  if (state.MaxErrorGiven && options.Technique != "auto")
  {
    error = "--max-error: only --technique auto chooses by an error target (got --technique " +
      options.Technique + "; for csm use --set max_texel_px=N)";
    return 2;
  }
  vtkNew<vtkShadowTechnique> probe;
  probe->SetName(options.Technique.c_str());
  for (const auto& setting : options.Settings)
  {
    if (!probe->SetOption(setting.first.c_str(), setting.second))
    {
      error = "--set: technique " + options.Technique + " has no setting \"" + setting.first +
        "\" or the value is out of range (got \"" + setting.first + "=" +
        std::to_string(setting.second) + "\"; see docs/techniques.md)";
      return 2;
    }
  }
  if (options.Image.empty())
  {
    error = "missing --image OUT.png";
    return 2;
  }
  return 0;
}
}

int ParseRenderOptions(int argc, char* argv[], RenderOptions& options, std::string& error)
{
  ParseState state;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      std::cout << RenderUsage();
      return -1;
    }
    if (arg == "--list-techniques")
    {
      PrintTechniques(std::cout);
      return -1;
    }
    if (TakesValue(arg))
    {
      if (i + 1 >= argc)
      {
        error = arg + ": missing value";
        return 2;
      }
      if (ParseValueOption(arg, argv[++i], options, state, error) != 0)
      {
        return 2;
      }
    }
    else if (arg == "--quiet")
    {
      options.Quiet = true;
    }
    else if (arg == "--matte")
    {
      options.Matte = true;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      error = "unknown option \"" + arg + "\"";
      return 2;
    }
    else if (options.Scene.empty())
    {
      options.Scene = arg;
    }
    else
    {
      error = "unexpected argument \"" + arg + "\" (one scene per run)";
      return 2;
    }
  }
  return CheckRenderOptions(options, state, error);
}
