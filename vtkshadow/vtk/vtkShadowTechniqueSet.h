// vtkShadowTechniqueSet.h - which techniques vtkAutoShadowPass chose, as a
// set of bits; names only for display. No VTK: unit-tested on its own.
#ifndef vtkShadowTechniqueSet_h
#define vtkShadowTechniqueSet_h

#include "vsh_auto.h"

namespace vtkshadow
{
/**
 * A set of techniques (the core's VSH_AUTO_* values): one light's choice is
 * a single member or None, a frame's choice the union over its lights.
 */
enum class TechniqueSet : unsigned
{
  None = VSH_AUTO_NONE,
  Planar = VSH_AUTO_PLANAR,
  Cascaded = VSH_AUTO_CSM,
  Volume = VSH_AUTO_VOLUME,
  RayTraced = VSH_AUTO_RAYTRACE
};

constexpr TechniqueSet operator|(TechniqueSet a, TechniqueSet b)
{
  return static_cast<TechniqueSet>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}

constexpr TechniqueSet operator&(TechniqueSet a, TechniqueSet b)
{
  return static_cast<TechniqueSet>(static_cast<unsigned>(a) & static_cast<unsigned>(b));
}

inline TechniqueSet& operator|=(TechniqueSet& a, TechniqueSet b)
{
  return a = a | b;
}

/**
 * Whether `set` holds every technique of `members` (and members is not None).
 */
constexpr bool Has(TechniqueSet set, TechniqueSet members)
{
  return members != TechniqueSet::None && (set & members) == members;
}

/**
 * The frame's set from the per-light masks of vsh_auto_light_masks.
 */
constexpr TechniqueSet FromLightMasks(
  unsigned int planar, unsigned int cascaded, unsigned int volume = 0, unsigned int rayTraced = 0)
{
  return (planar ? TechniqueSet::Planar : TechniqueSet::None) |
    (cascaded ? TechniqueSet::Cascaded : TechniqueSet::None) |
    (volume ? TechniqueSet::Volume : TechniqueSet::None) |
    (rayTraced ? TechniqueSet::RayTraced : TechniqueSet::None);
}

/**
 * The display name: the members' technique names joined by '+' in the
 * order planar, csm, volume, raytrace ("none", "planar", "csm",
 * "planar+csm", "raytrace", "csm+raytrace", ...): what
 * vtkAutoShadowPass::GetChoice and --stats print.
 */
inline const char* TechniqueSetName(TechniqueSet set)
{
  static const char* const names[16] = { "none", "planar", "csm", "planar+csm", "volume",
    "planar+volume", "csm+volume", "planar+csm+volume", "raytrace", "planar+raytrace",
    "csm+raytrace", "planar+csm+raytrace", "volume+raytrace", "planar+volume+raytrace",
    "csm+volume+raytrace", "planar+csm+volume+raytrace" };
  return names[static_cast<unsigned>(set) & 15u];
}
}

#endif
