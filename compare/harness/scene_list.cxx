// scene_list.cxx - finding the scenes of a run and naming them.
#include "scene_list.h"

#include "harness_files.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <set>

namespace vsh_harness
{

std::string SafeName(const std::string& id)
{
  std::string r;
  for (char c : id)
    r += (c == '/')                                                                  ? '-'
      : (isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c
                                                                                     : '_';
  return r;
}

namespace
{

bool EndsWith(const std::string& s, const std::string& tail)
{
  return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string FindThresholds(const std::string& scene_abs)
{
  std::string dir = DirName(scene_abs);
  while (!dir.empty())
  {
    std::string cand = dir + "/thresholds.json";
    if (FileExists(cand))
      return cand;
    std::string parent = DirName(dir);
    if (parent == dir || parent.empty())
      break;
    dir = parent;
  }
  return "";
}

void CollectScenes(const std::string& input, std::vector<std::string>& out)
{
  if (!vtksys::SystemTools::FileIsDirectory(input))
  {
    out.push_back(input);
    return;
  }
  vtksys::Directory d;
  d.Load(input);
  std::vector<std::string> names;
  for (unsigned long i = 0; i < d.GetNumberOfFiles(); ++i)
    names.push_back(d.GetFile(i));
  std::sort(names.begin(), names.end());
  for (const auto& n : names)
  {
    if (n == "." || n == ".." || n == "meshes" || n == "references" || n == "thresholds.json" ||
      n == "known-failures.json")
      continue;
    std::string p = input + "/" + n;
    if (vtksys::SystemTools::FileIsDirectory(p))
      CollectScenes(p, out);
    else if (EndsWith(n, ".json"))
      out.push_back(p);
  }
}

} // namespace

bool ListScenes(const std::vector<std::string>& inputs, const std::string& thresholds_option,
  std::vector<SceneEntry>& scenes, std::string& error)
{
  std::vector<std::string> files;
  for (const auto& in : inputs)
  {
    if (!FileExists(in))
    {
      error = in + ": no such file or folder";
      return false;
    }
    CollectScenes(in, files);
  }
  std::set<std::string> used;
  for (const auto& f : files)
  {
    SceneEntry e;
    e.path = f;
    const std::string abs = AbsPath(f);
    e.thresholds = thresholds_option.empty() ? FindThresholds(abs) : AbsPath(thresholds_option);
    const std::string base = e.thresholds.empty() ? DirName(abs) : DirName(e.thresholds);
    std::string rel = abs.rfind(base + "/", 0) == 0 ? abs.substr(base.size() + 1)
                                                    : vtksys::SystemTools::GetFilenameName(abs);
    if (EndsWith(rel, ".json"))
      rel.resize(rel.size() - 5);
    e.id = rel;
    e.dir_id = SafeName(rel);
    while (used.count(e.dir_id))
      e.dir_id += "_";
    used.insert(e.dir_id);
    scenes.push_back(e);
  }
  return true;
}

} // namespace vsh_harness
