// The real `landslide` binary in a child process, for tests of what a user
// types: its exit status and what it printed.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace apptest {

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr together
};

// Runs `landslide ARGS` in `dir` (LANDSLIDE_BINARY names the binary).
inline Result landslide(const std::string& args, const std::filesystem::path& dir) {
  const std::string command =
      "cd '" + dir.string() + "' && '" LANDSLIDE_BINARY "' " + args + " 2>&1";
  Result r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    r.output.append(buffer, n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace apptest
