// Run time against error: how much accuracy each second of solver time buys.
//
// 1. The laterally confined elastic column (scenarios/elastic-column.json)
//    against its closed form (validation/elastic_column.hpp, method notes section 5),
//    at 4..32 cells over the height (--full: also 64), 1x1 and 2x2 points per
//    cell, Courant 0.1, 0.25, 0.5: relative L2 error of sigma_yy.
// 2. The paper's slope at phi = 20 deg (Andersen & Andersen, Section 7) at the
//    1661- and 8370-point resolutions (--full adds 28711, not at Courant 0.1:
//    too long), same Courant numbers, against the finest run (finest
//    resolution, smallest Courant): relative runout error and RMS difference
//    of the final free surface (slope_surface.hpp).
// 3. The granular scenes (bench/accuracy_granular.cpp): the Bui et al. (2008)
//    column against the experiment's toe on two bases, and a column of
//    aspect ratio 1 against its finest run.
// 4. The paper's slope at phi = 10 deg, as 2. (table only).
// Prints the tables and writes accuracy-elastic-column.png and
// accuracy-paper-slope.png (wall seconds on x, error on y, log-log). Prints
// figures; never fails on timing.
//
// Usage: accuracy [--full] [--out DIR]   (PNGs into DIR, default ".")
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench/accuracy_granular.hpp"
#include "bench/loglog_plot.hpp"
#include "bench/slope_surface.hpp"
#include "render/png_io.hpp"
#include "validation/elastic_column.hpp"
#include "sim/run/simulation.hpp"

namespace {

const double kCourants[] = {0.1, 0.25, 0.5};

struct Run {
  std::string scene;  // "column" or the slope's resolution label
  int cells = 0;      // over the column's height; 0 for the slope
  int per_cell = 0;   // points per cell along each axis
  std::size_t points = 0;
  double courant = 0, cell_size = 0;
  long steps = 0;
  double wall = 0;        // s, construction (seeding) and every stage
  double error = 0;       // column: L2 of sigma_yy; slope: relative runout error
  double surface_rms = 0; // slope: RMS free-surface difference to the reference, m
  double runout = 0;      // slope, m
  bench::SurfaceProfile surface;  // slope
};

sim::Scenario load(const std::string& name) {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/" + name + ".json");
  s.output.frame_interval = 0;  // no frames, no VTK: solver time only
  s.output.vtk = "none";
  return s;
}

// Runs the scenario at the Courant number, without frames or VTK, into `run`
// (wall time, points, steps), then hands the finished simulation to `measure`.
template <typename Measure>
void timed_run(sim::Scenario s, double courant, Run& run, Measure measure) {
  s.time_step.mode = sim::TimeStepSpec::Mode::Courant;
  s.time_step.courant = courant;
  run.courant = courant;
  run.cell_size = s.cell_size;
  const auto start = std::chrono::steady_clock::now();
  sim::Simulation simulation(s);
  sim::Observer quiet;
  simulation.run(quiet);
  run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.points = simulation.world().points.size();
  for (const sim::StageResult& r : simulation.results()) run.steps += r.steps;
  measure(s, simulation);
}

// The cheapest (least wall time) run with error below `limit` among those
// with `per_cell` points per cell (0: any), or -1.
int cheapest_below(const std::vector<Run>& runs, double limit, int per_cell = 0) {
  int best = -1;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Run& r = runs[k];
    if (r.error < limit && r.error > 0 && (per_cell == 0 || r.per_cell == per_cell) &&
        (best < 0 || r.wall < runs[best].wall))
      best = static_cast<int>(k);
  }
  return best;
}

std::string courant_name(double c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "Courant %g", c);
  return buf;
}

int courant_index(double c) {
  for (int k = 0; k < 3; ++k)
    if (kCourants[k] == c) return k;
  return 0;
}

