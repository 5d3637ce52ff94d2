// What a sweep reports per member, read from its summary.json: DIR/sweep.csv
// (byte-identical between runs and rank counts: no wall times in it) and
// DIR/sweep.json (the same and each member's wall time).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/image.hpp"

#include "sweep/sweep_file.hpp"

namespace sweep {

struct MemberResult {
  int index = 0;
  std::vector<nlohmann::json> values;  // one per axis
  int sample = 0;                      // of the random fields
  std::vector<std::uint64_t> seeds;    // one per random field
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
// for each combination of the other axes' values (the mean over the samples
// where the sweep has random fields); and with random fields
// DIR/sweep-exceedance.png, P(runout > L) with its confidence band.
void write_plots(const Sweep& sweep, const std::vector<MemberResult>& results,
                 const std::filesystem::path& out);

// The empirical exceedance curve P(runout > L) of n runouts, as a staircase
// (x rising, p falling from 1 to 0), and a simultaneous confidence band of
// level `confidence` around it: the Dvoretzky-Kiefer-Wolfowitz inequality
// with Massart's constant (Ann. Math. Stat. 27 (1956) 642-669; Ann. Probab.
// 18 (1990) 1269-1283), P(sup |F_n - F| > eps) <= 2 exp(-2 n eps^2), so
// eps = sqrt(ln(2 / (1 - confidence)) / (2 n)) holds for any n and any F.
struct Exceedance {
  int n = 0;
  double eps = 0;  // half-width of the band
  std::vector<double> x, p;  // staircase vertices
};
Exceedance exceedance(std::vector<double> runouts, double confidence);

// "PATH = VALUE, ..." of a member's axes but axis `skip` (axes.size(): none
// skipped), as the plots' legends name a curve.
std::string axes_label(const Sweep& sweep, const MemberResult& result, std::size_t skip);

// The colour of curve k of a sweep's plots (they cycle).
render::Rgba curve_colour(std::size_t k);

// DIR/sweep-exceedance.png: one curve and band per combination of the axes,
// over the members that finished with a runout.
void write_exceedance_plot(const Sweep& sweep, const std::vector<MemberResult>& results,
                           const std::filesystem::path& out);

}  // namespace sweep
