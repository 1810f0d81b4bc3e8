// compare_options.cxx - command line of vtkshadow-compare.
#include "compare_options.h"

#include "harness_files.h"
#include "technique_variant.h"

#include "vtkShadowTechnique.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace vsh_harness
{

bool Options::Has(const std::string& r) const
{
  return std::find(renderers.begin(), renderers.end(), r) != renderers.end();
}

std::vector<std::string> RegisteredTechniques()
{
  // The registry's names (vtkShadowTechniqueRegistry, through
  // vtkShadowTechnique); the one place the harness asks for them.
  std::vector<std::string> r;
  std::stringstream known(vtkShadowTechnique::GetKnownTechniques());
  for (std::string t; known >> t;)
    r.push_back(t);
  return r;
}

const std::vector<std::string>& KnownRenderers()
{
  static const std::vector<std::string> r{ "vtk", "povray", "cycles", "eevee", "eevee-best" };
  return r;
}

const std::vector<std::string>& BlenderRenderers()
{
  static const std::vector<std::string> r{ "cycles", "eevee", "eevee-best" };
  return r;
}

const char* Usage()
{
  return "usage: vtkshadow-compare SCENE|DIR... --out DIR [options]\n"
         "  --renderers LIST      any of vtk,povray,cycles,eevee,eevee-best\n"
         "                        (default vtk,povray,cycles)\n"
         "  --techniques LIST     VTK techniques (default: all that vtkshadow knows); an\n"
         "                        entry NAME:KEY=VALUE[:KEY=VALUE...] is a variant, run with\n"
         "                        vtkshadow-render --set KEY=VALUE and named so in the rows\n"
         "                        (e.g. volume:soft_samples=64,raytrace:samples=256:adaptive=1);\n"
         "                        'all' stands for every technique at its defaults\n"
         "  --scale F             image size = scene size * F (default 1)\n"
         "  --check               compare with thresholds.json; exit 3 on a regression\n"
         "  --thresholds FILE     thresholds file (default: thresholds.json in the\n"
         "                        nearest folder above each scene)\n"
         "  --known-failures FILE known failures (default: known-failures.json beside\n"
         "                        the thresholds file)\n"
         "  --jobs N              scenes rendered in parallel (default 1)\n"
         "  --threads N           threads per ray-tracer render (default: cores / jobs)\n"
         "  --timeout S           per-render time limit in seconds (default 600)\n"
         "  --cache DIR           reference cache (default OUT/cache)\n"
         "  --no-cache            always render POV-Ray, Cycles and EEVEE fresh (no cache\n"
         "                        nor shipped reference read)\n"
         "  --references DIR      shipped references, read first, never written (default:\n"
         "                        references/ beside each scene's thresholds.json)\n"
         "  --no-references       do not read shipped references\n"
         "  --require-references  a reference that is not shipped is an error of its scene\n"
         "                        (naming scripts/update-references.sh), not a render\n"
         "  --cycles-samples N    Cycles samples per pixel (default 1, pixel centre)\n"
         "  --soft-samples N      Cycles samples per pixel centre for scenes with a light\n"
         "                        with a size (default 1024)\n"
         "  --povray-grid N       POV-Ray area-light grid N x N, N = 2^k+1 in 3..129 (default 17)\n"
         "  --seed N              seed of the soft-light samples, 0..2147483647 (default 0)\n"
         "  --povray-binary P     (default povray)\n"
         "  --blender-binary P    (default blender)\n"
         "  --render-binary P     vtkshadow-render (default: next to this program)\n"
         "  --cycles-script P     Blender script of Cycles and EEVEE\n"
         "                        (default: compare/blender/render_cycles.py of the source)\n"
         "  --no-report           skip index.html and the plot\n"
         "  --keep-work           keep the exported scene.pov / scene.bin (debugging, tests)\n"
         "Exit status: 0 all good, 1 a render or metric failed (other scenes go on),\n"
         "2 bad usage, 3 --check found a regression.\n";
}

std::vector<std::string> SplitList(const std::string& s)
{
  std::vector<std::string> r;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty())
      r.push_back(item);
  return r;
}

