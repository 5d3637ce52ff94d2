// The scene the checkpoint and series tests run (tests/app/).
#pragma once

// A soil block settling and slumping for 1.5 s of simulated time: long
// enough for the test to see a checkpoint before the run ends.
inline const char* const kSlumpingBlock = R"json({
  "name": "checkpoint-block",
  "description": "App test: a block settling, then slumping after losing its cohesion.",
  "domain": {"min": [0, 0], "max": [4, 3]},
  "grid": {"cell_size": 0.25, "padding_cells": 2, "points_per_cell": 2},
  "gravity": [0, -9.81],
  "boundaries": {"left": "roller", "right": "roller", "bottom": "fixed", "top": "free"},
  "materials": {
    "block": {"model": "mohr-coulomb", "density": 2000, "youngs_modulus": 2e7,
              "poisson_ratio": 0.25, "cohesion": 5000, "friction_angle": 30,
              "dilation_angle": 0, "critical_density": 1900}
  },
  "bodies": [{"name": "block", "material": "block", "rectangle": {"min": [1, 0], "max": [3, 1.5]}}],
  "time_step": {"courant": 0.5},
  "stages": [
    {"name": "settle", "type": "gravity", "duration": 0.5, "ramp_fraction": 0.5, "damping": 0.01},
    {"name": "soften", "type": "material-change", "material": "block", "set": {"cohesion": 0}},
    {"name": "slump", "type": "dynamic", "duration": 1.0}
  ],
  "output": {"frame_interval": 0.1, "frame_stages": ["slump"],
             "fields": ["displacement-x"], "colour_map": "viridis", "vtk": "stage-end",
             "image_size": [160, 90]}
})json";
