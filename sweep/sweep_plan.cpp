#include "sweep/sweep_plan.hpp"

#include <algorithm>
#include <iostream>
#include <map>

#include "output/amount_text.hpp"
#include "output/counted.hpp"
#include "output/state_cache.hpp"

namespace sweep {

namespace fs = std::filesystem;

namespace {

// The plan's wall time: rank 0 runs `first` while the others wait at the
// barrier, then each rank its share of `rest`.
double elapsed_seconds(const Plan& plan, const std::map<int, double>& seconds, int ranks) {
  double first = 0;
  for (int index : plan.first) first += seconds.at(index);
  std::vector<double> rank_seconds(std::max(ranks, 1), 0.0);
  for (std::size_t k = 0; k < plan.rest.size(); ++k)
    rank_seconds[rest_rank(plan, k, ranks)] += seconds.at(plan.rest[k]);
  return first + *std::max_element(rank_seconds.begin(), rank_seconds.end());
}

}  // namespace

Plan make_plan(const Sweep& s, const fs::path& cache, const std::vector<bool>& done) {
  Plan p;
  std::map<fs::path, bool> seen;
  std::set<fs::path> computed;  // by a member of `first`
  for (const Member& m : s.members) {
    const fs::path state = app::cached_state_path(cache, m.scenario);
    const bool needs_state = !state.empty() && !seen[state] && !fs::exists(state);
    if (!state.empty()) seen[state] = true;
    if (done[m.index]) continue;
    if (needs_state) computed.insert(state);
    else if (computed.count(state)) p.reuses.insert(m.index);
    (needs_state ? p.first : p.rest).push_back(m.index);
  }
  return p;
}

int rest_rank(const Plan& plan, std::size_t k, int ranks) {
  return static_cast<int>((k + plan.first.size()) % static_cast<std::size_t>(std::max(ranks, 1)));
}

MemberRun member_run(const SweepOptions& o, int index) {
  MemberRun r;
  r.out = member_dir(o.out_dir, index);
  r.scene = r.out / "scene.json";
  r.state_cache = fs::path(o.out_dir) / "state-cache";
  r.threads = o.threads;
  r.allow_long = o.allow_long;
  return r;
}

bool check_members(const Sweep& s, const Plan& plan, const SweepOptions& o,
                   const CheckMember& check, int ranks, SweepEstimate& e) {
  std::vector<int> order = plan.first;
  order.insert(order.end(), plan.rest.begin(), plan.rest.end());
  std::sort(order.begin(), order.end());
  e = SweepEstimate{};
  e.ranks = ranks;
  std::map<int, double> seconds;
  for (int index : order) {
    const Member& m = s.members[index];
    const MemberCheck c = check(member_run(o, index), m.scenario);
    if (!c.refusal.empty()) {
      std::cerr << "error: " << member_name(s, m) << ": " << c.refusal << '\n';
      return false;
    }
    if (!c.warning.empty())
      std::cerr << "warning: " << member_name(s, m) << ": " << c.warning
                << "; going on (--allow-long)\n";
    // Its gravity stages come from the cache: a member of `first` computes them.
    const double skipped = plan.reuses.count(index) ? c.shared_point_steps : 0;
    seconds[index] = c.wall_seconds - (skipped > 0 ? skipped / c.point_steps_per_second : 0);
    e.members += 1;
    e.point_steps += c.point_steps - skipped;
    e.member_seconds += seconds[index];
    e.point_steps_per_second = c.point_steps_per_second;
    e.threads = c.threads;
    e.may_end_early = e.may_end_early || c.may_end_early;
  }
  if (!order.empty()) e.elapsed_seconds = elapsed_seconds(plan, seconds, ranks);
  return true;
}

void print_sweep_estimate(std::ostream& out, const SweepEstimate& e) {
  if (e.members == 0) {
    out << "sweep estimate: no member to run\n";
    return;
  }
  const char* upto = e.may_end_early ? "up to " : "";
  out << "sweep estimate: " << app::counted(e.members, "member") << " to run, " << upto
      << app::count_text(e.point_steps) << " point-steps (shared gravity stages once)\n"
      << "  wall time: " << upto << "about " << app::duration_text(e.elapsed_seconds) << " on "
      << app::counted(e.ranks, "rank") << " (" << app::duration_text(e.member_seconds)
      << " of member runs at " << app::count_text(e.point_steps_per_second)
      << " point-steps/s on " << app::counted(e.threads, "thread")
      << " per rank, measured now)\n";
}

}  // namespace sweep
