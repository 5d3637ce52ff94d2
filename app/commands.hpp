// The subcommands of `landslide`. Each returns the process exit status:
// 0 done, 2 bad input (nothing written), 1 the run failed.
#pragma once

#include <string>

namespace app {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

struct RunOptions {
  std::string scenario;
  std::string out_dir;
  int threads = 0;  // 0: OpenMP's default
};

int run_command(const RunOptions& options);
int check_command(const std::string& scenario);

}  // namespace app
