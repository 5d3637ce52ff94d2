// Saved gravity-stage states shared between runs (`landslide run
// --state-cache DIR`, and the gallery): DIR/gravity-<key>.state, where the
// key (sim::stage_prefix_key) covers every input that defines the stages the
// state ends. A scene whose first stages match a saved state starts from it
// instead of computing them again. Beside it, gravity-<key>.series.csv: the
// rows of output/series.hpp those stages wrote, so the run's series.csv is the
// same either way. The .state file holds "LSCACHE", the state and a CRC-32
// (output/checksum.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "sim/run/simulation.hpp"

namespace app {

// The file a scenario's shared stages are saved in; empty if it has none.
std::filesystem::path cached_state_path(const std::filesystem::path& dir,
                                        const sim::Scenario& scenario);
std::filesystem::path cached_series_path(const std::filesystem::path& dir,
                                         const sim::Scenario& scenario);
// Restores the saved state if there is one (with its series beside it); returns the stages it
// skips (0 when nothing was restored). A damaged file (its CRC-32 does not match) or one of an
// older build is noted on stderr and not used: the run computes the stages and replaces it.
// Throws sim::StateError for a state whose checksum holds but which does not fit the scenario.
std::size_t restore_cached_state(const std::filesystem::path& dir, sim::Simulation& sim);
// Saves the state at the end of the shared stages (call then, and only
// then), and `series_csv`, the series so far.
void save_cached_state(const std::filesystem::path& dir, const sim::Simulation& sim,
                       const std::string& series_csv);

}  // namespace app
