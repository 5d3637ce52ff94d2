// Progress of a long run: a redrawn bar on a terminal, a plain line every few
// seconds otherwise (logs, CI). Writes to stderr so stdout stays clean.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "sim/scene/scenario.hpp"

namespace app {

class Progress {
 public:
  Progress();
  // The run's stages, so that the line shows an ETA: the wall time per
  // simulated second of the stage so far, times the simulated time left in
  // it and the timed stages after it ("ETA <=" where one may end at rest).
  void set_stages(const std::vector<sim::StageSpec>& stages);
  // Reports stage time t of duration, steps taken; prints at most ~10 times a
  // second on a terminal and every 5 s otherwise.
  void update(const std::string& stage, double t, double duration, long steps);
  // Ends the current bar line (a stage finished), with a closing message.
  void finish(const std::string& message);

 private:
  bool terminal_;
  bool open_line_ = false;
  std::string eta(double t, double duration, double wall) const;

  std::chrono::steady_clock::time_point stage_start_, last_print_;
  std::string stage_;
  double stage_t0_ = 0;  // stage time of the first report of this stage (resumed: > 0)
  std::vector<sim::StageSpec> stages_;
};

}  // namespace app
