// Saved gravity-stage states shared between runs (`landslide run
// --state-cache DIR`, and the gallery): DIR/gravity-<key>.state, where the
// key (sim::stage_prefix_key) covers every input that defines the stages the
// state ends. A scene whose first stages match a saved state starts from it
// instead of computing them again.
#pragma once

#include <filesystem>

#include "sim/simulation.hpp"

namespace app {

// The file a scenario's shared stages are saved in; empty if it has none.
std::filesystem::path cached_state_path(const std::filesystem::path& dir,
                                        const sim::Scenario& scenario);
// Restores the saved state if there is one; returns the stages it skips (0
// when nothing was restored). Throws sim::StateError for a damaged file.
std::size_t restore_cached_state(const std::filesystem::path& dir, sim::Simulation& sim);
// Saves the state at the end of the shared stages (call then, and only then).
void save_cached_state(const std::filesystem::path& dir, const sim::Simulation& sim);

}  // namespace app
