#pragma once
// Regression scenes: run a scene as `landslide run` would (same painter, same
// summary), then compare its frames and summary numbers with the committed
// expected files in tests/regression/expected/<scene>/.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace regression {

// What a scene run produced: the summary without what changes from run to
// run (wall times, threads, version, file path), and the painted PNGs.
struct SceneRun {
  nlohmann::json numbers;
  struct Image {
    std::string name;  // "<field>-<frame>.png", its name under expected/<scene>/
    std::filesystem::path file;
  };
  std::vector<Image> images;
};

// Runs `scene` (a scenario JSON) with its frames written under `work`.
// Throws what the loader, the simulation or the painter throw.
SceneRun run_scene(const std::filesystem::path& scene, const std::filesystem::path& work);

// The summary of a run as make_summary() writes it, less the entries that
// differ between two identical runs.
nlohmann::json stable_numbers(nlohmann::json summary);

// Relative tolerance of every number; see tests/regression/README.md.
struct NumberTolerance {
  double relative = 0;
  // Differences below this are equal whatever the relative change: numbers
  // that should be 0 come out as round-off of either sign.
  double absolute = 0;
};

// One line per entry of `expected` that differs or is missing, naming it by
// its path ("stages[2] (slide).metrics.runout_m") with the expected and the
// actual value and the relative change. Empty when every entry matches.
// With a zero tolerance it lists every change, which is what a regeneration
// prints for its commit message.
std::vector<std::string> compare_numbers(const nlohmann::json& expected,
                                         const nlohmann::json& actual,
                                         const NumberTolerance& tol);

// "path: value" for each entry of `actual` that `expected` lacks. A summary
// that reports something new has not changed what it reported before, so
// these are notes, not failures, until the next regeneration records them.
std::vector<std::string> new_entries(const nlohmann::json& expected, const nlohmann::json& actual);

}  // namespace regression
