// `landslide run`, `resume` and `check`: the preflight (app/preflight.hpp)
// before anything is written, then the time loop, handed to sim::Simulation.
#include "landslide_version.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "output/checkpoint.hpp"
#include "app/commands.hpp"
#include "output/counted.hpp"
#include "output/frames.hpp"
#include "output/output_dir.hpp"
#include "app/preflight.hpp"
#include "output/run_observer.hpp"
#include "sim/physics/team.hpp"
#include "output/state_cache.hpp"
#include "sim/io/binary_io.hpp"
#include "sim/run/simulation.hpp"
#include "sim/io/vtk.hpp"
#include "sim/run/watchdog.hpp"
#include "render/video.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// One run of a scenario into `out`: fresh, from cached gravity states, or
// resumed from a checkpoint.
struct RunSetup {
  sim::Scenario scenario;
  RunSource source;
  fs::path out;
  int threads = 0;
  const Checkpoint* checkpoint = nullptr;  // resume from it
  bool overwrite = false, allow_long = false;
};

// Where the threads asked for outnumber the CPUs the process may run on,
// the step uses no more threads than those (sim/physics/team.hpp): say so.
std::string cpus_note(int threads) {
  const int cpus = sim::usable_cpus();
  if (cpus < 1 || threads <= cpus) return "";
  return " (at most " + std::to_string(cpus) + " at once: the " + counted(cpus, "CPU") +
         " of this process's affinity mask)";
}

PreflightRequest preflight_request(const RunSetup& r, int threads) {
  PreflightRequest q;
  q.scenario = &r.scenario;
  q.scenario_file = r.source.scenario_file;
  q.out = r.out;
  q.state_cache = r.source.state_cache;
  q.checkpoint = r.checkpoint;
  q.overwrite = r.overwrite;
  q.allow_long = r.allow_long;
  q.threads = threads;
  return q;
}

// A run's setup from its command-line options; false (after printing why)
// if the scenario cannot be read.
bool set_up_run(const RunOptions& options, RunSetup& r) {
  try {
    r.source.scenario_text = sim::read_scenario_text(options.scenario);
    r.scenario = sim::parse_scenario(r.source.scenario_text, options.scenario);
  } catch (const sim::ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return false;
  }
  r.source.scenario_file = options.scenario;
  r.source.checkpoint_every = options.checkpoint_every;
  r.source.state_cache = options.state_cache;
  r.out = options.out_dir;
  r.threads = options.threads;
  r.overwrite = options.overwrite;
  r.allow_long = options.allow_long;
  return true;
}

// The state before a failure, as DIR/vtk/last-good.vtu, for a look at what
// led up to it.
void write_last_good_state(const RunSetup& r, const sim::WatchdogError& e) {
  if (e.last_good_state.empty()) return;
  try {
    sim::Simulation good(r.scenario);
    good.restore_state(e.last_good_state, "the last good state");
    const fs::path file = r.out / "vtk" / "last-good.vtu";
    fs::create_directories(file.parent_path());
    sim::write_vtu(file.string(), good.world(), good.time());
    std::cerr << "last good state (t = " << good.time() << " s): " << file.string() << '\n';
  } catch (const std::exception& x) {
    std::cerr << "error: writing the last good state: " << x.what() << '\n';
  }
}

int execute(RunSetup& r) {
  const int threads = use_threads(r.threads);
  Prepared prepared;
  if (!preflight(preflight_request(r, threads), prepared, std::cerr)) return kExitBadInput;
  std::unique_ptr<FrameRecorder> recorder = std::move(prepared.recorder);
  std::unique_ptr<sim::Simulation> simulation = std::move(prepared.simulation);
  r.source.reused_stages = prepared.reused_stages;
  std::unique_ptr<RunObserver> observer;
  try {
    if (r.overwrite && !r.checkpoint) remove_earlier_outputs(r.out);
    fs::create_directories(r.out);
    std::cerr << "landslide " << LANDSLIDE_VERSION << ": " << r.scenario.name << ", "
              << simulation->world().points.size() << " points, h = " << r.scenario.cell_size
              << " m, " << counted(threads, "thread") << cpus_note(threads) << " -> "
              << r.out.string() << '\n';
    if (r.checkpoint)
      std::cerr << "resuming at t = " << simulation->time() << " s from "
                << checkpoint_path(r.out).string() << '\n';
    if (r.source.reused_stages > 0)
      std::cerr << "starting after stage '"
                << r.scenario.stages[r.source.reused_stages - 1].name << "' from "
                << cached_state_path(r.source.state_cache, r.scenario).string() << '\n';
    observer = std::make_unique<RunObserver>(r.scenario, r.out, threads, std::move(recorder),
                                             r.source);
    if (r.checkpoint)
      observer->resume(*r.checkpoint, simulation->time());
    else
      observer->start_fresh();
    if (r.source.reused_stages > 0) observer->stages_restored(*simulation);
    catch_interrupt();
    simulation->run(*observer);
    release_interrupt();
    observer->write_summary(*simulation, "finished");
    observer->remove_checkpoint();
  } catch (const Interrupted& stop) {
    release_interrupt();
    std::cerr << "\nstopped at t = " << stop.time << " s; continue with: landslide resume "
              << r.out.string() << '\n';
    observer->write_summary(*simulation, stop.status());
    return stop.exit_status();
  } catch (const std::exception& e) {
    release_interrupt();
    std::cerr << "\nerror: " << e.what() << '\n';
    if (const auto* w = dynamic_cast<const sim::WatchdogError*>(&e))
      write_last_good_state(r, *w);
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
  std::cerr << "summary: " << (r.out / "summary.json").string() << '\n';
  return kExitOk;
}

}  // namespace

int run_command(const RunOptions& options) {
  RunSetup r;
  if (!set_up_run(options, r)) return kExitBadInput;
  return execute(r);
}

int check_command(const RunOptions& options) {
  RunSetup r;
  if (!set_up_run(options, r)) return kExitBadInput;
  Prepared prepared;
  if (!preflight(preflight_request(r, use_threads(r.threads)), prepared, std::cout))
    return kExitBadInput;
  const sim::Scenario& s = r.scenario;
  std::cout << options.scenario << ": ok (" << counted(s.materials.size(), "material") << ", "
            << counted(s.bodies.size(), "body", "bodies") << ", "
            << counted(s.stages.size(), "stage") << ")\n";
  return kExitOk;
}

int resume_command(const ResumeOptions& options) {
  RunSetup r;
  r.out = options.dir;
  Checkpoint checkpoint;
  try {
    checkpoint = read_checkpoint(checkpoint_path(r.out));
    r.scenario = sim::parse_scenario(checkpoint.scenario_text, checkpoint.scenario_file);
  } catch (const sim::StateError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const sim::ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
  r.source.scenario_text = checkpoint.scenario_text;
  r.source.scenario_file = checkpoint.scenario_file;
  r.source.checkpoint_every = options.checkpoint_every;
  r.threads = options.threads;
  r.allow_long = options.allow_long;
  r.checkpoint = &checkpoint;
  return execute(r);
}

}  // namespace app
