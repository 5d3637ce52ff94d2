// The run summary (DIR/summary.json): what ran, how long it took, and the
// state at the end of each stage. Rewritten after every stage, so the file is
// valid even if a later stage fails.
#pragma once

#include <nlohmann/json.hpp>

#include "sim/simulation.hpp"

namespace app {

nlohmann::json make_summary(const sim::Simulation& simulation, int threads, double wall_time,
                            const std::string& status);

}  // namespace app
