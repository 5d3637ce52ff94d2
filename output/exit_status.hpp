// The exit status of every `landslide` command: 0 done, 2 bad input
// (nothing written), 1 the run failed, 130 stopped by Ctrl-C and 143 by
// SIGTERM, after writing a checkpoint.
#pragma once

namespace app {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as shells report it
// 128 + SIGTERM: a job script tells "stopped by its scheduler or `timeout`"
// from Ctrl-C, and either way the checkpoint is there.
constexpr int kExitTerminated = 143;

}  // namespace app
