// The aluminium-rod column of Bui et al. (2008) in `landslide validate`:
// scenarios/validation/bui2008-column.json at several cell sizes, its final
// state against the experiment's final free surface and failure line
// (scenarios/validation/data/, digitised by Huo et al. 2025), and the same
// column on a smooth (roller) base as a check of the base condition.
// tests/validation/README.md gives the sources and why each measure is
// defined as it is.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "validation/bui_experiment.hpp"
#include "validation/validation_cases.hpp"
#include "validation/validation_util.hpp"
#include "sim/run/runout.hpp"

namespace app {

namespace {

// The toe is where the deposit becomes thinner than 1.5 mm: the simulation's
// is the runout's toe (sim/run/runout.hpp, 1.5 % of the column's 100 mm), and
// 1.5 mm is the lowest height of the digitised surface (its last point stands
// 1.52 mm high at x = 0.442 m), so the experiment's toe is defined by its own
// data, and about the rods' size (HydraxMPM's mu(I) model of this column,
// examples/iacmag_2025/mpm_collapse.py, takes a grain diameter of 1.25 mm).
// The experiment's deposit is a dense pack of rods, so its surface height is
// its thickness.
constexpr double kToeHeight = sim::kToeThicknessFraction * 0.1;
// A point "moved" when its horizontal displacement exceeds 1 mm: the
// threshold Huo et al. (2025, LandslideSIM/Archive_MaterialPointSolver.jl_paper
// 02_soil_collapse/post_process.jl) and HydraxMPM (examples/iacmag_2025/
// mpm_collapse_plotval.py) use to draw their simulations against this failure
// line. The previous measure's 5 mm (5 % of the height) is reported beside it.
constexpr double kMoved = 0.001, kMovedCoarse = 0.005;
// Issue 13: on the friction base the toe within 5 % of the experiment at
// h = 5, 2.5 and 1.25 mm (3 % is the goal, reported), and a change of under
// 3 % from 2.5 to 1.25 mm. Issue 8: on the scene's no-slip base, within 10 %
// at its own 2.5 mm.
constexpr double kToeTolerance = 0.05, kToeChange = 0.03, kSceneToeTolerance = 0.10;

// The wall height: within 5 % of the experiment (as against the initial 0.1 m
// before the experiment's data were found).
constexpr double kWallTolerance = 0.05;

struct Experiment {
  Curve surface, failure;
  std::string surface_file, failure_file;  // names as printed in the table
  double toe = 0, wall_height = 0;
};

Experiment read_experiment(const std::string& scenarios) {
  Experiment e;
  e.surface_file = "bui2008-experiment-surface.csv";
  e.failure_file = "bui2008-experiment-failure.csv";
  const std::string dir = scenarios + "/validation/data/";
  e.surface = read_curve(dir + e.surface_file, 2);
  e.failure = read_curve(dir + e.failure_file, 3);
  e.toe = curve_toe(e.surface, kToeHeight);
  e.wall_height = e.surface.y.front();
  return e;
}

// The final state of one run against the experiment, the toe checked within
// `toe_tolerance` (< 0: reported).
std::vector<ValidationRow> experiment_rows(const std::string& name, const sim::Scenario& s,
                                           const Run& run, const Experiment& e,
                                           double toe_tolerance) {
  const sim::Particles& p = run.simulation->world().points;
  const double spacing = s.cell_size / s.points_per_cell;
  double height = 0, length = 0;  // of the initial column
  for (std::size_t i = 0; i < p.size(); ++i) {
    height = std::max(height, p.y0[i] + 0.5 * spacing);
    length = std::max(length, p.x0[i] + 0.5 * spacing);
  }
  const std::string from_surface = "%.4g (" + e.surface_file + ")";
  std::vector<ValidationRow> rows;
  const sim::StageMetrics& m = run.simulation->results().back().metrics;
  rows.push_back(compared(name, "toe from the wall, deposit >= 1.5 mm [m]", m.toe, e.toe,
                          toe_tolerance, from_surface.c_str()));
  rows.push_back(compared(name, "runout beyond the initial toe [m]", m.toe - length, e.toe - length,
                          -1, from_surface.c_str()));
  rows.push_back(compared(name, "height at the wall [m]", surface_height(p, 0.0, s.cell_size),
                          e.wall_height, kWallTolerance, from_surface.c_str()));
  rows.push_back(row(name, "free surface RMS difference [m]",
                     rms_surface_difference(p, e.surface, 0.5 * s.cell_size),
                     "0; " + std::to_string(e.surface.x.size()) + " points of " + e.surface_file));
  // The failure line over the middle 80 % of the height, on both sides: the
  // base row sticks to the no-slip base and the top row is the free surface.
  const Marks experiment_line = curve_band(e.failure, 0.1 * height, 0.9 * height);
  const std::string from_failure = "%.1f (fit, " + e.failure_file + ")";
  for (const double moved : {kMoved, kMovedCoarse}) {
    const Marks line = unmoved_boundary(p, spacing, 0.1 * height, 0.9 * height, moved);
    const std::string label = "ux > " + fmt("%g", moved * 1000) + " mm";
    rows.push_back(compared(name, "failure line angle, " + label + " [deg]", line_angle_deg(line),
                            line_angle_deg(experiment_line), -1, from_failure.c_str()));
    rows.push_back(row(name, "failure line RMS x offset, " + label + " [m]",
                       rms_offset_x(line, e.failure), "0; " + e.failure_file));
  }
  return rows;
}

// The deposit slope, whether the collapse ended at rest (checked when
// `rest_checked`: the smooth base is not expected to stop) and the energy rows.
std::vector<ValidationRow> run_rows(const std::string& name, const Run& run, bool rest_checked) {
  const sim::StageResult& collapse = run.simulation->results().back();
  std::vector<ValidationRow> rows;
  rows.push_back(row(name, "deposit slope [deg]", collapse.metrics.deposit_slope_deg, "-"));
  rows.push_back(row(name, "soil packed, within 10 % of its density",
                     collapse.metrics.packed_fraction, "-"));
  rows.push_back(row(name, "soil disconnected, below its critical density",
                     collapse.metrics.disconnected_fraction, "-"));
  ValidationRow rest = row(name, "collapse ended at rest (1 = yes)", collapse.ended_at_rest, "1");
  rest.at_least = rest_checked;
  rest.tolerance = rest_checked ? 0.5 : -1;
  rows.push_back(rest);
  for (const ValidationRow& r : energy_rows(name, run)) rows.push_back(r);
  return rows;
}

std::string run_name(const std::string& base, double h, const Run& run) {
  return base + " h = " + fmt("%g", h * 1000) + " mm (" +
         std::to_string(run.simulation->world().points.size()) + " points)";
}

}  // namespace

// The scene on its no-slip (fixed) base, the base of the reproductions of
// Huo et al. (2025) and HydraxMPM, at h = 10, 5 and 2.5 mm (the scene's own;
// --quick: 10 mm only), then on a friction base at the same and, with
// --finest, at 1.25 mm (about 8 times the 2.5 mm run's time); each against
// the experiment, and the toe's change from one resolution to the next.
std::vector<ValidationRow> bui_column_case(const ValidationSuite& suite) {
  const sim::Scenario scene =
      sim::load_scenario(suite.scenarios + "/validation/bui2008-column.json");
  const Experiment experiment = read_experiment(suite.scenarios);
  std::vector<ValidationRow> rows;
  for (const bool friction : {false, true}) {
    if (friction && suite.quick) break;
    std::vector<double> sizes = suite.quick ? std::vector<double>{0.01}
                                            : std::vector<double>{0.01, 0.005, 0.0025};
    if (friction && suite.finest) sizes.push_back(0.00125);
    sim::Scenario base = scene;
    if (friction) base.boundaries.bottom = {sim::BoundaryKind::Friction, kRodsBaseFriction};
    const std::string label =
        friction ? "Bui column, friction base mu = " + fmt("%g", kRodsBaseFriction) + "," : "Bui column";
    std::vector<double> toes;
    for (const double h : sizes) {
      sim::Scenario s = base;
      s.cell_size = h;
      const Run run = run_with_progress(s);
      const std::string name = run_name(label, h, run);
      const double tolerance = friction ? (h <= 0.005 ? kToeTolerance : -1)
                                        : (h == scene.cell_size ? kSceneToeTolerance : -1);
      const std::vector<ValidationRow> part = experiment_rows(name, s, run, experiment, tolerance);
      toes.push_back(part.front().value);
      rows.insert(rows.end(), part.begin(), part.end());
      for (const ValidationRow& r : run_rows(name, run, true)) rows.push_back(r);
    }
    const bool finest = friction && suite.finest;
    for (const ValidationRow& r : change_rows(label, "toe change", sizes, 1000, "mm", toes, false,
                                              finest ? kToeChange : -1))
      rows.push_back(r);
  }
  return rows;
}

}  // namespace app
