#include "sweep/sweep_file.hpp"

#include "sweep/json_path.hpp"
#include "sweep/sweep_fields.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace sweep {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

Json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw SweepError(file.string() + ": cannot be read");
  try {
    return Json::parse(in);
  } catch (const Json::exception& e) {
    throw SweepError(file.string() + ": not JSON: " + e.what());
  }
}

Axis read_axis(const Json& node, const std::string& where, const Json& base,
               const std::string& base_name) {
  require_keys(node, {"path", "values"}, where);
  if (!node.contains("path") || !node["path"].is_string())
    throw SweepError(where + ".path: expected a JSON path into the base scene (a string)");
  if (!node.contains("values") || !node["values"].is_array())
    throw SweepError(where + ".values: expected an array of numbers, strings or booleans");
  Axis a{node["path"].get<std::string>(), {}};
  const std::string here = where + " (" + a.path + ")";
  Json copy = base;
  if (!find_path(copy, a.path))
    throw SweepError(here + ": the base scene " + base_name + " has no " + a.path);
  if (node["values"].empty()) throw SweepError(here + ".values: empty (give at least one)");
  for (const Json& v : node["values"]) {
    if (!v.is_primitive() || v.is_null())
      throw SweepError(here + ".values: " + v.dump() + ": expected a number, string or boolean");
    a.values.push_back(v);
  }
  return a;
}

// Members paint nothing unless asked: no frames, no VTK states.
void without_painting(Json& scene) {
  Json& output = scene["output"];
  output["frame_interval"] = 0;
  output["vtk"] = "none";
  output.erase("vtk_interval");
}

// A painted member of a sweep with random fields also paints each field's
// property ("friction-angle", "cohesion"): its soil, point by point.
void paint_field_properties(Json& scene, const SweepFields& f) {
  Json& output = scene["output"];
  if (!output.contains("fields")) output["fields"] = {"displacement-x"};  // the reader's default
  for (const FieldAxis& field : f.fields) {
    const std::string name = field.path.substr(field.path.rfind('.') + 1) == "cohesion"
                                 ? "cohesion" : "friction-angle";
    if (std::find(output["fields"].begin(), output["fields"].end(), name) == output["fields"].end())
      output["fields"].push_back(name);
  }
}

Member make_member(const Sweep& s, const Json& base, int index, const std::set<int>& painted,
                   const fs::path& out) {
  Member m;
  m.index = index;
  m.painted = painted.count(index) > 0;
  Json scene = base;
  int rest = index / s.fields.samples;
  m.sample = index % s.fields.samples;
  m.values.resize(s.axes.size());
  for (std::size_t k = s.axes.size(); k-- > 0;) {  // the first axis slowest
    const Axis& a = s.axes[k];
    m.values[k] = a.values[rest % a.values.size()];
    rest /= static_cast<int>(a.values.size());
  }
  if (!m.painted) without_painting(scene);
  if (m.painted) paint_field_properties(scene, s.fields);
  for (std::size_t k = 0; k < s.axes.size(); ++k) *find_path(scene, s.axes[k].path) = m.values[k];
  m.seeds = put_fields(scene, s.fields, m.sample);
  m.scene_text = scene.dump(2) + "\n";
  const std::string label = (member_dir(out, index) / "scene.json").string();
  try {
    m.scenario = sim::parse_scenario(m.scene_text, label);
  } catch (const sim::ScenarioError& e) {
    throw SweepError(member_name(s, m) + ": " + e.what());
  }
  return m;
}

}  // namespace

std::string member_name(const Sweep& s, const Member& m) {
  std::string values;
  for (std::size_t k = 0; k < s.axes.size(); ++k)
    values += (k ? ", " : "") + s.axes[k].path + " = " + m.values[k].dump();
  if (!s.fields.fields.empty())
    values += (values.empty() ? "sample " : ", sample ") + std::to_string(m.sample);
  return s.file.string() + ": member " + std::to_string(m.index) + " (" + values + ")";
}

fs::path member_dir(const fs::path& out, int index) {
  char name[16];
  std::snprintf(name, sizeof name, "%04d", index);
  return out / "members" / name;
}

Sweep read_sweep(const fs::path& file, const fs::path& out, const std::set<int>& painted) {
  Sweep s;
  s.file = file;
  const Json doc = read_json(file);
  const std::string f = file.string();
  require_keys(doc, {"base", "axes", "random_fields", "samples", "seed"}, f);
  if (!doc.contains("base") || !doc["base"].is_string())
    throw SweepError(f + ": base: expected the base scene's file (a string)");
  // Without random fields the axes are the sweep; with them they may be left out.
  const bool axes_needed = !doc.contains("random_fields") || doc.contains("axes");
  if (axes_needed && (!doc.contains("axes") || !doc["axes"].is_array() || doc["axes"].empty()))
    throw SweepError(f + ": axes: expected a non-empty array of {\"path\", \"values\"}");
  s.base = file.parent_path() / doc["base"].get<std::string>();
  const Json base = read_json(s.base);
  s.fields = read_sweep_fields(doc, f, base, s.base.string());
  long long count = s.fields.samples;
  const Json axes = doc.value("axes", Json::array());
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const std::string where = f + ": axes[" + std::to_string(k) + "]";
    s.axes.push_back(read_axis(axes[k], where, base, s.base.string()));
    for (std::size_t j = 0; j < k; ++j)
      if (s.axes[j].path == s.axes[k].path)
        throw SweepError(where + " (" + s.axes[k].path + "): also axes[" + std::to_string(j) +
                         "]'s path (each path may be swept once)");
    count *= static_cast<long long>(s.axes.back().values.size());
    if (count > 9999)
      throw SweepError(f + ": axes" + (s.fields.samples > 1 ? " times samples" : "") +
                       ": more than 9999 members");
  }
  for (int p : painted)
    if (p < 0 || p >= count)
      throw SweepError("--paint " + std::to_string(p) + ": expected a member from 0 to " +
                       std::to_string(count - 1));
  for (int i = 0; i < count; ++i) s.members.push_back(make_member(s, base, i, painted, out));
  return s;
}

}  // namespace sweep
