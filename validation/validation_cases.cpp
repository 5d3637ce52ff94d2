// The cases of `landslide validate` (tests/validation/README.md): the confined
// elastic column against its closed form at several resolutions and the
// energy balance of the paper's Eq. (3) in every run (the Bui et al. (2008)
// column is in validation/validation_bui.cpp), and the helpers they share
// (validation/validation_util.hpp).
#include "output/counted.hpp"
#include "validation/validation_cases.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "output/progress.hpp"
#include "validation/validation_util.hpp"
#include "validation/elastic_column.hpp"
#include "sim/run/simulation.hpp"

namespace app {

std::string fmt(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

namespace {

// Progress of one validation run on stderr (the table goes to stdout at the
// end): the full suite runs for minutes.
class RunProgress : public sim::Observer {
 public:
  void progress(const sim::Simulation& sim, const sim::StageSpec& stage, long steps) override {
    bar_.update(sim.scenario().name + " " + stage.name, sim.stage_time(), stage.duration, steps);
  }
  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                  const sim::StageResult& r) override {
    if (stage.type != sim::StageType::MaterialChange)
      bar_.finish(sim.scenario().name + " " + stage.name + ": " + counted(r.steps, "step") +
                  ", " + fmt("%.1f s wall", r.wall_time));
  }

 private:
  Progress bar_;
};

}  // namespace

Run run_with_progress(const sim::Scenario& s) {
  Run r;
  const auto start = std::chrono::steady_clock::now();
  r.simulation = std::make_unique<sim::Simulation>(s);
  RunProgress progress;
  r.simulation->run(progress);
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

ValidationRow row(const std::string& case_name, const std::string& measure, double value,
                  const std::string& reference) {
  ValidationRow r;
  r.case_name = case_name;
  r.measure = measure;
  r.value = value;
  r.reference = reference;
  return r;
}

ValidationRow compared(const std::string& case_name, const std::string& measure, double value,
                       double reference, double tolerance, const char* format) {
  ValidationRow r = row(case_name, measure, value, fmt(format, reference));
  r.error = (value - reference) / std::fabs(reference);
  r.has_error = true;
  r.tolerance = tolerance;
  return r;
}

// The transfer loss is StepReport::transfer_loss.
std::vector<ValidationRow> energy_rows(const std::string& case_name, const Run& run,
                                       bool check_dynamic) {
  std::vector<ValidationRow> rows;
  for (const sim::StageResult& s : run.simulation->results()) {
    if (s.type == sim::StageType::MaterialChange) continue;
    const sim::EnergyBalance& e = s.energy;
    ValidationRow r = row(case_name, "energy balance error (Eq. 3), " + s.name, e.relative_error, "0");
    r.error = e.relative_error;
    r.has_error = true;
    const bool checked = check_dynamic || s.type != sim::StageType::Dynamic;
    r.tolerance = checked ? kEnergyTolerance : -1;
    if (rows.empty()) r.wall = run.wall;
    rows.push_back(r);
    const double share = e.external_work != 0 ? e.transfer_loss / std::fabs(e.external_work) : 0.0;
    rows.push_back(row(case_name, "transfer loss / external work, " + s.name, share, "-"));
  }
  return rows;
}

std::vector<ValidationRow> change_rows(const std::string& name, const std::string& measure,
                                       const std::vector<double>& cells, double scale,
                                       const char* unit, const std::vector<double>& values,
                                       bool shrinking, double last_tolerance) {
  std::vector<ValidationRow> rows;
  double before = -1;
  for (std::size_t k = 1; k < values.size(); ++k) {
    const double change = std::fabs(values[k] - values[k - 1]) / std::fabs(values[k]);
    ValidationRow r = row(name, measure + ", h = " + fmt("%g", cells[k - 1] * scale) + " -> " +
                                    fmt("%g", cells[k] * scale) + " " + unit,
                          change, "relative to the finer run");
    if (shrinking && before >= 0) {
      r.at_most = true;
      r.tolerance = before;
      r.reference += "; below the change before";
    }
    if (last_tolerance >= 0 && k + 1 == values.size()) {
      if (r.at_most) rows.push_back(r);  // the check against the change before, then this one
      r.at_most = true;
      r.tolerance = last_tolerance;
      r.reference = "relative to the finer run; the finest change below " +
                    fmt("%g", 100 * last_tolerance) + " %";
    }
    rows.push_back(r);
    before = change;
  }
  return rows;
}

namespace {

std::string cells_label(const std::string& base, int cells) {
  return base + " (" + std::to_string(cells) + " cells)";
}

}  // namespace

// The column of scenarios/validation/elastic-column-n*.json: sigma_yy and the
// settlement against the closed form (validation/elastic_column.hpp) per resolution,
// and the observed order of both errors. With 2x2 points per cell the stress
// is constant per cell while the points keep to their cells, so its L2 error
// is about sqrt(3) / (4 n) (tests/sim/test_elastic_column.cpp); each run is
// held below 1.1 times that, as the test does.
std::vector<ValidationRow> elastic_column_case(const ValidationSuite& suite) {
  std::vector<ValidationRow> rows;
  std::vector<double> h, syy, settlement;
  const std::vector<int> cells = suite.quick ? std::vector<int>{4, 8, 16}
                                             : std::vector<int>{4, 8, 16, 32, 64};
  for (const int n : cells) {
    const std::string name = cells_label("elastic column", n);
    const sim::Scenario s = sim::load_scenario(suite.scenarios + "/validation/elastic-column-n" +
                                               std::to_string(n) + ".json");
    const Run run = run_with_progress(s);
    const sim::ElasticColumnErrors e = sim::elastic_column_errors(s, run.simulation->world());
    const double floor = std::sqrt(3.0) / (4.0 * n);
    ValidationRow stress = row(name, "sigma_yy relative L2 error", e.syy,
                               "closed form; floor " + fmt("%.4f", floor));
    stress.at_most = true;
    stress.tolerance = 1.1 * floor;
    rows.push_back(stress);
    ValidationRow u = row(name, "settlement relative L2 error", e.settlement, "closed form");
    rows.push_back(u);
    rows.push_back(compared(name, "top settlement [m]", -e.top_settlement,
                            sim::elastic_column_top_settlement(s), -1, "%.6f"));
    for (const ValidationRow& r : energy_rows(name, run)) rows.push_back(r);
    h.push_back(e.h);
    syy.push_back(e.syy);
    settlement.push_back(e.settlement);
  }
  const std::string range = "elastic column (" + std::to_string(cells.front()) + "-" +
                            std::to_string(cells.back()) + " cells)";
  ValidationRow order = row(range, "observed order of sigma_yy error",
                            sim::observed_order(h.data(), syy.data(), h.size()), "> 1");
  order.at_least = true;
  order.tolerance = 1.0;
  rows.push_back(order);
  rows.push_back(row(range, "observed order of settlement error",
                     sim::observed_order(h.data(), settlement.data(), h.size()), "-"));
  return rows;
}

}  // namespace app
