// Run time against error for the granular scenes of issue 13 (a part of
// bench/accuracy): the Bui et al. (2008) column against the experiment's toe,
// on the scene's no-slip base and on a friction base, and the collapse of
// columns of aspect ratio 0.5, 1 and 2 on the friction base against their finest run, each
// at several cell sizes and Courant numbers; then the paper's slope with the
// paper's FLIP update beside APIC (sim/physics/apic.hpp), the candidate cure for the
// transfer loss. The runout is sim/run/runout.hpp's.
#include "bench/accuracy_granular.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "validation/bui_experiment.hpp"
#include "validation/validation_cases.hpp"
#include "sim/run/runout.hpp"
#include "sim/run/simulation.hpp"

namespace bench {

namespace {

struct GranularRun {
  double h = 0, courant = 0, wall = 0, value = 0, error = 0;
  std::size_t points = 0;
  long steps = 0;
};

GranularRun run(sim::Scenario s, double h, double courant) {
  s.cell_size = h;
  s.time_step.courant = courant;
  s.output.frame_interval = 0;
  s.output.vtk = "none";
  GranularRun r;
  r.h = h;
  r.courant = courant;
  const auto start = std::chrono::steady_clock::now();
  sim::Simulation simulation(s);
  sim::Observer quiet;
  simulation.run(quiet);
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.points = simulation.world().points.size();
  for (const sim::StageResult& res : simulation.results()) r.steps += res.steps;
  r.value = simulation.results().back().metrics.toe;
  return r;
}

void print(const char* title, const char* measure, const std::vector<GranularRun>& runs) {
  std::printf("\n%s\n%8s %7s %8s %8s %9s %12s %10s\n", title, "h [mm]", "points", "Courant",
              "steps", "wall [s]", measure, "error");
  for (const GranularRun& r : runs)
    std::printf("%8.3g %7zu %8.2f %8ld %9.2f %12.4f %+9.2f%%\n", r.h * 1000, r.points, r.courant,
                r.steps, r.wall, r.value, 100 * r.error);
  std::fflush(stdout);
}

std::vector<double> cell_sizes(bool full) {
  std::vector<double> h = {0.01, 0.005, 0.0025};
  if (full) h.push_back(0.00125);
  return h;
}

}  // namespace

void granular_studies(const std::string& scenarios, bool full) {
  const sim::Scenario bui = sim::load_scenario(scenarios + "/validation/bui2008-column.json");
  const app::Curve surface =
      app::read_curve(scenarios + "/validation/data/bui2008-experiment-surface.csv", 2);
  const double toe = app::curve_toe(surface, sim::kToeThicknessFraction * 0.1);
  for (const bool friction : {false, true}) {
    sim::Scenario s = bui;
    if (friction) s.boundaries.bottom = {sim::BoundaryKind::Friction, app::kRodsBaseFriction};
    std::vector<GranularRun> runs;
    for (const double h : cell_sizes(full))
      for (const double courant : {0.5, 0.25}) {
        GranularRun r = run(s, h, courant);
        r.error = (r.value - toe) / toe;
        runs.push_back(r);
      }
    const std::string title = std::string("Bui column, ") +
                              (friction ? "friction base" : "no-slip base (the scene)") +
                              ": toe against the experiment's " + std::to_string(toe) + " m";
    print(title.c_str(), "toe [m]", runs);
  }
  // The collapse columns of validate (validation/validation_collapse.cpp) on the
  // friction base; the reference is each one's finest grid at the smaller
  // Courant number.
  for (const double aspect : {0.5, 1.0, 2.0}) {
    std::vector<GranularRun> runs;
    for (const double h : cell_sizes(full))
      for (const double courant : {0.5, 0.25})
        runs.push_back(run(app::collapse_column(bui, aspect, h), h, courant));
    const double reference = runs.back().value;
    for (GranularRun& r : runs) r.error = (r.value - reference) / reference;
    const std::string title = "Column collapse, aspect ratio " + std::to_string(aspect).substr(0, 3) +
                              ", friction base: toe against the finest run";
    print(title.c_str(), "toe [m]", runs);
  }
  transfer_study(scenarios, full);
}

// The paper's slope at phi = 20 and 10 with each transfer scheme, at 1661
// and 8370 points (--full: 28711) and Courant 0.5 and 0.25: the runout, how
// much of gravity's work the transfers lose, the balance of Eq. (3), and the
// runout's change when the step halves.
void transfer_study(const std::string& scenarios, bool full) {
  std::printf("\nPaper slope, FLIP (the paper's Eq. 30) and APIC (Jiang et al. 2015)\n");
  std::printf("%4s %5s %7s %7s %8s %9s %10s %12s %10s %14s\n", "phi", "", "points", "Courant",
              "steps", "wall [s]", "runout [m]", "transfer/W", "balance", "vs Courant 0.5");
  std::vector<double> cells = {1.127, 0.5};
  if (full) cells.push_back(0.270);
  for (const int phi : {20, 10})
    for (const sim::TransferScheme scheme : {sim::TransferScheme::Flip, sim::TransferScheme::Apic})
      for (const double h : cells) {
        double own = 0;
        for (const double courant : {0.5, 0.25}) {
          sim::Scenario s = sim::load_scenario(scenarios + "/paper-slope-phi" +
                                               std::to_string(phi) + ".json");
          s.cell_size = h;
          s.time_step.courant = courant;
          s.transfer = scheme;
          s.output.frame_interval = 0;
          s.output.vtk = "none";
          const auto start = std::chrono::steady_clock::now();
          sim::Simulation simulation(s);
          sim::Observer quiet;
          simulation.run(quiet);
          const double wall =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const sim::StageResult& slide = simulation.results().back();
          const double runout = slide.metrics.runout;
          if (courant == 0.5) own = runout;
          std::printf("%4d %5s %7zu %7.2f %8ld %9.2f %10.3f %12.4f %+9.2f%% %+13.2f%%\n", phi,
                      scheme == sim::TransferScheme::Apic ? "APIC" : "FLIP",
                      simulation.world().points.size(), courant, slide.steps, wall, runout,
                      slide.energy.transfer_loss / slide.energy.external_work,
                      100 * slide.energy.relative_error, 100 * (runout - own) / own);
          std::fflush(stdout);
        }
      }
}

}  // namespace bench
