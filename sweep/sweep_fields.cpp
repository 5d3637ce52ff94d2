#include "sweep/sweep_fields.hpp"

#include "sweep/json_path.hpp"
#include "sweep/sweep_file.hpp"

namespace sweep {

using Json = nlohmann::json;

namespace {

constexpr double kMaxSeed = 9007199254740991.0;  // 2^53 - 1: kept exactly by any JSON tool
constexpr int kMaxSamples = 9999;                // members are numbered in four digits

bool whole_number_in(const Json& v, double lo, double hi) {
  const bool whole = v.is_number_unsigned() || v.is_number_integer();
  return whole && v.get<double>() >= lo && v.get<double>() <= hi;
}

FieldAxis read_field(const Json& node, const std::string& where, const Json& base,
                     const std::string& base_name) {
  require_keys(node, {"path", "distribution", "cov", "lower", "upper", "scale_of_fluctuation"},
               where);
  if (!node.contains("path") || !node["path"].is_string())
    throw SweepError(where + ".path: expected a JSON path to a cohesion or friction_angle of "
                     "the base scene (a string)");
  FieldAxis f{node["path"].get<std::string>(), node};
  f.parameters.erase("path");
  const std::string here = where + " (" + f.path + ")";
  const std::string last = f.path.substr(f.path.rfind('.') + 1);
  if (last != "cohesion" && last != "friction_angle")
    throw SweepError(here + ": expected the path of a cohesion or friction_angle (the "
                     "properties a random field can set)");
  Json copy = base;
  const Json* at = find_path(copy, f.path);
  if (!at) throw SweepError(here + ": the base scene " + base_name + " has no " + f.path);
  if (!at->is_number())
    throw SweepError(here + ": " + at->dump() + " in " + base_name +
                     ": expected a number there (it becomes the field's mean)");
  return f;
}

}  // namespace

SweepFields read_sweep_fields(const Json& doc, const std::string& f, const Json& base,
                              const std::string& base_name) {
  SweepFields s;
  if (!doc.contains("random_fields")) {
    for (const char* key : {"samples", "seed"})
      if (doc.contains(key))
        throw SweepError(f + ": " + key + ": given without random_fields (it counts or seeds "
                         "their samples)");
    return s;
  }
  const Json& list = doc["random_fields"];
  if (!list.is_array() || list.empty())
    throw SweepError(f + ": random_fields: expected a non-empty array of {\"path\", "
                     "\"distribution\", ...}");
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string where = f + ": random_fields[" + std::to_string(k) + "]";
    s.fields.push_back(read_field(list[k], where, base, base_name));
    for (std::size_t j = 0; j < k; ++j)
      if (s.fields[j].path == s.fields[k].path)
        throw SweepError(where + " (" + s.fields[k].path + "): also random_fields[" +
                         std::to_string(j) + "]'s path (each path may have one field)");
  }
  if (!doc.contains("samples") || !whole_number_in(doc["samples"], 1, kMaxSamples))
    throw SweepError(f + ": samples = " + (doc.contains("samples") ? doc["samples"].dump() : "missing") +
                     ": expected a whole number in [1, 9999] (runs of each combination of the axes)");
  if (!doc.contains("seed") || !whole_number_in(doc["seed"], 0, kMaxSeed))
    throw SweepError(f + ": seed = " + (doc.contains("seed") ? doc["seed"].dump() : "missing") +
                     ": expected a whole number in [0, 2^53 - 1]");
  s.samples = doc["samples"].get<int>();
  s.seed = doc["seed"].get<std::uint64_t>();
  return s;
}

std::uint64_t field_seed(std::uint64_t seed, int sample, std::size_t field) {
  auto splitmix64 = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  const std::uint64_t which = (static_cast<std::uint64_t>(sample) << 16) | field;
  return splitmix64(seed ^ splitmix64(which)) >> 11;
}

std::vector<std::uint64_t> put_fields(Json& scene, const SweepFields& f, int sample) {
  std::vector<std::uint64_t> seeds;
  for (std::size_t k = 0; k < f.fields.size(); ++k) {
    Json* at = find_path(scene, f.fields[k].path);
    if (!at || !at->is_number())  // an axis put a number where the path went on
      throw SweepError("random_fields[" + std::to_string(k) + "] (" + f.fields[k].path +
                       "): an axis replaced the object holding it; sweep the number itself");
    Json field = f.fields[k].parameters;
    field["mean"] = *at;  // the base's value, or an axis's
    seeds.push_back(field_seed(f.seed, sample, k));
    field["seed"] = seeds.back();
    *at = {{"random_field", field}};
  }
  return seeds;
}

}  // namespace sweep
