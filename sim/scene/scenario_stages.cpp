// Stages, output settings and the memory budget of a scenario.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include "sim/scene/scenario_geometry.hpp"
#include "sim/scene/scenario_parts.hpp"

namespace sim {

using namespace scenario_json;

namespace {

constexpr double kPi = 3.14159265358979323846;

RestCriterion parse_rest(const Node& node, double duration) {
  require_object(node, {"kinetic_ratio", "min_time"});
  RestCriterion r;
  r.enabled = true;
  r.kinetic_ratio = positive(required(node, "kinetic_ratio"));
  r.min_time = number(required(node, "min_time"), 0, Bound::Closed, duration, Bound::Closed);
  return r;
}

}  // namespace

int material_index(const Node& name, const std::vector<MaterialSpec>& materials) {
  const std::string wanted = string(name);
  std::string defined;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    if (materials[i].name == wanted) return static_cast<int>(i);
    defined += (i == 0 ? "\"" : ", \"") + materials[i].name + "\"";
  }
  fail(name, "the name of a material in materials (defined: " + defined + ")");
}

namespace {

// The materials as the stages so far leave them, and the lowest friction
// angle any point of each can have (a random field's lower bound).
struct MaterialsNow {
  std::vector<MaterialSpec> specs;
  std::vector<double> lowest_friction;
};

// A cohesion or friction angle given as {"random_field": ...} (scenario_fields.cpp).
bool is_field(const Node& v, const std::string& property) {
  return v.value.is_object() && (property == "cohesion" || property == "friction_angle");
}

void parse_change(const Node& v, MaterialChange& c, MaterialSpec& m, double& lowest_friction,
                  const Scenario& s) {
  if (is_field(v, c.property)) {
    c.has_field = true;
    c.field = parse_random_field(v, c.property, m, s);
    c.value = c.field.mean;
    if (c.property == "cohesion") m.cohesion = c.value;
    if (c.property == "friction_angle") m.friction_angle = c.value, lowest_friction = c.field.lower;
    return;
  }
  if (c.property == "cohesion") c.value = m.cohesion = non_negative(v);
  if (c.property == "youngs_modulus") c.value = m.youngs_modulus = positive(v);
  if (c.property == "poisson_ratio")
    c.value = m.poisson_ratio = number(v, 0, Bound::Closed, 0.5, Bound::Open);
  if (c.property == "friction_angle")
    c.value = lowest_friction = m.friction_angle =
        number(v, 0, Bound::Open, 90, Bound::Open) * kPi / 180;
  if (c.property == "dilation_angle")
    c.value = m.dilation_angle = number(v, 0, Bound::Closed, 90, Bound::Open) * kPi / 180;
}

// Applies a material-change stage to the materials as they stand at that
// stage, so later stages and the dilation <= friction rule see the changes.
void parse_changes(const Node& node, StageSpec& stage, MaterialsNow& now, const Scenario& s) {
  const Node name = required(node, "material", "required for a material-change stage");
  const int index = material_index(name, now.specs);
  MaterialSpec& m = now.specs[index];
  const Node set = required(node, "set", "required for a material-change stage");
  if (m.model == MaterialModel::MohrCoulomb)
    require_object(set, {"cohesion", "friction_angle", "dilation_angle", "youngs_modulus",
                         "poisson_ratio"}, "mohr-coulomb material \"" + m.name + "\"");
  else
    require_object(set, {"youngs_modulus", "poisson_ratio"},
                   "linear-elastic material \"" + m.name + "\"");
  if (set.value.empty()) fail(set, "at least one property to change");
  // nlohmann orders keys alphabetically: dilation_angle is read before
  // friction_angle, so a field's bounds are checked against the new dilation.
  for (const auto& item : set.value.items()) {
    MaterialChange c;
    c.material = index;
    c.property = item.key();
    parse_change(set.at(item.key()), c, m, now.lowest_friction[index], s);
    stage.changes.push_back(c);
  }
  if (m.dilation_angle > now.lowest_friction[index]) {
    std::ostringstream msg;
    msg << node.path << " (" << stage.name << ") leaves materials." << m.name
        << " with dilation_angle " << m.dilation_angle * 180 / kPi << " > friction_angle "
        << now.lowest_friction[index] * 180 / kPi
        << (now.lowest_friction[index] == m.friction_angle ? "" : " (its field's lower bound)")
        << ": expected dilation_angle <= friction_angle";
    fail_at(node.file, msg.str());
  }
}

StageSpec parse_stage(const Node& node, MaterialsNow& now, const Scenario& scenario) {
  StageSpec s;
  if (!node.value.is_object()) fail(node, "an object");
  s.name = string(required(node, "name"));
  if (s.name.empty()) fail(node.at("name"), "a non-empty name");
  const Node type = required(node, "type");
  const std::string kind = one_of(type, {"gravity", "material-change", "dynamic"});
  const std::string need = "required for a " + kind + " stage";
  if (kind == "material-change") {
    s.type = StageType::MaterialChange;
    require_object(node, {"name", "type", "material", "set"}, "a material-change stage");
    parse_changes(node, s, now, scenario);
    return s;
  }
  s.type = kind == "gravity" ? StageType::Gravity : StageType::Dynamic;
  if (s.type == StageType::Gravity) {
    require_object(node, {"name", "type", "duration", "ramp_fraction", "damping", "stop_at_rest"},
                   "a gravity stage");
    s.duration = positive(required(node, "duration", need));
    s.ramp_fraction = number(required(node, "ramp_fraction", need), 0, Bound::Open, 1, Bound::Closed);
    s.damping = non_negative(required(node, "damping", need));
  } else {
    require_object(node, {"name", "type", "duration", "damping", "stop_at_rest"},
                   "a dynamic stage");
    s.duration = positive(required(node, "duration", need));
    if (node.has("damping")) s.damping = non_negative(node.at("damping"));
  }
  if (node.has("stop_at_rest")) s.rest = parse_rest(node.at("stop_at_rest"), s.duration);
  return s;
}

// [width, height] or [width, "auto"], in pixels.
std::array<int, 2> parse_image_size(const Node& size) {
  const char* what = "[width, height] or [width, \"auto\"] in pixels";
  if (!size.value.is_array() || size.value.size() != 2) fail(size, what);
  const int width = integer(size.at(0), 64, 8192);
  const Node height = size.at(1);
  const char* what_height = "an integer in [64, 8192] or \"auto\"";
  if (height.value.is_string()) {
    if (height.value.get<std::string>() != "auto") fail(height, what_height);
    return {width, kAutoHeight};
  }
  const double h = height.value.is_number() ? height.value.get<double>() : 0;
  if (!(h >= 64 && h <= 8192 && h == std::floor(h))) fail(height, what_height);
  return {width, static_cast<int>(h)};
}

}  // namespace

