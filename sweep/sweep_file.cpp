#include "sweep/sweep_file.hpp"

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

void require_keys(const Json& node, const std::set<std::string>& allowed,
                  const std::string& where) {
  if (!node.is_object()) throw SweepError(where + ": expected an object");
  for (const auto& item : node.items())
    if (!allowed.count(item.key())) {
      std::string list;
      for (const std::string& k : allowed) list += (list.empty() ? "" : ", ") + k;
      throw SweepError(where + "." + item.key() + ": unknown key (allowed: " + list + ")");
    }
}

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
  return parts;
}

// The value at `path` in `scene`; null if the scene does not have it.
Json* find_path(Json& scene, const std::string& path) {
  Json* at = &scene;
  for (const std::string& part : split_path(path)) {
    if (part.empty()) return nullptr;
    if (at->is_object()) {
      auto it = at->find(part);
      if (it == at->end()) return nullptr;
      at = &*it;
    } else if (at->is_array()) {
      if (part.find_first_not_of("0123456789") != std::string::npos) return nullptr;
      const unsigned long k = std::stoul(part);
      if (k >= at->size()) return nullptr;
      at = &(*at)[k];
    } else {
      return nullptr;
    }
  }
  return at;
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

Member make_member(const Sweep& s, const Json& base, int index, const std::set<int>& painted,
                   const fs::path& out) {
  Member m;
  m.index = index;
  m.painted = painted.count(index) > 0;
  Json scene = base;
  int rest = index;
  m.values.resize(s.axes.size());
  for (std::size_t k = s.axes.size(); k-- > 0;) {  // the first axis slowest
    const Axis& a = s.axes[k];
    m.values[k] = a.values[rest % a.values.size()];
    rest /= static_cast<int>(a.values.size());
  }
  if (!m.painted) without_painting(scene);
  for (std::size_t k = 0; k < s.axes.size(); ++k) *find_path(scene, s.axes[k].path) = m.values[k];
  m.scene_text = scene.dump(2) + "\n";
  const std::string label = (member_dir(out, index) / "scene.json").string();
  try {
    m.scenario = sim::parse_scenario(m.scene_text, label);
  } catch (const sim::ScenarioError& e) {
    std::string values;
    for (std::size_t k = 0; k < s.axes.size(); ++k)
      values += (k ? ", " : "") + s.axes[k].path + " = " + m.values[k].dump();
    throw SweepError(s.file.string() + ": member " + std::to_string(index) + " (" + values +
                     "): " + e.what());
  }
  return m;
}

}  // namespace

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
  require_keys(doc, {"base", "axes"}, f);
  if (!doc.contains("base") || !doc["base"].is_string())
    throw SweepError(f + ": base: expected the base scene's file (a string)");
  if (!doc.contains("axes") || !doc["axes"].is_array() || doc["axes"].empty())
    throw SweepError(f + ": axes: expected a non-empty array of {\"path\", \"values\"}");
  s.base = file.parent_path() / doc["base"].get<std::string>();
  const Json base = read_json(s.base);
  long long count = 1;
  for (std::size_t k = 0; k < doc["axes"].size(); ++k) {
    const std::string where = f + ": axes[" + std::to_string(k) + "]";
    s.axes.push_back(read_axis(doc["axes"][k], where, base, s.base.string()));
    for (std::size_t j = 0; j < k; ++j)
      if (s.axes[j].path == s.axes[k].path)
        throw SweepError(where + " (" + s.axes[k].path + "): also axes[" + std::to_string(j) +
                         "]'s path (each path may be swept once)");
    count *= static_cast<long long>(s.axes.back().values.size());
    if (count > 9999) throw SweepError(f + ": axes: more than 9999 members");
  }
  for (int p : painted)
    if (p < 0 || p >= count)
      throw SweepError("--paint " + std::to_string(p) + ": expected a member from 0 to " +
                       std::to_string(count - 1));
  for (int i = 0; i < count; ++i) s.members.push_back(make_member(s, base, i, painted, out));
  return s;
}

}  // namespace sweep
