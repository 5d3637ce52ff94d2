#include "app/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace app {

Progress::Progress() : terminal_(::isatty(STDERR_FILENO) != 0) {}

void Progress::update(const std::string& stage, double t, double duration, long steps) {
  const auto now = std::chrono::steady_clock::now();
  if (stage != stage_) {
    stage_ = stage;
    stage_start_ = last_print_ = now;
  }
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (terminal_ ? 0.1 : 5.0)) return;
  last_print_ = now;
  const double wall = std::chrono::duration<double>(now - stage_start_).count();
  const double rate = wall > 0 ? steps / wall : 0.0;
  const double share = duration > 0 ? t / duration : 1.0;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(share * kWidth);
    std::fprintf(stderr, "\r%-10s [", stage.c_str());
    for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : '.', stderr);
    std::fprintf(stderr, "] t = %7.3f / %.3g s  %8ld steps  %7.0f steps/s ", t, duration, steps,
                 rate);
    open_line_ = true;
  } else {
    std::fprintf(stderr, "%s: t = %.3f / %.3g s, %ld steps, %.0f steps/s\n", stage.c_str(), t,
                 duration, steps, rate);
  }
  std::fflush(stderr);
}

void Progress::finish(const std::string& message) {
  if (open_line_) std::fputc('\n', stderr);
  open_line_ = false;
  std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
}

}  // namespace app
