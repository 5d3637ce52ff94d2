// Inputs built to hurt the reader: deep nesting, huge arrays and strings,
// many stages and bodies, and token soup. Each ends in a ScenarioError (or a
// valid scene) with a short message, quickly.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "sim/scene/scenario.hpp"
#include "tests/scenario/example.hpp"

namespace {

using Json = nlohmann::json;

// The message of the ScenarioError that `text` raises.
std::string message_for(const std::string& text) {
  try {
    sim::parse_scenario(text, "scn.json");
  } catch (const sim::ScenarioError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

// The example with the value at `key` replaced by raw JSON text.
std::string example_with(const std::string& key, const std::string& raw) {
  Json doc = scenario_test::example_json();
  doc[key] = "@@PLACEHOLDER@@";
  std::string text = doc.dump();
  const std::string mark = "\"@@PLACEHOLDER@@\"";
  text.replace(text.find(mark), mark.size(), raw);
  return text;
}

std::string nested_arrays(std::size_t depth) {
  return std::string(depth, '[') + std::string(depth, ']');
}

bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n;
  }
  return true;
}

double seconds_for(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(ScenarioLimits, DeepNestingIsRefusedWhereItIs) {
  // A million levels would overflow the stack of any recursive pass.
  EXPECT_EQ(message_for(nested_arrays(1000000)).rfind("scn.json: [0][0][0]", 0), 0u);
  for (const char* key : {"name", "gravity", "unknown"}) {
    const std::string what = message_for(example_with(key, nested_arrays(1000000)));
    EXPECT_EQ(what.rfind(std::string("scn.json: ") + key + "[0][0]", 0), 0u) << what;
    EXPECT_NE(what.find(": arrays and objects nested deeper than 64 levels"), std::string::npos)
        << what;
    EXPECT_LT(what.size(), 200u) << what;
  }
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += "{\"a\":";
  objects += "1" + std::string(100000, '}');
  EXPECT_EQ(message_for(example_with("description", objects)).rfind("scn.json: description.a.a.a", 0),
            0u);
}

TEST(ScenarioLimits, ModerateNestingIsReadAndShownShort) {
  const std::string what = message_for(example_with("name", nested_arrays(60)));
  EXPECT_EQ(what, "scn.json: name = " + std::string(57, '[') + "...: expected a string");
}

TEST(ScenarioLimits, HugeValuesAreShownShort) {
  std::string ones = "[1";
  for (int i = 0; i < 1000000; ++i) ones += ",1";
  ones += "]";
  const std::string array = message_for(example_with("gravity", ones));
  EXPECT_EQ(array, "scn.json: gravity = [1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,"
                   "...: expected a pair of numbers [x, y]");
  const std::string text = message_for(example_with("name", "\"" + std::string(1000000, 'a') + "\""));
  EXPECT_LT(text.size(), 150u) << text;
  EXPECT_NE(text.find(": expected 1 to 100 characters from A-Z a-z 0-9 . _ -"), std::string::npos);
}

TEST(ScenarioLimits, ShortenedValuesStayValidUtf8) {
  std::string euros;
  for (int i = 0; i < 40; ++i) euros += "\u20ac";
  for (const std::string& raw : {"\"" + euros + "\"", "[\"" + euros + "\"]", "[1, \"" + euros + "\"]"}) {
    const std::string what = message_for(example_with("name", raw));
    EXPECT_TRUE(valid_utf8(what)) << what;
    EXPECT_NE(what.find("...: expected"), std::string::npos) << what;
  }
}

TEST(ScenarioLimits, PolygonVertexCount) {
  Json doc = scenario_test::example_json();
  Json circle = Json::array();
  for (int i = 0; i < 10001; ++i) {
    const double t = 2 * M_PI * i / 10001;
    circle.push_back({60 + 5 * std::cos(t), 10 + 5 * std::sin(t)});
  }
  doc["bodies"][2]["polygon"] = circle;
  doc["bodies"][2].erase("rectangle");
  doc["bodies"][2]["material"] = "soil";
  const std::string what = message_for(doc.dump());
  EXPECT_EQ(what.rfind("scn.json: bodies[2].polygon = [[65.0,10.0],", 0), 0u) << what;
  EXPECT_NE(what.find("...: expected an array of 3 to 10000 vertices [x, y]"), std::string::npos);
  circle.erase(circle.end() - 1);  // 10000 is allowed
  doc["bodies"][2]["polygon"] = circle;
  EXPECT_NO_THROW(sim::parse_scenario(doc.dump(), "scn.json"));
}

TEST(ScenarioLimits, VerticesOfAllBodiesTogether) {
  Json doc = scenario_test::example_json();
  for (int b = 0; b < 3; ++b) {
    Json circle = Json::array();
    for (int i = 0; i < 8000; ++i) {
      const double t = 2 * M_PI * i / 8000;
      circle.push_back({10 + 10 * b + 4 * std::cos(t), 7 + 4 * std::sin(t)});
    }
    doc["bodies"].push_back({{"name", "blob" + std::to_string(b)}, {"material", "soil"},
                             {"polygon", circle}});
  }
  const std::string what = message_for(doc.dump());
  EXPECT_EQ(what.rfind("scn.json: bodies[5].polygon = ", 0), 0u) << what;
  EXPECT_NE(what.find(": expected at most 20000 vertices in all bodies together (this body "
                      "brings them to 24012)"),
            std::string::npos)
      << what;
}

TEST(ScenarioLimits, ManyTouchingBodiesAreCheckedQuickly) {
  // 1000 tiles in alternating materials: every pair is considered, and every
  // neighbour touches along an edge.
  Json doc = scenario_test::example_json();
  doc["bodies"] = Json::array();
  for (int i = 0; i < 1000; ++i) {
    const double x = (i % 40) * 2.0, y = (i / 40) * 0.8;
    doc["bodies"].push_back({{"name", "tile" + std::to_string(i)},
                             {"material", (i + i / 40) % 2 ? "soil" : "bedrock"},
                             {"rectangle", {{"min", {x, y}}, {"max", {x + 2, y + 0.8}}}}});
  }
  sim::Scenario s;
  EXPECT_LT(seconds_for([&] { s = sim::parse_scenario(doc.dump(), "scn.json"); }), 10.0);
  EXPECT_EQ(s.bodies.size(), 1000u);
  doc["bodies"].push_back(doc["bodies"][0]);
  doc["bodies"][1000]["name"] = "one-too-many";
  EXPECT_NE(message_for(doc.dump()).find("bodies = [{"), std::string::npos);
  EXPECT_NE(message_for(doc.dump()).find(": expected an array of 1 to 1000 bodies"),
            std::string::npos);
}

TEST(ScenarioLimits, ManyStagesAreCheckedQuickly) {
  // Names and frame stages are looked up, not compared pairwise.
  Json doc = scenario_test::example_json();
  Json stages = Json::array(), frames = Json::array();
  for (int i = 0; i < 200000; ++i) {
    stages.push_back({{"name", "s" + std::to_string(i)}, {"type", "dynamic"}, {"duration", 1}});
    frames.push_back("s" + std::to_string(i));
  }
  doc["stages"] = stages;
  doc["output"]["frame_stages"] = frames;
  sim::Scenario s;
  EXPECT_LT(seconds_for([&] { s = sim::parse_scenario(doc.dump(), "scn.json"); }), 20.0);
  EXPECT_EQ(s.output.frame_stages.size(), 200000u);
  doc["stages"][199999]["name"] = "s7";
  EXPECT_EQ(message_for(doc.dump()),
            "scn.json: stages[199999].name = \"s7\": expected a name no other stage has "
            "(stages[7] has it)");
}

TEST(ScenarioLimits, TokenSoupNeverEscapesAsAnythingElse) {
  static const char* const tokens[] = {"{", "}", "[", "]", ",", ":", "\"name\"", "\"stages\"",
                                       "\"x\"", "1e999", "-0", "0.5", "1e308", "null", "true",
                                       "\"\\u0000\"", "\"\\ud800\"", " ", "\n", "\"bodies\"",
                                       "\xff", "tru", "-", "1.", "\"\u20ac\""};
  std::uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::size_t>(state >> 33);
  };
  for (int i = 0; i < 3000; ++i) {
    std::string text = i % 2 ? "{" : "";
    const std::size_t n = next() % 40;
    for (std::size_t k = 0; k < n; ++k) text += tokens[next() % (sizeof tokens / sizeof *tokens)];
    try {
      sim::parse_scenario(text, "soup.json");
    } catch (const sim::ScenarioError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("soup.json: ", 0), 0u) << e.what();
    } catch (...) {
      ADD_FAILURE() << "not a ScenarioError for: " << text;
    }
  }
}

TEST(ScenarioLimits, HugeFileIsNotReadWhole) {
  // A sparse file: 65 MiB long, no disk used.
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "landslide-scenario-huge.json";
  { std::ofstream(path.string()) << "{"; }
  std::filesystem::resize_file(path, 65u << 20);
  std::string what;
  try {
    sim::load_scenario(path.string());
  } catch (const sim::ScenarioError& e) {
    what = e.what();
  }
  std::filesystem::remove(path);
  EXPECT_EQ(what, path.string() + ": cannot read file: it is 65 MiB (a scenario is at most 64 MiB)");
}

}  // namespace
