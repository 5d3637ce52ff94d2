// A sweep file (`landslide sweep SWEEP.json`, README.md "landslide sweep"):
// a base scene and axes, each a JSON path into it and the values it takes.
// Its members are the Cartesian product of the axes, the first axis slowest,
// times the samples of its random fields (sweep/sweep_fields.hpp), the
// sample fastest; each member's scene is the base with its values put in and is read by the
// scene reader (sim::parse_scenario) before any member runs.
#pragma once

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scenario.hpp"
#include "sweep/sweep_fields.hpp"

namespace sweep {

// A refusal of the sweep file: one line naming the file, the member where
// there is one, the JSON path and what was wrong.
class SweepError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Axis {
  std::string path;                   // "materials.soil.friction_angle", "stages.1.set.cohesion"
  std::vector<nlohmann::json> values;  // scalars
};

struct Member {
  int index = 0;                       // its place in the product, from 0
  std::vector<nlohmann::json> values;  // one per axis
  int sample = 0;                      // of the random fields (0 without them)
  std::vector<std::uint64_t> seeds;    // one per random field
  std::string scene_text;              // the member's scene, as written to its folder
  sim::Scenario scenario;
  bool painted = false;                // --paint: the base scene's frames and VTK states
};

struct Sweep {
  std::filesystem::path file;
  std::filesystem::path base;  // relative to the sweep file's folder
  std::vector<Axis> axes;
  SweepFields fields;
  std::vector<Member> members;
};

// "SWEEP: member N (PATH = VALUE, ..., sample S)", as messages name a member.
std::string member_name(const Sweep& sweep, const Member& member);

// The folder of member `index` under the sweep's output folder: members/NNNN.
std::filesystem::path member_dir(const std::filesystem::path& out, int index);

// Reads the sweep file and every member's scene (labelled as its file in
// member_dir(out, index)/scene.json); members not in `painted` paint no
// frames and write no VTK states. Throws SweepError.
Sweep read_sweep(const std::filesystem::path& file, const std::filesystem::path& out,
                 const std::set<int>& painted);

}  // namespace sweep
