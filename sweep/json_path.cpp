#include "sweep/json_path.hpp"

#include <sstream>
#include <vector>

#include "sweep/sweep_file.hpp"

namespace sweep {

using Json = nlohmann::json;

namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
  return parts;
}

}  // namespace

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

Json* find_path(Json& scene, const std::string& path) {
  Json* at = &scene;
  for (const std::string& part : split_path(path)) {
    if (part.empty()) return nullptr;
    if (at->is_object()) {
      auto it = at->find(part);
      if (it == at->end()) return nullptr;
      at = &*it;
    } else if (at->is_array()) {
      // An index of more than 9 digits is past the end of any scene's array.
      if (part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos)
        return nullptr;
      const unsigned long k = std::stoul(part);
      if (k >= at->size()) return nullptr;
      at = &(*at)[k];
    } else {
      return nullptr;
    }
  }
  return at;
}

}  // namespace sweep