std::vector<StageSpec> parse_stages(const Node& node, const Scenario& scenario) {
  if (!node.value.is_array() || node.value.empty()) fail(node, "an array of stages (at least one)");
  MaterialsNow now{scenario.materials, {}};
  for (const MaterialSpec& m : scenario.materials) now.lowest_friction.push_back(m.friction_angle);
  std::vector<StageSpec> stages;
  std::map<std::string, std::size_t> names;
  for (std::size_t i = 0; i < node.value.size(); ++i) {
    stages.push_back(parse_stage(node.at(i), now, scenario));
    const auto [seen, fresh] = names.emplace(stages[i].name, i);
    if (!fresh)
      fail(node.at(i).at("name"),
           "a name no other stage has (stages[" + std::to_string(seen->second) + "] has it)");
  }
  return stages;
}

namespace {

// output.frame_stages: gravity or dynamic stages, each once; all of them
// when absent.
std::vector<std::string> parse_frame_stages(const Node& node, const std::vector<StageSpec>& stages) {
  std::vector<std::string> names;
  if (!node.has("frame_stages")) {
    for (const StageSpec& s : stages)
      if (s.type != StageType::MaterialChange) names.push_back(s.name);
    return names;
  }
  const Node list = node.at("frame_stages");
  if (!list.value.is_array()) fail(list, "an array of stage names");
  std::set<std::string> timed, listed;
  for (const StageSpec& s : stages)
    if (s.type != StageType::MaterialChange) timed.insert(s.name);
  for (std::size_t i = 0; i < list.value.size(); ++i) {
    const std::string name = string(list.at(i));
    if (!timed.count(name)) fail(list.at(i), "the name of a gravity or dynamic stage");
    if (!listed.insert(name).second) fail(list.at(i), "each stage once");
    names.push_back(name);
  }
  return names;
}

// output.fields: each field once; displacement-x when absent.
std::vector<std::string> parse_fields(const Node& node) {
  if (!node.has("fields")) return {"displacement-x"};
  const Node list = node.at("fields");
  if (!list.value.is_array() || list.value.empty()) fail(list, "a non-empty array of fields");
  std::vector<std::string> fields;
  for (std::size_t i = 0; i < list.value.size(); ++i) {
    const std::string f = one_of(list.at(i), {"displacement-x", "displacement-y",
                                              "relative-yield", "stress-yy", "velocity",
                                              "material", "cohesion", "friction-angle"});
    if (std::find(fields.begin(), fields.end(), f) != fields.end())
      fail(list.at(i), "each field once");
    fields.push_back(f);
  }
  return fields;
}

void parse_ranges_and_view(const Node& node, OutputSpec& o) {
  if (node.has("ranges")) {
    const Node ranges = node.at("ranges");
    require_object(ranges, {"displacement-x", "displacement-y", "relative-yield", "stress-yy",
                            "velocity", "cohesion", "friction-angle"});
    for (const auto& item : ranges.value.items()) {
      const Node r = ranges.at(item.key());
      if (!r.value.is_array() || r.value.size() != 2) fail(r, "[low, high], low < high");
      const Vec2 lh = vec2(r);
      if (!(lh[0] < lh[1])) fail(r, "[low, high], low < high");
      o.ranges[item.key()] = {lh[0], lh[1]};
    }
  }
  if (node.has("view")) {
    const Node view = node.at("view");
    require_object(view, {"min", "max"});
    o.view_min = vec2(required(view, "min"));
    o.view_max = vec2(required(view, "max"));
    if (!(o.view_max[0] > o.view_min[0] && o.view_max[1] > o.view_min[1]))
      fail(view.at("max"), "max > min in x and y");
    o.has_view = true;
  }
}

}  // namespace

