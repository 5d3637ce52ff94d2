// The subcommands of `landslide`. Each returns the process exit status
// (output/exit_status.hpp); validate and gallery are declared in their folders.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gallery/src/gallery.hpp"
#include "output/exit_status.hpp"
#include "validation/validate.hpp"

namespace app {

struct RunOptions {
  std::string scenario;
  std::string out_dir;
  int threads = 0;  // 0: OpenMP's default
  double checkpoint_every = 0;  // s of simulated time between checkpoints; 0: none
  // A folder of saved gravity-stage states shared by runs: a scenario whose
  // first stages match a saved one (sim::stage_prefix_key) starts from it.
  std::string state_cache;  // "": no reuse
  // An earlier run's outputs in out_dir are removed first (without it such a
  // folder is refused: output/output_dir.hpp).
  bool overwrite = false;
  bool allow_long = false;  // run past the estimate's limits (app/estimate.hpp)
};

int run_command(const RunOptions& options);
// `landslide check`: the preflight of `run` with the same options (out_dir
// may be empty: the output folder is then not checked); prints the estimate
// to stdout, writes nothing.
int check_command(const RunOptions& options);

// `landslide resume DIR`: continues the run whose checkpoint is
// DIR/checkpoint.lsck, writing into DIR as the run would have.
struct ResumeOptions {
  std::string dir;
  int threads = 0;
  double checkpoint_every = 0;
  bool allow_long = false;
};
int resume_command(const ResumeOptions& options);

// `landslide render`: re-paints saved VTK states without simulating.
struct RenderOptions {
  std::string input;     // a .vtu file, or a run directory (DIR/vtk/points.pvd) or its vtk/
  std::string scenario;  // the scenario of the run: materials, domain, image size, name
  std::string field;     // one of field_names()
  std::string colour_map;                          // "" : the scenario's
  std::optional<std::pair<double, double>> range;  // none: per stage, as the run does
  std::string out;  // a .png file (one state) or a directory; "" : see README
  bool video = false;  // also encode OUT/<field>.mp4 and .gif
  // Each frame with the run's series plot (RUN/series.csv) beside it, a
  // marker at the frame's time (output/series_plot.hpp).
  bool series = false;
};
int render_command(const RenderOptions& options);

// Whether s ends with suffix, ignoring case (".PNG" is ".png").
bool ends_with(std::string s, const std::string& suffix);

// `landslide panel`: several PNGs with captions on one page.
struct PanelOptions {
  std::string out;  // .png
  std::string title;
  int cols = 2;
  std::vector<std::string> items;  // IMAGE CAPTION IMAGE CAPTION ...
};
int panel_command(const PanelOptions& options);

}  // namespace app
