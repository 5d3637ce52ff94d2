// What the cases of `landslide validate` share (validation/validation_cases.cpp,
// validation/validation_bui.cpp): running a scenario with progress on stderr, and
// making rows of the table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "validation/validation_cases.hpp"
#include "sim/run/simulation.hpp"

namespace app {

struct Run {
  std::unique_ptr<sim::Simulation> simulation;
  double wall = 0;  // s
};

// Runs every stage of s, drawing progress on stderr (the table goes to stdout).
Run run_with_progress(const sim::Scenario& s);

// printf of one number.
std::string fmt(const char* format, double v);

// A reported row: no error, no check.
ValidationRow row(const std::string& case_name, const std::string& measure, double value,
                  const std::string& reference);

// A row with its error relative to `reference`, checked when tolerance >= 0.
ValidationRow compared(const std::string& case_name, const std::string& measure, double value,
                       double reference, double tolerance, const char* format = "%.4g");

// The energy balance error of Eq. (3) of each gravity and dynamic stage of the
// run, checked against kEnergyTolerance, and each stage's transfer loss as a
// share of its external work; the first row carries the run's wall time.
// With check_dynamic false, the dynamic stages' balance is reported, not
// checked (the paper slope at its own time step, see paper_slope_energy_case).
std::vector<ValidationRow> energy_rows(const std::string& case_name, const Run& run,
                                       bool check_dynamic = true);

// The relative change of `values` from one cell size to the next finer one
// (cells[k] * scale printed with `unit`), one row each: with `shrinking`,
// each change is checked to be below the one before; the last change is
// checked below last_tolerance when that is >= 0.
std::vector<ValidationRow> change_rows(const std::string& name, const std::string& measure,
                                       const std::vector<double>& cells, double scale,
                                       const char* unit, const std::vector<double>& values,
                                       bool shrinking, double last_tolerance);

}  // namespace app
