#include "sweep/sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <vector>

#include "output/exit_status.hpp"
#include "output/output_dir.hpp"
#include "sim/io/atomic_file.hpp"
#include "sweep/ranks.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_results.hpp"
#include "sweep/whole_lines.hpp"

namespace sweep {

namespace fs = std::filesystem;

namespace {

bool stopped(int status) {
  return status == app::kExitInterrupted || status == app::kExitTerminated;
}

// Runs one member (writing its scene first); the worse of `status` and its own.
int run_one(const Sweep& s, const SweepOptions& o, const RunMember& run_member, int index,
            int rank, int status) {
  if (stopped(status)) return status;  // Ctrl-C: no further members
  const Member& m = s.members[index];
  const MemberRun r = member_run(o, index);
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

// Rank 0 alone puts the members through the preflight (one calibration of
// the step rate, one set of messages); every rank gets its verdict, so all
// stop or go on together (an exception on rank 0 too: the others would wait
// for it forever). Prints to `say`: stdout for --check, else stderr.
int preflight_members(const Sweep& s, const Plan& plan, const SweepOptions& o,
                      const CheckMember& check_member, Ranks& ranks, std::ostream& say) {
  int status = app::kExitOk;
  if (ranks.rank() == 0) {
    try {
      SweepEstimate e;
      if (check_members(s, plan, o, check_member, ranks.size(), e))
        print_sweep_estimate(say, e);
      else
        status = app::kExitBadInput;
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << '\n';
      status = app::kExitFailed;
    }
  }
  return ranks.max_over_ranks(status);
}

}  // namespace

int run_sweep(const SweepOptions& o, const RunMember& run_member,
              const CheckMember& check_member) {
  Ranks ranks;
  // Several ranks share the terminal: each line goes out whole.
  std::optional<WholeLines> whole_errors, whole_output;
  if (ranks.size() > 1) {
    whole_errors.emplace(std::cerr, STDERR_FILENO);
    whole_output.emplace(std::cout, STDOUT_FILENO);
  }
  Sweep s;
  if (checked_sweep(o, s, ranks.rank() == 0) != app::kExitOk) return app::kExitBadInput;
  std::vector<bool> done(s.members.size());
  int skipped = 0;
  for (const Member& m : s.members)
    skipped += done[m.index] = member_finished(member_dir(o.out_dir, m.index), m.scene_text);
  const Plan plan = make_plan(s, fs::path(o.out_dir) / "state-cache", done);
  std::ostream& say = o.check_only ? std::cout : std::cerr;
  if (ranks.rank() == 0)
    say << "sweep: " << s.members.size() << " members over " << ranks.size() << " rank(s); "
        << skipped << " already finished, not run again\n";
  if (const int verdict = preflight_members(s, plan, o, check_member, ranks, say);
      verdict != app::kExitOk)
    return verdict;
  if (o.check_only) {
    if (ranks.rank() == 0) say << o.file << ": ok (nothing run, nothing written)\n";
    return app::kExitOk;
  }
  int status = app::kExitOk;
  if (ranks.rank() == 0)
    for (int index : plan.first) status = run_one(s, o, run_member, index, 0, status);
  ranks.barrier();
  for (std::size_t k = 0; k < plan.rest.size(); ++k)
    if (rest_rank(plan, k, ranks.size()) == ranks.rank())
      status = run_one(s, o, run_member, plan.rest[k], ranks.rank(), status);
  status = ranks.max_over_ranks(status);
  if (ranks.rank() == 0) report(s, o.out_dir);
  return status;
}

}  // namespace sweep
