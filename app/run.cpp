// `landslide run` and `landslide check`: validate the whole scenario before
// anything is written, then hand the time loop to sim::Simulation and listen.
#include "landslide_version.hpp"
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/commands.hpp"
#include "app/frames.hpp"
#include "app/progress.hpp"
#include "app/summary.hpp"
#include "sim/atomic_file.hpp"
#include "sim/simulation.hpp"
#include "sim/vtk.hpp"
#include "render/error.hpp"
#include "render/video.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// Writes what the scenario asks for while the simulation runs.
class RunObserver : public sim::Observer {
 public:
  // `recorder` is null when the scenario paints nothing.
  RunObserver(const sim::Scenario& scenario, fs::path out, int threads,
              std::unique_ptr<FrameRecorder> recorder)
      : out_(std::move(out)), threads_(threads), recorder_(std::move(recorder)) {
    for (const sim::StageSpec& s : scenario.stages)
      if (s.type != sim::StageType::MaterialChange && paints(scenario, s))
        last_painted_stage_ = s.name;
    if (recorder_) recorder_->start();
  }

  void stage_begins(const sim::Simulation&, const sim::StageSpec& stage) override {
    stage_start_ = std::chrono::steady_clock::now();
    progress_.update(stage.name, 0, stage.duration, 0);
  }

  void frame(const sim::Simulation& sim, const sim::StageSpec& stage, int frame) override {
    if (recorder_) recorder_->capture(sim.world(), sim.stage_time(), frame, stage.name);
    if (sim.scenario().output.vtk == "frames") {
      char name[32];
      std::snprintf(name, sizeof name, "frame-%06d.vtu", frame);
      write_state(sim, stage, name, frame);
    }
  }

  void progress(const sim::Simulation& sim, const sim::StageSpec& stage, long steps) override {
    progress_.update(stage.name, sim.stage_time(), stage.duration, steps);
  }

  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                  const sim::StageResult& r) override {
    if (stage.type != sim::StageType::MaterialChange && sim.scenario().output.vtk == "stage-end")
      write_state(sim, stage, stage.name + "-end.vtu", -1);
    std::ostringstream msg;
    msg << stage.name << ": done";
    if (stage.type != sim::StageType::MaterialChange) {
      msg << " at t = " << r.simulated_time << " s" << (r.ended_at_rest ? " (at rest)" : "")
          << ", " << r.steps << " steps, " << r.wall_time << " s wall, kinetic energy "
          << r.kinetic_energy << " J/m";
    }
    progress_.finish(msg.str());
    if (recorder_ && recorder_->pending() > 0) paint(stage.name);
    if (recorder_ && stage.name == last_painted_stage_) encode();
    write_summary(sim, "running");
  }

  // After a failed stage: paint what was captured before the failure, and
  // the videos, so the frames leading up to it can be looked at.
  void paint_after_failure(const std::string& stage) {
    if (!recorder_) return;
    try {
      if (recorder_->pending() > 0) paint(stage);
      encode();
    } catch (const std::exception& e) {
      std::cerr << "error: painting the frames before the failure: " << e.what() << '\n';
    }
  }

  void report_outputs() const {
    if (!recorder_) return;
    for (const Field f : recorder_->fields())
      std::cerr << "frames: " << recorder_->frames_dir(f).string() << "/\n";
    for (const render::VideoFiles& v : videos_)
      std::cerr << "video: " << v.mp4 << (v.gif.empty() ? "" : ", " + v.gif) << '\n';
  }

  void write_summary(const sim::Simulation& sim, const std::string& status) {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start_).count();
    const nlohmann::json summary = make_summary(sim, threads_, wall, status);
    sim::write_file_atomically((out_ / "summary.json").string(),
                               [&](std::ostream& o) { o << summary.dump(2) << '\n'; });
  }

 private:
  static bool paints(const sim::Scenario& s, const sim::StageSpec& stage) {
    const auto& names = s.output.frame_stages;
    return s.output.frame_interval > 0 &&
           std::find(names.begin(), names.end(), stage.name) != names.end();
  }

  void paint(const std::string& stage) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t frames = recorder_->pending();
    const int files = recorder_->paint_pending();
    std::cerr << stage << ": painted " << frames << " frames, " << files << " PNG files in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s\n";
  }

  void encode() {
    const auto start = std::chrono::steady_clock::now();
    videos_ = recorder_->encode_videos();
    if (!videos_.empty())
      std::cerr << "encoded " << videos_.size() << " videos in "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                       .count()
                << " s\n";
  }

  // The .vtu file, the .pvd collection, and vtk/states.json: which stage each
  // state belongs to and its time within the stage, so `landslide render`
  // can label and colour it as the run did.
  void write_state(const sim::Simulation& sim, const sim::StageSpec& stage,
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
    const nlohmann::json doc = {{"states", states_}};
    sim::write_file_atomically((out_ / "vtk" / "states.json").string(),
                               [&](std::ostream& o) { o << doc.dump(1) << '\n'; });
  }

  fs::path out_;
  int threads_;
  Progress progress_;
  std::chrono::steady_clock::time_point run_start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point stage_start_;
  std::vector<std::pair<double, std::string>> vtk_files_;
  nlohmann::json states_ = nlohmann::json::array();
  std::unique_ptr<FrameRecorder> recorder_;
  std::string last_painted_stage_;
  std::vector<render::VideoFiles> videos_;
};

}  // namespace

