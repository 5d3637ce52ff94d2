// The one owner of the time loop: runs the scenario's stages in order, picks
// each time step, lands exactly on frame times and stage ends, and tells an
// observer (the app: frames, VTK, progress) when something happens.
#pragma once

#include <string>
#include <vector>

#include "sim/diagnostics.hpp"
#include "sim/scenario.hpp"
#include "sim/step.hpp"
#include "sim/world.hpp"

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
  // Called every step; the observer decides how often to print.
  virtual void progress(const Simulation&, const StageSpec&, long /*steps*/) {}
};

class Simulation {
 public:
  explicit Simulation(const Scenario& scenario);

  // Runs every stage in order.
  void run(Observer& observer);

  const Scenario& scenario() const { return scenario_; }
  const World& world() const { return world_; }
  double time() const { return time_; }              // since the start of the run
  double stage_time() const { return stage_time_; }  // since the start of this stage
  const std::vector<StageResult>& results() const { return results_; }
  bool paints(const StageSpec& stage) const;

 private:
  void run_timed_stage(const StageSpec& stage, Observer& observer);
  void change_materials(const StageSpec& stage);
  double choose_time_step(double max_signal) const;
  void close_energy_balance(StageResult& r, double kinetic_start, double elastic_start) const;
  double stage_gravity_factor(const StageSpec& stage, double t) const;
  bool at_rest(const StageSpec& stage, const StageResult& r) const;

  Scenario scenario_;
  World world_;
  double time_ = 0, stage_time_ = 0;
  double gravity_factor_ = 0;  // share of full gravity applied; the gravity stage ramps it to 1
  int frames_ = 0;
  std::vector<StageResult> results_;
};

}  // namespace sim
