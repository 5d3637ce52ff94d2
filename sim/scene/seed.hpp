// Turning the scenario's bodies into material points (paper Eqs. 5-7):
// points_per_cell^2 points per cell at sub-cell centres, each carrying the
// mass of its sub-cell, zero stress and zero velocity.
#pragma once

#include "sim/physics/world.hpp"
#include "sim/scene/scenario.hpp"

namespace sim {

// Builds the world of a scenario: grid, material constants and points.
World make_world(const Scenario& scenario);

}  // namespace sim
