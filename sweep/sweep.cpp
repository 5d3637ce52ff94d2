#include "sweep/sweep.hpp"

#include <algorithm>
#include <iostream>
#include <map>
#include <vector>

#include "output/exit_status.hpp"
#include "output/output_dir.hpp"
#include "output/state_cache.hpp"
#include "sim/io/atomic_file.hpp"
#include "sweep/ranks.hpp"
#include "sweep/sweep_results.hpp"

namespace sweep {

namespace fs = std::filesystem;

namespace {

// Which rank runs which member. Rank 0 first runs, for each distinct set of
// shared gravity stages (one cached state file), the first member that needs
// it, so that state is computed once and lies in the cache before any other
// rank looks for it; the other members go round-robin over the ranks.
struct Plan {
  std::vector<int> first;  // rank 0, before the barrier
  std::vector<int> rest;   // member rest[k] on rank k % ranks
};

Plan make_plan(const Sweep& s, const fs::path& cache, const std::vector<bool>& done) {
  Plan p;
  std::map<fs::path, bool> seen;
  for (const Member& m : s.members) {
    const fs::path state = app::cached_state_path(cache, m.scenario);
    const bool needs_state = !state.empty() && !seen[state] && !fs::exists(state);
    if (!state.empty()) seen[state] = true;
    if (done[m.index]) continue;
    (needs_state ? p.first : p.rest).push_back(m.index);
  }
  return p;
}

bool stopped(int status) {
  return status == app::kExitInterrupted || status == app::kExitTerminated;
}

// Runs one member (writing its scene first); the worse of `status` and its own.
int run_one(const Sweep& s, const SweepOptions& o, const RunMember& run_member, int index,
            int rank, int status) {
  if (stopped(status)) return status;  // Ctrl-C: no further members
  const Member& m = s.members[index];
  MemberRun r;
  r.out = member_dir(o.out_dir, index);
  r.scene = r.out / "scene.json";
  r.state_cache = fs::path(o.out_dir) / "state-cache";
  r.threads = o.threads;
  r.allow_long = o.allow_long;
  fs::create_directories(r.out);
  sim::write_file_atomically(r.scene.string(), [&](std::ostream& os) { os << m.scene_text; });
  std::cerr << "sweep: member " << index << " of " << s.members.size() << " on rank " << rank
            << '\n';
  const int own = run_member(r);
  if (stopped(own)) return own;
  return own == app::kExitOk ? status : std::max(status, app::kExitFailed);
}

// Rank 0: sweep.csv, sweep.json and the plots, from the members' summaries.
void report(const Sweep& s, const fs::path& out) {
  std::vector<MemberResult> results;
  for (const Member& m : s.members) results.push_back(read_result(m, out));
  write_results(s, results, out);
  write_plots(s, results, out);
  std::cerr << "sweep: " << (out / "sweep.csv").string() << ", " << (out / "sweep.json").string()
            << '\n';
}

int checked_sweep(const SweepOptions& o, Sweep& s, bool speaks) {
  try {
    app::check_writable_dir(o.out_dir, "--out");
    s = read_sweep(o.file, o.out_dir, o.paint);
  } catch (const std::exception& e) {  // SweepError, app::PathError
    if (speaks) std::cerr << "error: " << e.what() << '\n';
    return app::kExitBadInput;
  }
  return app::kExitOk;
}

}  // namespace

int run_sweep(const SweepOptions& o, const RunMember& run_member) {
  Ranks ranks;
  Sweep s;
  if (checked_sweep(o, s, ranks.rank() == 0) != app::kExitOk) return app::kExitBadInput;
  std::vector<bool> done(s.members.size());
  int skipped = 0;
  for (const Member& m : s.members)
    skipped += done[m.index] = member_finished(member_dir(o.out_dir, m.index), m.scene_text);
  const Plan plan = make_plan(s, fs::path(o.out_dir) / "state-cache", done);
  if (ranks.rank() == 0)
    std::cerr << "sweep: " << s.members.size() << " members over " << ranks.size()
              << " rank(s); " << skipped << " already finished, not run again\n";
  int status = app::kExitOk;
  if (ranks.rank() == 0)
    for (int index : plan.first) status = run_one(s, o, run_member, index, 0, status);
  ranks.barrier();
  for (std::size_t k = 0; k < plan.rest.size(); ++k)
    if (static_cast<int>(k % ranks.size()) == ranks.rank())
      status = run_one(s, o, run_member, plan.rest[k], ranks.rank(), status);
  status = ranks.max_over_ranks(status);
  if (ranks.rank() == 0) report(s, o.out_dir);
  return status;
}

}  // namespace sweep
