#include "output/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace app {

Progress::Progress() : terminal_(::isatty(STDERR_FILENO) != 0) {}

void Progress::set_stages(const std::vector<sim::StageSpec>& stages) { stages_ = stages; }

std::string Progress::eta(double t, double duration, double wall) const {
  if (!(t > stage_t0_) || wall <= 0) return "";
  double left = std::max(0.0, duration - t);
  bool may_end_early = false;
  bool after = false;
  for (const sim::StageSpec& s : stages_) {
    if (s.name == stage_) {
      after = true;
      may_end_early = s.rest.enabled;
    } else if (after && s.type != sim::StageType::MaterialChange) {
      left += s.duration;
      may_end_early = may_end_early || s.rest.enabled;
    }
  }
  const long secs = std::lround(wall / (t - stage_t0_) * left);
  char text[48];
  if (secs >= 3600)
    std::snprintf(text, sizeof text, "%ldh%02ldm", secs / 3600, secs / 60 % 60);
  else if (secs >= 60)
    std::snprintf(text, sizeof text, "%ldm%02lds", secs / 60, secs % 60);
  else
    std::snprintf(text, sizeof text, "%lds", secs);
  return std::string(may_end_early ? "ETA <= " : "ETA ") + text;
}

void Progress::update(const std::string& stage, double t, double duration, long steps) {
  const auto now = std::chrono::steady_clock::now();
  if (stage != stage_) {
    stage_ = stage;
    stage_start_ = last_print_ = now;
    stage_t0_ = t;
  }
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (terminal_ ? 0.1 : 5.0)) return;
  last_print_ = now;
  const double wall = std::chrono::duration<double>(now - stage_start_).count();
  const double rate = wall > 0 ? steps / wall : 0.0;
  const double share = duration > 0 ? t / duration : 1.0;
  const std::string left = eta(t, duration, wall);
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(share * kWidth);
    std::fprintf(stderr, "\r%-10s [", stage.c_str());
    for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : '.', stderr);
    std::fprintf(stderr, "] t = %7.3f / %.3g s  %8ld step%s  %7.0f steps/s  %-16s", t, duration,
                 steps, steps == 1 ? " " : "s", rate, left.c_str());
    open_line_ = true;
  } else {
    std::fprintf(stderr, "%s: t = %.3f / %.3g s, %ld step%s, %.0f steps/s%s%s\n", stage.c_str(),
                 t, duration, steps, steps == 1 ? "" : "s", rate, left.empty() ? "" : ", ",
                 left.c_str());
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
