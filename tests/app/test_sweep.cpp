// `landslide sweep` with the real binary: one and two MPI ranks give the same
// sweep.csv, a resumed sweep runs only what is not finished, --paint paints
// only the members named, and bad sweep files are refused (exit 2) before any
// member runs, naming the member and the JSON path; so is a member that
// run's preflight refuses, and `--check` stops after the preflight.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <nlohmann/json.hpp>

#include "run_binary.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using apptest::landslide;
using apptest::read_text;

// The slope template at h = 2 m (524 points), 2 s of gravity, a 2 s slide.
json base_scene() {
  json s = json::parse(read_text(fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios/templates/slope.json"));
  s["grid"]["cell_size"] = 2;
  s["stages"][0]["duration"] = 2;
  s["stages"][2]["duration"] = 2;
  s["stages"][2]["stop_at_rest"]["min_time"] = 0.5;
  return s;
}

json friction_sweep() {
  return {{"base", "base.json"},
          {"axes", json::array({{{"path", "stages.1.set.friction_angle"},
                                 {"values", {15, 20, 25}}}})}};
}

class Sweep : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("landslide-sweep-" + std::string(::testing::UnitTest::GetInstance()
                                                 ->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "base.json") << base_scene().dump(1);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write_sweep(const json& sweep) { std::ofstream(dir_ / "sweep.json") << sweep.dump(1); }
  // Each sweep exits 2 naming what it should, and no member ran.
  template <class Cases>
  void expect_refused(const Cases& cases) {
    for (const auto& c : cases) {
      write_sweep(c.sweep);
      const auto r = landslide("sweep sweep.json --out out --threads 1", dir_);
      EXPECT_EQ(r.status, 2) << c.what << ": " << r.output;
      for (const std::string& n : c.named)
        EXPECT_NE(r.output.find(n), std::string::npos) << c.what << ": " << r.output;
      EXPECT_FALSE(fs::exists(dir_ / "out")) << c.what << ": a member ran";
    }
  }
  // `mpirun -np 2 landslide ARGS` in the test's folder, its output in two.log;
  // the shell's exit status.
  int two_ranks(const std::string& args) {
    const std::string command = "cd '" + dir_.string() + "' && '" LANDSLIDE_MPIRUN
                                "' --oversubscribe --allow-run-as-root -np 2 '" LANDSLIDE_BINARY
                                "' " + args + " > two.log 2>&1";
    return std::system(command.c_str());
  }
  fs::path dir_;
};

// Why the MPI tests cannot run here ("" if they can).
std::string no_mpi() {
  if (!LANDSLIDE_WITH_MPI) return "built without MPI (CMake found none)";
  if (std::string(LANDSLIDE_MPIRUN).empty() || !fs::exists(LANDSLIDE_MPIRUN))
    return "no mpirun found (install openmpi-bin)";
  return "";
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST_F(Sweep, OneAndTwoRanksWriteTheSameCsv) {
  if (const std::string why = no_mpi(); !why.empty()) GTEST_SKIP() << why;
  write_sweep(friction_sweep());
  const auto one = landslide("sweep sweep.json --out one --threads 1", dir_);
  ASSERT_EQ(one.status, 0) << one.output;
  ASSERT_EQ(two_ranks("sweep sweep.json --out two --threads 1"), 0)
      << read_text(dir_ / "two.log");
  const std::string log = read_text(dir_ / "two.log");
  EXPECT_NE(log.find("over 2 rank(s)"), std::string::npos) << log;
  EXPECT_NE(log.find("on rank 1"), std::string::npos) << log;  // rank 1 ran a member
  const std::string csv = read_text(dir_ / "one" / "sweep.csv");
  EXPECT_EQ(csv, read_text(dir_ / "two" / "sweep.csv"));
  const auto rows = lines(csv);
  ASSERT_EQ(rows.size(), 4u) << csv;
  EXPECT_EQ(rows[0].rfind("member,stages.1.set.friction_angle,status,runout_m", 0), 0u);
  EXPECT_EQ(rows[1].rfind("0,15,finished,", 0), 0u) << rows[1];
  EXPECT_NE(rows[1].substr(13), rows[3].substr(13));  // the friction angle moves the runout
  // Each distinct gravity stage is computed once: one cached state.
  int states = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "two" / "state-cache"))
    states += e.path().extension() == ".state";
  EXPECT_EQ(states, 1);
  EXPECT_TRUE(fs::exists(dir_ / "two" / "sweep-stages.1.set.friction_angle.png"));
}

TEST_F(Sweep, ResumedSweepRunsOnlyUnfinishedMembers) {
  write_sweep(friction_sweep());
  const auto first = landslide("sweep sweep.json --out out --threads 1", dir_);
  ASSERT_EQ(first.status, 0) << first.output;
  const fs::path out = dir_ / "out";
  const std::string summary0 = read_text(out / "members/0000/summary.json");
  const std::string csv = read_text(out / "sweep.csv");
  fs::remove(out / "members/0001/summary.json");  // as if killed during member 1
  fs::remove(out / "sweep.csv");
  const auto again = landslide("sweep sweep.json --out out --threads 1", dir_);
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("2 already finished"), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("member 0 of"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("member 1 of"), std::string::npos) << again.output;
  // Its wall time would differ had it run again.
  EXPECT_EQ(read_text(out / "members/0000/summary.json"), summary0);
  EXPECT_EQ(read_text(out / "sweep.csv"), csv);
  const json result = json::parse(read_text(out / "sweep.json"));
  EXPECT_TRUE(result["members"][0]["wall_time_s"].is_number());
}

TEST_F(Sweep, PaintsOnlyTheMembersNamed) {
  json sweep = friction_sweep();
  sweep["axes"][0]["values"] = {15, 25};
  write_sweep(sweep);
  const auto r = landslide("sweep sweep.json --out out --threads 1 --paint 1", dir_);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out/members/0000/frames"));
  EXPECT_FALSE(fs::exists(dir_ / "out/members/0000/vtk"));
  EXPECT_TRUE(fs::exists(dir_ / "out/members/0001/frames"));
  EXPECT_TRUE(fs::exists(dir_ / "out/members/0001/vtk"));
}

struct BadCase {
  const char* what;
  json sweep;
  std::vector<std::string> named;  // in the message
};

TEST_F(Sweep, BadSweepFilesAreRefusedBeforeAnyMemberRuns) {
  auto axis = [](const std::string& path, json values) {
    return json::array({{{"path", path}, {"values", values}}});
  };
  const std::vector<BadCase> cases = {
      {"unknown key", {{"base", "base.json"}, {"axes", axis("grid.cell_size", {2})}, {"sample", 4}},
       {"sweep.json.sample: unknown key"}},
      {"unknown axis key",
       {{"base", "base.json"},
        {"axes", json::array({{{"path", "grid.cell_size"}, {"values", {2}}, {"step", 1}}})}},
       {"axes[0].step: unknown key"}},
      {"path the base lacks", {{"base", "base.json"}, {"axes", axis("materials.soil.nope", {1})}},
       {"axes[0] (materials.soil.nope)", "has no materials.soil.nope"}},
      {"index past the end", {{"base", "base.json"}, {"axes", axis("stages.7.duration", {1})}},
       {"has no stages.7.duration"}},
      {"value the scene refuses",
       {{"base", "base.json"}, {"axes", axis("materials.soil.poisson_ratio", {0.3, 0.7})}},
       {"member 1 (materials.soil.poisson_ratio = 0.7)", "poisson_ratio = 0.7"}},
      {"one path twice",
       {{"base", "base.json"},
        {"axes", json::array({{{"path", "grid.cell_size"}, {"values", {2}}},
                              {{"path", "grid.cell_size"}, {"values", {3}}}})}},
       {"axes[1] (grid.cell_size): also axes[0]'s path"}},
      {"empty axis", {{"base", "base.json"}, {"axes", axis("grid.cell_size", json::array())}},
       {"axes[0] (grid.cell_size).values: empty"}},
  };
  expect_refused(cases);
}

// A random friction angle after the trigger: 4 samples of the base scene.
json field_sweep() {
  return {{"base", "base.json"},
          {"random_fields", json::array({{{"path", "stages.1.set.friction_angle"},
                                          {"distribution", "truncated-normal"},
                                          {"cov", 0.2},
                                          {"lower", 12},
                                          {"upper", 30},
                                          {"scale_of_fluctuation", {20, 4}}}})},
          {"samples", 4},
          {"seed", 2026}};
}

TEST_F(Sweep, RandomFieldSamplesHaveTheirOwnSeedsAndAnExceedancePlot) {
  write_sweep(field_sweep());
  const auto r = landslide("sweep sweep.json --out out --threads 1 --paint 2", dir_);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto rows = lines(read_text(dir_ / "out/sweep.csv"));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].rfind("member,sample,stages.1.set.friction_angle seed,status,runout_m", 0), 0u)
      << rows[0];
  std::set<std::string> seeds, runouts;
  std::vector<std::string> seed_of_member;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    std::vector<std::string> cells;
    std::stringstream in(rows[k]);
    for (std::string c; std::getline(in, c, ',');) cells.push_back(c);
    ASSERT_GE(cells.size(), 5u) << rows[k];
    EXPECT_EQ(cells[1], std::to_string(k - 1));
    EXPECT_EQ(cells[3], "finished") << rows[k];
    seeds.insert(cells[2]);
    seed_of_member.push_back(cells[2]);
    runouts.insert(cells[4]);
  }
  EXPECT_EQ(seeds.size(), 4u) << "each sample its own field";
  EXPECT_GT(runouts.size(), 1u) << "the fields change the runout";
  // The member's scene is a scene of its own: the field, its mean and seed.
  const json scene = json::parse(read_text(dir_ / "out/members/0002/scene.json"));
  const json& field = scene["stages"][1]["set"]["friction_angle"]["random_field"];
  EXPECT_EQ(field["mean"], base_scene()["stages"][1]["set"]["friction_angle"]);
  EXPECT_EQ(std::to_string(field["seed"].get<std::uint64_t>()), seed_of_member[2]);
  EXPECT_TRUE(fs::exists(dir_ / "out/sweep-exceedance.png"));
  // The painted member also paints its friction angle, point by point.
  EXPECT_TRUE(fs::exists(dir_ / "out/members/0002/frames/friction-angle"));
  EXPECT_FALSE(fs::exists(dir_ / "out/members/0001/frames"));
  // Rerun alone, a member's scene gives the runout the sweep reported.
  const auto again = landslide("run out/members/0002/scene.json --out again --threads 1", dir_);
  ASSERT_EQ(again.status, 0) << again.output;
  const json summary = json::parse(read_text(dir_ / "again/summary.json"));
  const json member = json::parse(read_text(dir_ / "out/members/0002/summary.json"));
  EXPECT_EQ(summary["stages"].back()["metrics"]["runout_m"],
            member["stages"].back()["metrics"]["runout_m"]);
}

