#include "app/sweep_command.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/preflight.hpp"

namespace app {

namespace {

// --paint 0,3: the members, each a number.
std::set<int> parse_members(const std::string& text) {
  std::set<int> members;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    int n = -1;
    try {
      n = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || n < 0)
      throw CLI::ValidationError("--paint " + text + ": '" + item +
                                 "': expected member numbers from 0, separated by commas");
    members.insert(n);
  }
  return members;
}

int run_member(const sweep::MemberRun& m) {
  RunOptions run;
  run.scenario = m.scene.string();
  run.out_dir = m.out.string();
  run.state_cache = m.state_cache.string();
  run.threads = m.threads;
  run.allow_long = m.allow_long;
  run.overwrite = true;  // a member stopped part-way runs again from its start
  return run_command(run);
}

// The point-steps, still to run in `p`, of the stages a cached gravity state
// skips: a member that finds its state in the cache does not run them.
double shared_point_steps(const sim::Scenario& s, const Prepared& p) {
  if (p.reused_stages > 0) return 0;  // restored already: not in the estimate
  double steps = 0;
  std::size_t timed = 0;  // the estimate lists timed stages only
  for (std::size_t k = 0; k < sim::reusable_stages(s); ++k)
    if (s.stages[k].type != sim::StageType::MaterialChange)
      steps += p.estimate.stages.at(timed++).steps;
  return steps * double(p.estimate.points);
}

// The preflight run_member's `landslide run` will go through at the member's
// turn, with the same options, asked now.
sweep::MemberCheck check_member(const sweep::MemberRun& m, const sim::Scenario& scenario) {
  PreflightRequest q;
  q.scenario = &scenario;
  q.scenario_file = m.scene.string();
  q.out = m.out;
  q.state_cache = m.state_cache;
  q.overwrite = true;  // as run_member
  q.allow_long = m.allow_long;
  q.threads = use_threads(m.threads);
  Prepared p;
  std::ostringstream unused;  // the sweep prints one estimate for all its members
  const Verdict v = preflight_verdict(q, p, unused);
  sweep::MemberCheck c;
  c.refusal = v.refusal;
  c.warning = v.warning;
  if (!c.refusal.empty()) return c;
  c.point_steps = p.estimate.point_steps;
  c.shared_point_steps = shared_point_steps(scenario, p);
  c.wall_seconds = p.estimate.wall_seconds;
  c.point_steps_per_second = p.estimate.point_steps_per_second;
  c.threads = p.estimate.threads;
  c.may_end_early = p.estimate.may_end_early;
  return c;
}

}  // namespace

CLI::App* add_sweep_command(CLI::App& cli, sweep::SweepOptions& o) {
  CLI::App* cmd = cli.add_subcommand(
      "sweep", "Run a scene over a grid of parameter values (spread over MPI ranks under mpirun)");
  cmd->add_option("sweep", o.file, "Sweep JSON file: the base scene and the axes")->required();
  cmd->add_option("--out", o.out_dir, "Output directory")->required();
  cmd->add_option_function<std::string>(
      "--paint", [&o](const std::string& text) { o.paint = parse_members(text); },
      "Members that paint the base scene's frames and VTK states, e.g. 0,3 (default: none)");
  add_threads_option(*cmd, o.threads, "OpenMP threads of each member (default: all cores)");
  cmd->add_flag("--allow-long", o.allow_long,
                "Run members whose estimate passes the limits (time, steps, memory, disk)");
  cmd->add_flag("--check", o.check_only,
                "Put every member to run through run's preflight and print the sweep's "
                "estimate; run nothing, write nothing");
  return cmd;
}

int sweep_command(const sweep::SweepOptions& options) {
  try {
    return sweep::run_sweep(options, run_member, check_member);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitFailed;
  }
}

}  // namespace app
