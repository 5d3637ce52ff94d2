// What `landslide` says, read from the real binary in a child process: each
// message names the value and what is allowed, counts read as words do ("1
// thread"), a stage's closing line gives the kinetic energy its rest test
// compared, and threads beyond the CPUs the process may use are named.
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "output/counted.hpp"
#include "block_scene.hpp"
#include "run_binary.hpp"
#include "render/video.hpp"

namespace {

namespace fs = std::filesystem;

using apptest::landslide;
using apptest::Result;

// One material, one body, one stage (with a rest test), one painted field.
std::string single_scene() {
  std::string s = kSlumpingBlock;
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  };
  replace(R"({"name": "settle", "type": "gravity", "duration": 0.5, "ramp_fraction": 0.5, "damping": 0.01},
    {"name": "soften", "type": "material-change", "material": "block", "set": {"cohesion": 0}},
    {"name": "slump", "type": "dynamic", "duration": 1.0})",
          R"({"name": "slump", "type": "dynamic", "duration": 0.3,
     "stop_at_rest": {"kinetic_ratio": 1e-9, "min_time": 0.1}})");
  replace(R"("frame_interval": 0.1)", R"("frame_interval": 0.15)");
  return s;
}

class CliMessages : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("landslide-cli-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    std::ofstream(root_ / "one.json") << single_scene();
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST(Counted, OneAndMany) {
  EXPECT_EQ(app::counted(1, "thread"), "1 thread");
  EXPECT_EQ(app::counted(0, "thread"), "0 threads");
  EXPECT_EQ(app::counted(2, "body", "bodies"), "2 bodies");
  EXPECT_EQ(app::counted(1, "body", "bodies"), "1 body");
}

TEST_F(CliMessages, CheckpointEveryZeroSaysWhatIsAllowed) {
  for (const char* command : {"run one.json --out out", "resume out"}) {
    const Result r = landslide(std::string(command) + " --checkpoint-every 0", root_);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_NE(r.output.find("--checkpoint-every = 0: expected a positive (finite) number of "
                            "simulated seconds"),
              std::string::npos)
        << r.output;
    // CLI::PositiveNumber printed its range: a number of 309 digits.
    EXPECT_FALSE(std::regex_search(r.output, std::regex(R"(\d{20})"))) << r.output;
  }
  EXPECT_FALSE(fs::exists(root_ / "out"));
}

TEST_F(CliMessages, ValidateAndGalleryOutsideTheRepositoryPointAtScenarios) {
  for (const char* command : {"validate --quick", "gallery --out pictures"}) {
    const Result r = landslide(command, root_);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_NE(r.output.find("scenarios: no such folder"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--scenarios DIR"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(root_ / "pictures"));
}

TEST_F(CliMessages, CountsInTheSingular) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "the scene paints; no ffmpeg";
  const Result check = landslide("check one.json", root_);
  EXPECT_EQ(check.status, 0) << check.output;
  EXPECT_NE(check.output.find("(1 material, 1 body, 1 stage)"), std::string::npos)
      << check.output;
  const Result run = landslide("run one.json --out out --threads 1", root_);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find(", 1 thread -> "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("encoded 1 video in "), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find(" 1 threads"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find(" 1 videos"), std::string::npos) << run.output;
}

// More threads asked than the CPUs of the affinity mask (taskset -c 0 here,
// which the child inherits): the run line says how many run at once.
TEST_F(CliMessages, ThreadsBeyondTheAffinityMaskAreNamed) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "the scene paints; no ffmpeg";
  cpu_set_t before, one;
  ASSERT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
  CPU_ZERO(&one);
  CPU_SET(sched_getcpu(), &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  const Result run = landslide("run one.json --out out --threads 2", root_);
  sched_setaffinity(0, sizeof before, &before);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find(", 2 threads (at most 1 at once: the 1 CPU of this process's "
                            "affinity mask) -> "),
            std::string::npos)
      << run.output;
}

// The closing line of a stage gives the kinetic energy its rest test used
// (summary.json's moving_kinetic_energy_J_per_m), not the points' own.
TEST_F(CliMessages, StageLineGivesTheRestTestsKineticEnergy) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "the scene paints; no ffmpeg";
  const Result run = landslide("run one.json --out out --threads 1", root_);
  ASSERT_EQ(run.status, 0) << run.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      run.output, m,
      std::regex(R"(slump: done at t = \S+ s, \d+ steps, \S+ s wall, moving kinetic energy (\S+) )"
                 R"(J/m \(at rest once <= 1e-09 x gravity work (\S+) J/m\))")))
      << run.output;
  std::ifstream in(root_ / "out" / "summary.json");
  const nlohmann::json stage = nlohmann::json::parse(in).at("stages").at(0);
  const double moving = stage.at("moving_kinetic_energy_J_per_m").get<double>();
  const double points = stage.at("kinetic_energy_J_per_m").get<double>();
  // The line prints 6 significant digits.
  EXPECT_NEAR(std::stod(m[1].str()), moving, 1e-5 * moving);
  EXPECT_GT(std::fabs(points - moving), 1e-3 * moving) << "the two energies must differ for "
                                                          "this test to tell them apart";
  EXPECT_GT(std::stod(m[2].str()), 0);
}

// A block dropped through a free floor leaves the grid: the run stops (exit
// 1) and says which wall it passed, that the wall is free and what holds it.
TEST_F(CliMessages, PointPastAFreeWallNamesTheWallAndTheFix) {
  std::ofstream(root_ / "drop.json") << R"({
    "name": "drop", "domain": {"min": [0, 0], "max": [2, 2]},
    "grid": {"cell_size": 0.5, "padding_cells": 2, "points_per_cell": 1},
    "gravity": [0, -9.81],
    "boundaries": {"left": "roller", "right": "roller", "bottom": "free", "top": "free"},
    "materials": {"rock": {"model": "linear-elastic", "density": 2000, "youngs_modulus": 1e6,
                           "poisson_ratio": 0.25}},
    "bodies": [{"name": "rock", "material": "rock", "rectangle": {"min": [0.5, 1], "max": [1.5, 2]}}],
    "time_step": {"courant": 0.5},
    "stages": [{"name": "fall", "type": "dynamic", "duration": 2}],
    "output": {}})";
  const Result r = landslide("run drop.json --out out --threads 1", root_);
  EXPECT_EQ(r.status, 1) << r.output;
  for (const char* part : {"left the grid", "it passed the bottom wall (y = 0 m), which is \"free\"",
                           "grid.padding_cells = 2 cells beyond it",
                           "Make boundaries.bottom \"roller\", \"fixed\" or {\"friction\": mu}",
                           "move domain.min[1] far enough out"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
}

}  // namespace
