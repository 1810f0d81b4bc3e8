// reference_cache.h - the cache of reference renders (docs/harness.md,
// "Cache"): DIR/cache/<renderer>/<key>/ holds light<K>_visibility.png,
// light<K>_mask.png (a tinted scene's also light<K>_visibility_g.png and
// light<K>_visibility_b.png), key.txt and, written last, `complete`: the manifest of
// the entry (MD5 of every image). An entry is used only when its manifest
// is there and every image matches it; anything else is a miss, and a
// damaged entry is deleted (it is rebuilt by the render that follows).
#ifndef VTKSHADOW_REFERENCE_CACHE_H
#define VTKSHADOW_REFERENCE_CACHE_H

#include <string>

namespace vsh_harness
{

enum class CacheLoadResult
{
  Miss,    // no usable entry (absent, incomplete): render
  Hit,     // the images are in the output folder
  Corrupt, // the entry was damaged (message in `why`) and is deleted (unless read-only)
  Failed   // the entry is good but the output could not be written (`why`)
};

// A damaged entry is deleted unless `read_only` (the shipped references,
// which only scripts/update-references.sh writes).
// `tinted`: the entry holds the green and blue visibility files too.
CacheLoadResult CacheLoad(const std::string& cdir, const std::string& outdir, int lights,
  bool tinted, std::string& why, bool read_only = false);

// Stores the light images of `outdir` under `cdir`. A failure (full disk)
// leaves no `complete` marker, so the entry is never used; `why` says what.
bool CacheStore(const std::string& cdir, const std::string& outdir, int lights, bool tinted,
  const std::string& keytext, std::string& why);

} // namespace vsh_harness

#endif
