// The paper's two parameter studies as the gallery runs them: Fig. 11's
// resolutions and Fig. 12's friction angles are the members of the shipped
// sweep files (scenarios/sweeps/, read by sweep::read_sweep as `landslide
// sweep` reads them), so that editing a sweep file changes its figure and the
// figure shows what `landslide sweep` runs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_file.hpp"

namespace app::gallery {

// One study: its sweep, whose one axis is the path the figure is about.
struct Study {
  const char* file;  // under the scenarios folder
  const char* path;  // the one axis the figure's captions describe
  sweep::Sweep sweep;
};

// The friction angle the paper slope's trigger sets (stage 1 of its scenes).
constexpr const char* kTriggerFrictionAngle = "stages.1.set.friction_angle";

struct Studies {
  Study resolutions{"sweeps/fig11-resolutions.json", "grid.cell_size", {}};
  Study friction_angles{"sweeps/fig12-friction-angles.json", kTriggerFrictionAngle, {}};
};

// Reads both sweep files under `scenarios` and every member's scene. Throws
// sweep::SweepError naming the file (and the member and JSON path) for what
// read_sweep refuses, and for a sweep whose axes are not the study's one
// axis: a figure's captions say what that axis is (phi, h).
Studies read_studies(const std::filesystem::path& scenarios);

// The member's scene for the gallery, named after the sweep file and the
// member ("fig12-friction-angles member 0 [stages.1.set.friction_angle =
// 25]"): the base scene's name would be the same for every member, and the
// name is all that the gallery's messages show of a run.
sim::Scenario member_scenario(const Study& study, const sweep::Member& member);

// The value at `path` (keys and indices joined by dots, as a sweep axis
// names it) in the member's scene, as its JSON writes it ("25"); "" where
// the scene has none.
std::string scene_value(const sweep::Member& member, const std::string& path);

// "four" for 4 (one to twelve), digits above: a figure's title counts its members.
std::string count_word(std::size_t n);

}  // namespace app::gallery
