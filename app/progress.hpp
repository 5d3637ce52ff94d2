// Progress of a long run: a redrawn bar on a terminal, a plain line every few
// seconds otherwise (logs, CI). Writes to stderr so stdout stays clean.
#pragma once

#include <chrono>
#include <string>

namespace app {

class Progress {
 public:
  Progress();
  // Reports stage time t of duration, steps taken; prints at most ~10 times a
  // second on a terminal and every 5 s otherwise.
  void update(const std::string& stage, double t, double duration, long steps);
  // Ends the current bar line (a stage finished), with a closing message.
  void finish(const std::string& message);

 private:
  bool terminal_;
  bool open_line_ = false;
  std::chrono::steady_clock::time_point stage_start_, last_print_;
  std::string stage_;
};

}  // namespace app
