#include "sweep/sweep_results.hpp"

#include <fstream>
#include <sstream>

#include "sim/io/atomic_file.hpp"

namespace sweep {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The summary.json in `dir`; null if there is none or it is not JSON.
Json read_summary(const fs::path& dir) {
  const fs::path file = dir / "summary.json";
  if (!fs::exists(file)) return nullptr;
  try {
    return Json::parse(read_text(file));
  } catch (const Json::exception&) {
    return nullptr;
  }
}

const Json* last_dynamic_stage(const Json& summary) {
  const Json* last = nullptr;
  const auto stages = summary.find("stages");
  if (stages == summary.end() || !stages->is_array()) return nullptr;
  for (const Json& st : *stages)
    if (st.value("type", "") == "dynamic") last = &st;
  return last;
}

void fill_from_stage(const Json& stage, MemberResult& r) {
  const Json& m = stage.at("metrics");
  r.runout_m = m.value("runout_m", Json());
  r.deposit_slope_deg = m.value("deposit_slope_deg", Json());
  double largest = 0;
  for (const Json& mm : m.value("materials", Json::array()))
    largest = std::max(largest, mm.value("max_displacement_m", 0.0));
  r.max_displacement_m = largest;
  r.at_rest = stage.value("ended_at_rest", Json());
  r.energy_relative_error = stage.at("energy").value("relative_error", Json());
}

// A CSV cell: numbers as JSON writes them (the shortest text that reads back
// the same double), strings quoted where they hold a comma or quote.
std::string cell(const Json& v) {
  if (v.is_null()) return "";
  if (!v.is_string()) return v.dump();
  const std::string s = v.get<std::string>();
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void write_csv(std::ostream& os, const Sweep& s, const std::vector<MemberResult>& results) {
  const bool fields = !s.fields.fields.empty();
  os << "member";
  for (const Axis& a : s.axes) os << ',' << cell(a.path);
  if (fields) os << ",sample";
  for (const FieldAxis& f : s.fields.fields) os << ',' << cell(f.path + " seed");
  os << ",status,runout_m,deposit_slope_deg,max_displacement_m,at_rest,energy_relative_error\n";
  for (const MemberResult& r : results) {
    os << r.index;
    for (const Json& v : r.values) os << ',' << cell(v);
    if (fields) os << ',' << r.sample;
    for (std::uint64_t seed : r.seeds) os << ',' << seed;
    os << ',' << cell(r.status) << ',' << cell(r.runout_m) << ',' << cell(r.deposit_slope_deg)
       << ',' << cell(r.max_displacement_m) << ',' << cell(r.at_rest) << ','
       << cell(r.energy_relative_error) << '\n';
  }
}

Json results_json(const Sweep& s, const std::vector<MemberResult>& results) {
  Json axes = Json::array();
  for (const Axis& a : s.axes) axes.push_back({{"path", a.path}, {"values", a.values}});
  Json fields = Json::array();
  for (const FieldAxis& f : s.fields.fields) {
    Json field = f.parameters;
    field["path"] = f.path;
    fields.push_back(field);
  }
  Json members = Json::array();
  for (const MemberResult& r : results)
    members.push_back({{"member", r.index},
                       {"values", r.values},
                       {"sample", r.sample},
                       {"seeds", r.seeds},
                       {"status", r.status},
                       {"runout_m", r.runout_m},
                       {"deposit_slope_deg", r.deposit_slope_deg},
                       {"max_displacement_m", r.max_displacement_m},
                       {"at_rest", r.at_rest},
                       {"energy_relative_error", r.energy_relative_error},
                       {"wall_time_s", r.wall_time_s}});
  return {{"sweep_file", s.file.string()}, {"base", s.base.string()}, {"axes", axes},
          {"random_fields", fields}, {"samples", s.fields.samples}, {"seed", s.fields.seed},
          {"members", members}};
}

}  // namespace

bool member_finished(const fs::path& dir, const std::string& scene_text) {
  if (!fs::exists(dir / "scene.json") || read_text(dir / "scene.json") != scene_text) return false;
  const Json summary = read_summary(dir);
  return summary.is_object() && summary.value("status", "") == "finished";
}

MemberResult read_result(const Member& member, const fs::path& out) {
  MemberResult r;
  r.index = member.index;
  r.values = member.values;
  r.sample = member.sample;
  r.seeds = member.seeds;
  const fs::path dir = member_dir(out, member.index);
  const Json summary = read_summary(dir);
  if (!summary.is_object() || read_text(dir / "scene.json") != member.scene_text) {
    r.status = "not run";
    return r;
  }
  r.status = summary.value("status", "");
  r.wall_time_s = summary.value("wall_time_s", Json());
  if (const Json* stage = last_dynamic_stage(summary)) fill_from_stage(*stage, r);
  return r;
}

void write_results(const Sweep& s, const std::vector<MemberResult>& results, const fs::path& out) {
  sim::write_file_atomically((out / "sweep.csv").string(),
                             [&](std::ostream& os) { write_csv(os, s, results); });
  sim::write_file_atomically((out / "sweep.json").string(), [&](std::ostream& os) {
    os << results_json(s, results).dump(2) << '\n';
  });
}

}  // namespace sweep
