// What `landslide run` and `landslide resume` do while the simulation runs:
// progress lines, frames, VTK states (at stage ends, frames or an interval),
// the time series (output/series.hpp), the summary after every stage, and
// checkpoints (every so many simulated seconds, and on Ctrl-C).
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "output/checkpoint.hpp"
#include "output/frames.hpp"
#include "output/progress.hpp"
#include "output/series.hpp"
#include "render/video.hpp"
#include "sim/run/simulation.hpp"

namespace app {

// Thrown from a step once Ctrl-C was pressed (or SIGTERM came) and the
// checkpoint is written.
struct Interrupted {
  double time = 0;  // simulated time of the checkpoint
  int signal = 0;   // SIGINT or SIGTERM
  // summary.json's status: "interrupted [by SIGTERM] at t = ... s (checkpoint.lsck)".
  std::string status() const;
  // kExitInterrupted (SIGINT) or kExitTerminated (SIGTERM).
  int exit_status() const;
};

// Ctrl-C (SIGINT) or SIGTERM asks the run to stop at the end of the current
// step; a second one ends the process at once (the handler resets itself).
// The message printed says a checkpoint is written where `writes_checkpoint`.
void catch_interrupt(bool writes_checkpoint = true);
void release_interrupt();
// The signal caught since catch_interrupt() (SIGINT or SIGTERM); 0: none.
int interrupt_signal();

// Where a run comes from and what it keeps; the checkpoint stores the first
// two so a resumed run needs nothing else.
struct RunSource {
  std::string scenario_text;
  std::string scenario_file;
  double checkpoint_every = 0;  // s of simulated time; 0: only on Ctrl-C
  std::filesystem::path state_cache;  // "": no gravity-stage reuse
  std::size_t reused_stages = 0;      // stages restored from the cache
};

class RunObserver : public sim::Observer {
 public:
  // `recorder` is null when the scenario paints nothing.
  RunObserver(const sim::Scenario& scenario, std::filesystem::path out, int threads,
              std::unique_ptr<FrameRecorder> recorder, RunSource source);

  // A run that is not resumed: removes an earlier run's checkpoint, its
  // numbered frames and its spilled frames.
  void start_fresh();
  // A resumed run: the checkpoint's bookkeeping and pending frames, and the
  // simulated time it was written at. Throws nlohmann::json::exception if
  // the bookkeeping lacks an entry.
  void resume(const Checkpoint& checkpoint, double time);
  // A run that starts from a cached state: writes what the skipped stages'
  // ends would have written (their VTK state, the summary).
  void stages_restored(const sim::Simulation& sim);

  void stage_begins(const sim::Simulation&, const sim::StageSpec& stage) override;
  void frame(const sim::Simulation& sim, const sim::StageSpec& stage, int frame) override;
  void progress(const sim::Simulation& sim, const sim::StageSpec& stage, long steps) override;
  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                  const sim::StageResult& r) override;

  // After a failed stage: paint what was captured before the failure, and
  // the videos, so the frames leading up to it can be looked at.
  void paint_after_failure(const std::string& stage);
  void report_outputs() const;
  void write_summary(const sim::Simulation& sim, const std::string& status);
  void write_checkpoint(const sim::Simulation& sim);
  // Removes the checkpoint of a finished run.
  void remove_checkpoint() const;

 private:
  void paint(const std::string& stage);
  void encode();
  void write_state(const sim::Simulation& sim, const sim::StageSpec& stage,
                   const std::string& name, int frame);
  void write_interval_state(const sim::Simulation& sim, const sim::StageSpec& stage,
                            bool end = false);
  double wall_time() const;

  std::filesystem::path out_;
  int threads_;
  RunSource source_;
  Progress progress_;
  std::chrono::steady_clock::time_point run_start_ = std::chrono::steady_clock::now();
  double wall_before_ = 0;  // of the run before it was resumed
  double next_checkpoint_ = 0;
  std::vector<std::pair<double, std::string>> vtk_files_;
  long next_state_ = 0;          // vtk = "interval": the next state at this * vtk_interval
  double last_state_time_ = -1;  // stage time of the stage's last such state
  nlohmann::json states_ = nlohmann::json::array();
  std::unique_ptr<FrameRecorder> recorder_;
  SeriesRecorder series_;
  std::string last_painted_stage_;
  std::vector<render::VideoFiles> videos_;
};

}  // namespace app
