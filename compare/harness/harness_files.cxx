// harness_files.cxx - files, folders, paths and MD5 (harness_files.h).
#include "harness_files.h"

#include <vtksys/MD5.h>
#include <vtksys/SystemTools.hxx>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace vsh_harness
{

bool ReadFile(const std::string& path, std::string& out)
{
  std::ifstream f(path, std::ios::binary);
  if (!f)
    return false;
  std::ostringstream ss;
  ss << f.rdbuf();
  out = ss.str();
  return true;
}

bool WriteFileAtomic(const std::string& path, const std::string& data, std::string& err)
{
  // Temporary name in the same folder, then rename: a reader (or a later
  // run) sees the old file or the whole new one, never a part.
  std::string tmp = path + ".tmp" + std::to_string(getpid()) + "_" +
    std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()) % 100000);
  FILE* f = fopen(tmp.c_str(), "wb");
  if (!f)
  {
    err = path + ": cannot create (" + strerror(errno) + ")";
    return false;
  }
  int e = 0;
  if (fwrite(data.data(), 1, data.size(), f) != data.size())
    e = errno;
  if (fflush(f) != 0 && !e)
    e = errno;
  if (fclose(f) != 0 && !e)
    e = errno;
  if (!e && rename(tmp.c_str(), path.c_str()) != 0)
    e = errno;
  if (e)
  {
    err = path + ": cannot write (" + strerror(e) + ")";
    unlink(tmp.c_str());
    return false;
  }
  return true;
}

bool MakeDirs(const std::string& path)
{
  return vtksys::SystemTools::MakeDirectory(path).IsSuccess();
}

bool MakeDirs(const std::string& path, std::string& why)
{
  vtksys::Status st = vtksys::SystemTools::MakeDirectory(path);
  if (st.IsSuccess())
    return true;
  why = st.GetString();
  return false;
}

bool MakeWorkDir(
  const std::string& dir, const std::string& name, const std::string& data, std::string& err)
{
  RemoveTree(dir);
  return MakeDirs(dir, err) && WriteFileAtomic(dir + "/" + name, data, err);
}

bool CanWriteIn(const std::string& dir, std::string& why)
{
  // One byte is enough to find ENOSPC on a full file system (a new file
  // needs a block) and EROFS / EACCES on a read-only one.
  std::string err;
  const std::string probe = dir + "/.vtkshadow-compare-probe";
  if (!WriteFileAtomic(probe, "x", err))
  {
    why = err;
    return false;
  }
  unlink(probe.c_str());
  return true;
}

void RemoveTree(const std::string& path)
{
  vtksys::SystemTools::RemoveADirectory(path);
}

bool FileExists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

std::string DirName(const std::string& path)
{
  return vtksys::SystemTools::GetFilenamePath(path);
}

std::string AbsPath(const std::string& path)
{
  return vtksys::SystemTools::CollapseFullPath(path);
}

std::string MD5Hex(const std::string& data)
{
  vtksysMD5* md5 = vtksysMD5_New();
  vtksysMD5_Initialize(md5);
  vtksysMD5_Append(
    md5, reinterpret_cast<const unsigned char*>(data.data()), static_cast<int>(data.size()));
  char hex[33];
  vtksysMD5_FinalizeHex(md5, hex);
  hex[32] = 0;
  vtksysMD5_Delete(md5);
  return hex;
}

} // namespace vsh_harness
