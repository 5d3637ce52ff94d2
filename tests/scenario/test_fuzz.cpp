// Seeded random damage to every committed scenario: the reader either accepts
// the result or throws ScenarioError naming the source; nothing else.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sim/scene/scenario.hpp"
#include "tests/scenario/example.hpp"

namespace {

using Json = nlohmann::json;
using Pointer = Json::json_pointer;

constexpr int kMutationsPerFile = 300;
constexpr const char* kPlaceholder = "0.123456789";

// Small deterministic generator (the standard distributions differ between
// libraries; this does not).
struct Rng {
  std::uint64_t state;
  std::uint64_t next() {
    state += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
};

void collect(const Json& v, const Pointer& at, std::vector<Pointer>& out) {
  if (!at.empty()) out.push_back(at);
  if (v.is_object())
    for (const auto& item : v.items()) collect(item.value(), at / item.key(), out);
  if (v.is_array())
    for (std::size_t i = 0; i < v.size(); ++i) collect(v[i], at / i, out);
}

// One random change; returns the text and a note of what was done.
std::string mutate(const Json& original, Rng& rng, std::string& note) {
  Json doc = original;
  std::vector<Pointer> pointers;
  collect(doc, Pointer(), pointers);
  const Pointer at = pointers[rng.below(pointers.size())];
  Json& target = doc[at];
  const std::size_t kind = rng.below(12);
  note = "at " + at.to_string() + ", kind " + std::to_string(kind);
  bool infinite = false;
  switch (kind) {
    case 0: {  // delete the key or element
      Json& parent = doc[at.parent_pointer()];
      if (parent.is_object()) parent.erase(at.back());
      else parent.erase(std::stoul(at.back()));
      break;
    }
    case 1: target = "text"; break;
    case 2: target = nullptr; break;
    case 3: target = rng.below(2) ? Json::array() : Json::array({1, 2, 3}); break;
    case 4: target = 1e300; break;
    case 5: target = target.is_number() ? Json(-target.get<double>()) : Json(-1); break;
    case 6: target = 0.123456789, infinite = true; break;  // becomes 1e999
    case 7: target = rng.below(2) ? Json::object() : Json{{"unknown", 1}}; break;
    case 8: target = true; break;
    case 9: {  // scale a number by a factor that reaches the range limits
      static const double factors[] = {0, 1e-9, 1e-3, 0.5, 1.0000001, 2, 1e3, 1e9, 1e200};
      const double f = factors[rng.below(9)];
      target = target.is_number() ? Json(target.get<double>() * f) : Json(f);
      break;
    }
    case 10: target = rng.below(2) ? Json(0) : Json(4.5); break;
    default: {  // cut the text short
      const std::string text = original.dump(2);
      const std::size_t cut = rng.below(text.size());
      note = "truncated at byte " + std::to_string(cut);
      return text.substr(0, cut);
    }
  }
  std::string text = doc.dump(2);
  if (infinite) {
    const std::size_t pos = text.find(kPlaceholder);
    if (pos != std::string::npos) text.replace(pos, std::string(kPlaceholder).size(), "1e999");
  }
  return text;
}

// Parses and returns "" if the outcome is allowed, or what went wrong.
std::string check(const std::string& text, const std::string& label) {
  try {
    sim::parse_scenario(text, label);
  } catch (const sim::ScenarioError& e) {
    const std::string what = e.what();
    if (what.rfind(label + ": ", 0) != 0) return "message without the label: " + what;
    // The catch-all for library errors has no JSON path: the checks must
    // foresee every such error before it happens.
    if (what.find("cannot read the scenario") != std::string::npos) return "no path: " + what;
  } catch (const std::exception& e) {
    return std::string("not a ScenarioError: ") + e.what();
  } catch (...) {
    return "a non-standard exception";
  }
  return "";
}

std::vector<std::filesystem::path> committed_scenarios() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(LANDSLIDE_SOURCE_DIR) + "/scenarios"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

void fuzz(const Json& doc, const std::string& name, std::uint64_t seed) {
  Rng rng{seed};
  for (int i = 0; i < kMutationsPerFile; ++i) {
    std::string note;
    const std::string text = mutate(doc, rng, note);
    const std::string label = name + "#" + std::to_string(i);
    ASSERT_EQ(check(text, label), "") << label << " (" << note << ")";
  }
}

TEST(ScenarioFuzz, CommittedScenariosSurviveRandomDamage) {
  const auto files = committed_scenarios();
  ASSERT_GE(files.size(), 2u);
  std::uint64_t seed = 20240611;
  for (const auto& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const Json doc = Json::parse(text.str());
    ASSERT_EQ(check(text.str(), file.filename().string()), "");  // the original is valid
    fuzz(doc, file.filename().string(), seed++);
  }
}

TEST(ScenarioFuzz, FullExampleSurvivesRandomDamage) {
  fuzz(scenario_test::example_json(), "example", 7);
}

TEST(ScenarioFuzz, DoubleDamage) {
  // Two changes at once reach states one change cannot (a wrong type behind
  // another wrong key, a body moved after its material went away, ...).
  const Json example = scenario_test::example_json();
  Rng rng{99};
  for (int i = 0; i < kMutationsPerFile; ++i) {
    std::string note1, note2;
    Json once;
    try {
      once = Json::parse(mutate(example, rng, note1));
    } catch (const Json::exception&) {
      continue;  // truncated or overflowing: already covered
    }
    const std::string text = mutate(once, rng, note2);
    const std::string label = "double#" + std::to_string(i);
    ASSERT_EQ(check(text, label), "") << label << " (" << note1 << "; " << note2 << ")";
  }
}

// The damage a careless edit does to a real scene, aimed rather than random:
// every body folded into a bow-tie or moved out of the domain, and a grid too
// fine for the memory budget, is refused with the JSON path of the culprit.
std::string refusal(const Json& doc, const std::string& label) {
  try {
    sim::parse_scenario(doc.dump(), label);
  } catch (const sim::ScenarioError& e) {
    return e.what();
  }
  return "accepted";
}

Json polygon_of(const Json& body) {
  if (body.contains("polygon")) return body.at("polygon");
  const Json& r = body.at("rectangle");
  const double x0 = r.at("min")[0], y0 = r.at("min")[1], x1 = r.at("max")[0], y1 = r.at("max")[1];
  return Json::array({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

TEST(ScenarioFuzz, FoldedMovedAndOversizedScenesAreRefusedAtTheirPath) {
  int bodies = 0;
  for (const auto& file : committed_scenarios()) {
    std::ifstream in(file);
    const Json doc = Json::parse(in);
    const std::string name = file.filename().string();
    const double width = doc.at("domain").at("max")[0].get<double>() -
                         doc.at("domain").at("min")[0].get<double>();
    for (std::size_t k = 0; k < doc.at("bodies").size(); ++k) {
      const std::string at = "bodies[" + std::to_string(k) + "]";
      Json folded = doc, moved = doc;
      Json polygon = polygon_of(doc["bodies"][k]);
      std::swap(polygon[0], polygon[1]);  // edges 1-2 and 3-0 now cross
      folded["bodies"][k].erase("rectangle");
      folded["bodies"][k]["polygon"] = polygon;
      Json shifted = polygon_of(doc["bodies"][k]);
      for (Json& v : shifted) v[0] = v[0].get<double>() + 5 * width;
      moved["bodies"][k].erase("rectangle");
      moved["bodies"][k]["polygon"] = shifted;
      ++bodies;
      for (const auto& [what, bad] : {std::make_pair("folded", folded), {"moved", moved}}) {
        const std::string message = refusal(bad, name);
        EXPECT_NE(message.find(name + ": " + at + ".polygon"), std::string::npos)
            << name << " " << at << " " << what << ": " << message;
      }
    }
    Json fine = doc;
    fine["grid"]["cell_size"] = doc.at("grid").at("cell_size").get<double>() * 1e-4;
    const std::string message = refusal(fine, name);
    EXPECT_NE(message.find("grid.cell_size"), std::string::npos) << name << ": " << message;
    EXPECT_NE(message.find("at most"), std::string::npos) << name << ": " << message;
  }
  EXPECT_GE(bodies, 15);  // 8 committed scenes, most with two bodies
}

}  // namespace
