// `landslide run` and `landslide check`: validate the whole scenario before
// anything is written, then hand the time loop to sim::Simulation and listen.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/summary.hpp"
#include "sim/atomic_file.hpp"
#include "sim/simulation.hpp"
#include "sim/vtk.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// Writes what the scenario asks for while the simulation runs.
class RunObserver : public sim::Observer {
 public:
  RunObserver(fs::path out, int threads) : out_(std::move(out)), threads_(threads) {}

  void stage_begins(const sim::Simulation&, const sim::StageSpec& stage) override {
    stage_start_ = std::chrono::steady_clock::now();
    progress_.update(stage.name, 0, stage.duration, 0);
  }

  void frame(const sim::Simulation& sim, const sim::StageSpec&, int frame) override {
    if (sim.scenario().output.vtk == "frames") {
      char name[32];
      std::snprintf(name, sizeof name, "frame-%06d.vtu", frame);
      write_state(sim, name);
    }
  }

  void progress(const sim::Simulation& sim, const sim::StageSpec& stage, long steps) override {
    progress_.update(stage.name, sim.stage_time(), stage.duration, steps);
  }

  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                  const sim::StageResult& r) override {
    if (stage.type != sim::StageType::MaterialChange && sim.scenario().output.vtk == "stage-end")
      write_state(sim, stage.name + "-end.vtu");
    std::ostringstream msg;
    msg << stage.name << ": done";
    if (stage.type != sim::StageType::MaterialChange) {
      msg << " at t = " << r.simulated_time << " s" << (r.ended_at_rest ? " (at rest)" : "")
          << ", " << r.steps << " steps, " << r.wall_time << " s wall, kinetic energy "
          << r.kinetic_energy << " J/m";
    }
    progress_.finish(msg.str());
    write_summary(sim, "running");
  }

  void write_summary(const sim::Simulation& sim, const std::string& status) {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start_).count();
    const nlohmann::json summary = make_summary(sim, threads_, wall, status);
    sim::write_file_atomically((out_ / "summary.json").string(),
                               [&](std::ostream& o) { o << summary.dump(2) << '\n'; });
  }

 private:
  void write_state(const sim::Simulation& sim, const std::string& name) {
    fs::create_directories(out_ / "vtk");
    sim::write_vtu((out_ / "vtk" / name).string(), sim.world(), sim.time());
    vtk_files_.emplace_back(sim.time(), name);
    sim::write_pvd((out_ / "vtk" / "points.pvd").string(), vtk_files_);
  }

  fs::path out_;
  int threads_;
  Progress progress_;
  std::chrono::steady_clock::time_point run_start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point stage_start_;
  std::vector<std::pair<double, std::string>> vtk_files_;
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
  std::unique_ptr<sim::Simulation> simulation;
  std::unique_ptr<RunObserver> observer;
  try {
    simulation = std::make_unique<sim::Simulation>(scenario);
    fs::create_directories(out);
    std::cerr << "landslide " << LANDSLIDE_VERSION << ": " << scenario.name << ", "
              << simulation->world().points.size() << " points, h = " << scenario.cell_size
              << " m, " << threads << " threads -> " << out.string() << '\n';
    observer = std::make_unique<RunObserver>(out, threads);
    simulation->run(*observer);
    observer->write_summary(*simulation, "finished");
  } catch (const std::exception& e) {
    std::cerr << "\nerror: " << e.what() << '\n';
    if (observer) observer->write_summary(*simulation, std::string("failed: ") + e.what());
    return kExitFailed;
  }
  std::cerr << "summary: " << (out / "summary.json").string() << '\n';
  return kExitOk;
}

}  // namespace app
