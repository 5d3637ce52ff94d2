// Before a sweep runs: which rank runs which member, every member to run
// through `landslide run`'s preflight, and what the sweep will cost
// (README.md, "landslide sweep"). A member that run would refuse stops the
// sweep here, before any member runs or any member folder is made.
#pragma once

#include <filesystem>
#include <ostream>
#include <set>
#include <vector>

#include "sweep/sweep.hpp"
#include "sweep/sweep_file.hpp"

namespace sweep {

// Which rank runs which member. Rank 0 first runs, for each distinct set of
// shared gravity stages (one cached state file), the first member that needs
// it, so that state is computed once and lies in the cache before any other
// rank looks for it; the other members go round-robin over the ranks,
// starting where `first` left off (rest_rank).
struct Plan {
  std::vector<int> first;  // rank 0, before the barrier
  std::vector<int> rest;   // member rest[k] on rank rest_rank(plan, k, ranks)
  std::set<int> reuses;    // members of rest that start from a state `first` computes
};

// The plan for the members not `done`, against what the cache holds now.
Plan make_plan(const Sweep& s, const std::filesystem::path& cache, const std::vector<bool>& done);

// The rank of member rest[k]: (k + first.size()) % ranks. Rank 0 has run the
// members of `first` while the others waited, so the round starts after it:
// 8 members on 2 ranks, one of them first, run 4 and 4, not 5 and 3.
int rest_rank(const Plan& plan, std::size_t k, int ranks);

// Member `index`'s run as run_one hands it to RunMember.
MemberRun member_run(const SweepOptions& o, int index);

// The sum of the members' estimates.
struct SweepEstimate {
  int members = 0;               // to run
  double point_steps = 0;        // a shared gravity stage counted once
  double member_seconds = 0;     // the members' wall times added up
  double elapsed_seconds = 0;    // the plan's: rank 0's first members, then the slowest rank
  double point_steps_per_second = 0;  // on one rank
  int threads = 1, ranks = 1;
  bool may_end_early = false;    // a member may come to rest sooner
};

// Each member of the plan through `check` in member order. On the first
// refusal prints "error: SWEEP: member N (PATH = VALUE, ...): MESSAGE" on
// stderr and returns false; a limit --allow-long lets pass is a "warning:"
// line in the same form.
bool check_members(const Sweep& s, const Plan& plan, const SweepOptions& o,
                   const CheckMember& check, int ranks, SweepEstimate& estimate);

// One line: members to run, point-steps, wall time over the ranks.
void print_sweep_estimate(std::ostream& out, const SweepEstimate& e);

}  // namespace sweep
