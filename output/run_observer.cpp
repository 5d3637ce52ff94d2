#include "output/run_observer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include "output/checkpoint.hpp"
#include "output/exit_status.hpp"
#include "output/counted.hpp"
#include "output/state_cache.hpp"
#include "output/summary.hpp"
#include "sim/io/atomic_file.hpp"
#include "sim/io/vtk.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// The signal that asked the run to stop (SIGINT or SIGTERM); 0: none.
volatile std::sig_atomic_t interrupt_requested = 0;
// Whether the stop writes a checkpoint (`run`, `resume`) or not (`gallery`).
volatile std::sig_atomic_t stop_writes_checkpoint = 1;

extern "C" void on_interrupt(int signal) {
  interrupt_requested = signal;
  // Only write(2) and strlen are safe here (async-signal-safe, POSIX): no
  // formatting, so one fixed text per case, [writes a checkpoint][SIGTERM].
  static const char* const texts[2][2] = {
      {"\nCtrl-C: stopping after this step or figure (Ctrl-C again quits at once)\n",
       "\nSIGTERM: stopping after this step or figure (a second SIGTERM quits at once)\n"},
      {"\nCtrl-C: stopping after this step and writing a checkpoint (Ctrl-C again quits at "
       "once)\n",
       "\nSIGTERM: stopping after this step and writing a checkpoint (a second SIGTERM quits "
       "at once)\n"}};
  const char* text = texts[stop_writes_checkpoint ? 1 : 0][signal == SIGTERM ? 1 : 0];
  [[maybe_unused]] const ssize_t n = ::write(2, text, std::strlen(text));
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}


// "slump: done at t = ... (at rest), ...": the kinetic energy shown is the
// one the rest test compares (that of the velocity that moves the points),
// beside the bound it was compared with; the points' own velocities can keep
// far more (scenarios/README.md, stop_at_rest), and summary.json has both.
std::string stage_done_line(const sim::StageSpec& stage, const sim::StageResult& r) {
  std::ostringstream msg;
  msg << stage.name << ": done";
  if (stage.type == sim::StageType::MaterialChange) return msg.str();
  msg << " at t = " << r.simulated_time << " s" << (r.ended_at_rest ? " (at rest)" : "") << ", "
      << counted(r.steps, "step") << ", " << r.wall_time << " s wall, moving kinetic energy "
      << r.moving_kinetic_energy << " J/m";
  if (stage.rest.enabled)
    msg << " (at rest once <= " << stage.rest.kinetic_ratio << " x gravity work "
        << std::max(r.gravity_work, 0.0) << " J/m)";
  return msg.str();
}

}  // namespace