TEST_F(Sweep, BadRandomFieldsAreRefusedBeforeAnyMemberRuns) {
  auto with = [](const std::function<void(json&)>& change) {
    json s = field_sweep();
    change(s);
    return s;
  };
  const std::vector<BadCase> cases = {
      {"no samples", with([](json& s) { s.erase("samples"); }),
       {"samples = missing: expected a whole number in [1, 9999]"}},
      {"zero samples", with([](json& s) { s["samples"] = 0; }), {"samples = 0"}},
      {"fractional seed", with([](json& s) { s["seed"] = 1.5; }),
       {"seed = 1.5: expected a whole number in [0, 2^53 - 1]"}},
      {"samples without fields",
       {{"base", "base.json"},
        {"axes", json::array({{{"path", "grid.cell_size"}, {"values", {2}}}})},
        {"samples", 3}},
       {"samples: given without random_fields"}},
      {"unknown field key", with([](json& s) { s["random_fields"][0]["theta"] = 3; }),
       {"random_fields[0].theta: unknown key"}},
      {"a property no field can set",
       with([](json& s) { s["random_fields"][0]["path"] = "materials.soil.density"; }),
       {"random_fields[0] (materials.soil.density): expected the path of a cohesion or "
        "friction_angle"}},
      {"a path the base lacks",
       with([](json& s) { s["random_fields"][0]["path"] = "stages.2.set.cohesion"; }),
       {"random_fields[0] (stages.2.set.cohesion): the base scene", "has no stages.2.set.cohesion"}},
      {"a cohesion field of mean 0",
       with([](json& s) { s["random_fields"][0]["path"] = "stages.1.set.cohesion"; }),
       {"member 0 (sample 0)", "stages[1].set.cohesion.random_field.mean = 0: expected a number in "
        "(0, inf)"}},
      {"a field of the materials",
       with([](json& s) { s["random_fields"][0]["path"] = "materials.soil.friction_angle"; }),
       {"member 0 (sample 0)", "materials.soil.friction_angle = {\"random_field\""}},
      {"a value the scene refuses",
       with([](json& s) { s["random_fields"][0]["lower"] = 1; }),
       {"member 0 (sample 0)", "stages[1].set.friction_angle.random_field.lower = 1: expected a "
        "number in ["}},
      {"lognormal friction",
       with([](json& s) {
         s["random_fields"][0].erase("lower");
         s["random_fields"][0].erase("upper");
         s["random_fields"][0]["distribution"] = "lognormal";
       }),
       {"random_field.distribution = \"lognormal\": expected \"truncated-normal\""}},
  };
  expect_refused(cases);
}

