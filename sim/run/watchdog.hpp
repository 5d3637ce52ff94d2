// The watchdog: the limits a run must stay within, checked between steps.
// A run that leaves them stops with a message naming the stage, step, time,
// point, position and material, and hands the app the last state that was
// still within them, so a failure after an hour loses nothing.
#pragma once

#include <string>

#include "sim/physics/step.hpp"
#include "sim/physics/world.hpp"
#include "sim/scene/scenario.hpp"

namespace sim {

// Largest density of a point relative to its material's initial density. The
// soils here strain about 1 % under their own weight; a point squeezed to
// two-thirds of its volume means a crushed stencil, not soil. (Expansion has
// no bound: soil below its critical density carries no stress, so a torn-off
// point may stretch as far as the grid takes it, sim/physics/granular.hpp.)
constexpr double kMaxCompression = 1.5;

// Steps between full scans of the points. A non-finite value anywhere is
// caught every step through the step's sums; the density bound is checked
// at every scan.
constexpr int kWatchdogScanSteps = 50;

// Steps between saves of the last good state, each at a scan that passed. A
// save copies every point array, about half a step's time, while the time
// loop holds the team. On the 66,787-point slope, 2 threads, 16,119 steps
// (a throw-away timer, issue 17, fortieth pass): at every scan 322 saves
// took 0.44 s of a 35.9 s run (1.2 %), at every fifth 64 took 0.08 s of
// 32.8 s. A failure loses at most these steps' work (about a second on
// that slope; a few minutes at 10 M points).
constexpr int kWatchdogSaveSteps = 250;
static_assert(kWatchdogSaveSteps % kWatchdogScanSteps == 0, "a save needs a scan");

// The run stopped by a watchdog (or by any SimulationError of the step).
// `last_good_state` is Simulation::save_state() from the last save (the
// stage's start, or a scan that passed at a multiple of kWatchdogSaveSteps;
// empty if none had yet), at simulated time `last_good_time`.
class WatchdogError : public SimulationError {
 public:
  WatchdogError(const std::string& what, std::string last_good_state, double last_good_time)
      : SimulationError(what),
        last_good_state(std::move(last_good_state)),
        last_good_time(last_good_time) {}
  std::string last_good_state;
  double last_good_time;
};

// True when every sum of the step is finite: a NaN or infinity in any
// velocity, stress or density shows up in them.
bool step_sums_finite(const StepReport& report);

// The first point (by scene index, wherever it is stored) with a non-finite
// position, velocity, stress or density, or a density above the bound: a
// message naming it, its position and its material; "" when every point is
// within the limits.
std::string find_bad_point(const World& world);

// What to do about world.bad_point, the first point that left the grid: the
// wall it passed (by its position against the domain), what that wall holds
// and the fix, e.g. "; it passed the right wall (x = 80 m), which is "free":
// ...". A point cannot be dropped (the run's mass and energy balance hold
// every point), and the grid ends padding_cells beyond each wall, so past a
// free wall the run cannot go on. "" when the point's position is not finite
// or inside the domain.
std::string left_grid_advice(const World& world, const Scenario& scenario);

}  // namespace sim
