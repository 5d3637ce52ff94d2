// JSON paths into a scene ("stages.1.set.friction_angle": object keys and
// array indices, dot-separated) and the sweep file's key checks.
#pragma once

#include <set>
#include <string>

#include <nlohmann/json.hpp>

namespace sweep {

// The value at `path` in `scene`; null if the scene does not have it.
nlohmann::json* find_path(nlohmann::json& scene, const std::string& path);

// `node` is an object whose keys are all in `allowed`; throws SweepError
// naming `where` and the first other key.
void require_keys(const nlohmann::json& node, const std::set<std::string>& allowed,
                  const std::string& where);

}  // namespace sweep
