// What a stage did, measured on the points at its end: how far the soil went,
// whether it stayed together, how steep the deposit is, and the energy
// balance of the paper's Eq. (3). Soil means points of Mohr-Coulomb
// materials; the rest (the house) is reported per material.
#pragma once

#include <string>
#include <vector>

#include "sim/physics/world.hpp"

namespace sim {

// Energy of Eq. (3) over a stage, J per metre of thickness. The balance:
// external_work = kinetic_change + internal_work + damping_loss + wall_loss + friction_work
//                 + transfer_loss,
// where the internal (stress) work splits into elastic_energy_change + plastic_dissipation.
struct EnergyBalance {
  double external_work = 0;          // by gravity
  double kinetic_change = 0;         // of the points
  double internal_work = 0;          // sum over steps of V sigma : d eps
  double elastic_energy_change = 0;  // stored strain energy, end minus start
  double plastic_dissipation = 0;    // internal_work - elastic_energy_change
  double damping_loss = 0;           // taken by v := v / (1 + theta)
  double wall_loss = 0;              // taken by the walls' holds and contact (inelastic)
  double friction_work = 0;          // taken by the friction of friction walls
  double transfer_loss = 0;          // lost by the point-grid transfers (StepReport::transfer_loss)
  double relative_error = 0;  // what the terms above leave of external_work, / |external_work|
};

struct MaterialMotion {
  std::string material;
  double mean_ux = 0, mean_uy = 0;  // mean displacement from the initial positions, m
  double max_displacement = 0;      // largest |u|, m
};

// The band of density, relative to the initial one, that counts as packed.
constexpr double kPackedDensityBand = 0.10;

// How far the soil and each material went: what a row of series.csv reads.
struct StageMotion {
  double max_soil_ux = 0;       // largest |x - x0| of soil, m
  // The soil's toe before any load and now, and the runout toe -
  // initial_toe, m: one definition everywhere (sim/run/runout.hpp).
  double initial_toe = 0, toe = 0, runout = 0;
  std::vector<MaterialMotion> materials;
};

// And the state of the soil's body, as summary.json reports it per stage.
struct StageMetrics : StageMotion {
  double main_body_fraction = 1;  // soil points in the largest connected group of cells
  // Soil mass within kPackedDensityBand of its material's initial density: a
  // packed deposit, not a loose cloud (sim/physics/granular.hpp).
  double packed_fraction = 1;
  // Soil mass below its critical density: disconnected, carrying no stress.
  double disconnected_fraction = 0;
  double yielding_fraction = 0;   // soil points that yielded in the last step
  double deposit_slope_deg = 0;   // NaN where no slope can be fitted (see .cpp)
};

// Both measure the points where they are stored, on the run's threads, with
// the same bits at any thread count (sim/run/point_chunks.hpp).
StageMotion measure_motion(const World& world);
StageMetrics measure_stage(const World& world);

// Kinetic energy of the points, sum m |v|^2 / 2, J/m.
double kinetic_energy(const World& world);

// Strain energy stored in the points, sum V sigma : C^-1 : sigma / 2, J/m.
double elastic_energy(const World& world);

}  // namespace sim