// SIGTERM is what `timeout`, `kill` and batch schedulers send before they
// give up on a job: it must leave a checkpoint just as Ctrl-C does.
void catch_interrupt(bool writes_checkpoint) {
  interrupt_requested = 0;
  stop_writes_checkpoint = writes_checkpoint ? 1 : 0;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

void release_interrupt() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

std::string Interrupted::status() const {
  return std::string("interrupted") + (signal == SIGTERM ? " by SIGTERM" : "") + " at t = " +
         std::to_string(time) + " s (checkpoint.lsck)";
}

int interrupt_signal() { return interrupt_requested; }

int Interrupted::exit_status() const {
  return signal == SIGTERM ? kExitTerminated : kExitInterrupted;
}

RunObserver::RunObserver(const sim::Scenario& scenario, fs::path out, int threads,
                         std::unique_ptr<FrameRecorder> recorder, RunSource source)
    : out_(std::move(out)),
      threads_(threads),
      source_(std::move(source)),
      next_checkpoint_(source_.checkpoint_every),
      recorder_(std::move(recorder)),
      series_(scenario, out_) {
  progress_.set_stages(scenario.stages);
  for (const sim::StageSpec& s : scenario.stages)
    if (s.type != sim::StageType::MaterialChange && sim::stage_is_painted(scenario, s))
      last_painted_stage_ = s.name;
}

void RunObserver::start_fresh() {
  remove_checkpoint();  // an earlier run's: `resume` must not pick it up
  if (recorder_) recorder_->start();
}

void RunObserver::resume(const Checkpoint& c, double time) {
  const nlohmann::json& run = c.run;
  for (const auto& f : run.at("vtk_files")) vtk_files_.emplace_back(f.at(0), f.at(1));
  states_ = run.at("states");
  wall_before_ = run.at("wall_time_s");
  series_.resume(run.at("series"));
  if (recorder_) recorder_->resume(c.frames, c.extent, run.at("pngs_written"));
  next_state_ = run.at("next_state");
  last_state_time_ = run.at("last_state_time_s");
  const double every = source_.checkpoint_every;
  if (every > 0) next_checkpoint_ = (std::floor(time / every) + 1) * every;
}

void RunObserver::stages_restored(const sim::Simulation& sim) {
  const auto& stages = sim.scenario().stages;
  for (std::size_t k = 0; k < sim.stage_index(); ++k)
    if (stages[k].type != sim::StageType::MaterialChange && sim.scenario().output.vtk == "stage-end")
      write_state(sim, stages[k], stages[k].name + "-end.vtu", -1);
  series_.restore(read_series(cached_series_path(source_.state_cache, sim.scenario())));
  series_.write();
  write_summary(sim, "running");
}

void RunObserver::stage_begins(const sim::Simulation& sim, const sim::StageSpec& stage) {
  progress_.update(stage.name, sim.stage_time(), stage.duration, 0);
  series_.stage_begins(sim, stage);
  if (sim.stage_time() == 0) {  // not a stage resumed halfway
    next_state_ = 0;
    last_state_time_ = -1;
    write_interval_state(sim, stage);
  }
}

void RunObserver::frame(const sim::Simulation& sim, const sim::StageSpec& stage, int frame) {
  if (recorder_) recorder_->capture(sim.world(), sim.stage_time(), frame, stage.name);
  series_.frame(sim);
  if (sim.scenario().output.vtk == "frames") {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06d.vtu", frame);
    write_state(sim, stage, name, frame);
  }
}

void RunObserver::progress(const sim::Simulation& sim, const sim::StageSpec& stage, long steps) {
  progress_.update(stage.name, sim.stage_time(), stage.duration, steps);
  series_.progress(sim, stage);  // before a checkpoint, which keeps the rows
  write_interval_state(sim, stage);
  const double every = source_.checkpoint_every;
  const bool due = every > 0 && sim.time() >= next_checkpoint_;
  if (!due && !interrupt_requested) return;
  write_checkpoint(sim);
  if (every > 0) next_checkpoint_ = (std::floor(sim.time() / every) + 1) * every;
  if (interrupt_requested) throw Interrupted{sim.time(), int(interrupt_requested)};
}

void RunObserver::stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                             const sim::StageResult& r) {
  series_.stage_ends(sim, stage, r);
  if (stage.type != sim::StageType::MaterialChange && sim.scenario().output.vtk == "stage-end")
    write_state(sim, stage, stage.name + "-end.vtu", -1);
  // A stage that ended between two state times still leaves its end.
  if (stage.type != sim::StageType::MaterialChange && sim.scenario().output.vtk == "interval" &&
      last_state_time_ < sim.stage_time())
    write_interval_state(sim, stage, true);
  progress_.finish(stage_done_line(stage, r));
  if (!source_.state_cache.empty() && source_.reused_stages == 0 &&
      sim.stage_index() == sim::reusable_stages(sim.scenario()))
    save_cached_state(source_.state_cache, sim, series_.csv());
  // Every frame is painted once the last painted stage has captured its
  // frames: the view is the region the material covers in all of them.
  if (recorder_ && stage.name == last_painted_stage_) {
    if (recorder_->pending() > 0) paint(stage.name);
    encode();
  }
  write_summary(sim, "running");
}

void RunObserver::paint_after_failure(const std::string& stage) {
  try {
    series_.write();
  } catch (const std::exception& e) {
    std::cerr << "error: writing the series before the failure: " << e.what() << '\n';
  }
  if (!recorder_) return;
  try {
    if (recorder_->pending() > 0) paint(stage);
    encode();
  } catch (const std::exception& e) {
    std::cerr << "error: painting the frames before the failure: " << e.what() << '\n';
  }
}

void RunObserver::report_outputs() const {
  if (!recorder_) return;
  for (const Field f : recorder_->fields())
    std::cerr << "frames: " << recorder_->frames_dir(f).string() << "/\n";
  for (const render::VideoFiles& v : videos_)
    std::cerr << "video: " << v.mp4 << (v.gif.empty() ? "" : ", " + v.gif) << '\n';
}

