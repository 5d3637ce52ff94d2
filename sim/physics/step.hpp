// One explicit GIMP time step, in the paper's order (Section 5):
// update stress first (USF), momentum form, particle velocities updated by
// increments (Eqs. 26-31).
#pragma once

#include "sim/physics/world.hpp"

namespace sim {

struct StepInput {
  double dt = 0;
  Vec2 gravity{};      // body force per unit mass at this step
  double damping = 0;  // theta in v := v / (1 + theta) (paper Section 6)
};

// Sums over all points after the step, taken in a fixed order.
struct StepReport {
  double gravity_work = 0;    // work done by gravity during the step, J/m
  double kinetic_energy = 0;  // of the points after the step (and after damping), J/m
  // Of the velocity that moves the points, sum_i S_ip v_i^{k+1} (Eq. 29).
  // Point velocities (Eq. 30) can keep a part the grid cannot see, a null
  // space of the incremental update, so rest is judged on this one.
  double moving_kinetic_energy = 0;
  double internal_work = 0;   // sum_p V_p sigma : d eps over the step (Eq. 3), J/m
  double damping_loss = 0;    // kinetic energy the damping took, J/m
  // Kinetic energy the walls took from the grid, J/m: all of it at fixed and
  // roller walls, the normal part at friction walls.
  double wall_loss = 0;
  // Kinetic energy friction walls took from the grid through the tangential
  // impulse: the work of friction, J/m (sim/physics/wall_friction.hpp).
  double friction_work = 0;
  // The velocity change dv_i the walls make as the points receive it through
  // Eq. (30): sum_p m_p |sum_i S_ip dv_i|^2 / 2, J/m.
  double wall_change_on_points = 0;
  // Kinetic energy the grid-to-point transfer of the walls' change dissipates
  // beyond what the walls took, J/m. The points keep their own velocity and
  // add the interpolated change, so where the grid loses sum_i m_i |dv_i|^2 / 2
  // (at a hold: all of p_i, so the grid's loss is also wall_loss) the points
  // lose sum_i p_i . dv_i minus wall_change_on_points: transfer_loss = sum_i
  // m_i |dv_i|^2 / 2 - wall_change_on_points, >= 0 by Jensen's inequality.
  // Measured on the grid and the stencils, not taken as what closes the
  // balance of Eq. (3).
  double transfer_loss = 0;
  double max_signal = 0;      // max_p (c_p + |v_p|), m/s, for the next stable step
};

void step(World& world, const StepInput& input, StepReport& report);

// The phases, in the order step() runs them. Public so tests can drive them
// one by one (outside a parallel region the one thread owns every band).
void locate_points(World& world);  // GIMP stencils, Eqs. (12), (13); sorts into bands; throws
                                   // SimulationError if a point left the grid
void reset_grid(World& world);
void points_to_grid(World& world);  // nodal mass and momentum, Eqs. (26), (27), or APIC's; wall gaps
void enforce_walls_on_momentum(World& world);  // kinetic energy taken: grid.row_sums
// Eqs. (31), (24), (21)-(23), (25), then (16), (17); stress work: band_sums.
void update_stress_and_forces(World& world, const StepInput& input);
void update_nodal_momentum(World& world, double dt);  // Eq. (28)
void grid_to_points(World& world, const StepInput& input);  // Eqs. (29), (30); sums: band_sums
StepReport sum_step_report(const World& world);  // the sums above, in a fixed order

// locate_points as step() runs it, by every thread of its team: after
// prepare_locate (outside the team), locate_and_sort returns false on every
// thread if a point left the grid (world.bad_point), and the step then
// throws with throw_point_left_grid.
void prepare_locate(World& world);
bool locate_and_sort(World& world);
[[noreturn]] void throw_point_left_grid(const World& world);

// The stress update alone, every point in index order: returns the stress work.
double update_stress(World& world, double dt);

// Largest c_p + |v_p| over the points: the signal speed of the stable step
// (method notes, section 4).
double max_signal_speed(const World& world);

}  // namespace sim
