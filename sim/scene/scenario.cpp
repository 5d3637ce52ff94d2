// Reading a scenario: every key is checked against what is allowed before the
// simulation is built (scenarios/README.md documents the format).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "sim/scene/scenario_geometry.hpp"
#include "sim/scene/scenario_json.hpp"
#include "sim/scene/scenario_parts.hpp"

namespace sim {

using namespace scenario_json;

namespace {

constexpr double kPi = 3.14159265358979323846;

MaterialSpec parse_material(const Node& node, const std::string& name) {
  if (!node.value.is_object()) fail(node, "an object");
  const std::string model = one_of(required(node, "model"), {"linear-elastic", "mohr-coulomb"});
  MaterialSpec m;
  m.name = name;
  m.model = model == "mohr-coulomb" ? MaterialModel::MohrCoulomb : MaterialModel::LinearElastic;
  if (m.model == MaterialModel::MohrCoulomb)
    require_object(node, {"model", "density", "youngs_modulus", "poisson_ratio", "cohesion",
                          "friction_angle", "dilation_angle", "critical_density"},
                   "a mohr-coulomb material");
  else
    require_object(node, {"model", "density", "youngs_modulus", "poisson_ratio"},
                   "a linear-elastic material");
  const std::string need = "required for a " + model + " material";
  m.density = positive(required(node, "density", need));
  m.youngs_modulus = positive(required(node, "youngs_modulus", need));
  m.poisson_ratio = number(required(node, "poisson_ratio", need), 0, Bound::Closed, 0.5, Bound::Open);
  if (m.model == MaterialModel::MohrCoulomb) {
    for (const char* key : {"cohesion", "friction_angle"})
      if (node.has(key) && node.at(key).value.is_object())
        fail(node.at(key), "a number (a random field of it is set by a material-change "
                           "stage's \"set\", scenarios/README.md \"Random fields\")");
    m.cohesion = non_negative(required(node, "cohesion", need));
    // Compared in degrees as given: a round trip through radians could put
    // the bound a hair below an equal dilation angle.
    const double friction =
        number(required(node, "friction_angle", need), 0, Bound::Open, 90, Bound::Open);
    const double dilation = number(required(node, "dilation_angle", need), 0, Bound::Closed,
                                   friction, Bound::Closed);
    m.friction_angle = friction * kPi / 180;
    m.dilation_angle = dilation * kPi / 180;
    m.critical_density = number(required(node, "critical_density", need), 0, Bound::Open,
                                m.density, Bound::Closed);
  }
  return m;
}

std::vector<MaterialSpec> parse_materials(const Node& node) {
  if (!node.value.is_object() || node.value.empty())
    fail(node, "an object of named materials (at least one)");
  if (node.value.size() > 255) fail(node, "at most 255 materials");
  std::vector<MaterialSpec> materials;
  for (const auto& item : node.value.items())
    materials.push_back(parse_material(node.at(item.key()), item.key()));
  return materials;
}

// Validation compares every pair of edges in a polygon and of two bodies, so
// the sizes are capped where that stays well under a second.
constexpr std::size_t kMaxVertices = 10000;       // one polygon
constexpr std::size_t kMaxTotalVertices = 20000;  // all bodies together
constexpr std::size_t kMaxBodies = 1000;

std::string domain_text(const Scenario& s) {
  std::ostringstream text;
  text << "[" << s.domain_min[0] << ", " << s.domain_max[0] << "] x [" << s.domain_min[1] << ", "
       << s.domain_max[1] << "]";
  return text.str();
}

// Distances below this are round-off: 1e-9 of the domain's larger extent.
double round_off(const Scenario& s) {
  return 1e-9 * std::max(s.domain_max[0] - s.domain_min[0], s.domain_max[1] - s.domain_min[1]);
}

// A body vertex, which must lie inside the walls (to round-off).
Vec2 vertex(const Node& node, const Scenario& s) {
  const Vec2 v = vec2(node);
  const double tol = round_off(s);
  if (v[0] < s.domain_min[0] - tol || v[0] > s.domain_max[0] + tol ||
      v[1] < s.domain_min[1] - tol || v[1] > s.domain_max[1] + tol)
    fail(node, "a point inside the domain " + domain_text(s));
  return v;
}

std::vector<Vec2> parse_polygon(const Node& node, const Scenario& s) {
  if (!node.value.is_array() || node.value.size() < 3 || node.value.size() > kMaxVertices)
    fail(node, "an array of 3 to " + std::to_string(kMaxVertices) + " vertices [x, y]");
  std::vector<Vec2> polygon;
  for (std::size_t i = 0; i < node.value.size(); ++i) polygon.push_back(vertex(node.at(i), s));
  if (const auto contact = polygon_self_contact(polygon)) {
    const std::size_t n = polygon.size(), i = (*contact)[0], j = (*contact)[1];
    const auto edge = [n](std::size_t k) {
      return std::to_string(k) + "-" + std::to_string((k + 1) % n);
    };
    if (i == j && i == n - 1)
      fail(node, "a simple polygon (the last vertex repeats the first; it is closed already)");
    fail(node, i == j ? "a simple polygon (vertices " + edge(i) + " are the same point)"
                      : "a simple polygon (edges " + edge(i) + " and " + edge(j) +
                            " cross or touch; vertices count from 0)");
  }
  const double area = signed_area(polygon);
  if (area == 0) fail(node, "a polygon of non-zero area");
  if (area < 0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// `names` maps the names of the bodies before this one to their indices.
BodySpec parse_body(const Node& node, const Scenario& s,
                    const std::map<std::string, std::size_t>& names) {
  require_object(node, {"name", "material", "rectangle", "polygon"});
  BodySpec b;
  const Node name_node = required(node, "name");
  b.name = string(name_node);
  if (b.name.empty()) fail(name_node, "a non-empty name");
  if (const auto seen = names.find(b.name); seen != names.end())
    fail(name_node,
         "a name no other body has (bodies[" + std::to_string(seen->second) + "] has it)");
  const Node material = required(node, "material");
  b.material = material_index(material, s.materials);
  if (node.has("rectangle") == node.has("polygon"))
    fail(node, "exactly one of \"rectangle\" or \"polygon\"");
  if (node.has("polygon")) {
    b.polygon = parse_polygon(node.at("polygon"), s);
  } else {
    const Node r = node.at("rectangle");
    require_object(r, {"min", "max"});
    const Vec2 lo = vertex(required(r, "min"), s), hi = vertex(required(r, "max"), s);
    if (!(hi[0] > lo[0] && hi[1] > lo[1])) fail(r.at("max"), "max > min in x and y");
    b.polygon = {lo, {hi[0], lo[1]}, hi, {lo[0], hi[1]}};
  }
  return b;
}

void parse_bodies(const Node& node, Scenario& s) {
  if (!node.value.is_array() || node.value.empty() || node.value.size() > kMaxBodies)
    fail(node, "an array of 1 to " + std::to_string(kMaxBodies) + " bodies");
  std::map<std::string, std::size_t> names;
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < node.value.size(); ++i) {
    const Node body = node.at(i);
    s.bodies.push_back(parse_body(body, s, names));
    const BodySpec& b = s.bodies.back();
    names.emplace(b.name, i);
    vertices += b.polygon.size();
    if (vertices > kMaxTotalVertices)
      fail(body.at(body.has("polygon") ? "polygon" : "rectangle"),
           "at most " + std::to_string(kMaxTotalVertices) +
               " vertices in all bodies together (this body brings them to " +
               std::to_string(vertices) + ")");
    for (std::size_t k = 0; k < i; ++k) {
      if (s.bodies[k].material != b.material &&
          polygons_overlap(s.bodies[k].polygon, b.polygon, round_off(s)))
        fail_at(node.file, body.path + " (" + b.name + ") overlaps bodies[" + std::to_string(k) +
                               "] (" + s.bodies[k].name + ") of a different material");
    }
  }
}

// A wall is a kind by name, or {"friction": mu}: a Coulomb friction wall.
Wall parse_wall(const Node& node) {
  Wall w;
  if (node.value.is_object()) {
    require_object(node, {"friction"}, "a friction wall");
    w.kind = BoundaryKind::Friction;
    w.friction = non_negative(required(node, "friction", "the Coulomb coefficient mu"));
    return w;
  }
  const std::string kind = node.value.is_string() ? node.value.get<std::string>() : "";
  if (kind == "fixed") w.kind = BoundaryKind::Fixed;
  else if (kind == "roller") w.kind = BoundaryKind::Roller;
  else if (kind == "free") w.kind = BoundaryKind::Free;
  else fail(node, "one of \"fixed\", \"roller\", \"free\", or {\"friction\": mu} with mu >= 0");
  return w;
}

Boundaries parse_boundaries(const Node& node) {
  require_object(node, {"left", "right", "bottom", "top"});
  Boundaries b;
  b.left = parse_wall(required(node, "left"));
  b.right = parse_wall(required(node, "right"));
  b.bottom = parse_wall(required(node, "bottom"));
  b.top = parse_wall(required(node, "top"));
  return b;
}

TimeStepSpec parse_time_step(const Node& node) {
  require_object(node, {"courant", "fixed"});
  if (node.has("courant") == node.has("fixed"))
    fail(node, "exactly one of \"courant\" or \"fixed\"");
  TimeStepSpec t;
  if (node.has("courant")) {
    t.mode = TimeStepSpec::Mode::Courant;
    t.courant = number(node.at("courant"), 0, Bound::Open, 0.5, Bound::Closed);
  } else {
    t.mode = TimeStepSpec::Mode::Fixed;
    t.fixed_dt = positive(node.at("fixed"));
  }
  return t;
}

Scenario parse_document(const Json& doc, const std::string& file) {
  const Node root{doc, "", file};
  require_object(root, {"name", "description", "domain", "grid", "gravity", "boundaries",
                        "materials", "bodies", "time_step", "transfer", "stages", "output"});
  Scenario s;
  s.source_path = file;
  const Node name = required(root, "name");
  s.name = string(name);
  // The name becomes part of file names and titles: keep it to safe characters.
  const bool safe = std::all_of(s.name.begin(), s.name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
           c == '.' || c == '_' || c == '-';
  });
  if (s.name.empty() || s.name.size() > 100 || !safe)
    fail(name, "1 to 100 characters from A-Z a-z 0-9 . _ -");
  if (root.has("description")) s.description = string(root.at("description"));
  const Node domain = required(root, "domain");
  require_object(domain, {"min", "max"});
  s.domain_min = vec2(required(domain, "min"));
  s.domain_max = vec2(required(domain, "max"));
  if (!(s.domain_max[0] > s.domain_min[0] && s.domain_max[1] > s.domain_min[1]))
    fail(domain.at("max"), "max > min in x and y");
  const Node grid = required(root, "grid");
  require_object(grid, {"cell_size", "padding_cells", "points_per_cell"});
  s.cell_size = positive(required(grid, "cell_size"));
  s.padding_cells = integer(required(grid, "padding_cells"), 2, 100);
  s.points_per_cell = integer(required(grid, "points_per_cell"), 1, 8);
  s.gravity = vec2(required(root, "gravity"));
  s.boundaries = parse_boundaries(required(root, "boundaries"));
  s.materials = parse_materials(required(root, "materials"));
  check_memory_budget_of_grid(root, s);
  parse_bodies(required(root, "bodies"), s);
  check_memory_budget_of_points(root, s);
  s.time_step = parse_time_step(required(root, "time_step"));
  if (root.has("transfer"))
    s.transfer = one_of(root.at("transfer"), {"flip", "apic"}) == "apic" ? TransferScheme::Apic
                                                                        : TransferScheme::Flip;
  s.stages = parse_stages(required(root, "stages"), s);
  s.output = parse_output(required(root, "output"), s.stages);
  return s;
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& label) {
  const Json doc = parse_text(text, label);
  try {
    return parse_document(doc, label);
  } catch (const ScenarioError&) {
    throw;
  } catch (const std::exception& e) {  // a library error the checks above did not foresee
    fail_at(label, std::string("cannot read the scenario: ") + e.what());
  }
}

std::string read_scenario_text(const std::string& path) {
  std::error_code ec;  // a directory opens as a stream and then reads as empty text
  if (std::filesystem::is_directory(path, ec)) fail_at(path, "cannot read file: it is a directory");
  // A scenario is kilobytes; a path to something huge is a mistake, and
  // reading it whole would only exhaust memory.
  constexpr std::uintmax_t kMaxBytes = 64u << 20;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxBytes)
    fail_at(path, "cannot read file: it is " + std::to_string(size >> 20) +
                      " MiB (a scenario is at most 64 MiB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_at(path, "cannot read file: " + std::string(std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail_at(path, "cannot read file: " + std::string(std::strerror(errno)));
  return text.str();
}

Scenario load_scenario(const std::string& path) {
  return parse_scenario(read_scenario_text(path), path);
}

}  // namespace sim
