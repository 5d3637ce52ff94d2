// What `landslide gallery` hears from each run: the states its figures
// show (gravity end, slide times, slide end, every slide frame for the
// side-by-side animation), progress every 10 s, and the saved state of a
// gravity stage the next scene can start from.
#pragma once

#include <atomic>
#include <csignal>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/frames.hpp"
#include "gallery/src/gallery_parts.hpp"
#include "output/run_observer.hpp"
#include "output/series.hpp"
#include "sim/run/simulation.hpp"

namespace app::gallery {

// The fields every run keeps (values are captured for all of them).
const std::vector<Field> kFields = {Field::DisplacementX, Field::StressYY, Field::RelativeYield};
inline std::size_t field_index(Field f) {
  for (std::size_t k = 0; k < kFields.size(); ++k)
    if (kFields[k] == f) return k;
  return 0;
}

// Slide times (s into the slide) the figures show.
const std::vector<double> kSlideTimes = {3, 4, 8, 12, 16};

// Thrown between two steps of a run once `stop` is set (Gallery::stop_runs):
// a run on the other lane (gallery_lanes.hpp) failed, and its error is the
// one the gallery reports, without waiting for this run to end.
struct RunsStopped : std::runtime_error {
  RunsStopped() : std::runtime_error("stopped: a run on the other lane failed") {}
};

// Thrown between two steps of a run, and after a figure, once Ctrl-C or
// SIGTERM came (output/run_observer.hpp's catch_interrupt): the gallery
// stops there, removes its work folder and exits 130 or 143. Not a
// std::exception, so that no run takes it for a failure of its own.
struct GalleryInterrupted {
  int signal = 0;
  const char* by() const { return signal == SIGTERM ? "SIGTERM" : "Ctrl-C"; }
};

inline void stop_if_interrupted() {
  if (const int signal = interrupt_signal()) throw GalleryInterrupted{signal};
}

class GalleryObserver : public sim::Observer {
 public:
  // `series` (may be null) records the run's time series.
  GalleryObserver(RunResult& r, const std::atomic<bool>& stop, FrameRecorder* recorder,
                  SeriesRecorder* series = nullptr)
      : r_(r), stop_(stop), recorder_(recorder), series_(series) {}

  void stage_begins(const sim::Simulation& sim, const sim::StageSpec& stage) override {
    if (series_) series_->stage_begins(sim, stage);
  }

  // Saves the state into `saved` when the run has finished its first
  // `stages` stages, for the next scene that shares them.
  void save_after(std::size_t stages, std::string* saved) {
    save_after_ = stages;
    saved_ = saved;
  }

  void frame(const sim::Simulation& sim, const sim::StageSpec& stage, int frame) override {
    if (recorder_) recorder_->capture(sim.world(), sim.stage_time(), frame, stage.name);
    if (series_) series_->frame(sim);
    if (stage.type != sim::StageType::Dynamic) return;
    r_.last = capture_frame(sim.world(), kFields, frame, sim.stage_time(), stage.name);
    r_.has_last = true;
    r_.slide_frames.push_back(
        capture_frame(sim.world(), {Field::DisplacementX}, frame, sim.stage_time(), stage.name));
    for (const double t : kSlideTimes)
      if (std::abs(sim.stage_time() - t) < 1e-6)
        r_.at[t] = capture_frame(sim.world(), kFields, frame, sim.stage_time(), stage.name);
  }

  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                  const sim::StageResult& res) override {
    if (series_) series_->stage_ends(sim, stage, res);
    if (stage.type == sim::StageType::Gravity)
      r_.gravity_end = capture_frame(sim.world(), kFields, 0, sim.stage_time(), stage.name);
    if (stage.type == sim::StageType::Dynamic) {
      r_.slide_end = capture_frame(sim.world(), kFields, 0, sim.stage_time(), stage.name);
      r_.slide_time = res.simulated_time;
      r_.at_rest = res.ended_at_rest;
      r_.runout = res.metrics.runout;
      r_.max_ux = res.metrics.max_soil_ux;
    }
    if (saved_ && sim.stage_index() == save_after_) *saved_ = sim.save_state();
    if (recorder_ && recorder_->pending() > 0) recorder_->paint_pending();
  }

  void progress(const sim::Simulation& sim, const sim::StageSpec& stage, long steps) override {
    stop_if_interrupted();
    if (stop_.load(std::memory_order_relaxed)) throw RunsStopped();
    if (series_) series_->progress(sim, stage);
    if (std::chrono::steady_clock::now() - last_ < std::chrono::seconds(10)) return;
    last_ = std::chrono::steady_clock::now();
    std::ostringstream line;
    line << "  " << sim.scenario().name << ": " << stage.name << " t = " << sim.stage_time() << " s, "
         << steps << " steps";
    log_line(line.str());
  }

 private:
  RunResult& r_;
  const std::atomic<bool>& stop_;
  FrameRecorder* recorder_;
  SeriesRecorder* series_;
  std::size_t save_after_ = 0;
  std::string* saved_ = nullptr;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace app::gallery
