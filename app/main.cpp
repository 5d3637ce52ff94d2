// landslide: simulate a scenario (and paint it), resume a stopped run, check
// a scenario, re-paint saved states, compose a panel of frames.
#include "landslide_version.hpp"
#include <CLI/CLI.hpp>

#include <cmath>
#include <functional>
#include <sstream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/new_command.hpp"
#include "app/gallery_monte_carlo.hpp"
#include "app/sweep_command.hpp"

namespace {

// --checkpoint-every: CLI::PositiveNumber would answer 0 with its range, a
// number of 309 digits; this says what the value means.
std::function<void(double)> positive_seconds(double& target) {
  return [&target](double v) {
    if (!(v > 0) || !std::isfinite(v)) {
      std::ostringstream msg;
      msg << "--checkpoint-every = " << v
          << ": expected a positive (finite) number of simulated seconds";
      throw CLI::ValidationError(msg.str());
    }
    target = v;
  };
}

// Each subcommand's arguments, read into the options its command takes
// (app/commands.hpp); `new` and `sweep` declare theirs beside their commands.
CLI::App* add_run_command(CLI::App& cli, app::RunOptions& run) {
  CLI::App* run_cmd = cli.add_subcommand("run", "Run a scenario and write its outputs");
  run_cmd->add_option("scenario", run.scenario, "Scenario JSON file")->required();
  run_cmd->add_option("--out", run.out_dir, "Output directory")->required();
  app::add_threads_option(*run_cmd, run.threads, "OpenMP threads (default: all cores)");
  run_cmd->add_option_function<double>(
      "--checkpoint-every", positive_seconds(run.checkpoint_every),
      "Write OUT/checkpoint.lsck every this many seconds of simulated time (Ctrl-C and "
      "SIGTERM always write one)");
  run_cmd->add_option("--state-cache", run.state_cache,
                      "Folder of saved gravity-stage states: start from a matching one, save "
                      "this run's if there is none");
  run_cmd->add_flag("--overwrite", run.overwrite,
                    "Remove an earlier run's outputs from --out first (without it such a folder "
                    "is refused)");
  run_cmd->add_flag("--allow-long", run.allow_long,
                    "Run a scene whose estimate passes the limits (time, steps, memory, disk)");
  return run_cmd;
}

CLI::App* add_resume_command(CLI::App& cli, app::ResumeOptions& resume) {
  CLI::App* resume_cmd = cli.add_subcommand(
      "resume", "Continue a stopped run from DIR/checkpoint.lsck, as if it had never stopped");
  resume_cmd->add_option("dir", resume.dir, "The stopped run's output directory")->required();
  app::add_threads_option(*resume_cmd, resume.threads, "OpenMP threads (default: all cores)");
  resume_cmd->add_option_function<double>(
      "--checkpoint-every", positive_seconds(resume.checkpoint_every),
      "Go on writing checkpoints every this many simulated seconds");
  resume_cmd->add_flag("--allow-long", resume.allow_long,
                       "Go on although the estimate of what is left passes the limits");
  return resume_cmd;
}

CLI::App* add_check_command(CLI::App& cli, app::RunOptions& check) {
  CLI::App* check_cmd = cli.add_subcommand(
      "check", "Everything `run` checks before simulating, and the run's estimate; write nothing");
  check_cmd->add_option("scenario", check.scenario, "Scenario JSON file")->required();
  check_cmd->add_option("--out", check.out_dir, "Check this output directory too");
  app::add_threads_option(*check_cmd, check.threads, "Threads the estimate is for");
  check_cmd->add_option("--state-cache", check.state_cache, "Check this state cache folder too");
  check_cmd->add_flag("--overwrite", check.overwrite,
                      "Accept an --out that holds an earlier run's outputs (run would remove them)");
  check_cmd->add_flag("--allow-long", check.allow_long,
                      "Accept an estimate past the limits (print it, exit 0)");
  return check_cmd;
}

// --range's two numbers land in `range`; main makes them render.range.
CLI::App* add_render_command(CLI::App& cli, app::RenderOptions& render,
                             std::vector<double>& range) {
  CLI::App* render_cmd =
      cli.add_subcommand("render", "Re-paint saved VTK states without simulating");
  render_cmd->add_option("input", render.input, "A .vtu file, or a run directory (DIR/vtk/points.pvd)")
      ->required();
  render_cmd->add_option("--scenario", render.scenario, "The run's scenario JSON file")
      ->required();
  render_cmd->add_option("--field", render.field,
                         "displacement-x | displacement-y | relative-yield | stress-yy | "
                         "velocity | material | cohesion | friction-angle")
      ->required();
  render_cmd->add_option("--colour-map", render.colour_map,
                         "jet | viridis (default: the scenario's)");
  render_cmd->add_option("--range", range, "Fixed colour range LO HI (default: per stage)")
      ->expected(2);
  render_cmd->add_option("--out", render.out,
                         "PNG file (one state) or directory (default: DIR/render/FIELD/, or "
                         "STATE-FIELD.png beside a .vtu)");
  render_cmd->add_flag("--video", render.video, "Also encode OUT/FIELD.mp4 and OUT/FIELD.gif");
  render_cmd->add_flag("--series", render.series,
                       "Put the run's series plot (RUN/series.csv) beside each frame, marked at "
                       "its time");
  return render_cmd;
}

CLI::App* add_panel_command(CLI::App& cli, app::PanelOptions& panel) {
  CLI::App* panel_cmd =
      cli.add_subcommand("panel", "Compose PNGs with captions into one rows x cols page");
  panel_cmd->add_option("out", panel.out, "Output .png")->required();
  panel_cmd->add_option("items", panel.items, "IMAGE.png CAPTION [IMAGE.png CAPTION ...]")
      ->required();
  panel_cmd->add_option("--title", panel.title, "Title above the panel");
  panel_cmd->add_option("--cols", panel.cols, "Images per row (default 2)")
      ->check(CLI::Range(1, 64));
  return panel_cmd;
}

CLI::App* add_gallery_command(CLI::App& cli, app::GalleryOptions& gallery) {
  CLI::App* gallery_cmd = cli.add_subcommand(
      "gallery", "Regenerate the paper's figures (5, 6, 9-12), the phi = 20 animation, the four "
      "friction angles side by side and (not with --quick) the Monte Carlo runout");
  gallery_cmd->add_option("--out", gallery.out, "Output directory")->required();
  gallery_cmd->add_option("--scenarios", gallery.scenarios,
                          "Folder of the paper-slope scenarios (default: scenarios)");
  gallery_cmd->add_flag("--quick", gallery.quick,
                        "Every run at the 1661-point resolution (h = 1.127 m), for a fast check");
  return gallery_cmd;
}

CLI::App* add_validate_command(CLI::App& cli, app::ValidateOptions& validate) {
  CLI::App* validate_cmd =
      cli.add_subcommand("validate", "Run the validation suite and print its table");
  validate_cmd->add_option("--scenarios", validate.scenarios, "Scenario folder (default: scenarios)");
  validate_cmd->add_flag("--quick", validate.quick, "Coarse resolutions only (the CI version)");
  validate_cmd->add_flag("--finest", validate.finest,
                         "Also the Bui column at h = 1.25 mm (minutes on one thread; not with --quick)");
  return validate_cmd;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Landslide Studio: GIMP landslide simulation, painted off-screen"};
  cli.set_version_flag("--version", LANDSLIDE_VERSION);
  cli.require_subcommand(1);

  app::RunOptions run;
  CLI::App* run_cmd = add_run_command(cli, run);
  app::ResumeOptions resume;
  CLI::App* resume_cmd = add_resume_command(cli, resume);
  app::RunOptions check;
  CLI::App* check_cmd = add_check_command(cli, check);
  app::RenderOptions render;
  std::vector<double> range;
  CLI::App* render_cmd = add_render_command(cli, render, range);
  app::PanelOptions panel;
  CLI::App* panel_cmd = add_panel_command(cli, panel);
  app::GalleryOptions gallery;
  CLI::App* gallery_cmd = add_gallery_command(cli, gallery);
  app::ValidateOptions validate;
  CLI::App* validate_cmd = add_validate_command(cli, validate);
  app::NewOptions made;
  CLI::App* new_cmd = app::add_new_command(cli, made);
  sweep::SweepOptions sweep;
  CLI::App* sweep_cmd = app::add_sweep_command(cli, sweep);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : app::kExitBadInput;
  }
  if (*run_cmd) return app::run_command(run);
  if (*resume_cmd) return app::resume_command(resume);
  if (*check_cmd) return app::check_command(check);
  if (*render_cmd) {
    if (range.size() == 2) render.range = std::make_pair(range[0], range[1]);
    return app::render_command(render);
  }
  if (*panel_cmd) return app::panel_command(panel);
  if (*gallery_cmd) {
    const int status = app::gallery_command(gallery);
    return status != app::kExitOk || gallery.quick ? status : app::gallery_monte_carlo(gallery);
  }
  if (*validate_cmd) return app::validate_command(validate);
  if (*new_cmd) return app::new_command(made);
  if (*sweep_cmd) return app::sweep_command(sweep);
  return app::kExitBadInput;
}
