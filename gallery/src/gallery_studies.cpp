#include "gallery/src/gallery_studies.hpp"

#include <nlohmann/json.hpp>

namespace app::gallery {

namespace fs = std::filesystem;

namespace {

void read_study(Study& study, const fs::path& scenarios) {
  const fs::path file = scenarios / study.file;
  // The gallery writes no member folders: read_sweep's `out` only labels a
  // member's scene in its messages, as `landslide sweep FILE --out
  // FILE-without-.json` would write it.
  fs::path label = file;
  label.replace_extension();
  study.sweep = sweep::read_sweep(file, label, {});
  const std::vector<sweep::Axis>& axes = study.sweep.axes;
  if (axes.size() == 1 && axes[0].path == study.path) return;
  std::string found;
  for (const sweep::Axis& a : axes) found += (found.empty() ? "" : ", ") + a.path;
  throw sweep::SweepError(file.string() + ": axes: the gallery's figure of this study needs " +
                          "exactly one axis, " + study.path + " (found: " + found + ")");
}

}  // namespace

Studies read_studies(const fs::path& scenarios) {
  Studies s;
  read_study(s.resolutions, scenarios);
  read_study(s.friction_angles, scenarios);
  return s;
}

sim::Scenario member_scenario(const Study& study, const sweep::Member& member) {
  sim::Scenario s = member.scenario;
  s.name = fs::path(study.file).stem().string() + " member " + std::to_string(member.index) +
           " [" + study.path + " = " + member.values.front().dump() + "]";
  return s;
}

std::string scene_value(const sweep::Member& member, const std::string& path) {
  std::string pointer = "/" + path;
  for (char& c : pointer)
    if (c == '.') c = '/';
  const nlohmann::json scene = nlohmann::json::parse(member.scene_text);
  const nlohmann::json::json_pointer at(pointer);
  return scene.contains(at) ? scene.at(at).dump() : "";
}

std::string count_word(std::size_t n) {
  static const char* const words[] = {"one", "two",   "three",  "four", "five",   "six",
                                      "seven", "eight", "nine", "ten",  "eleven", "twelve"};
  return n >= 1 && n <= 12 ? words[n - 1] : std::to_string(n);
}

}  // namespace app::gallery