OutputSpec parse_output(const Node& node, const std::vector<StageSpec>& stages) {
  require_object(node, {"frame_interval", "frame_stages", "fields", "colour_map", "ranges",
                        "displacement_reference", "vtk", "vtk_interval", "image_size",
                        "view"});
  OutputSpec o;
  // At most kMaxFrames frames (or states) per stage, so a tiny interval cannot stall a run.
  double longest = 0;
  for (const StageSpec& s : stages) longest = std::max(longest, s.duration);
  const std::string per_stage = "at least the longest stage / " +
                                std::to_string(static_cast<long>(kMaxFrames)) +
                                " s (at most that many per stage)";
  if (node.has("frame_interval")) {
    o.frame_interval = non_negative(node.at("frame_interval"));
    if (o.frame_interval > 0 && longest / o.frame_interval > kMaxFrames)
      fail(node.at("frame_interval"), "0 (no frames) or " + per_stage);
  }
  o.frame_stages = parse_frame_stages(node, stages);
  o.fields = parse_fields(node);
  if (node.has("colour_map")) o.colour_map = one_of(node.at("colour_map"), {"viridis", "jet"});
  if (node.has("displacement_reference"))
    o.displacement_reference = one_of(node.at("displacement_reference"), {"initial", "stage-start"});
  if (node.has("vtk")) o.vtk = one_of(node.at("vtk"), {"none", "stage-end", "frames", "interval"});
  if (o.vtk == "interval") {
    const Node every = required(node, "vtk_interval", "required when vtk is \"interval\"");
    o.vtk_interval = positive(every);
    if (longest / o.vtk_interval > kMaxFrames) fail(every, per_stage);
  } else if (node.has("vtk_interval")) {
    fail(node.at("vtk_interval"), "no vtk_interval unless vtk is \"interval\"");
  }
  if (node.has("image_size")) o.image_size = parse_image_size(node.at("image_size"));
  parse_ranges_and_view(node, o);
  return o;
}

namespace {

// A count as a whole number ("20000000", not "2e+07"), or "inf".
std::string count_text(double n) {
  if (!std::isfinite(n)) return std::isnan(n) ? "nan" : "inf";
  std::ostringstream text;
  if (n < 1e15) text << std::fixed << std::setprecision(0) << n;
  else text << n;
  return text.str();
}

}  // namespace

void check_memory_budget_of_grid(const Node& root, const Scenario& s) {
  const double nodes = ((s.domain_max[0] - s.domain_min[0]) / s.cell_size + 2 * s.padding_cells + 2) *
                       ((s.domain_max[1] - s.domain_min[1]) / s.cell_size + 2 * s.padding_cells + 2);
  if (!(nodes <= kMaxGridNodes)) {
    std::ostringstream msg;
    msg << "a grid of at most " << count_text(kMaxGridNodes)
        << " nodes; this domain, cell size and padding need about " << count_text(nodes);
    fail(root.at("grid").at("cell_size"), msg.str());
  }
}

void check_memory_budget_of_points(const Node& root, const Scenario& s) {
  // Areas in units of the point spacing, measured from the domain's corner:
  // bounded by the grid budget, where square metres of a scene with huge
  // coordinates could overflow to inf / inf = NaN and slip through.
  const double spacing = s.cell_size / s.points_per_cell;
  double points = 0;
  for (const BodySpec& b : s.bodies) {
    std::vector<Vec2> scaled = b.polygon;
    for (Vec2& v : scaled)
      v = {(v[0] - s.domain_min[0]) / spacing, (v[1] - s.domain_min[1]) / spacing};
    points += std::fabs(signed_area(scaled));
  }
  if (!(points <= kMaxPoints)) {
    std::ostringstream msg;
    msg << "at most " << count_text(kMaxPoints) << " points (body area / (cell_size / "
        << "points_per_cell)^2); the bodies need about " << count_text(points);
    fail(root.at("grid"), msg.str());
  }
}

}  // namespace sim
