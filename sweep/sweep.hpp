// `landslide sweep SWEEP.json --out DIR` (README.md, "landslide sweep"): runs
// every member of a sweep (sweep/sweep_file.hpp) into DIR/members/NNNN/, its
// gravity stages shared through DIR/state-cache, then writes DIR/sweep.csv,
// DIR/sweep.json and DIR/sweep-AXIS.png. The run of one member is handed in
// (app/ holds it: the command line's `run`), so this part does not depend on
// the command line.
#pragma once

#include <filesystem>
#include <functional>
#include <set>
#include <string>

namespace sweep {

struct SweepOptions {
  std::string file;     // the sweep file
  std::string out_dir;  // DIR
  std::set<int> paint;  // members that paint the base scene's frames
  int threads = 0;      // OpenMP threads of each member's run; 0: OpenMP's default
  bool allow_long = false;
};

// One member's run: `landslide run SCENE --out OUT --state-cache CACHE
// --overwrite`, returning its exit status (output/exit_status.hpp).
struct MemberRun {
  std::filesystem::path scene, out, state_cache;
  int threads = 0;
  bool allow_long = false;
};
using RunMember = std::function<int(const MemberRun&)>;

// The exit status: 2 (nothing run) for a bad sweep file, 1 if a member
// failed, 130 / 143 if one was stopped, else 0.
int run_sweep(const SweepOptions& options, const RunMember& run_member);

}  // namespace sweep
