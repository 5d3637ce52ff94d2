// The scenario: everything a run needs, read from one JSON file and fully
// validated before step 0 (see scenarios/README.md for the format).
// Angles are stored in radians here; the JSON gives degrees.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/physics/spec.hpp"

namespace sim {

// A body is a simple polygon (counter-clockwise after loading); rectangles are
// stored as four-vertex polygons.
struct BodySpec {
  std::string name;
  int material = -1;  // index into Scenario::materials
  std::vector<Vec2> polygon;
};

struct TimeStepSpec {
  enum class Mode { Courant, Fixed } mode = Mode::Courant;
  double courant = 0;   // Mode::Courant: dt = courant * h / max_p(c_p + |v_p|)
  double fixed_dt = 0;  // Mode::Fixed: checked every step against the bound
};

// A stage "at rest" test: kinetic energy divided by the work done by gravity
// since the start of the stage, below `kinetic_ratio`, once at least
// `min_time` of the stage has passed.
struct RestCriterion {
  bool enabled = false;
  double kinetic_ratio = 0;
  double min_time = 0;
};

// A spatially correlated random value of cohesion or friction angle, set by
// a material-change stage in place of a number (scenarios/README.md, "Random
// fields"; drawn by sim/scene/random_field.hpp on the lattice of the initial
// point spacing, each point taking its nearest node at its initial position).
struct RandomFieldSpec {
  enum class Distribution { LogNormal, TruncatedNormal };
  Distribution distribution = Distribution::LogNormal;
  double mean = 0;  // SI (rad for angles): of the log-normal, of the parent normal if truncated
  double cov = 0;   // coefficient of variation, standard deviation / |mean|
  double lower = 0, upper = 0;      // truncated-normal only, SI
  double theta_x = 0, theta_y = 0;  // scales of fluctuation, m (Fenton & Griffiths 2008)
  std::uint64_t seed = 0;           // the field is set by it alone
};

struct MaterialChange {
  int material = -1;      // index into Scenario::materials
  std::string property;   // "cohesion", "friction_angle", ...
  double value = 0;       // SI, radians for angles; a field's mean
  bool has_field = false; // cohesion / friction_angle drawn from `field` point by point
  RandomFieldSpec field;
};

enum class StageType { Gravity, MaterialChange, Dynamic };

struct StageSpec {
  StageType type = StageType::Dynamic;
  std::string name;
  double duration = 0;       // s (gravity, dynamic): the stage ends here at the latest
  double ramp_fraction = 0;  // gravity: fraction of duration over which g rises linearly
  double damping = 0;        // theta in v := v / (1 + theta), applied every step
  RestCriterion rest;        // gravity, dynamic
  std::vector<MaterialChange> changes;  // material-change
};

// image_size's height when it is "auto".
constexpr int kAutoHeight = 0;

struct OutputSpec {
  double frame_interval = 0;              // s of simulated time; 0: no frames
  std::vector<std::string> frame_stages;  // names of stages that are painted
  std::vector<std::string> fields;        // fields painted at each frame
  std::string colour_map = "viridis";     // "viridis" | "jet"
  std::string displacement_reference = "initial";  // "initial" | "stage-start"
  std::string vtk = "none";               // "none" | "stage-end" | "frames" | "interval"
  double vtk_interval = 0;                // s of stage time, with vtk = "interval"
  // Painted frames' size; a height of kAutoHeight ("auto") follows the view.
  std::array<int, 2> image_size = {1280, kAutoHeight};
  // The world window painted, when the scenario fixes it; otherwise the
  // material's extent over the painted stages (app::view_window).
  bool has_view = false;
  Vec2 view_min{}, view_max{};
  // Colour range per field, SI units; a field not named here is painted with
  // its range over each painted stage.
  std::map<std::string, std::array<double, 2>> ranges;
};

struct Scenario {
  std::string name;
  std::string description;
  std::string source_path;  // file it came from, for messages
  Vec2 domain_min{}, domain_max{};  // walls lie on these lines
  double cell_size = 0;             // h, m
  int padding_cells = 0;            // empty cells outside the walls
  int points_per_cell = 0;          // per direction
  Vec2 gravity{};                   // m/s^2, full value reached by the ramp
  Boundaries boundaries;
  std::vector<MaterialSpec> materials;
  std::vector<BodySpec> bodies;
  TimeStepSpec time_step;
  TransferScheme transfer = TransferScheme::Flip;  // optional key; the paper's by default
  std::vector<StageSpec> stages;
  OutputSpec output;
};

// True when frames of `stage` are painted: frames are on (frame_interval > 0)
// and the stage is named in output.frame_stages.
inline bool stage_is_painted(const Scenario& s, const StageSpec& stage) {
  const auto& names = s.output.frame_stages;
  return s.output.frame_interval > 0 &&
         std::find(names.begin(), names.end(), stage.name) != names.end();
}

// Bad input. what() reads "FILE: json.path = VALUE: expected ...".
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and validates a scenario file; throws ScenarioError on any problem.
Scenario load_scenario(const std::string& path);
// The text of a scenario file (at most 64 MiB); throws ScenarioError.
std::string read_scenario_text(const std::string& path);
// Same as load_scenario, from text already read (the label names the source
// in messages).
Scenario parse_scenario(const std::string& text, const std::string& label);

// Whether a stage draws a random field: each point then holds its own
// strength, and the draw its lattice (sim/scene/memory_budget.hpp).
inline bool sets_random_field(const Scenario& s) {
  for (const StageSpec& stage : s.stages)
    for (const MaterialChange& change : stage.changes)
      if (change.has_field) return true;
  return false;
}

}  // namespace sim
