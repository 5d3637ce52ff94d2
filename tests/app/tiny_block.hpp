// The app tests' tiny scene, shared by the run, view and recorder tests.
#pragma once

namespace apptest {

// A soil block resting on the floor with an elastic cap, under full gravity
// from the start (no gravity stage): it settles and rings. Two painted
// stages around a material change, so frame numbers continue across stages.
inline constexpr const char* kTinyBlock = R"json({
  "name": "tiny-block",
  "description": "App test: a Mohr-Coulomb block and an elastic cap settling.",
  "domain": {"min": [0, 0], "max": [4, 3]},
  "grid": {"cell_size": 0.5, "padding_cells": 2, "points_per_cell": 2},
  "gravity": [0, -9.81],
  "boundaries": {"left": "roller", "right": "roller", "bottom": "fixed", "top": "free"},
  "materials": {
    "block": {"model": "mohr-coulomb", "density": 2000, "youngs_modulus": 2e7,
              "poisson_ratio": 0.25, "cohesion": 5000, "friction_angle": 30,
              "dilation_angle": 0, "critical_density": 1900},
    "cap": {"model": "linear-elastic", "density": 500, "youngs_modulus": 2e7,
            "poisson_ratio": 0.25}
  },
  "bodies": [
    {"name": "block", "material": "block", "rectangle": {"min": [1, 0], "max": [3, 1]}},
    {"name": "cap", "material": "cap", "rectangle": {"min": [1.5, 1], "max": [2.5, 1.5]}}
  ],
  "time_step": {"courant": 0.5},
  "stages": [
    {"name": "settle", "type": "dynamic", "duration": 0.2},
    {"name": "soften", "type": "material-change", "material": "block", "set": {"cohesion": 0}},
    {"name": "slump", "type": "dynamic", "duration": 0.1}
  ],
  "output": {"frame_interval": 0.05, "frame_stages": ["settle", "slump"],
             "fields": ["displacement-y", "relative-yield", "velocity", "material"],
             "colour_map": "viridis", "vtk": "frames", "image_size": [320, 180]}
})json";

}  // namespace apptest
