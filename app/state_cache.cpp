#include "app/state_cache.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "sim/atomic_file.hpp"

namespace app {

namespace fs = std::filesystem;

fs::path cached_state_path(const fs::path& dir, const sim::Scenario& scenario) {
  const std::size_t stages = sim::reusable_stages(scenario);
  if (stages == 0) return {};
  char name[40];
  std::snprintf(name, sizeof name, "gravity-%016llx.state",
                static_cast<unsigned long long>(sim::stage_prefix_key(scenario, stages)));
  return dir / name;
}

fs::path cached_series_path(const fs::path& dir, const sim::Scenario& scenario) {
  fs::path file = cached_state_path(dir, scenario);
  return file.empty() ? file : file.replace_extension(".series.csv");
}

std::size_t restore_cached_state(const fs::path& dir, sim::Simulation& sim) {
  const fs::path file = cached_state_path(dir, sim.scenario());
  // A state saved without its series (by an older build) is computed again.
  if (file.empty() || !fs::exists(file) || !fs::exists(cached_series_path(dir, sim.scenario())))
    return 0;
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  sim.restore_state(bytes.str(), file.string());
  return sim.stage_index();
}

void save_cached_state(const fs::path& dir, const sim::Simulation& sim,
                       const std::string& series_csv) {
  const fs::path file = cached_state_path(dir, sim.scenario());
  if (file.empty()) return;
  fs::create_directories(dir);
  // The series first: a state without one beside it is not used.
  sim::write_file_atomically(cached_series_path(dir, sim.scenario()).string(),
                             [&](std::ostream& o) { o << series_csv; });
  const std::string state = sim.save_state();
  sim::write_file_atomically(file.string(), [&](std::ostream& o) {
    o.write(state.data(), std::streamsize(state.size()));
  });
}

}  // namespace app