double RunObserver::wall_time() const { return wall_before_ + seconds_since(run_start_); }

void RunObserver::write_summary(const sim::Simulation& sim, const std::string& status) {
  const nlohmann::json summary = make_summary(sim, threads_, wall_time(), status);
  sim::write_file_atomically((out_ / "summary.json").string(),
                             [&](std::ostream& o) { o << summary.dump(2) << '\n'; });
}

void RunObserver::write_checkpoint(const sim::Simulation& sim) {
  Checkpoint c;
  c.scenario_text = source_.scenario_text;
  c.scenario_file = source_.scenario_file;
  nlohmann::json files = nlohmann::json::array();
  for (const auto& [t, name] : vtk_files_) files.push_back({t, name});
  c.run = {{"vtk_files", files},
           {"states", states_},
           {"wall_time_s", wall_time()},
           {"pngs_written", recorder_ ? recorder_->written() : 0},
           {"series", series_.bookkeeping()},
           {"next_state", next_state_},
           {"last_state_time_s", last_state_time_}};
  c.state = sim.save_state();
  if (recorder_) {
    c.frames = recorder_->pending_frames();
    c.extent = recorder_->extent();
  }
  app::write_checkpoint(checkpoint_path(out_), c);
  series_.write();
  write_summary(sim, "running (checkpoint at t = " + std::to_string(sim.time()) + " s)");
}

void RunObserver::remove_checkpoint() const {
  std::error_code ec;
  fs::remove(checkpoint_path(out_), ec);
}

void RunObserver::paint(const std::string& stage) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t frames = recorder_->pending();
  const int files = recorder_->paint_pending();
  std::cerr << stage << ": painted " << counted(frames, "frame") << ", "
            << counted(files, "PNG file") << " in "
            << seconds_since(start) << " s\n";
}

void RunObserver::encode() {
  const auto start = std::chrono::steady_clock::now();
  videos_ = recorder_->encode_videos();
  if (!videos_.empty())
    std::cerr << "encoded " << counted(videos_.size(), "video") << " in " << seconds_since(start)
              << " s\n";
}

// With vtk = "interval": the state at the first step that reaches each
// multiple of vtk_interval in the stage (the steps stay as they are, so the
// run does not depend on it), and with `end` the stage's last state.
void RunObserver::write_interval_state(const sim::Simulation& sim, const sim::StageSpec& stage,
                                       bool end) {
  const sim::OutputSpec& o = sim.scenario().output;
  if (o.vtk != "interval" || stage.type == sim::StageType::MaterialChange) return;
  if (!end && sim.stage_time() < double(next_state_) * o.vtk_interval) return;
  char name[32];
  std::snprintf(name, sizeof name, "state-%06zu.vtu", vtk_files_.size());
  write_state(sim, stage, name, -1);
  next_state_ = std::lround(std::floor(sim.stage_time() / o.vtk_interval)) + 1;
  last_state_time_ = sim.stage_time();
}

// The .vtu file, the .pvd collection, and vtk/states.json: which stage each
// state belongs to and its time within the stage, so `landslide render`
// can label and colour it as the run did.
void RunObserver::write_state(const sim::Simulation& sim, const sim::StageSpec& stage,
                              const std::string& name, int frame) {
  fs::create_directories(out_ / "vtk");
  sim::write_vtu((out_ / "vtk" / name).string(), sim.world(), sim.time());
  vtk_files_.emplace_back(sim.time(), name);
  sim::write_pvd((out_ / "vtk" / "points.pvd").string(), vtk_files_);
  nlohmann::json entry = {{"file", name},
                          {"time_s", sim.time()},
                          {"stage", stage.name},
                          {"stage_time_s", sim.stage_time()}};
  entry["frame"] = frame >= 0 ? nlohmann::json(frame) : nlohmann::json(nullptr);
  states_.push_back(entry);
  // The scenario's name: `landslide render` refuses another scenario's.
  const nlohmann::json doc = {{"scenario", sim.scenario().name}, {"states", states_}};
  sim::write_file_atomically((out_ / "vtk" / "states.json").string(),
                             [&](std::ostream& o) { o << doc.dump(1) << '\n'; });
}

}  // namespace app
