// A valid scenario that uses every key, shared by the scenario tests.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace scenario_test {

// Three materials (indexed alphabetically: bedrock 0, house 1, soil 2), a
// clockwise polygon, two rectangles that touch it, every stage type and every
// output key.
inline const char* const kExample = R"json({
  "name": "full-example",
  "description": "Every key of the format.",
  "domain": {"min": [0, 0], "max": [80, 20]},
  "grid": {"cell_size": 1.0, "padding_cells": 3, "points_per_cell": 2},
  "gravity": [0.5, -9.81],
  "boundaries": {"left": "roller", "right": "free", "bottom": "fixed", "top": "free"},
  "materials": {
    "soil": {"model": "mohr-coulomb", "density": 2000, "youngs_modulus": 2e7,
             "poisson_ratio": 0.25, "cohesion": 40000, "friction_angle": 30,
             "dilation_angle": 10, "critical_density": 1900},
    "house": {"model": "linear-elastic", "density": 500, "youngs_modulus": 2e7,
              "poisson_ratio": 0.3},
    "bedrock": {"model": "linear-elastic", "density": 2600, "youngs_modulus": 1e9,
                "poisson_ratio": 0.2}
  },
  "bodies": [
    {"name": "base", "material": "bedrock", "rectangle": {"min": [0, 0], "max": [80, 2]}},
    {"name": "slope", "material": "soil", "polygon": [[0, 2], [0, 12], [40, 12], [52, 2]]},
    {"name": "house", "material": "house", "rectangle": {"min": [30, 12], "max": [36, 16]}}
  ],
  "time_step": {"fixed": 0.001},
  "stages": [
    {"name": "settle", "type": "gravity", "duration": 4, "ramp_fraction": 0.5, "damping": 0.01,
     "stop_at_rest": {"kinetic_ratio": 1e-5, "min_time": 3}},
    {"name": "trigger", "type": "material-change", "material": "soil",
     "set": {"friction_angle": 20, "cohesion": 0, "dilation_angle": 5,
             "youngs_modulus": 1e7, "poisson_ratio": 0.3}},
    {"name": "slide", "type": "dynamic", "duration": 30, "damping": 0.001,
     "stop_at_rest": {"kinetic_ratio": 1e-4, "min_time": 2}}
  ],
  "output": {"frame_interval": 0.5, "frame_stages": ["slide"],
             "fields": ["displacement-x", "relative-yield", "material"], "colour_map": "jet",
             "displacement_reference": "stage-start", "vtk": "frames", "image_size": [640, 360]}
})json";

inline nlohmann::json example_json() { return nlohmann::json::parse(kExample); }

}  // namespace scenario_test
