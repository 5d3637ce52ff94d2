// The runout: "the extent of an eventual slide" of the paper's introduction,
// defined once. StageMetrics (summary.json), `landslide validate`, the
// benches and the gallery all take it from here.
//
// The soil's deposit thickness along x is the area of its points (their
// volume per unit thickness, m_p / rho_p, spread evenly over the width of
// their squares, side sqrt(V_p) as the painter draws them) per unit length,
// averaged over a window 5 % of the soil's initial height wide (0.5 m for
// the paper's slope, 5 mm for the Bui column): a length of the scene, not
// of the grid, so that the same deposit has the same toe at every
// resolution. (A window of one cell saw the gaps between the points of a
// thin tail at fine grids: the paper slope's runout at 8370 points changed by
// 9.7 % when the time step halved.) For a packed deposit it is the height
// of the free surface; a tail of scattered points counts by the soil it
// holds, not by the height of its highest point, and a gap ends the deposit.
//
// The toe is where the deposit ends: walking in +x (the scenes slide that
// way) from a start, the first x where the thickness falls below 1.5 % of
// the soil's initial height. The initial toe is that walk over the initial
// state from the soil's leftmost point; the final toe is the walk over the
// state now from the initial toe. Runout = final toe - initial toe.
//
// 1.5 % comes from the Bui et al. (2008) column, whose digitised deposit
// ends at 1.52 mm of its 100 mm height (tests/validation/README.md): the
// experiment's toe is then defined by its own data, and the same fraction
// of the height serves every scene (0.15 m for the paper's 10 m slope).
#pragma once

#include <vector>

#include "sim/physics/world.hpp"

namespace sim {

constexpr double kToeThicknessFraction = 0.015;
constexpr double kToeWindowFraction = 0.05;

// The deposit thickness of the soil over a window `window` wide, sampled
// every `step` from x_begin: sample k is at x_begin + (k + 0.5) step.
struct ThicknessProfile {
  double x_begin = 0, step = 0;
  std::vector<double> thickness;
  double x(std::size_t k) const { return x_begin + (static_cast<double>(k) + 0.5) * step; }
};

// `initial`: the points at their initial positions, with their initial
// volumes (m_p / rho_0 of their material).
ThicknessProfile deposit_thickness(const World& world, bool initial, double window);

// The first x at or beyond `start` where the profile is thinner than
// `threshold` (linear between samples); the profile's end when it never is.
double toe_beyond(const ThicknessProfile& profile, double start, double threshold);

struct Runout {
  double initial_toe = 0, toe = 0, runout = 0;  // m
  double threshold = 0;                         // the thickness that ends the deposit, m
  double window = 0;                            // over which the thickness is taken, m
};

// The runout of the soil (Mohr-Coulomb points) of `world`; all zero without soil.
Runout measure_runout(const World& world);

}  // namespace sim
