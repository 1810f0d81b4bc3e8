// reference_cache.cxx - reference cache entries with a verified manifest.
#include "reference_cache.h"

#include "harness_files.h"
#include "visibility_io.h"

#include <map>
#include <sstream>
#include <vector>

namespace vsh_harness
{

namespace
{
const char* const kManifestHeader = "vtkshadow-compare cache entry 2";

// name -> MD5 from the `complete` file; false when it is not a manifest.
bool ReadManifest(const std::string& path, std::map<std::string, std::string>& md5)
{
  std::string text;
  if (!ReadFile(path, text))
    return false;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kManifestHeader)
    return false;
  std::string sum, name;
  while (in >> sum >> name)
    md5[name] = sum;
  return true;
}
} // namespace

CacheLoadResult CacheLoad(const std::string& cdir, const std::string& outdir, int lights,
  bool tinted, std::string& why, bool read_only)
{
  const std::string marker = cdir + "/complete";
  if (!FileExists(marker))
    return CacheLoadResult::Miss;
  std::map<std::string, std::string> md5;
  std::vector<std::pair<std::string, std::string>> files; // name, bytes
  bool good = ReadManifest(marker, md5);
  if (!good)
    why = marker + ": not a cache manifest";
  for (int k = 0; k < lights && good; ++k)
    for (const std::string& name : LightFileNames(k, tinted))
    {
      std::string bytes;
      if (!ReadFile(cdir + "/" + name, bytes) || !md5.count(name) || MD5Hex(bytes) != md5[name])
      {
        why = cdir + "/" + name + ": missing or does not match the entry's manifest";
        good = false;
        break;
      }
      files.emplace_back(name, bytes);
    }
  if (!good)
  {
    if (!read_only)
      RemoveTree(cdir);
    return CacheLoadResult::Corrupt;
  }
  for (const auto& f : files)
    if (!WriteFileAtomic(outdir + "/" + f.first, f.second, why))
    {
      RemoveLightFiles(outdir, lights);
      return CacheLoadResult::Failed;
    }
  return CacheLoadResult::Hit;
}

bool CacheStore(const std::string& cdir, const std::string& outdir, int lights, bool tinted,
  const std::string& keytext, std::string& why)
{
  if (!MakeDirs(cdir, why))
  {
    why = cdir + ": " + why;
    return false;
  }
  std::string manifest = std::string(kManifestHeader) + "\n";
  for (int k = 0; k < lights; ++k)
    for (const std::string& name : LightFileNames(k, tinted))
    {
      std::string bytes;
      if (!ReadFile(outdir + "/" + name, bytes))
      {
        why = outdir + "/" + name + ": cannot read";
        return false;
      }
      if (!WriteFileAtomic(cdir + "/" + name, bytes, why))
        return false;
      manifest += MD5Hex(bytes) + " " + name + "\n";
    }
  return WriteFileAtomic(cdir + "/key.txt", keytext, why) &&
    WriteFileAtomic(cdir + "/complete", manifest, why); // last: marks the entry usable
}

} // namespace vsh_harness