int check_command(const std::string& path) {
  try {
    const sim::Scenario s = sim::load_scenario(path);
    std::cout << path << ": ok (" << s.materials.size() << " materials, " << s.bodies.size()
              << " bodies, " << s.stages.size() << " stages)\n";
    return kExitOk;
  } catch (const sim::ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
}

int run_command(const RunOptions& options) {
  sim::Scenario scenario;
  try {
    scenario = sim::load_scenario(options.scenario);
  } catch (const sim::ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const int threads = omp_get_max_threads();
  const fs::path out(options.out_dir);
  // Painting is set up before anything runs or is written: a missing ffmpeg
  // or OSMesa must not show up after hours of simulation.
  std::unique_ptr<FrameRecorder> recorder;
  if (paints_frames(scenario)) {
    std::string why;
    if (!render::ffmpeg_available(&why)) {
      std::cerr << "error: " << options.scenario
                << " asks for painted frames (output.frame_interval > 0), which are encoded "
                   "into mp4 and gif by ffmpeg: "
                << why << '\n';
      return kExitBadInput;
    }
    try {
      recorder = std::make_unique<FrameRecorder>(scenario, out);
    } catch (const std::exception& e) {
      std::cerr << "error: cannot set up the off-screen painter: " << e.what() << '\n';
      return kExitBadInput;
    }
  }
  std::unique_ptr<sim::Simulation> simulation;
  try {
    simulation = std::make_unique<sim::Simulation>(scenario);  // seeds the points
  } catch (const sim::ScenarioError& e) {  // e.g. a body that holds no point
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
  std::unique_ptr<RunObserver> observer;
  try {
    fs::create_directories(out);
    std::cerr << "landslide " << LANDSLIDE_VERSION << ": " << scenario.name << ", "
              << simulation->world().points.size() << " points, h = " << scenario.cell_size
              << " m, " << threads << " threads -> " << out.string() << '\n';
    observer = std::make_unique<RunObserver>(scenario, out, threads, std::move(recorder));
    simulation->run(*observer);
    observer->write_summary(*simulation, "finished");
  } catch (const std::exception& e) {
    std::cerr << "\nerror: " << e.what() << '\n';
    if (observer) {
      const std::size_t done = simulation->results().size();
      const auto& stages = simulation->scenario().stages;
      observer->paint_after_failure(done < stages.size() ? stages[done].name : "");
      observer->report_outputs();
      observer->write_summary(*simulation, std::string("failed: ") + e.what());
    }
    return kExitFailed;
  }
  observer->report_outputs();
  std::cerr << "summary: " << (out / "summary.json").string() << '\n';
  return kExitOk;
}

}  // namespace app
