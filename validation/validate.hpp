// `landslide validate`, declared apart from the command line (app/) so that
// app/ only parses the options.
#pragma once

#include <string>

namespace app {

// `landslide validate`: the validation suite (tests/validation/README.md).
struct ValidateOptions {
  std::string scenarios;  // "" : ./scenarios
  bool quick = false;     // coarse resolutions only (the CI version)
  bool finest = false;    // adds the Bui column at h = 1.25 mm
};
int validate_command(const ValidateOptions& options);

}  // namespace app