namespace
{

bool SetFlag(Options& opt, const std::string& a)
{
  if (a == "--check")
    opt.check = true;
  else if (a == "--no-cache")
    opt.no_cache = true;
  else if (a == "--no-references")
    opt.no_references = true;
  else if (a == "--require-references")
    opt.require_references = true;
  else if (a == "--no-report")
    opt.report = false;
  else if (a == "--keep-work")
    opt.keep_work = true;
  else
    return false;
  return true;
}

// The soft-light options; false when `a` is not one of them. A bad value
// sets `error`.
bool SetSoftValue(Options& opt, const std::string& a, const std::string& v, std::string& error)
{
  char* end = nullptr;
  const long n = strtol(v.c_str(), &end, 10);
  const bool whole = !v.empty() && !*end;
  if (a == "--soft-samples")
  {
    if (!whole || n < 1 || n > 65536)
      error = a + ": expected a whole number in 1..65536 (got '" + v + "')";
    else
      opt.soft_samples = int(n);
  }
  else if (a == "--povray-grid")
  {
    // 2^k + 1: the grid's edge rows then get half weight and the light's
    // width is the axis length (docs/harness.md).
    const bool pow2plus1 = whole && n >= 3 && n <= 129 && ((n - 1) & (n - 2)) == 0;
    if (!pow2plus1)
      error = a + ": expected 2^k+1 in 3..129 (3, 5, 9, 17, 33, 65, 129) (got '" + v + "')";
    else
      opt.povray_grid = int(n);
  }
  else if (a == "--seed")
  {
    if (!whole || n < 0 || n > 2147483647L)
      error = a + ": expected a whole number in 0..2147483647 (got '" + v + "')";
    else
      opt.seed = int(n);
  }
  else
    return false;
  return true;
}

// --techniques LIST, with 'all' replaced by every registered technique.
std::vector<std::string> TechniqueList(const std::string& v)
{
  std::vector<std::string> r;
  for (const std::string& t : SplitList(v))
  {
    if (t != "all")
      r.push_back(t);
    else
      for (const std::string& k : RegisteredTechniques())
        r.push_back(k);
  }
  return r;
}

// An option with a value `v`; false with `error` set when it is bad or unknown.
bool SetValue(Options& opt, const std::string& a, const std::string& v, std::string& error)
{
  std::string* text = a == "--out" ? &opt.out
    : a == "--thresholds"          ? &opt.thresholds
    : a == "--known-failures"      ? &opt.known_failures
    : a == "--cache"               ? &opt.cache
    : a == "--references"          ? &opt.references
    : a == "--povray-binary"       ? &opt.povray
    : a == "--blender-binary"      ? &opt.blender
    : a == "--render-binary"       ? &opt.render_bin
    : a == "--cycles-script"       ? &opt.cycles_script
                                   : nullptr;
  char* end = nullptr;
  if (text)
    *text = v;
  else if (a == "--renderers")
    opt.renderers = SplitList(v);
  else if (a == "--techniques")
    opt.techniques = TechniqueList(v);
  else if (a == "--scale" || a == "--timeout")
  {
    double d = strtod(v.c_str(), &end);
    if (*end || !(d > 0) || !std::isfinite(d) || (a == "--scale" && d > 16))
      error = a + ": expected a positive number (got '" + v + "')";
    else
      (a == "--scale" ? opt.scale : opt.timeout) = d;
  }
  else if (a == "--jobs" || a == "--threads" || a == "--cycles-samples")
  {
    long n = strtol(v.c_str(), &end, 10);
    if (*end || n < 1 || n > 1024)
      error = a + ": expected a whole number >= 1 (got '" + v + "')";
    else
      (a == "--jobs" ? opt.jobs : a == "--threads" ? opt.threads : opt.cycles_samples) = int(n);
  }
  else if (!SetSoftValue(opt, a, v, error))
    error = "unknown option " + a;
  return error.empty();
}

// The names given are ones the harness knows.
bool ValidateLists(const Options& opt, std::string& error)
{
  if (opt.out.empty())
    error = "missing required option --out";
  else if (opt.inputs.empty())
    error = "no scene given";
  for (const auto& r : opt.renderers)
    if (error.empty() &&
      std::find(KnownRenderers().begin(), KnownRenderers().end(), r) == KnownRenderers().end())
      error =
        "--renderers: unknown renderer '" + r + "' (known: vtk, povray, cycles, eevee, eevee-best)";
  for (auto t = opt.techniques.begin(); error.empty() && t != opt.techniques.end(); ++t)
  {
    TechniqueVariant v;
    if (!ParseTechniqueVariant(*t, v, error))
      break;
    if (std::find(opt.techniques.begin(), t, *t) != t)
      error = "--techniques: '" + *t + "' is given twice";
  }
  return error.empty();
}

std::string SelfDir()
{
  char buf[4096];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0)
    return ".";
  buf[n] = 0;
  return DirName(buf);
}

} // namespace

ParseStatus ParseOptions(int argc, char* argv[], Options& opt, std::string& error)
{
  opt.techniques = RegisteredTechniques();
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h")
      return ParseStatus::Help;
    if (SetFlag(opt, a))
      continue;
    if (a.rfind("--", 0) != 0)
    {
      opt.inputs.push_back(a);
      continue;
    }
    if (i + 1 >= argc)
    {
      error = a + ": missing value";
      return ParseStatus::Error;
    }
    if (!SetValue(opt, a, argv[++i], error))
      return ParseStatus::Error;
  }
  return ValidateLists(opt, error) ? ParseStatus::Run : ParseStatus::Error;
}

bool FinishOptions(Options& opt, std::string& error)
{
  const std::string self = SelfDir();
  if (opt.render_bin.empty())
    opt.render_bin = self + "/vtkshadow-render";
  if (opt.cycles_script.empty())
  {
#ifdef VTKSHADOW_CYCLES_SCRIPT
    opt.cycles_script = VTKSHADOW_CYCLES_SCRIPT;
#endif
    if (!FileExists(opt.cycles_script))
      opt.cycles_script = self + "/../share/vtkshadow/render_cycles.py";
  }
  opt.cycles_script = AbsPath(opt.cycles_script);
  if (opt.threads == 0)
    opt.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / opt.jobs);
  std::string why;
  if (!MakeDirs(opt.out, why))
  {
    error = "cannot create the output folder " + opt.out + ": " + why;
    return false;
  }
  opt.out = AbsPath(opt.out);
  // A read-only or full output folder is found here, before any render.
  if (!CanWriteIn(opt.out, why))
  {
    error = "cannot write in the output folder " + opt.out + ": " + why;
    return false;
  }
  if (opt.cache.empty())
    opt.cache = opt.out + "/cache";
  opt.cache = AbsPath(opt.cache);
  if (!opt.references.empty())
    opt.references = AbsPath(opt.references);
  if (opt.require_references && (opt.no_references || opt.no_cache))
  {
    error = "--require-references reads the shipped references, which --no-references and "
            "--no-cache turn off";
    return false;
  }
  return true;
}

} // namespace vsh_harness
