// compare_options.h - the command line of vtkshadow-compare (docs/harness.md).
#ifndef VTKSHADOW_COMPARE_OPTIONS_H
#define VTKSHADOW_COMPARE_OPTIONS_H

#include <string>
#include <vector>

namespace vsh_harness
{

struct Options
{
  std::vector<std::string> inputs;
  std::string out;
  std::vector<std::string> renderers{ "vtk", "povray", "cycles" };
  std::vector<std::string> techniques; // default: every registered technique
  double scale = 1.0;
  bool check = false;
  std::string thresholds;
  std::string known_failures; // default: known-failures.json beside the thresholds file
  int jobs = 1;
  int threads = 0;
  double timeout = 600;
  std::string cache;
  bool no_cache = false;
  // Shipped references (docs/harness.md, "Shipped references"): entries of
  // the cache's layout, read first and never written. Default: references/
  // beside each scene's thresholds.json. require_references makes a missing
  // one a scene error instead of a render.
  std::string references;
  bool no_references = false;
  bool require_references = false;
  int cycles_samples = 1;
  // Lights with a size (docs/harness.md, "Lights with a size"): Cycles
  // samples per pixel centre for scenes that have one, POV-Ray's area-light
  // grid (n x n, n = 2^k + 1), and the seed of both (Cycles' seed; POV-Ray's
  // grid is turned by an angle made from it, its jitter being fixed).
  int soft_samples = 1024; // noise < 1% on glyphs-soft (docs/harness.md)
  int povray_grid = 17;
  int seed = 0;
  std::string povray = "povray";
  std::string blender = "blender";
  std::string render_bin;
  std::string cycles_script;
  bool report = true;
  bool keep_work = false;

  bool Has(const std::string& renderer) const;
};

// The technique names, in registry order. The only source is the module's
// technique registry (vtkShadowTechnique); nothing here lists names.
std::vector<std::string> RegisteredTechniques();

// Every renderer --renderers accepts, and the Blender ones among them (one
// script, told which preset; each has its own folder, cache, rows and seconds).
const std::vector<std::string>& KnownRenderers();
const std::vector<std::string>& BlenderRenderers();

const char* Usage();

enum class ParseStatus
{
  Run,  // options complete, go on
  Help, // --help printed
  Error // usage error in `error`: exit 2
};

// Parses argv into `opt` (defaults filled in except paths, see FinishOptions).
ParseStatus ParseOptions(int argc, char* argv[], Options& opt, std::string& error);

// Fills in the defaults that depend on the file system (render binary,
// Blender script, threads, absolute output and cache folders) and makes
// sure the output folder exists and can be written. False: `error` says why.
bool FinishOptions(Options& opt, std::string& error);

std::vector<std::string> SplitList(const std::string& s);

} // namespace vsh_harness

#endif
