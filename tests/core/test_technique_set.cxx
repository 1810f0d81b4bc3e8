// test_technique_set.cxx - vtkshadow::TechniqueSet: the bit operators, the
// membership test, the set from light masks and the display names (which
// --stats and GetChoice() print, so they must not change).
#include "vsh_check.h"
#include "vtkShadowTechniqueSet.h"

#include <cstring>
#include <string>

using vtkshadow::TechniqueSet;

int main()
{
  const TechniqueSet both = TechniqueSet::Planar | TechniqueSet::Cascaded;
  CHECK(static_cast<unsigned>(both) == 3u);
  CHECK((both & TechniqueSet::Planar) == TechniqueSet::Planar);
  CHECK((TechniqueSet::Planar & TechniqueSet::Cascaded) == TechniqueSet::None);
  TechniqueSet set = TechniqueSet::None;
  set |= TechniqueSet::Cascaded;
  CHECK(set == TechniqueSet::Cascaded);
  CHECK(vtkshadow::Has(both, TechniqueSet::Planar));
  CHECK(vtkshadow::Has(both, TechniqueSet::Cascaded));
  CHECK(vtkshadow::Has(both, both));
  CHECK(!vtkshadow::Has(set, TechniqueSet::Planar));
  CHECK(!vtkshadow::Has(set, both));
  CHECK(!vtkshadow::Has(both, TechniqueSet::None));
  CHECK(!vtkshadow::Has(TechniqueSet::None, TechniqueSet::None));
  // The core's per-light technique values are the set's members.
  CHECK(static_cast<TechniqueSet>(VSH_AUTO_PLANAR) == TechniqueSet::Planar);
  CHECK(static_cast<TechniqueSet>(VSH_AUTO_CSM) == TechniqueSet::Cascaded);
  CHECK(static_cast<TechniqueSet>(VSH_AUTO_NONE) == TechniqueSet::None);
  CHECK(vtkshadow::FromLightMasks(0, 0) == TechniqueSet::None);
  CHECK(vtkshadow::FromLightMasks(9, 0) == TechniqueSet::Planar);
  CHECK(vtkshadow::FromLightMasks(0, 0x80000000u) == TechniqueSet::Cascaded);
  CHECK(vtkshadow::FromLightMasks(1, 2) == both);
  CHECK(std::strcmp(vtkshadow::TechniqueSetName(TechniqueSet::None), "none") == 0);
  CHECK(std::strcmp(vtkshadow::TechniqueSetName(TechniqueSet::Planar), "planar") == 0);
  CHECK(std::strcmp(vtkshadow::TechniqueSetName(TechniqueSet::Cascaded), "csm") == 0);
  CHECK(std::strcmp(vtkshadow::TechniqueSetName(both), "planar+csm") == 0);
  // The exact techniques and every combination's name, built independently.
  CHECK(static_cast<TechniqueSet>(VSH_AUTO_VOLUME) == TechniqueSet::Volume);
  CHECK(static_cast<TechniqueSet>(VSH_AUTO_RAYTRACE) == TechniqueSet::RayTraced);
  CHECK(vtkshadow::FromLightMasks(0, 0, 0, 4) == TechniqueSet::RayTraced);
  CHECK(vtkshadow::FromLightMasks(1, 0, 2, 4) ==
    (TechniqueSet::Planar | TechniqueSet::Volume | TechniqueSet::RayTraced));
  const char* const members[4] = { "planar", "csm", "volume", "raytrace" };
  for (unsigned bits = 0; bits < 16; ++bits)
  {
    std::string expected;
    for (int m = 0; m < 4; ++m)
    {
      if (bits & (1u << m))
      {
        expected += (expected.empty() ? "" : "+") + std::string(members[m]);
      }
    }
    if (expected.empty())
    {
      expected = "none";
    }
    CHECK(expected == vtkshadow::TechniqueSetName(static_cast<TechniqueSet>(bits)));
  }
  return vsh_check_report("core.technique_set");
}
