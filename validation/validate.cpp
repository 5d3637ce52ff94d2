// `landslide validate`: runs the validation suite (validation/validation_cases.cpp)
// and prints one table: case, measure, value, reference, error, tolerance,
// wall time. Exit status 0 when every check passes, 1 when one fails, 2 when
// a scenario or experiment data file of the suite cannot be read.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "output/exit_status.hpp"
#include "output/output_dir.hpp"
#include "validation/validate.hpp"
#include "output/counted.hpp"
#include "validation/validation_cases.hpp"
#include "sim/scene/scenario.hpp"
#include "sim/physics/world.hpp"

namespace app {

namespace {

std::string error_text(const ValidationRow& r) {
  if (r.at_least || r.at_most) return "";
  if (!r.has_error) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f %%", 100 * r.error);
  return text;
}

std::string tolerance_text(const ValidationRow& r) {
  char text[32];
  if (r.at_least)
    std::snprintf(text, sizeof text, "> %g", r.tolerance);
  else if (r.at_most)
    std::snprintf(text, sizeof text, "< %.4g", r.tolerance);
  else if (r.checked())
    std::snprintf(text, sizeof text, "%g %%", 100 * r.tolerance);
  else
    return "-";
  return text;
}

void print_table(const std::vector<ValidationRow>& rows) {
  std::printf("| case | measure | value | reference | error | tolerance | wall [s] | check |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const ValidationRow& r : rows) {
    char wall[32] = "";
    if (r.wall >= 0) std::snprintf(wall, sizeof wall, "%.1f", r.wall);
    std::printf("| %s | %s | %.5g | %s | %s | %s | %s | %s |\n", r.case_name.c_str(),
                r.measure.c_str(), r.value, r.reference.c_str(), error_text(r).c_str(),
                tolerance_text(r).c_str(), wall,
                !r.checked() ? "" : r.passed() ? "pass" : "FAIL");
  }
  std::fflush(stdout);
}

}  // namespace

int validate_command(const ValidateOptions& options) {
  ValidationSuite suite;
  suite.scenarios = options.scenarios.empty() ? "scenarios" : options.scenarios;
  if (!scenarios_folder_found(suite.scenarios, !options.scenarios.empty(), "landslide validate"))
    return kExitBadInput;
  suite.quick = options.quick;
  suite.finest = options.finest;
  const auto start = std::chrono::steady_clock::now();
  std::vector<ValidationRow> rows;
  try {
    for (auto* run_case :
         {&elastic_column_case, &bui_column_case, &column_collapse_case, &paper_slope_case}) {
      const std::vector<ValidationRow> part = run_case(suite);
      rows.insert(rows.end(), part.begin(), part.end());
    }
  } catch (const sim::ScenarioError& e) {
    std::cerr << "error: " << e.what() << " (--scenarios DIR names the scenarios folder)\n";
    return kExitBadInput;
  } catch (const sim::SimulationError& e) {
    print_table(rows);
    std::cerr << "error: a validation run failed: " << e.what() << '\n';
    return kExitFailed;
  }
  print_table(rows);
  int failed = 0;
  for (const ValidationRow& r : rows) failed += r.checked() && !r.passed();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("\n%s suite: %s failed, %.1f s wall\n", suite.quick ? "quick" : "full",
              counted(failed, "check").c_str(), wall);
  return failed == 0 ? kExitOk : kExitFailed;
}

}  // namespace app
