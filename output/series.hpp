// The slide's progress as a time series, OUT/series.csv: one row at every
// frame time of a painted stage; in a timed stage that is not painted, one
// at its start, one at the first step at or after every output.frame_interval
// of stage time (every 1/100 of the stage's duration when frame_interval is
// 0), and one at its end. Material changes take no time and get no row.
//
// Columns (series_columns()):
//   time_s                         since the run began
//   stage, stage_time_s, steps     the stage, the time and steps since it began
//   kinetic_energy_J_per_m         of the points, sum m |v|^2 / 2
//   moving_kinetic_energy_J_per_m  of the velocity that moves them (the rest criterion)
//   front_x_m, runout_m            the soil's toe and its runout (sim/run/runout.hpp)
//   max_soil_ux_m                  largest |x - x0| of the soil
//   max_displacement_m             largest |u| of any point
//   external_work_J_per_m ... relative_error
//                                  the stage's energy balance (Eq. 3) since
//                                  it began (app::energy_terms)
// The last row of a stage holds what summary.json reports at its end.
// Numbers are written in the shortest form that reads back exactly.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/font.hpp"
#include "sim/run/simulation.hpp"

namespace app {

// A series.csv that cannot be read: the message names the file and line.
class SeriesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The numeric columns after time_s and stage, in the file's order; the
// energy terms follow kMaxDisplacement.
enum SeriesColumn {
  kStageTime, kSteps, kKinetic, kMovingKinetic, kFrontX, kRunout, kMaxSoilUx, kMaxDisplacement
};

struct SeriesRow {
  double time = 0;  // s since the run began
  std::string stage;
  std::vector<double> values;  // one per column after stage
  double at(SeriesColumn c) const { return values[c]; }
};

const std::vector<std::string>& series_columns();

// The stage time between the rows of a stage that is not painted:
// output.frame_interval, or 1/100 of the stage's duration where that is 0.
double series_interval(const sim::Scenario& scenario, const sim::StageSpec& stage);

// The state now: `r` is the stage's result so far (sim::Simulation::
// stage_so_far) or the ended stage's, `m` how far the points have gone now
// (sim::measure_motion, or the ended stage's metrics).
SeriesRow series_row(const sim::Simulation& sim, const sim::StageResult& r,
                     const sim::StageMotion& m);

std::string series_csv(const std::vector<SeriesRow>& rows);
// Throws SeriesError naming `label` and the line: a header other than
// series_columns(), a row with the wrong number of fields or a field that
// is not a number, or times that go back.
std::vector<SeriesRow> parse_series(const std::string& text, const std::string& label);
// The same from a file, which must hold at least one row.
std::vector<SeriesRow> read_series(const std::filesystem::path& file);

// Collects the rows while a run runs and writes OUT/series.csv and
// OUT/series.png (each under a temporary name, then renamed) at the end of
// every timed stage, at checkpoints and after a failure.
class SeriesRecorder {
 public:
  SeriesRecorder(const sim::Scenario& scenario, std::filesystem::path out_dir);

  void stage_begins(const sim::Simulation& sim, const sim::StageSpec& stage);
  void frame(const sim::Simulation& sim);
  void progress(const sim::Simulation& sim, const sim::StageSpec& stage);
  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                  const sim::StageResult& r);

  // For checkpoints and cached gravity stages: the rows so far and where
  // the next one falls. Throws SeriesError for a damaged entry.
  nlohmann::json bookkeeping() const;
  void resume(const nlohmann::json& bookkeeping);
  std::string csv() const { return series_csv(rows_); }
  void restore(std::vector<SeriesRow> rows);

  // series.csv and series.png; nothing when there is no row yet.
  void write();

 private:
  void add(SeriesRow row);

  const sim::Scenario& scenario_;
  std::filesystem::path out_;
  std::unique_ptr<render::Font> font_;  // set up before the run, not after its first stage
  std::vector<SeriesRow> rows_;
  long next_row_ = 0;  // in a stage that is not painted: at stage time next_row_ * interval
};

}  // namespace app
