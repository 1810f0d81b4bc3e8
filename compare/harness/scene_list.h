// scene_list.h - the scenes of a vtkshadow-compare run: files found under
// the inputs, each with its id, output folder name and thresholds file.
#ifndef VTKSHADOW_SCENE_LIST_H
#define VTKSHADOW_SCENE_LIST_H

#include <string>
#include <vector>

namespace vsh_harness
{

struct SceneEntry
{
  std::string path;       // as found
  std::string id;         // e.g. "basic/sphere-plane" (relative to the thresholds folder)
  std::string dir_id;     // "basic-sphere-plane": folder name under OUT
  std::string thresholds; // thresholds.json governing it ("" if none)
};

// `id` made a file name: '/' -> '-', anything unusual -> '_'.
std::string SafeName(const std::string& id);

// The scenes named by `inputs` (files, or folders searched for *.json except
// thresholds.json, known-failures.json, meshes/ and references/), in a
// stable order.
// False with `error` when an input does not exist.
bool ListScenes(const std::vector<std::string>& inputs, const std::string& thresholds_option,
  std::vector<SceneEntry>& scenes, std::string& error);

} // namespace vsh_harness

#endif
