// harness_process.cxx - child processes with a time-out (harness_process.h).
#include "harness_process.h"

#include "harness_files.h"
#include "harness_progress.h"
#include "harness_text.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sstream>
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

RunResult RunLogged(const std::string& label, const std::vector<std::string>& argv,
  const std::string& cwd, const std::string& log, double timeout_s)
{
  RunResult r = RunProcess(argv, cwd, log, timeout_s);
  Progress(label + (r.ok() ? "" : " FAILED") + " (" + Fmt(r.seconds, "%.1f") + " s)");
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

} // namespace vsh_harness
