// technique_variant.h - a technique with settings as --techniques names it:
// NAME or NAME:KEY=VALUE[:KEY=VALUE...] (docs/harness.md, "Technique
// variants"). The full text names its rows (vtk/volume:soft_samples=64),
// its output folder and its limits in thresholds.json; each KEY=VALUE goes
// to vtkshadow-render as --set KEY=VALUE.
#ifndef VTKSHADOW_TECHNIQUE_VARIANT_H
#define VTKSHADOW_TECHNIQUE_VARIANT_H

#include <string>
#include <utility>
#include <vector>

namespace vsh_harness
{

struct TechniqueVariant
{
  std::string text;                                          // as given: volume:soft_samples=64
  std::string technique;                                     // volume
  std::vector<std::pair<std::string, std::string>> settings; // {soft_samples, 64}, as given
};

// Parses and checks one --techniques entry against the technique registry:
// a known technique, KEY=NUMBER pairs, each key once, and each setting one
// the technique takes (vtkShadowTechnique::SetOption, the check
// vtkshadow-render's --set makes). False: `error` names --techniques, the
// entry and what is wrong.
bool ParseTechniqueVariant(const std::string& text, TechniqueVariant& v, std::string& error);

// The vtkshadow-render arguments of an entry checked by
// ParseTechniqueVariant: --technique NAME [--set KEY=VALUE]...
std::vector<std::string> RenderArguments(const std::string& text);

} // namespace vsh_harness

#endif
