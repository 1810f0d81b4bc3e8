#include "render_options.h"

#include "vtkNew.h"
#include "vtkShadowTechnique.h"
#include "vtkShadowTechniqueRegistry.h"

#include <algorithm>
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
         "       vtkshadow-render --list-techniques | --list-settings\n"
         "         [--visibility V.png] [--mask M.png] [--light K] [--stats S.json]\n"
         "         [--visibility-red V.png] [--visibility-green V.png] [--visibility-blue V.png]\n"
         "         [--frames N] [--rounds R] [--warmup W] [--profile-frames P]\n"
         "         [--time-also SPEC]...\n"
         "         [--noise-tolerance T] [--fail-if-noisy]\n"
         "         [--map-resolution R] [--size WxH] [--set KEY=VALUE]...\n"
         "         [--max-error E | --max-error Npx] [--reflections auto|on|off|no-shadows]\n"
         "         [--matte] [--image-light K] [--quiet]\n"
         "\n"
         "Render SCENE (a vtkshadow scene file) with shadow technique T.\n"
         "  --technique T        one of the known techniques (required)\n"
         "  --image OUT.png      colour image with every light (required)\n"
         "  --visibility V.png   16-bit visibility of light K (65535 lit, 0 blocked)\n"
         "  --visibility-red V.png, --visibility-green V.png, --visibility-blue V.png\n"
         "                       16-bit visibility of light K in one colour channel\n"
         "                       (I_on / I_off of that channel; --visibility sums R+G+B)\n"
         "  --mask M.png         8-bit mask, 255 where light K reaches a visible surface\n"
         "  --light K            light index for --visibility and --mask (default 0)\n"
         "  --stats S.json       interleaved timing and shadow-map memory: T, none and\n"
         "                       none#2 (the noise floor) and every --time-also\n"
         "                       technique take turns in one window, a block of N\n"
         "                       frames each per round, the order rotated per round\n"
         "  --frames N           timed frames per block (default 15)\n"
         "  --rounds R           rounds (default 4)\n"
         "  --warmup W           untimed frames per technique before the rounds\n"
         "                       (default 5)\n"
         "  --profile-frames P   after the timing, P frames per technique with the\n"
         "                       stage profile on (glFinish after each stage: where\n"
         "                       the time goes, stage medians in the stats; default 0)\n"
         "  --time-also SPEC     also time SPEC = TECH[:KEY=VALUE[,KEY=VALUE]...],\n"
         "                       e.g. vtk:map_resolution=1024 or csm:cascades=2\n"
         "  --noise-tolerance T  the run is too noisy when none#2 / none is outside\n"
         "                       1 +- T (default 0.03)\n"
         "  --fail-if-noisy      exit with status 3 when the run is too noisy\n"
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
         "  --list-settings      print each technique's settings (key, range, integer,\n"
         "                       default, doc; tab-separated) and exit\n"
         "Exit status: 0 success, 1 rendering failure, 2 bad input, 3 timing too\n"
         "noisy with --fail-if-noisy (all outputs written).\n";
}

std::string MainTimingLabel(const RenderOptions& options)
{
  std::string settings;
  auto add = [&](const std::string& key, double value)
  {
    char number[64];
    std::snprintf(number, sizeof number, "%.17g", value);
    settings += (settings.empty() ? ":" : ",") + key + "=" + number;
  };
  for (const auto& setting : options.Settings)
  {
    add(setting.first, setting.second);
  }
  if (options.MapResolution != 2048)
  {
    add("map_resolution", options.MapResolution);
  }
  return options.Technique + settings;
}

