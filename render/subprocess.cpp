#include "render/subprocess.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "render/error.hpp"

extern char** environ;

namespace render {

std::string ProcessResult::status_text() const {
  if (!started) return spawn_error;
  if (signal != 0) return "killed by signal " + std::to_string(signal);
  return "exit status " + std::to_string(exit_code);
}

namespace {

// Closes the descriptors it holds on every path out of run_process.
struct Fds {
  int r = -1, w = -1;
  ~Fds() {
    if (r >= 0) close(r);
    if (w >= 0) close(w);
  }
};

struct Actions {
  posix_spawn_file_actions_t fa;
  Actions() { posix_spawn_file_actions_init(&fa); }
  ~Actions() { posix_spawn_file_actions_destroy(&fa); }
};

}  // namespace

ProcessResult run_process(const std::vector<std::string>& args, std::size_t keep_bytes) {
  if (args.empty() || args[0].empty()) throw InvalidArgument("run_process: empty command");
  ProcessResult res;
  Fds fds;
  int p[2];
  // O_CLOEXEC: a process spawned by another thread must not inherit the
  // write end, or our read would wait for that process to exit too.
  if (pipe2(p, O_CLOEXEC) != 0) {
    res.spawn_error = std::string("pipe failed: ") + std::strerror(errno);
    return res;
  }
  fds.r = p[0], fds.w = p[1];
  Actions act;
  posix_spawn_file_actions_addopen(&act.fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&act.fa, fds.w, 1);
  posix_spawn_file_actions_adddup2(&act.fa, fds.w, 2);

  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int err = posix_spawnp(&pid, argv[0], &act.fa, nullptr, argv.data(), environ);
  if (err != 0) {
    res.spawn_error = "cannot run '" + args[0] + "': " + std::strerror(err);
    return res;
  }
  res.started = true;
  close(fds.w);
  fds.w = -1;

  char buf[4096];
  for (;;) {
    const ssize_t n = read(fds.r, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    res.output.append(buf, std::size_t(n));
    // Trim in chunks so long outputs cost linear time.
    if (res.output.size() > 2 * keep_bytes + sizeof buf) {
      res.output.erase(0, res.output.size() - keep_bytes);
    }
  }
  if (res.output.size() > keep_bytes) res.output.erase(0, res.output.size() - keep_bytes);

  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      res.spawn_error = std::string("waitpid failed: ") + std::strerror(errno);
      res.started = false;
      return res;
    }
  }
  if (WIFSIGNALED(status)) {
    res.signal = WTERMSIG(status);
  } else {
    res.exit_code = WEXITSTATUS(status);
  }
  return res;
}

}  // namespace render
