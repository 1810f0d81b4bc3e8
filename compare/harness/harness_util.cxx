#include "harness_util.h"

#include <vtksys/MD5.h>
#include <vtksys/SystemTools.hxx>

#include <png.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <mutex>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace vsh_harness
{

RunResult RunProcess(const std::vector<std::string>& argv, const std::string& cwd,
  const std::string& log, double timeout_s)
{
  RunResult r;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<char*> cargv;
  for (const auto& a : argv)
    cargv.push_back(const_cast<char*>(a.c_str()));
  cargv.push_back(nullptr);
  int errpipe[2];
  if (pipe2(errpipe, O_CLOEXEC) != 0)
  {
    r.error = std::string("pipe: ") + strerror(errno);
    return r;
  }
  pid_t pid = fork();
  if (pid < 0)
  {
    r.error = std::string("fork: ") + strerror(errno);
    close(errpipe[0]);
    close(errpipe[1]);
    return r;
  }
  if (pid == 0)
  {
    setpgid(0, 0);
    close(errpipe[0]);
    int e = 0;
    if (!cwd.empty() && chdir(cwd.c_str()) != 0)
      e = errno;
    if (!e)
    {
      int fd = open(log.empty() ? "/dev/null" : log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
      int in = open("/dev/null", O_RDONLY);
      if (fd >= 0)
      {
        dup2(fd, 1);
        dup2(fd, 2);
      }
      if (in >= 0)
        dup2(in, 0);
      execvp(cargv[0], cargv.data());
      e = errno;
    }
    ssize_t n = write(errpipe[1], &e, sizeof e);
    (void)n;
    _exit(127);
  }
  setpgid(pid, pid);
  close(errpipe[1]);
  int exec_errno = 0;
  ssize_t n = read(errpipe[0], &exec_errno, sizeof exec_errno);
  close(errpipe[0]);
  if (n == (ssize_t)sizeof exec_errno)
  {
    int st;
    waitpid(pid, &st, 0);
    r.error = "cannot run " + argv[0] + ": " + strerror(exec_errno);
    return r;
  }
  r.started = true;
  int status = 0;
  for (;;)
  {
    pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid)
      break;
    if (w < 0 && errno != EINTR)
    {
      r.error = std::string("waitpid: ") + strerror(errno);
      return r;
    }
    double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (timeout_s > 0 && el > timeout_s)
    {
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (r.timed_out)
  {
    char buf[64];
    snprintf(buf, sizeof buf, "%g", timeout_s);
    r.error = argv[0] + " timed out after " + buf + " s (killed)";
  }
  else if (WIFEXITED(status))
  {
    r.exit_code = WEXITSTATUS(status);
    if (r.exit_code != 0)
      r.error = argv[0] + " failed with exit status " + std::to_string(r.exit_code);
  }
  else if (WIFSIGNALED(status))
  {
    r.signal = WTERMSIG(status);
    r.error =
      argv[0] + " crashed (signal " + std::to_string(r.signal) + ", " + strsignal(r.signal) + ")";
  }
  if (!r.error.empty() && !log.empty())
    r.error += "; log: " + log;
  return r;
}

std::string CommandVersion(
  const std::vector<std::string>& argv, const std::string& contains, double timeout_s)
{
  char tmpl[] = "/tmp/vshversionXXXXXX";
  int fd = mkstemp(tmpl);
  if (fd < 0)
    return "";
  close(fd);
  RunResult r = RunProcess(argv, "", tmpl, timeout_s);
  std::string text;
  ReadFile(tmpl, text);
  unlink(tmpl);
  if (!r.started || r.timed_out || r.signal)
    return "";
  std::istringstream in(text);
  std::string line, first;
  while (std::getline(in, line))
  {
    if (line.empty())
      continue;
    if (first.empty())
      first = line;
    if (!contains.empty() && line.find(contains) != std::string::npos)
      return line;
  }
  return contains.empty() ? first : "";
}

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

bool CopyFileAtomic(const std::string& from, const std::string& to, std::string& err)
{
  std::string data;
  if (!ReadFile(from, data))
  {
    err = from + ": cannot read";
    return false;
  }
  return WriteFileAtomic(to, data, err);
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

bool ReadPNGChannel(
  const std::string& path, std::vector<float>& v, int& w, int& h, std::string& err)
{
  FILE* f = fopen(path.c_str(), "rb");
  if (!f)
  {
    err = path + ": cannot open (" + strerror(errno) + ")";
    return false;
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info)
  {
    fclose(f);
    err = path + ": out of memory";
    return false;
  }
  if (setjmp(png_jmpbuf(png)))
  {
    png_destroy_read_struct(&png, &info, nullptr);
    fclose(f);
    err = path + ": corrupt PNG";
    return false;
  }
  png_init_io(png, f);
  png_set_user_limits(png, 16384, 16384);
  png_read_png(png, info, PNG_TRANSFORM_PACKING | PNG_TRANSFORM_EXPAND, nullptr);
  w = png_get_image_width(png, info);
  h = png_get_image_height(png, info);
  int depth = png_get_bit_depth(png, info);
  int channels = png_get_channels(png, info);
  png_bytepp rows = png_get_rows(png, info);
  v.assign(static_cast<size_t>(w) * h, 0.0f);
  const double maxv = depth == 16 ? 65535.0 : 255.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      unsigned s = depth == 16
        ? (unsigned(rows[y][2 * channels * x]) << 8) | rows[y][2 * channels * x + 1]
        : rows[y][channels * x];
      v[static_cast<size_t>(y) * w + x] = static_cast<float>(s / maxv);
    }
  png_destroy_read_struct(&png, &info, nullptr);
  fclose(f);
  return true;
}

std::string HtmlEscape(const std::string& s)
{
  std::string o;
  for (char c : s)
  {
    switch (c)
    {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&#39;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

std::string JsonEscape(const std::string& s)
{
  std::string o;
  for (unsigned char c : s)
  {
    if (c == '"' || c == '\\')
    {
      o += '\\';
      o += static_cast<char>(c);
    }
    else if (c < 0x20)
    {
      char buf[8];
      snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
    }
    else
      o += static_cast<char>(c);
  }
  return o;
}

namespace
{
std::mutex g_progress_mutex;
}

void Progress(const std::string& msg)
{
  std::lock_guard<std::mutex> lock(g_progress_mutex);
  fprintf(stderr, "vtkshadow-compare: %s\n", msg.c_str());
  fflush(stderr);
}

std::string Fmt(double v, const char* fmt)
{
  char buf[64];
  snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

} // namespace vsh_harness
