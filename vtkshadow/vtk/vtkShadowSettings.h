/**
 * @file   vtkShadowSettings.h
 * @brief  The one declarative table of a technique's settings.
 *
 * Each pass declares its settings once, as rows of key, range, integer or
 * not, one line of documentation and how to set and get the member. From
 * the rows come vtkShadowPassBase::SetOption (validate, then set), the
 * settings lines of PrintSelf, vtkShadowTechnique's validation (without
 * building a pass), `vtkshadow-render --list-settings` and, from that
 * listing, the settings table of docs/techniques.md
 * (scripts/settings-table.py). Adding a setting is one row.
 *
 * @code{.cpp}
 * using vtkshadow::Integers;
 * vtkshadow::Row("cascades", Integers(0, 8), &vtkCascadedShadowMapPass::SetCascadeCount,
 *   &vtkCascadedShadowMapPass::GetCascadeCount, "cascades per directional light, 0 = auto")
 * @endcode
 */
#ifndef vtkShadowSettings_h
#define vtkShadowSettings_h

#include "vtkshadowModule.h" // for export macro

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkShadowPassBase;

namespace vtkshadow
{
/**
 * The values a setting takes: [Min, Max], each end open or closed, all
 * reals or integers only. Built with Closed, Integers, Flag or Open*.
 */
struct SettingRange
{
  double Min;
  double Max;
  bool MinOpen;
  bool MaxOpen;
  bool Integer;
};

inline SettingRange Closed(double lo, double hi)
{
  return { lo, hi, false, false, false };
}
inline SettingRange Integers(double lo, double hi)
{
  return { lo, hi, false, false, true };
}
inline SettingRange Flag()
{
  return Integers(0, 1);
}
// Shadow map edge in texels: every technique takes it (vtkShadowTechnique).
inline SettingRange MapResolutionRange()
{
  return Integers(16, 16384);
}
inline SettingRange OpenAbove(double lo, double hi) // (lo, hi]
{
  return { lo, hi, true, false, false };
}
inline SettingRange OpenBelow(double lo, double hi) // [lo, hi)
{
  return { lo, hi, false, true, false };
}
inline SettingRange Open(double lo, double hi) // (lo, hi)
{
  return { lo, hi, true, true, false };
}

/**
 * One row. Set and Get receive the pass the table belongs to (the class
 * that declared the row, or a subclass); Get may be empty (a key taken and
 * unused, such as map_resolution for techniques without maps).
 */
struct VTKSHADOW_EXPORT Setting
{
  std::string Key;
  SettingRange Range;
  std::string Doc;
  std::function<void(vtkShadowPassBase&, double)> Set;
  std::function<double(vtkShadowPassBase&)> Get;

  /**
   * True when `value` is in the range (never for NaN or, unless an end is
   * infinite and closed, for infinities).
   */
  bool Accepts(double value) const;

  /**
   * The range as text: "[16, 16384]", "(0, 1]", "[0, inf)".
   */
  std::string RangeText() const;
};

/**
 * A table: rows in the order they are listed. Keys are unique.
 */
class VTKSHADOW_EXPORT Settings
{
public:
  Settings() = default;
  /**
   * The base table's rows first, then `rows` (a row with a key the base
   * has replaces it in place).
   */
  Settings(const Settings* base, std::vector<Setting> rows);

  const std::vector<Setting>& GetRows() const { return this->Rows; }
  const Setting* Find(const char* key) const;

  /**
   * Validate and set: false, changing nothing, for an unknown key or a
   * value out of range.
   */
  bool Apply(vtkShadowPassBase& pass, const char* key, double value) const;

  /**
   * The settings of technique `name` (vtkShadowTechniqueRegistry), found
   * without making a pass: its pass's table plus map_resolution, which
   * every technique takes (vtkShadowTechnique::SetOption). nullptr for an
   * unknown technique.
   */
  static const Settings* ForTechnique(const char* name);

private:
  std::vector<Setting> Rows;
};

/**
 * A shortest text for a number that reads back the same ("0.03", "1e+06",
 * "inf").
 */
VTKSHADOW_EXPORT std::string FormatNumber(double value);

/**
 * A row from a pass's setter and getter (any member function types whose
 * values convert to and from double: int, bool, double, long long).
 */
template <class PS, class T, class PG, class G>
Setting Row(
  std::string key, SettingRange range, void (PS::*set)(T), G (PG::*get)(), std::string doc)
{
  // A class's table is only ever applied to that class: static_cast is safe.
  return { std::move(key), range, std::move(doc),
    [set](vtkShadowPassBase& p, double v) { (static_cast<PS&>(p).*set)(static_cast<T>(v)); },
    [get](vtkShadowPassBase& p) { return static_cast<double>((static_cast<PG&>(p).*get)()); } };
}
}

#endif
// VTK-HeaderTest-Exclude: vtkShadowSettings.h
