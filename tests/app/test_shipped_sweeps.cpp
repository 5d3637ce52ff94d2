// The shipped sweep files (scenarios/sweeps/, the paper's studies) are read
// without error, and every member is the physics of a shipped scene that
// runs to its end elsewhere: so the members need no run of their own here.
// A Monte Carlo sweep's members are new soils: it runs to its end in
// ShippedSweep.MonteCarloExampleRunsToItsEnd (tests/app/test_sweep.cpp).
// A member's scene is compared with the scene file's, both without name,
// description and output (members paint nothing; the scenes differ in
// labels and views only).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_file.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
const fs::path kScenarios = fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios";

// Scenes that run to their end: the first five in ShippedScene.RunsToItsEnd
// (tests/sim/test_shipped_scenes.cpp), the finer two in `landslide validate
// --finest` (validation/validation_slope.cpp).
const char* const kRunScenes[] = {"paper-slope-phi25",        "paper-slope-phi20",
                                  "paper-slope-phi15",        "paper-slope-phi10",
                                  "paper-slope-phi20-n1661",  "paper-slope-phi20-n28711",
                                  "paper-slope-phi20-n66787"};

json physics(json scene) {
  for (const char* label : {"name", "description", "output"}) scene.erase(label);
  return scene;
}

json physics_of_file(const std::string& name) {
  std::ifstream in(kScenarios / (name + ".json"));
  return physics(json::parse(in));
}

std::vector<fs::path> shipped_sweeps() {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(kScenarios / "sweeps"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  return files;
}

TEST(ShippedSweep, TheStudiesAreShipped) {
  for (const char* f : {"fig11-resolutions.json", "fig12-friction-angles.json"})
    EXPECT_TRUE(fs::is_regular_file(kScenarios / "sweeps" / f)) << f;
}

TEST(ShippedSweep, EveryMemberIsTheSceneOfAShippedRun) {
  const std::vector<fs::path> files = shipped_sweeps();
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    sweep::Sweep s;
    try {
      s = sweep::read_sweep(file, fs::temp_directory_path() / "shipped-sweep", {});
    } catch (const sweep::SweepError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    EXPECT_FALSE(s.members.empty()) << file;
    if (!s.fields.fields.empty()) {  // its members are new soils, no shipped scene's
      EXPECT_EQ(file.filename(), "monte-carlo-phi20-n1661.json")
          << "a Monte Carlo sweep without a test that runs it to its end (as "
             "ShippedSweep.MonteCarloExampleRunsToItsEnd runs the shipped one)";
      continue;
    }
    for (const sweep::Member& m : s.members) {
      const json member = physics(json::parse(m.scene_text));
      std::string same;
      for (const char* scene : kRunScenes)
        if (physics_of_file(scene) == member) same = scene;
      EXPECT_FALSE(same.empty()) << file.filename().string() << " member " << m.index
                                 << " is no shipped scene that runs to its end:\n"
                                 << m.scene_text;
    }
  }
}

}  // namespace
