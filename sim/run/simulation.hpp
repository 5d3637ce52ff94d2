// The one owner of the time loop: runs the scenario's stages in order, picks
// each time step, lands exactly on frame times and stage ends, and tells an
// observer (the app: frames, VTK, progress) when something happens.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/run/diagnostics.hpp"
#include "sim/scene/scenario.hpp"
#include "sim/physics/step.hpp"
#include "sim/physics/point_order.hpp"
#include "sim/physics/world.hpp"

namespace sim {

struct StageResult {
  std::string name;
  StageType type = StageType::Dynamic;
  double simulated_time = 0;  // s spent in the stage
  double wall_time = 0;       // s
  long steps = 0;
  bool ended_at_rest = false;  // by its stop_at_rest criterion, before its duration
  double kinetic_energy = 0;   // of the points at the end, J/m
  double moving_kinetic_energy = 0;  // of the velocity that moves the points (the rest criterion)
  double gravity_work = 0;     // during the stage, J/m
  EnergyBalance energy;        // Eq. (3) over the stage
  StageMetrics metrics;        // at the end of the stage
};

class Simulation;

// What the app hears. Every callback gets the simulation in a consistent
// state between steps.
class Observer {
 public:
  virtual ~Observer() = default;
  virtual void stage_begins(const Simulation&, const StageSpec&) {}
  // A frame time of a painted stage; frame counts frames across the run.
  virtual void frame(const Simulation&, const StageSpec&, int /*frame*/) {}
  virtual void stage_ends(const Simulation&, const StageSpec&, const StageResult&) {}
  // Called after every step, with the run in a state save_state() can store
  // and a resumed run continues from exactly. The observer decides how often
  // to print or save; it may throw to stop the run.
  virtual void progress(const Simulation&, const StageSpec&, long /*steps*/) {}
};

class Simulation {
 public:
  explicit Simulation(const Scenario& scenario);

  // Runs every stage not yet run, in order (all of them, unless a saved state
  // was restored). A run that leaves the watchdog's limits (sim/run/watchdog.hpp)
  // throws WatchdogError with the last good state.
  void run(Observer& observer);

  // The whole state between two steps, or between two stages: the points,
  // the materials as they stand, the time, the results so far and the loop's
  // own variables. Restored into a Simulation of the same scenario, it
  // continues bit-identically. restore_state throws StateError (naming
  // `label`) for a state of another scenario, build or point count.
  std::string save_state() const;
  // The same, written into `buffer`'s memory (for states saved over and over).
  std::string save_state(std::string buffer) const;
  // After a failed restore the Simulation must not be run.
  void restore_state(const std::string& bytes, const std::string& label);

  const Scenario& scenario() const { return scenario_; }
  // The world with its points in scene order (sim/physics/point_order.hpp).
  const World& world() const {
    restore_scene_order(world_);
    return world_;
  }
  double time() const { return time_; }              // since the start of the run
  double stage_time() const { return stage_time_; }  // since the start of this stage
  const std::vector<StageResult>& results() const { return results_; }
  std::size_t stage_index() const { return stage_index_; }  // the stage running or next
  // Whether stage_index() has begun (a state saved mid-stage) and stage_time() counts in it.
  bool stage_started() const { return progress_.started; }
  // The timed stage running now as stage_ends would report it if it ended
  // here: its sums so far, its energy balance (Eq. 3) closed at the present
  // state, the kinetic energies of the last step (before the first step of
  // a stage: the total taken from the points, the moving one of the last
  // step before it). Metrics are left empty (measure_stage when needed).
  // Call it between steps of a timed stage (from frame() or progress()).
  StageResult stage_so_far() const;
  // The time step the next step would take, at the present state (before
  // the first step: at rest, or as restored). A fixed time_step above the
  // stable bound there is bad input, not a failed run: throws ScenarioError
  // naming the value and the bound, so `landslide check` refuses it.
  double next_time_step() const;

 private:
  void run_timed_stage(const StageSpec& stage, Observer& observer);
  void begin_timed_stage(const StageSpec& stage, Observer& observer);
  void finish_stage(const StageSpec& stage, const StageResult& r, Observer& observer);
  void change_materials(const StageSpec& stage);
  double choose_time_step(double max_signal) const;
  void close_energy_balance(StageResult& r, double kinetic_start, double elastic_start) const;
  double stage_gravity_factor(const StageSpec& stage, double t) const;
  bool at_rest(const StageSpec& stage, const StageResult& r) const;
  void watch(const StageSpec& stage, const StepReport& report);
  [[noreturn]] void stop_run(const StageSpec& stage, const std::string& why) const;

  Scenario scenario_;
  // Mutable: where the points are stored is not part of the state. The time
  // loop stores them in cell order for the step, and anything that reads
  // them, world() first, puts them back in scene order; the watchdog's scan
  // and save_state() read them where they are.
  mutable World world_;
  double time_ = 0, stage_time_ = 0;
  double gravity_factor_ = 0;  // share of full gravity applied; the gravity stage ramps it to 1
  int frames_ = 0;
  std::vector<StageResult> results_;
  std::size_t stage_index_ = 0;

  // What the time loop carries from one step to the next within a timed stage.
  struct StageProgress {
    bool started = false;
    StageResult result;      // sums so far
    long next_frame = 0;     // frame k falls at stage time k * frame_interval
    double max_signal = 0;   // of the last step, for the next time step
    double kinetic_start = 0, elastic_start = 0;  // for the energy balance
  };
  StageProgress progress_;
  std::chrono::steady_clock::time_point wall_start_;  // of this stage, or of its resumption
  std::string last_good_;     // save_state() at the watchdog's last passed scan
  double last_good_time_ = 0;
};

// A key of the inputs that define the first `stages` stages of a scenario
// (domain, grid, gravity, walls, materials, bodies, time step, those stages,
// and the output settings they use): two scenarios with the same key reach
// the same state at the end of those stages, so one can start from the
// other's saved state.
std::uint64_t stage_prefix_key(const Scenario& scenario, std::size_t stages);

// How many leading stages of a scenario another scenario can share: up to
// and including its first gravity stage, if none of them is painted (a
// reused stage paints no frames) and no VTK state is written at an interval
// (nor does it write those); 0 if there is no such stage.
std::size_t reusable_stages(const Scenario& scenario);

}  // namespace sim
