#pragma once
// Runs a program with an argument vector (posix_spawnp, no shell, so file
// names are never parsed as shell syntax) and collects its output.
#include <cstddef>
#include <string>
#include <vector>

namespace render {

struct ProcessResult {
  bool started = false;     // false: the program could not be run at all
  std::string spawn_error;  // why, when !started
  int exit_code = -1;       // valid when started and signal == 0
  int signal = 0;           // terminating signal, 0 if it exited
  std::string output;       // stdout + stderr interleaved, last keep_bytes
  bool ok() const { return started && signal == 0 && exit_code == 0; }
  // "exit status 1", "killed by signal 9" or the spawn error.
  std::string status_text() const;
};

// stdin is /dev/null. Keeps the last keep_bytes of the combined output.
ProcessResult run_process(const std::vector<std::string>& argv,
                          std::size_t keep_bytes = 8192);

}  // namespace render
