// landslide: simulate a scenario, check one, (and paint it, as the painter lands).
#include <CLI/CLI.hpp>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  CLI::App cli{"Landslide Studio: GIMP landslide simulation, painted off-screen"};
  cli.set_version_flag("--version", LANDSLIDE_VERSION);
  cli.require_subcommand(1);

  app::RunOptions run;
  CLI::App* run_cmd = cli.add_subcommand("run", "Run a scenario and write its outputs");
  run_cmd->add_option("scenario", run.scenario, "Scenario JSON file")->required();
  run_cmd->add_option("--out", run.out_dir, "Output directory")->required();
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (default: all cores)")
      ->check(CLI::Range(1, 1024));

  std::string check_path;
  CLI::App* check_cmd = cli.add_subcommand("check", "Validate a scenario; write nothing");
  check_cmd->add_option("scenario", check_path, "Scenario JSON file")->required();

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : app::kExitBadInput;
  }
  if (*run_cmd) return app::run_command(run);
  if (*check_cmd) return app::check_command(check_path);
  return app::kExitBadInput;
}