namespace
{
// What the checks after parsing need to know about the command line.
struct ParseState
{
  bool TechniqueGiven = false;
  bool MaxErrorGiven = false;
  std::string TimingOption; // the first option that only --stats uses
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

// The integer options, their targets and ranges.
struct IntegerOption
{
  const char* Name;
  int RenderOptions::*Target;
  long Low, High;
  bool Timing; // used only by --stats
};
const IntegerOption IntegerOptions[] = {
  { "--light", &RenderOptions::Light, 0, 1000000, false },
  { "--frames", &RenderOptions::Frames, 1, 100000, false }, // accepted alone, as before
  { "--rounds", &RenderOptions::Rounds, 1, 1000, true },
  { "--warmup", &RenderOptions::Warmup, 0, 10000, true },
  { "--profile-frames", &RenderOptions::ProfileFrames, 0, 10000, true },
  { "--map-resolution", &RenderOptions::MapResolution, 16, 16384, false },
};

const IntegerOption* FindIntegerOption(const std::string& arg)
{
  for (const auto& option : IntegerOptions)
  {
    if (arg == option.Name)
    {
      return &option;
    }
  }
  return nullptr;
}

// --light, --frames, --rounds, --warmup, --map-resolution: integers in their
// ranges.
int ParseIntegerOption(const IntegerOption& option, const char* v, RenderOptions& options,
  ParseState& state, std::string& error)
{
  const std::string arg = option.Name;
  const long low = option.Low, high = option.High;
  if (option.Timing && state.TimingOption.empty())
  {
    state.TimingOption = arg;
  }
  if (!ParseInt(v, low, high, options.*option.Target))
  {
    error = arg + ": expected an integer in [" + std::to_string(low) + ", " + std::to_string(high) +
      "] (got \"" + v + "\")";
    return 2;
  }
  return 0;
}

// --time-also TECH[:KEY=VALUE[,KEY=VALUE]...]: the form only; the technique
// and its keys are checked with the rest of the command line.
int ParseTimedSpec(const char* v, RenderOptions& options, std::string& error)
{
  const std::string text = v;
  const size_t colon = text.find(':');
  TimedSpec spec;
  spec.Label = text;
  spec.Technique = text.substr(0, colon);
  bool ok = !spec.Technique.empty();
  std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (colon != std::string::npos && rest.empty())
  {
    ok = false;
  }
  while (ok && !rest.empty())
  {
    const size_t comma = rest.find(',');
    const std::string item = rest.substr(0, comma);
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    const size_t eq = item.find('=');
    char* end = nullptr;
    const double number = eq == std::string::npos ? 0.0 : std::strtod(item.c_str() + eq + 1, &end);
    ok = eq != std::string::npos && eq > 0 && end && end != item.c_str() + eq + 1 && *end == '\0' &&
      std::isfinite(number) && !(comma != std::string::npos && rest.empty());
    spec.Settings.emplace_back(item.substr(0, eq), number);
  }
  if (!ok)
  {
    error = "--time-also: expected TECH or TECH:KEY=NUMBER[,KEY=NUMBER]... (got \"" + text + "\")";
    return 2;
  }
  options.TimeAlso.push_back(spec);
  return 0;
}

// --noise-tolerance T: a fraction in (0, 1).
int ParseNoiseTolerance(const char* v, RenderOptions& options, std::string& error)
{
  char* end = nullptr;
  const double number = std::strtod(v, &end);
  if (end == v || !end || *end != '\0' || !std::isfinite(number) || !(number > 0.0) ||
    !(number < 1.0))
  {
    error =
      std::string("--noise-tolerance: expected a number in (0, 1), e.g. 0.03 (got \"") + v + "\")";
    return 2;
  }
  options.NoiseTolerance = number;
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
  if (arg == "--image" || arg == "--visibility" || arg == "--mask" || arg == "--stats" ||
    arg == "--visibility-red" || arg == "--visibility-green" || arg == "--visibility-blue")
  {
    if (!*v)
    {
      error = arg + ": empty path";
      return 2;
    }
    std::string& target = arg == "--image" ? options.Image
      : arg == "--visibility"              ? options.Visibility
      : arg == "--visibility-red"          ? options.ChannelVisibility[0]
      : arg == "--visibility-green"        ? options.ChannelVisibility[1]
      : arg == "--visibility-blue"         ? options.ChannelVisibility[2]
      : arg == "--mask"                    ? options.Mask
                                           : options.Stats;
    target = v;
    return 0;
  }
  if (const IntegerOption* integer = FindIntegerOption(arg))
  {
    return ParseIntegerOption(*integer, v, options, state, error);
  }
  if (arg == "--time-also" || arg == "--noise-tolerance")
  {
    state.TimingOption = state.TimingOption.empty() ? arg : state.TimingOption;
    return arg == "--time-also" ? ParseTimedSpec(v, options, error)
                                : ParseNoiseTolerance(v, options, error);
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
  static const char* const withValue[] = { "--technique", "--image", "--visibility",
    "--visibility-red", "--visibility-green", "--visibility-blue", "--mask", "--stats", "--light",
    "--frames", "--rounds", "--warmup", "--profile-frames", "--map-resolution", "--size", "--set",
    "--max-error", "--time-also", "--noise-tolerance", "--reflections", "--image-light" };
  for (const char* name : withValue)
  {
    if (arg == name)
    {
      return true;
    }
  }
  return false;
}

// --time-also: a known technique with settings it takes, each label once
// (none and none#2 are always timed).
int CheckTimedSpec(const TimedSpec& spec, const std::vector<std::string>& taken, std::string& error)
{
  const std::string prefix = "--time-also: \"" + spec.Label + "\": ";
  if (!vtkShadowTechnique::IsKnownTechnique(spec.Technique.c_str()))
  {
    error = prefix + "unknown technique \"" + spec.Technique +
      "\" (known: " + vtkShadowTechnique::GetKnownTechniques() + ")";
    return 2;
  }
  vtkNew<vtkShadowTechnique> probe;
  probe->SetName(spec.Technique.c_str());
  for (const auto& setting : spec.Settings)
  {
    if (!probe->SetOption(setting.first.c_str(), setting.second))
    {
      error = prefix + "technique " + spec.Technique + " has no setting \"" + setting.first +
        "\" or the value is out of range (see docs/techniques.md)";
      return 2;
    }
  }
  if (std::find(taken.begin(), taken.end(), spec.Label) != taken.end())
  {
    error = prefix + "timed twice (none and none#2 are always timed, and so is --technique)";
    return 2;
  }
  return 0;
}

// The timing options: only with --stats; every --time-also entry valid.
int CheckTimingOptions(const RenderOptions& options, const ParseState& state, std::string& error)
{
  if (!state.TimingOption.empty() && options.Stats.empty())
  {
    error = state.TimingOption + ": only with --stats S.json (it sets how the timing runs)";
    return 2;
  }
  std::vector<std::string> taken = { "none", "none#2", MainTimingLabel(options) };
  for (const auto& spec : options.TimeAlso)
  {
    if (CheckTimedSpec(spec, taken, error) != 0)
    {
      return 2;
    }
    taken.push_back(spec.Label);
  }
  return 0;
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
  return CheckTimingOptions(options, state, error);
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
    if (arg == "--list-settings")
    {
      std::cout << vtkShadowTechnique::GetSettingsListing();
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
    else if (arg == "--fail-if-noisy")
    {
      options.FailIfNoisy = true;
      state.TimingOption = state.TimingOption.empty() ? arg : state.TimingOption;
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
