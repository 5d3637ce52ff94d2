// Every example the documentation gives runs to its end. The examples are
// read from the Markdown files themselves, so a README edit is tested as it
// is written: each ```json block (a whole scene), each scene a command line
// runs (`landslide run FILE`, `landslide check FILE`, `./run.sh`: run.sh's
// default scene) and each inline `"key": value` snippet, which is put into
// the complete example of scenarios/README.md and parsed there. Whole scenes
// run with the real binary, one thread, into a fresh folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_binary.hpp"

#include "sim/scene/scenario.hpp"

namespace {

namespace fs = std::filesystem;
using apptest::landslide;
using apptest::read_text;
using apptest::Result;
const fs::path kSource = LANDSLIDE_SOURCE_DIR;

// The Markdown files whose examples are checked.
std::vector<fs::path> documents() {
  std::vector<fs::path> docs = {"README.md", "scenarios/README.md", "bench/README.md",
                                "tests/validation/README.md", "gallery/README.md"};
  for (const fs::directory_entry& e : fs::directory_iterator(kSource / "docs"))
    if (e.path().extension() == ".md") docs.push_back(fs::relative(e.path(), kSource));
  return docs;
}

int line_of(const std::string& text, std::size_t at) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// Where an example comes from and what it is.
struct Example {
  std::string where;  // FILE:LINE
  std::string scene;  // path under the source folder (a command line), or ""
  std::string json;   // a ```json block, or a `"key": value` snippet
  std::string name;   // the test's name
};

void PrintTo(const Example& e, std::ostream* os) { *os << e.where; }

std::string test_name(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

// Scenes a command line names that the repository does not ship: the text
// describes each as a shipped scene changed by the `"key": value` snippets
// beside it, which DocumentedSnippet parses in context.
const char* const kDescribedNotShipped[] = {"mem2000.json"};

// Scenes that command lines name: `landslide run|check FILE.json` and
// `./run.sh` (whose default scene run.sh itself names). A FILE that an
// earlier `landslide new TEMPLATE FILE` of the same text writes is that
// template (the same text: NewCommand's tests); an upper-case FILE is a
// placeholder (SCENARIO.json).
void command_scenes(const fs::path& doc, const std::string& text, std::vector<Example>& out) {
  static const std::regex command(R"(landslide (?:(run|check)|new (\S+)) (\S+\.json))");
  static const std::regex placeholder(R"([A-Z_0-9]+\.json)");
  std::map<std::string, std::string> made;  // FILE written by `new` -> its template
  for (std::sregex_iterator m(text.begin(), text.end(), command), end; m != end; ++m) {
    std::string scene = (*m)[3].str();
    if (!(*m)[1].matched) {
      made[scene] = "scenarios/templates/" + (*m)[2].str() + ".json";
      continue;
    }
    if (std::regex_match(scene, placeholder) ||
        std::find(std::begin(kDescribedNotShipped), std::end(kDescribedNotShipped), scene) !=
            std::end(kDescribedNotShipped))
      continue;
    if (made.count(scene)) scene = made[scene];
    out.push_back({doc.string() + ":" + std::to_string(line_of(text, m->position())), scene, "", ""});
  }
  const std::size_t run_sh = text.find("./run.sh");
  if (run_sh == std::string::npos) return;
  std::smatch m;
  const std::string script = read_text(kSource / "run.sh");
  if (std::regex_search(script, m, std::regex(R"(scenario=\$\{1:-(\S+\.json)\})")))
    out.push_back({doc.string() + ":" + std::to_string(line_of(text, run_sh)) + " (./run.sh)",
                   m[1].str(), "", ""});
  else
    ADD_FAILURE() << "run.sh: no default scene (scenario=${1:-FILE.json}) found";
}

std::vector<Example> collect() {
  std::vector<Example> all;
  for (const fs::path& doc : documents()) {
    const std::string text = read_text(kSource / doc);
    const std::string open = "```json\n";
    for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
      const std::size_t end = text.find("```", at + open.size());
      all.push_back({doc.string() + ":" + std::to_string(line_of(text, at)), "",
                     text.substr(at + open.size(), end - at - open.size()), ""});
    }
    command_scenes(doc, text, all);
  }
  // One test per scene however often it is named; a scene is named after it.
  std::vector<Example> unique;
  std::map<std::string, std::size_t> seen;
  for (Example& e : all) {
    if (!e.scene.empty()) {
      const std::string key = fs::path(e.scene).lexically_normal().string();
      if (seen.count(key)) {
        unique[seen[key]].where += ", " + e.where;
        continue;
      }
      seen[key] = unique.size();
      e.name = test_name(fs::path(e.scene).stem().string());
    } else {
      e.name = test_name(e.where);
    }
    unique.push_back(e);
  }
  return unique;
}

// A `"key": value` snippet in the text: the value is put where the key first
// stands in the complete example of scenarios/README.md (at the top level if
// the example lacks the key) and the scene is parsed. A refusal is fine only
// when it is about another key (`"vtk": "interval"` needs vtk_interval), not
// about the snippet's own value.
struct Snippet {
  std::string where, text;
};

std::vector<Snippet> snippets() {
  std::vector<Snippet> out;
  static const std::regex span("`(\"[a-z_]+\": [^`]+)`");
  for (const fs::path& doc : documents()) {
    const std::string text = read_text(kSource / doc);
    for (std::sregex_iterator m(text.begin(), text.end(), span), end; m != end; ++m)
      out.push_back({doc.string() + ":" + std::to_string(line_of(text, m->position())), (*m)[1]});
  }
  return out;
}

// The path (in the messages' notation: a.b[2].c) of the first `key` in j.
bool find_key(const nlohmann::json& j, const std::string& key, const std::string& here,
              std::string& path) {
  if (j.is_object()) {
    if (j.contains(key)) {
      path = here.empty() ? key : here + "." + key;
      return true;
    }
    for (const auto& [k, v] : j.items())
      if (find_key(v, key, here.empty() ? k : here + "." + k, path)) return true;
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      if (find_key(j[i], key, here + "[" + std::to_string(i) + "]", path)) return true;
  }
  return false;
}

TEST(DocumentedSnippet, IsAllowedInTheCompleteExample) {
  const std::string readme = read_text(kSource / "scenarios/README.md");
  const std::size_t at = readme.find("```json\n");
  ASSERT_NE(at, std::string::npos);
  const nlohmann::json example =
      nlohmann::json::parse(readme.substr(at + 8, readme.find("```", at + 8) - at - 8));
  const std::vector<Snippet> all = snippets();
  EXPECT_FALSE(all.empty());
  for (const Snippet& s : all) {
    nlohmann::json piece;
    try {
      piece = nlohmann::json::parse("{" + s.text + "}");
    } catch (const nlohmann::json::exception& e) {
      ADD_FAILURE() << s.where << ": `" << s.text << "` is not JSON: " << e.what();
      continue;
    }
    const std::string key = piece.begin().key();
    std::string path;
    if (!find_key(example, key, "", path)) path = key;
    nlohmann::json scene = example;
    scene[nlohmann::json::json_pointer("/" + std::regex_replace(
                                               std::regex_replace(path, std::regex(R"(\[(\d+)\])"),
                                                                  "/$1"),
                                               std::regex(R"(\.)"), "/"))] = piece.begin().value();
    try {
      sim::parse_scenario(scene.dump(), "example");
    } catch (const sim::ScenarioError& e) {
      EXPECT_EQ(std::string(e.what()).find(path + " ="), std::string::npos)
          << s.where << ": `" << s.text << "` refused in the complete example: " << e.what();
    }
  }
}

class DocumentedScene : public ::testing::TestWithParam<Example> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("landslide-example-" + GetParam().name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The scene runs from the repository's top folder, as the command lines are
// written, to its end: exit 0 and a summary that says it finished.
TEST_P(DocumentedScene, RunsToItsEnd) {
  const Example& e = GetParam();
  fs::path scene = kSource / e.scene;
  if (e.scene.empty()) {
    scene = dir_ / "example.json";
    std::ofstream(scene) << e.json;
  }
  ASSERT_TRUE(fs::is_regular_file(scene)) << e.where << ": " << e.scene << " does not exist";
  const Result run = landslide("run '" + scene.string() + "' --out '" + (dir_ / "out").string() +
                                   "' --overwrite --threads 1",
                               kSource);
  ASSERT_EQ(run.status, 0) << e.where << "\n" << run.output;
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir_ / "out" / "summary.json"));
  EXPECT_EQ(summary.at("status"), "finished") << e.where;
}

INSTANTIATE_TEST_SUITE_P(Docs, DocumentedScene, ::testing::ValuesIn(collect()),
                         [](const ::testing::TestParamInfo<Example>& info) { return info.param.name; });

}  // namespace
