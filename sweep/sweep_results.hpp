// What a sweep reports per member, read from its summary.json: DIR/sweep.csv
// (byte-identical between runs and rank counts: no wall times in it) and
// DIR/sweep.json (the same and each member's wall time).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_file.hpp"

namespace sweep {

struct MemberResult {
  int index = 0;
  std::vector<nlohmann::json> values;  // one per axis
  std::string status;  // the summary's ("finished", "failed: ..."), or "not run"
  // Of the last dynamic stage; null where the member has none (or no summary).
  nlohmann::json runout_m, deposit_slope_deg, max_displacement_m, at_rest, energy_relative_error;
  nlohmann::json wall_time_s;  // the whole member run
};

// Whether the member's folder holds a finished run of exactly this scene.
bool member_finished(const std::filesystem::path& dir, const std::string& scene_text);

MemberResult read_result(const Member& member, const std::filesystem::path& out);

// sweep.csv and sweep.json, each written to a temporary name and renamed.
void write_results(const Sweep& sweep, const std::vector<MemberResult>& results,
                   const std::filesystem::path& out);

// DIR/sweep-AXIS.png for each axis of numbers: runout against it, one curve
// for each combination of the other axes' values.
void write_plots(const Sweep& sweep, const std::vector<MemberResult>& results,
                 const std::filesystem::path& out);

}  // namespace sweep
