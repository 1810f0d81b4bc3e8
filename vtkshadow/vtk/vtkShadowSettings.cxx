#include "vtkShadowSettings.h"
#include "vtkShadowPassBase.h"
#include "vtkShadowTechniqueRegistry.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>

namespace vtkshadow
{
//------------------------------------------------------------------------------
bool Setting::Accepts(double value) const
{
  const SettingRange& r = this->Range;
  // Written so that NaN fails every comparison and is refused.
  const bool aboveMin = r.MinOpen ? value > r.Min : value >= r.Min;
  const bool belowMax = r.MaxOpen ? value < r.Max : value <= r.Max;
  return aboveMin && belowMax && (!r.Integer || value == std::floor(value));
}

//------------------------------------------------------------------------------
std::string Setting::RangeText() const
{
  const SettingRange& r = this->Range;
  return (r.MinOpen ? "(" : "[") + FormatNumber(r.Min) + ", " + FormatNumber(r.Max) +
    (r.MaxOpen ? ")" : "]");
}

//------------------------------------------------------------------------------
std::string FormatNumber(double value)
{
  if (std::isinf(value))
  {
    return value > 0 ? "inf" : "-inf";
  }
  // Whole numbers in full (16384, 1000000), others in the fewest digits
  // that read back as the same double (tests set exactly the listed ends).
  char text[40];
  if (value == std::floor(value) && std::fabs(value) < 1e15)
  {
    std::snprintf(text, sizeof(text), "%.0f", value);
    return text;
  }
  for (int digits = 1; digits <= 17; ++digits)
  {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value)
    {
      break;
    }
  }
  return text;
}

//------------------------------------------------------------------------------
Settings::Settings(const Settings* base, std::vector<Setting> rows)
{
  if (base)
  {
    this->Rows = base->Rows;
  }
  for (Setting& row : rows)
  {
    Setting* same = nullptr;
    for (Setting& had : this->Rows)
    {
      same = had.Key == row.Key ? &had : same;
    }
    if (same)
    {
      *same = std::move(row);
    }
    else
    {
      this->Rows.push_back(std::move(row));
    }
  }
}

//------------------------------------------------------------------------------
const Setting* Settings::Find(const char* key) const
{
  for (const Setting& row : this->Rows)
  {
    if (key && row.Key == key)
    {
      return &row;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool Settings::Apply(vtkShadowPassBase& pass, const char* key, double value) const
{
  const Setting* row = this->Find(key);
  if (!row || !row->Accepts(value))
  {
    return false;
  }
  row->Set(pass, value);
  return true;
}

//------------------------------------------------------------------------------
const Settings* Settings::ForTechnique(const char* name)
{
  const int index = vtkShadowTechniqueRegistry::FindTechnique(name);
  if (index < 0)
  {
    return nullptr;
  }
  // Made on first use and kept: the tables never change.
  static std::mutex lock;
  static std::map<int, Settings> tables;
  std::lock_guard<std::mutex> guard(lock);
  auto found = tables.find(index);
  if (found == tables.end())
  {
    const Settings& pass = vtkShadowTechniqueRegistry::GetSettings(index);
    // vtkShadowTechnique keeps map_resolution itself and hands it to every
    // pass it makes; passes without maps take it and leave it unused.
    Setting unused{ "map_resolution", MapResolutionRange(),
      "shadow map edge in texels (this technique has no maps: taken, unused)",
      [](vtkShadowPassBase&, double) {}, nullptr };
    found = tables.emplace(index, Settings(&pass, {})).first;
    if (!pass.Find("map_resolution"))
    {
      found->second.Rows.push_back(std::move(unused));
    }
  }
  return &found->second;
}
}
