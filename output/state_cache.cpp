#include "output/state_cache.hpp"

#include <cstdio>
#include <iostream>

#include "output/checksum.hpp"
#include "sim/io/atomic_file.hpp"
#include "sim/io/file_bytes.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// "LSCACHE" and a format version; then the state and a CRC-32 of it all.
constexpr std::uint64_t kMagic = 0x4c53434143484501ULL;

// The state saved in `file`, or "" (after saying why) when it is damaged or
// from an older build: the stages are computed again and the file replaced,
// which gives the same run (it is deterministic), so a bad cache file never
// stops a run.
std::string read_cached_state(const fs::path& file) {
  try {
    std::string bytes = sim::read_file_bytes(file, file.string() + ": cannot read");
    sim::BinaryReader r(bytes, file.string());
    if (bytes.size() < 8 || r.get<std::uint64_t>() != kMagic)
      r.fail("not a cached state of this version of landslide (an older build's, without a "
             "checksum?)");
    strip_checksum(bytes, file);
    std::string state = r.get_string();
    if (!r.at_end()) r.fail("bytes after the end of the cached state");
    return state;
  } catch (const sim::StateError& e) {
    std::cerr << "note: " << e.what() << "; computing the shared stages again and replacing it\n";
    return "";
  }
}

}  // namespace

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
  const std::string state = read_cached_state(file);
  if (state.empty()) return 0;
  sim.restore_state(state, file.string());
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
  sim::BinaryWriter w;
  w.put(kMagic);
  w.put_string(sim.save_state());
  append_checksum(w);
  write_bytes_atomically(file, w);
}

}  // namespace app
