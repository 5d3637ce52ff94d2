#include "sim/run/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "sim/scene/random_field.hpp"
#include "sim/scene/seed.hpp"
#include "sim/run/watchdog.hpp"

namespace sim {

namespace {

// Largest Courant number the explicit GIMP step is run at (method notes,
// section 4): a fixed time step above C h / max(c_p + |v_p|) is refused.
constexpr double kMaxCourant = 0.5;

// Events closer than this fraction of a step count as reached, so round-off
// never leaves a sliver step.
constexpr double kEventSlack = 1e-9;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A step's terms of the energy balance (Eq. 3) added to its stage's, and the
// kinetic energies it ended with.
void add_step_to_stage(const StepReport& report, StageResult& r) {
  r.gravity_work += report.gravity_work;
  r.energy.internal_work += report.internal_work;
  r.energy.damping_loss += report.damping_loss;
  r.energy.wall_loss += report.wall_loss;
  r.energy.friction_work += report.friction_work;
  r.energy.transfer_loss += report.transfer_loss;
  r.kinetic_energy = report.kinetic_energy;
  r.moving_kinetic_energy = report.moving_kinetic_energy;
}

}  // namespace

Simulation::Simulation(const Scenario& scenario)
    : scenario_(scenario), world_(make_world(scenario)) {
  // Without a gravity stage the body force acts in full from the start.
  const bool ramped = std::any_of(scenario.stages.begin(), scenario.stages.end(),
                                  [](const StageSpec& s) { return s.type == StageType::Gravity; });
  gravity_factor_ = ramped ? 0.0 : 1.0;
}

void Simulation::run(Observer& observer) {
  while (stage_index_ < scenario_.stages.size()) {
    const StageSpec& stage = scenario_.stages[stage_index_];
    if (stage.type == StageType::MaterialChange) {
      observer.stage_begins(*this, stage);
      change_materials(stage);
      StageResult r;
      r.name = stage.name;
      r.type = stage.type;
      finish_stage(stage, r, observer);
    } else {
      run_timed_stage(stage, observer);
    }
  }
}

void Simulation::finish_stage(const StageSpec& stage, const StageResult& r, Observer& observer) {
  results_.push_back(r);
  ++stage_index_;
  progress_ = StageProgress{};
  observer.stage_ends(*this, stage, results_.back());
}

void Simulation::change_materials(const StageSpec& stage) {
  // The trigger of the paper (Section 7.1): properties change at once, the
  // stresses stay and are returned to the new surface by the next step.
  // A random field gives each point of the material its own value
  // (sim/physics/point_strength.hpp); the spec keeps the field's mean.
  restore_scene_order(world_);
  for (const MaterialChange& c : stage.changes) {
    apply_material_change(world_.material_specs[c.material], c.property, c.value);
    world_.materials[c.material] = make_material_constants(world_.material_specs[c.material]);
    if (c.has_field)
      set_point_strength(world_, c.material, c.property,
                         field_at_points(c.field, scenario_, world_.points, c.material));
    else
      follow_material_change(world_, c.material, c.property);
  }
}

// Gravity ramp of the paper's Figure 4: linear over ramp_fraction of the
// stage, then held.
double Simulation::stage_gravity_factor(const StageSpec& stage, double t) const {
  if (stage.type != StageType::Gravity) return gravity_factor_;
  const double ramp = stage.ramp_fraction * stage.duration;
  return std::min(1.0, t / ramp);
}

double Simulation::choose_time_step(double max_signal) const {
  const double bound = kMaxCourant * world_.grid.h / max_signal;
  if (scenario_.time_step.mode == TimeStepSpec::Mode::Courant)
    return scenario_.time_step.courant * world_.grid.h / max_signal;
  const double dt = scenario_.time_step.fixed_dt;
  if (dt > bound) {
    std::ostringstream msg;
    msg << "time_step.fixed = " << dt << " s exceeds the stable bound " << bound
        << " s (Courant " << kMaxCourant << ", h = " << world_.grid.h
        << " m, max c_p + |v_p| = " << max_signal << " m/s) at t = " << time_ << " s";
    throw SimulationError(msg.str());
  }
  return dt;
}

double Simulation::next_time_step() const {
  const double signal = progress_.started ? progress_.max_signal : max_signal_speed(world_);
  try {
    return choose_time_step(signal);
  } catch (const SimulationError& e) {
    throw ScenarioError(scenario_.source_path + ": " + e.what() +
                        ": expected a fixed step at most the bound, or time_step.courant");
  }
}

bool Simulation::at_rest(const StageSpec& stage, const StageResult& r) const {
  if (!stage.rest.enabled || stage_time_ < stage.rest.min_time) return false;
  if (stage.type == StageType::Gravity && stage_time_ < stage.ramp_fraction * stage.duration)
    return false;  // never stop before the full load is on
  return r.moving_kinetic_energy <= stage.rest.kinetic_ratio * std::max(r.gravity_work, 0.0);
}

void Simulation::close_energy_balance(StageResult& r, double kinetic_start,
                                      double elastic_start) const {
  EnergyBalance& e = r.energy;
  e.external_work = r.gravity_work;
  e.kinetic_change = kinetic_energy(world()) - kinetic_start;
  e.elastic_energy_change = elastic_energy(world()) - elastic_start;
  e.plastic_dissipation = e.internal_work - e.elastic_energy_change;
  const double residual = e.external_work - e.kinetic_change - e.internal_work - e.damping_loss -
                         e.wall_loss - e.friction_work - e.transfer_loss;
  e.relative_error = e.external_work != 0 ? residual / std::fabs(e.external_work) : 0.0;
}

StageResult Simulation::stage_so_far() const {
  StageResult r = progress_.result;
  r.simulated_time = stage_time_;
  if (r.steps == 0) {
    r.kinetic_energy = kinetic_energy(world());
    // The moving velocity is only known from a step: the last one run.
    for (auto it = results_.rbegin(); it != results_.rend(); ++it)
      if (it->type != StageType::MaterialChange) {
        r.moving_kinetic_energy = it->moving_kinetic_energy;
        break;
      }
  }
  close_energy_balance(r, progress_.kinetic_start, progress_.elastic_start);
  return r;
}

// The watchdog (sim/run/watchdog.hpp): a non-finite sum stops the run at once; a
// full scan every kWatchdogScanSteps steps checks every point, and every
// kWatchdogSaveSteps steps a scan that finds all within the limits keeps
// the state as the last good one.
void Simulation::watch(const StageSpec& stage, const StepReport& report) {
  const bool finite = step_sums_finite(report);
  const long steps = progress_.result.steps;
  if (finite && steps % kWatchdogScanSteps != 0) return;
  const std::string bad = find_bad_point(world_);  // where the points are stored
  if (!bad.empty()) stop_run(stage, bad);
  if (!finite) stop_run(stage, "a sum over the points is not finite");
  if (steps % kWatchdogSaveSteps != 0) return;
  last_good_ = save_state(std::move(last_good_));
  last_good_time_ = time_;
}

void Simulation::stop_run(const StageSpec& stage, const std::string& why) const {
  std::ostringstream msg;
  msg << "stage '" << stage.name << "', after step " << progress_.result.steps << ", t = "
      << time_ << " s (stage time " << stage_time_ << " s): " << why;
  throw WatchdogError(msg.str(), last_good_, last_good_time_);
}

void Simulation::begin_timed_stage(const StageSpec& stage, Observer& observer) {
  StageProgress& p = progress_;
  p = StageProgress{};
  p.started = true;
  p.result.name = stage.name;
  p.result.type = stage.type;
  stage_time_ = 0;
  restore_scene_order(world_);
  if (scenario_.output.displacement_reference == "stage-start") {
    world_.points.ref_x = world_.points.x;
    world_.points.ref_y = world_.points.y;
  }
  p.max_signal = max_signal_speed(world_);
  p.kinetic_start = kinetic_energy(world_);
  p.elastic_start = elastic_energy(world_);
  observer.stage_begins(*this, stage);  // with the energy balance's start in place
  last_good_ = save_state(std::move(last_good_));
  last_good_time_ = time_;
}

// The time loop of one stage. Every variable it carries between steps lives
// in progress_, so a state saved by the observer's progress() continues here.
void Simulation::run_timed_stage(const StageSpec& stage, Observer& observer) {
  wall_start_ = std::chrono::steady_clock::now();
  if (progress_.started)
    observer.stage_begins(*this, stage);  // resumed mid-stage from a saved state
  else
    begin_timed_stage(stage, observer);
  StageProgress& p = progress_;
  StageResult& r = p.result;
  const bool painted = stage_is_painted(scenario_, stage);
  const double interval = scenario_.output.frame_interval;
  StepReport report;
  while (true) {
    if (painted && p.next_frame * interval <= stage_time_ + kEventSlack * interval) {
      observer.frame(*this, stage, frames_++);
      ++p.next_frame;
    }
    if (stage_time_ >= stage.duration * (1 - kEventSlack) || (r.steps > 0 && at_rest(stage, r))) {
      r.ended_at_rest = stage_time_ < stage.duration * (1 - kEventSlack);
      break;
    }
    double dt = 0;
    try {
      dt = choose_time_step(p.max_signal);
    } catch (const SimulationError& e) {
      stop_run(stage, e.what());
    }
    double until = stage.duration - stage_time_;
    if (painted) until = std::min(until, p.next_frame * interval - stage_time_);
    if (dt >= until * (1 - kEventSlack)) dt = until;
    const double factor = stage_gravity_factor(stage, stage_time_ + 0.5 * dt);
    const Vec2 g{factor * scenario_.gravity[0], factor * scenario_.gravity[1]};
    if (sort_due(world_, r.steps)) sort_points_by_cell(world_);
    try {
      step(world_, StepInput{dt, g, stage.damping}, report);
    } catch (const SimulationError& e) {  // a point left the grid
      stop_run(stage, e.what() + left_grid_advice(world(), scenario_));
    }
    stage_time_ += dt;
    time_ += dt;
    ++r.steps;
    add_step_to_stage(report, r);
    p.max_signal = report.max_signal;
    watch(stage, report);
    observer.progress(*this, stage, r.steps);
  }
  if (stage.type == StageType::Gravity) gravity_factor_ = 1.0;
  if (painted && (p.next_frame - 1) * interval < stage_time_ - kEventSlack * interval)
    observer.frame(*this, stage, frames_++);  // the stage ended between frame times
  r.simulated_time = stage_time_;
  close_energy_balance(r, p.kinetic_start, p.elastic_start);
  r.metrics = measure_stage(world());
  r.wall_time += seconds_since(wall_start_);
  finish_stage(stage, r, observer);
}

}  // namespace sim