std::vector<Run> column_study(bool full) {
  const sim::Scenario base = load("elastic-column");
  const double H = base.domain_max[1] - base.domain_min[1];
  std::vector<int> cells = {4, 8, 16, 32};
  if (full) cells.push_back(64);
  std::printf("\nElastic column (H = %g m, closed form of sigma_yy: method notes section 5)\n", H);
  std::printf("%6s %5s %7s %8s %8s %9s %12s\n", "cells", "ppc", "points", "Courant", "steps",
              "wall [s]", "L2 sigma_yy");
  std::vector<Run> runs;
  for (const int per_cell : {1, 2})
    for (const double courant : kCourants)
      for (const int n : cells) {
        sim::Scenario s = base;
        s.cell_size = H / n;
        s.points_per_cell = per_cell;
        Run run;
        run.scene = "column";
        run.cells = n;
        run.per_cell = per_cell;
        timed_run(s, courant, run, [&](const sim::Scenario& sc, const sim::Simulation& sim) {
          run.error = sim::elastic_column_errors(sc, sim.world()).syy;
        });
        std::printf("%6d %5d %7zu %8.2f %8ld %9.3f %12.4e\n", n, per_cell, run.points, courant,
                    run.steps, run.wall, run.error);
        std::fflush(stdout);
        runs.push_back(run);
      }
  for (const int per_cell : {0, 1, 2}) {
    const int best = cheapest_below(runs, 0.01, per_cell);
    const std::string which =
        per_cell ? " with " + std::to_string(per_cell) + "x" + std::to_string(per_cell) +
                       " points per cell"
                 : "";
    if (best < 0) {
      std::printf("no run%s is under 1 %% error\n", which.c_str());
      continue;
    }
    const Run& b = runs[best];
    std::printf("cheapest run%s under 1 %%: %d cells, %d x %d points per cell, Courant %g: "
                "%.3f s, error %.3f %%\n",
                which.c_str(), b.cells, b.per_cell, b.per_cell, b.courant, b.wall, 100 * b.error);
  }
  return runs;
}

// The slope of paper-slope-phiN.json at the resolutions of 1661 and 8370
// points (--full: 28711 too), each at the three Courant numbers.
std::vector<Run> slope_study(int phi, bool full) {
  struct Resolution {
    const char* label;
    double h;
  };
  std::vector<Resolution> levels = {{"n1661", 1.127}, {"n8370", 0.5}};
  if (full) levels.push_back({"n28711", 0.270});
  const sim::Scenario scene = load("paper-slope-phi" + std::to_string(phi));
  std::vector<Run> runs;
  for (const Resolution& level : levels)
    for (int c = 2; c >= 0; --c) {  // cheapest first
      if (full && std::string(level.label) == "n28711" && c == 0) continue;  // 0.1: too long
      Run run;
      run.scene = level.label;
      sim::Scenario s = scene;
      s.cell_size = level.h;
      timed_run(s, kCourants[c], run,
                [&](const sim::Scenario& sc, const sim::Simulation& sim) {
                  run.runout = sim.results().back().metrics.runout;
                  run.surface = bench::soil_surface(sc, sim.world(), 1.0);
                });
      std::fprintf(stderr, "  slope %s Courant %g: %.1f s\n", level.label, kCourants[c], run.wall);
      runs.push_back(run);
    }
  const Run& ref = runs.back();  // finest resolution, smallest Courant number
  for (Run& run : runs) {
    run.error = std::fabs(run.runout - ref.runout) / ref.runout;
    run.surface_rms = bench::surface_rms_difference(run.surface, ref.surface);
  }
  std::printf("\nPaper slope phi = %d deg, reference: %s at Courant %g (runout %.3f m)\n", phi,
              ref.scene.c_str(), ref.courant, ref.runout);
  std::printf("%-7s %7s %7s %8s %8s %9s %10s %12s %14s\n", "scene", "h [m]", "points", "Courant",
              "steps", "wall [s]", "runout [m]", "runout err", "surface RMS [m]");
  for (const Run& r : runs)
    std::printf("%-7s %7.3f %7zu %8.2f %8ld %9.2f %10.3f %12.4e %14.4f\n", r.scene.c_str(),
                r.cell_size, r.points, r.courant, r.steps, r.wall, r.runout, r.error,
                r.surface_rms);
  const int best = cheapest_below(runs, 0.01);
  if (best < 0)
    std::printf("no run (other than the reference) is under 1 %% runout error\n");
  else
    std::printf("cheapest run under 1 %% runout error: %s at Courant %g: %.2f s, error %.3f %%\n",
                runs[best].scene.c_str(), runs[best].courant, runs[best].wall,
                100 * runs[best].error);
  return runs;
}

