// `landslide sweep SWEEP.json --out DIR` (README.md, "landslide sweep"): runs
// every member of a sweep (sweep/sweep_file.hpp) into DIR/members/NNNN/, its
// gravity stages shared through DIR/state-cache, then writes DIR/sweep.csv,
// DIR/sweep.json and DIR/sweep-AXIS.png. The run of one member and its
// preflight are handed in (app/ holds them: the command line's `run`), so
// this part does not depend on the command line.
#pragma once

#include <filesystem>
#include <functional>
#include <set>
#include <string>

#include "sim/scene/scenario.hpp"

namespace sweep {

struct SweepOptions {
  std::string file;     // the sweep file
  std::string out_dir;  // DIR
  std::set<int> paint;  // members that paint the base scene's frames
  int threads = 0;      // OpenMP threads of each member's run; 0: OpenMP's default
  bool allow_long = false;
  bool check_only = false;  // --check: the members' preflight and the estimate; run none
};

// One member's run: `landslide run SCENE --out OUT --state-cache CACHE
// --overwrite`, returning its exit status (output/exit_status.hpp).
struct MemberRun {
  std::filesystem::path scene, out, state_cache;
  int threads = 0;
  bool allow_long = false;
};
using RunMember = std::function<int(const MemberRun&)>;

// What `landslide run`'s preflight (app/preflight.hpp) finds for one member,
// asked before any member runs, so that a member run would refuse stops the
// sweep before the others have run.
struct MemberCheck {
  std::string refusal;  // "": the member would run; else the preflight's one-line message
  std::string warning;  // a limit of the estimate --allow-long lets it pass ("" if none)
  double point_steps = 0;         // its estimate's, of the stages still to run
  double shared_point_steps = 0;  // of those, in the stages a cached gravity state skips
  double wall_seconds = 0;        // its estimate's
  double point_steps_per_second = 0;  // the step rate that estimate is built on
  int threads = 1;                    // and its threads
  bool may_end_early = false;         // a stage may come to rest sooner
};
// The member's scene comes parsed: its scene.json is not written yet.
using CheckMember = std::function<MemberCheck(const MemberRun&, const sim::Scenario&)>;

// Every member to run goes through `check_member` first (rank 0; the others
// learn the verdict); the sweep's estimate is printed, then the members run
// (none with check_only). The exit status: 2 (nothing run, no member folder
// made) for a bad sweep file or a member the preflight refuses, 1 if a
// member failed, 130 / 143 if one was stopped, else 0.
int run_sweep(const SweepOptions& options, const RunMember& run_member,
              const CheckMember& check_member);

}  // namespace sweep