// The first line of the output that starts with `start` ("" if none).
std::string line_starting(const std::string& output, const std::string& start) {
  for (const std::string& line : lines(output))
    if (line.rfind(start, 0) == 0) return line;
  return "";
}

json modulus_sweep() {
  return {{"base", "base.json"},
          {"axes", json::array({{{"path", "materials.soil.youngs_modulus"},
                                 {"values", {2e7, 1e30}}}})}};
}

// E = 1e30 would take 2e15 steps: run's preflight refuses that member, so
// the sweep stops before member 0 runs, and makes no member folder.
TEST_F(Sweep, MemberRunWouldRefuseStopsTheSweepBeforeAnyMemberRuns) {
  write_sweep(modulus_sweep());
  const auto r = landslide("sweep sweep.json --out out --threads 1", dir_);
  EXPECT_EQ(r.status, 2) << r.output;
  const std::string error = line_starting(r.output, "error: ");
  EXPECT_EQ(error.rfind("error: sweep.json: member 1 (materials.soil.youngs_modulus = 1e+30): ", 0),
            0u) << r.output;
  EXPECT_NE(error.find("steps (first dt = "), std::string::npos) << r.output;
  EXPECT_NE(error.find("(or --allow-long)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("member 0 of"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a member ran or its folder was made";
}

// A frame too small for its annotations is refused for a painted member
// (without ffmpeg or OSMesa the painting is refused for that member too).
TEST_F(Sweep, PaintedMemberWithTooSmallFramesIsRefused) {
  json base = base_scene();
  base["output"]["image_size"] = {640, 360};
  std::ofstream(dir_ / "base.json") << base.dump(1);
  write_sweep({{"base", "base.json"},
               {"axes", json::array({{{"path", "output.image_size.0"}, {"values", {640, 64}}}})}});
  const auto r = landslide("sweep sweep.json --out out --threads 1 --paint 1", dir_);
  EXPECT_EQ(r.status, 2) << r.output;
  const std::string error = line_starting(r.output, "error: ");
  EXPECT_EQ(error.rfind("error: sweep.json: member 1 (output.image_size.0 = 64): ", 0), 0u)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a member ran or its folder was made";
}

// --check reads and preflights every member, prints the sweep's estimate
// and writes nothing.
TEST_F(Sweep, CheckPrintsTheEstimateAndWritesNothing) {
  write_sweep(friction_sweep());
  const auto r = landslide("sweep sweep.json --out out --threads 1 --check", dir_);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("sweep estimate: 3 members to run, up to "), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(" point-steps"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  wall time: up to about "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("sweep.json: ok"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("member 0 of"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "--check wrote into --out";
  write_sweep(modulus_sweep());
  const auto refused = landslide("sweep sweep.json --out out --threads 1 --check", dir_);
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("error: sweep.json: member 1 ("), std::string::npos)
      << refused.output;
}

// --allow-long lets a member past the estimate's limits through, as it lets
// `landslide run` (checked only: that member would run for days).
TEST_F(Sweep, AllowLongLetsAMemberPastTheLimitsThrough) {
  write_sweep(modulus_sweep());
  const auto r = landslide("sweep sweep.json --out out --threads 1 --check --allow-long", dir_);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(line_starting(r.output, "warning: ").rfind("warning: sweep.json: member 1 (", 0), 0u)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "--check wrote into --out";
}

// Under mpirun every rank stops, and the refusal is said once (rank 0's).
TEST_F(Sweep, RefusalUnderMpiStopsEveryRankAndIsSaidOnce) {
  if (const std::string why = no_mpi(); !why.empty()) GTEST_SKIP() << why;
  write_sweep(modulus_sweep());
  EXPECT_NE(two_ranks("sweep sweep.json --out out --threads 1"), 0);
  const std::string log = read_text(dir_ / "two.log");
  const std::size_t first = log.find("error: sweep.json: member 1 (");
  ASSERT_NE(first, std::string::npos) << log;
  EXPECT_EQ(log.find("error: sweep.json: member 1 (", first + 1), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a member ran or its folder was made";
}

// The shipped Monte Carlo example (100 samples of the paper's slope at 1661
// points with a random friction angle) runs to its end: every sample comes
// to rest, and the exceedance plot is drawn. About 90 s on one core.
TEST(ShippedSweep, MonteCarloExampleRunsToItsEnd) {
  const fs::path out = fs::temp_directory_path() / "landslide-sweep-monte-carlo";
  fs::remove_all(out);
  const auto r = landslide("sweep '" LANDSLIDE_SOURCE_DIR
                           "/scenarios/sweeps/monte-carlo-phi20-n1661.json' --out '" +
                               out.string() + "' --threads 1",
                           fs::temp_directory_path());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto rows = lines(read_text(out / "sweep.csv"));
  ASSERT_EQ(rows.size(), 101u);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    EXPECT_NE(rows[k].find(",finished,"), std::string::npos) << rows[k];
    EXPECT_NE(rows[k].find(",true,"), std::string::npos) << "not at rest: " << rows[k];
  }
  EXPECT_TRUE(fs::exists(out / "sweep-exceedance.png"));
  fs::remove_all(out);
}

}  // namespace
