#include "app/sweep_command.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

#include "app/commands.hpp"

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

}  // namespace

CLI::App* add_sweep_command(CLI::App& cli, sweep::SweepOptions& o) {
  CLI::App* cmd = cli.add_subcommand(
      "sweep", "Run a scene over a grid of parameter values (spread over MPI ranks under mpirun)");
  cmd->add_option("sweep", o.file, "Sweep JSON file: the base scene and the axes")->required();
  cmd->add_option("--out", o.out_dir, "Output directory")->required();
  cmd->add_option_function<std::string>(
      "--paint", [&o](const std::string& text) { o.paint = parse_members(text); },
      "Members that paint the base scene's frames and VTK states, e.g. 0,3 (default: none)");
  cmd->add_option("--threads", o.threads, "OpenMP threads of each member (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--allow-long", o.allow_long,
                "Run members whose estimate passes the limits (time, steps, memory, disk)");
  return cmd;
}

int sweep_command(const sweep::SweepOptions& options) {
  try {
    return sweep::run_sweep(options, run_member);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitFailed;
  }
}

}  // namespace app
