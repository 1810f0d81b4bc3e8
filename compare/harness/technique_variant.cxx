// technique_variant.cxx - NAME:KEY=VALUE entries of --techniques.
#include "technique_variant.h"

#include "vtkShadowTechnique.h"

#include <vtkNew.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace vsh_harness
{

namespace
{
std::vector<std::string> SplitColons(const std::string& s)
{
  std::vector<std::string> parts;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ':'))
    parts.push_back(item);
  if (!s.empty() && s.back() == ':')
    parts.emplace_back(); // a trailing ':' is an empty (malformed) pair
  return parts;
}

// Keys as the passes spell them: letters, digits and '_'. Anything else
// would also end up in folder names and in thresholds.json.
bool GoodKey(const std::string& k)
{
  return !k.empty() &&
    std::all_of(k.begin(), k.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// One KEY=VALUE; false with `why` set when it is malformed.
bool ParsePair(
  const std::string& pair, std::string& key, std::string& value, double& number, std::string& why)
{
  const size_t eq = pair.find('=');
  key = pair.substr(0, eq == std::string::npos ? pair.size() : eq);
  value = eq == std::string::npos ? "" : pair.substr(eq + 1);
  char* end = nullptr;
  number = value.empty() ? 0.0 : std::strtod(value.c_str(), &end);
  if (eq == std::string::npos || !GoodKey(key))
    why = "expected KEY=NUMBER with a key of letters, digits and '_' (got '" + pair + "')";
  else if (value.empty() || *end || !std::isfinite(number) || std::isspace((unsigned char)value[0]))
    why = "the value of " + key + " is not a number (got '" + value + "')";
  return why.empty();
}
} // namespace

bool ParseTechniqueVariant(const std::string& text, TechniqueVariant& v, std::string& error)
{
  const std::string where = "--techniques: '" + text + "': ";
  const std::vector<std::string> parts = SplitColons(text);
  v = TechniqueVariant();
  v.text = text;
  v.technique = parts.empty() ? "" : parts[0];
  if (!vtkShadowTechnique::IsKnownTechnique(v.technique.c_str()))
  {
    error = where + "unknown technique '" + v.technique +
      "' (known: " + vtkShadowTechnique::GetKnownTechniques() + ")";
    return false;
  }
  // The same check as vtkshadow-render's --set, so that a bad setting is an
  // exit-2 usage error here, before anything is rendered.
  vtkNew<vtkShadowTechnique> probe;
  probe->SetName(v.technique.c_str());
  for (size_t i = 1; i < parts.size(); ++i)
  {
    std::string key, value, why;
    double number = 0;
    if (!ParsePair(parts[i], key, value, number, why))
      error = where + why;
    else if (std::any_of(v.settings.begin(), v.settings.end(),
               [&](const std::pair<std::string, std::string>& s) { return s.first == key; }))
      error = where + "the setting " + key + " is given twice";
    else if (!probe->SetOption(key.c_str(), number))
      error = where + "technique " + v.technique + " has no setting '" + key +
        "' or the value is out of range (got " + key + "=" + value + "; see docs/techniques.md)";
    if (!error.empty())
      return false;
    v.settings.emplace_back(key, value);
  }
  return true;
}

std::vector<std::string> RenderArguments(const std::string& text)
{
  TechniqueVariant v;
  std::string error;
  if (!ParseTechniqueVariant(text, v, error))
    v.technique = text; // not reached: the options were checked while parsing
  std::vector<std::string> args{ "--technique", v.technique };
  for (const auto& s : v.settings)
  {
    args.push_back("--set");
    args.push_back(s.first + "=" + s.second);
  }
  return args;
}

} // namespace vsh_harness
