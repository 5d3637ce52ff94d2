// The run summary (DIR/summary.json): what ran, how long it took, and the
// state at the end of each stage. Rewritten after every stage, so the file is
// valid even if a later stage fails.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/run/simulation.hpp"

namespace app {

// The terms of a stage's energy balance (Eq. 3) under the names summary.json
// and series.csv give them, in the order of sim::EnergyBalance.
std::vector<std::pair<std::string, double>> energy_terms(const sim::EnergyBalance& e);

nlohmann::json make_summary(const sim::Simulation& simulation, int threads, double wall_time,
                            const std::string& status);

}  // namespace app