bench::LogLogPlot base_plot(const std::string& title, const std::string& y_label) {
  bench::LogLogPlot plot;
  plot.title = title;
  plot.x_label = "wall time [s], 1 run";
  plot.y_label = y_label;
  for (const double c : kCourants) plot.series.push_back(courant_name(c));
  return plot;
}

void plot_column(const std::vector<Run>& runs, const std::string& path, render::Font& font) {
  bench::LogLogPlot plot = base_plot("Elastic column: error of sigma_yy against run time "
                                     "(grey: cells over the height)",
                                     "relative L2 error of sigma_yy");
  plot.shape_names = {"1x1 points/cell", "2x2 points/cell"};
  for (const Run& r : runs)
    plot.points.push_back({r.wall, r.error, courant_index(r.courant), r.per_cell - 1, r.per_cell,
                           std::to_string(r.cells)});
  plot.threshold = 0.01;
  plot.threshold_label = "1 %";
  plot.highlight = cheapest_below(runs, 0.01);
  if (plot.highlight >= 0) {
    const Run& b = runs[plot.highlight];
    plot.highlight_label = "cheapest < 1 %: " + std::to_string(b.cells) + " cells, " +
                           std::to_string(b.per_cell) + "x" + std::to_string(b.per_cell);
  }
  render::Image image(960, 600);
  bench::draw_loglog(image, {0, 0, 960, 600}, plot, font);
  render::write_png(image, path);
}

void plot_slope(const std::vector<Run>& runs, const std::string& path, render::Font& font) {
  // Marker shape per resolution; points of one Courant number are joined across resolutions.
  std::vector<std::string> levels;
  for (const Run& r : runs)
    if (levels.empty() || levels.back() != r.scene) levels.push_back(r.scene);
  auto level_of = [&](const Run& r) {
    for (std::size_t k = 0; k < levels.size(); ++k)
      if (levels[k] == r.scene) return static_cast<int>(k);
    return 0;
  };
  char ref[64];  // the reference itself has no error and is not drawn
  std::snprintf(ref, sizeof ref, " (ref: %s, Courant %g)", runs.back().scene.c_str(),
                runs.back().courant);
  bench::LogLogPlot runout =
      base_plot(std::string("Paper slope: runout error") + ref, "|runout - ref| / ref");
  bench::LogLogPlot surface = base_plot(std::string("Paper slope: free-surface RMS") + ref,
                                        "RMS surface difference [m], 1 m bins");
  for (const std::string& l : levels) runout.shape_names.push_back(l), surface.shape_names.push_back(l);
  for (const Run& r : runs) {
    runout.points.push_back({r.wall, r.error, courant_index(r.courant), level_of(r), 0, ""});
    surface.points.push_back({r.wall, r.surface_rms, courant_index(r.courant), level_of(r), 0, ""});
  }
  runout.threshold = 0.01;
  runout.threshold_label = "1 %";
  runout.highlight = cheapest_below(runs, 0.01);
  if (runout.highlight >= 0)
    runout.highlight_label = "cheapest < 1 %: " + runs[runout.highlight].scene;
  render::Image image(1600, 560);
  bench::draw_loglog(image, {0, 0, 800, 560}, runout, font);
  bench::draw_loglog(image, {800, 0, 800, 560}, surface, font);
  render::write_png(image, path);
}

}  // namespace

int main(int argc, char** argv) {
  bool full = false;
  std::string out = ".";
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--full")) full = true;
    else if (!std::strcmp(argv[k], "--out") && k + 1 < argc) out = argv[++k];
    else {
      std::fprintf(stderr, "usage: accuracy [--full] [--out DIR]\n");
      return 2;
    }
  }
  std::printf("accuracy study, %d thread(s)%s\n", omp_get_max_threads(), full ? ", --full" : "");
  render::Font font;
  const std::vector<Run> column = column_study(full);
  plot_column(column, out + "/accuracy-elastic-column.png", font);
  const std::vector<Run> slope = slope_study(20, full);
  plot_slope(slope, out + "/accuracy-paper-slope.png", font);
  slope_study(10, full);
  bench::granular_studies(LANDSLIDE_SOURCE_DIR "/scenarios", full);
  std::printf("\nwrote %s/accuracy-elastic-column.png and %s/accuracy-paper-slope.png\n",
              out.c_str(), out.c_str());
  return 0;
}
