// harness_files.h - the files and folders of a vtkshadow-compare run:
// whole-file reads, atomic writes, folders, paths, and the MD5 of bytes
// that content keys are made of.
#ifndef VTKSHADOW_HARNESS_FILES_H
#define VTKSHADOW_HARNESS_FILES_H

#include <string>

namespace vsh_harness
{

bool ReadFile(const std::string& path, std::string& out);
bool WriteFileAtomic(const std::string& path, const std::string& data, std::string& err);
bool MakeDirs(const std::string& path);
// The same, with the reason of a failure (e.g. "Read-only file system").
bool MakeDirs(const std::string& path, std::string& why);
// A fresh work folder: `dir` emptied of what an earlier run left (or made)
// and holding the one file `name` with `data`, the input of a renderer.
bool MakeWorkDir(
  const std::string& dir, const std::string& name, const std::string& data, std::string& err);
// Whether a file can be created in `dir` (writes and removes a probe file):
// finds a read-only or full folder before any work is done.
bool CanWriteIn(const std::string& dir, std::string& why);
void RemoveTree(const std::string& path);
bool FileExists(const std::string& path);
std::string DirName(const std::string& path);
std::string AbsPath(const std::string& path);

// Hex MD5 of a string (vtksys): the content keys of scenes, exports and
// cache entries.
std::string MD5Hex(const std::string& data);

} // namespace vsh_harness

#endif
