// scene_export.h - the loaded scene turned into the renderers' numbers
// (ExportScene, harness_export.h) and the content part of the cache key.
#ifndef VTKSHADOW_SCENE_EXPORT_H
#define VTKSHADOW_SCENE_EXPORT_H

#include "harness_export.h"

#include <string>

class vtkShadowScene;
struct vsh_scene;

namespace vsh_harness
{

// MD5 of the scene file's bytes and of every mesh file's bytes, one line
// each. False with `err` when a file cannot be read.
bool ContentKey(const vsh_scene* s, const std::string& path, std::string& key, std::string& err);

// The loader's triangles (world space, per-vertex normals), camera and
// lights in the normalized frame of ExportScene, at w x h pixels.
bool BuildExport(vtkShadowScene* vs, const vsh_scene* s, int w, int h, ExportScene& ex);

} // namespace vsh_harness

#endif
