// `landslide new`: every template shipped in scenarios/templates/ is listed,
// written where asked (never over an existing file without --overwrite) and
// runs to its end; the binary carries the templates, so it works from any
// folder (each test runs it in a fresh temporary one).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_binary.hpp"

namespace {

namespace fs = std::filesystem;
using apptest::landslide;
using apptest::read_text;
using apptest::Result;

const fs::path kTemplates = fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios" / "templates";

std::vector<std::string> shipped() {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(kTemplates))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class NewCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("landslide-new-" + test + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// One line per template, in name order, each the template's name and the
// first sentence of its description.
TEST_F(NewCommand, ListsEveryShippedTemplate) {
  const Result r = landslide("new --list", dir_);
  ASSERT_EQ(r.status, 0) << r.output;
  std::istringstream lines(r.output);
  std::vector<std::string> names;
  for (std::string line; std::getline(lines, line);) {
    const std::string name = line.substr(0, line.find(' '));
    names.push_back(name);
    const nlohmann::json scene = nlohmann::json::parse(read_text(kTemplates / (name + ".json")));
    const std::string description = scene.at("description");
    EXPECT_NE(line.find(description.substr(0, description.find(". ") + 1)), std::string::npos)
        << line;
  }
  EXPECT_EQ(names, shipped());
}

TEST_F(NewCommand, RefusesAnExistingFileUnlessOverwrite) {
  const std::string name = shipped().front();
  std::ofstream(dir_ / "mine.json") << "my own scene";
  const Result refused = landslide("new " + name + " mine.json", dir_);
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("mine.json: already exists"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--overwrite"), std::string::npos) << refused.output;
  EXPECT_EQ(read_text(dir_ / "mine.json"), "my own scene");
  const Result replaced = landslide("new " + name + " mine.json --overwrite", dir_);
  EXPECT_EQ(replaced.status, 0) << replaced.output;
  EXPECT_EQ(read_text(dir_ / "mine.json"), read_text(kTemplates / (name + ".json")));
  std::size_t files = 0;
  for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir_)) ++files;
  EXPECT_EQ(files, 1u) << "no temporary file left beside it";
}

TEST_F(NewCommand, UnknownTemplateNamesTheTemplates) {
  const Result r = landslide("new no-such-template out.json", dir_);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("template = \"no-such-template\": expected one of"), std::string::npos)
      << r.output;
  for (const std::string& name : shipped()) EXPECT_NE(r.output.find(name), std::string::npos) << name;
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
  EXPECT_EQ(landslide("new", dir_).status, 2);
}

class EachTemplate : public ::testing::TestWithParam<std::string> {};

// new, then check, then run, to its end: exit 0 each, the run finished with
// every stage of the scene in its summary.
TEST_P(EachTemplate, RunsToItsEnd) {
  const fs::path dir = fs::temp_directory_path() /
                       ("landslide-template-" + GetParam() + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Result made = landslide("new " + GetParam() + " scene.json", dir);
  ASSERT_EQ(made.status, 0) << made.output;
  EXPECT_EQ(read_text(dir / "scene.json"), read_text(kTemplates / (GetParam() + ".json")));
  const Result check = landslide("check scene.json --out out --threads 1", dir);
  ASSERT_EQ(check.status, 0) << check.output;
  const Result run = landslide("run scene.json --out out --threads 1", dir);
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  EXPECT_EQ(summary.at("status"), "finished");
  const nlohmann::json scene = nlohmann::json::parse(read_text(dir / "scene.json"));
  EXPECT_EQ(summary.at("stages").size(), scene.at("stages").size());
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Templates, EachTemplate, ::testing::ValuesIn(shipped()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
