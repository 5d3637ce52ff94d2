// `landslide check` is run's preflight: every scene, option and output folder
// that `run` refuses, `check` refuses first, with the same one-line message
// and exit 2, and `run` refuses it before writing anything. The real binary
// runs in a child process, as a user would run it.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/estimate.hpp"
#include "render/video.hpp"
#include "sim/scene/memory_budget.hpp"
#include "sim/scene/random_field.hpp"
#include "sim/scene/scenario.hpp"
#include "tests/app/tiny_block.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Result {
  int status = -1;
  std::string out, err;
  // The message of the last "error: " line of stderr ("" if none).
  std::string error() const {
    const std::size_t at = err.rfind("error: ");
    return at == std::string::npos ? "" : err.substr(at, err.find('\n', at) - at);
  }
};

class Preflight : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("landslide-preflight-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    painting_ = render::ffmpeg_available(nullptr);
  }
  void TearDown() override { fs::remove_all(root_); }

  // `landslide ARGS...`, its exit status, stdout and stderr.
  Result landslide(const std::vector<std::string>& args) {
    const fs::path out = root_ / "stdout.txt", err = root_ / "stderr.txt";
    const pid_t child = ::fork();
    if (child == 0) {
      ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
      ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
      std::vector<char*> argv{const_cast<char*>(LANDSLIDE_BINARY)};
      for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(LANDSLIDE_BINARY, argv.data());
      ::_exit(127);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return Result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
  }

  fs::path write_scene(const std::string& name, const json& scene) {
    const fs::path file = root_ / (name + ".json");
    std::ofstream(file) << scene.dump(1);
    return file;
  }
  static json tiny_block() { return json::parse(apptest::kTinyBlock); }
  static json shipped_slope() {
    return json::parse(
        read_text(fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios/paper-slope-phi20-n1661.json"));
  }

  // `check` and `run` of the scene with the same extra options both exit 2
  // with the same message, which names `expected`; the run wrote nothing.
  void expect_refused(const fs::path& scene, const std::string& expected,
                      const std::vector<std::string>& options = {}) {
    const fs::path out = root_ / ("out-" + scene.stem().string());
    std::vector<std::string> check = {"check", scene.string(), "--threads", "1"};
    std::vector<std::string> run = {"run", scene.string(), "--out", out.string(), "--threads", "1"};
    for (const std::string& o : options) check.push_back(o), run.push_back(o);
    const Result c = landslide(check), r = landslide(run);
    EXPECT_EQ(c.status, 2) << c.err;
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(c.error().find(expected), std::string::npos) << c.err;
    EXPECT_EQ(c.error(), r.error());
    EXPECT_FALSE(fs::exists(out)) << "the refused run wrote " << out;
  }

  fs::path root_;
  bool painting_ = false;
};

TEST_F(Preflight, ImageSizesTooSmallForTheirAnnotations) {
  if (!painting_) GTEST_SKIP() << "ffmpeg is not available";
  for (const json& size : {json{64, 64}, json{8192, 64}, json{64, "auto"}}) {
    json scene = tiny_block();
    scene["output"]["image_size"] = size;
    expect_refused(write_scene("small-image", scene), "output.image_size = [" +
                                                          std::to_string(size[0].get<int>()));
  }
}

TEST_F(Preflight, FixedTimeStepAboveTheStableBoundAtStepZero) {
  json scene = tiny_block();
  scene["time_step"] = {{"fixed", 0.5}};
  expect_refused(write_scene("fixed-dt", scene), "time_step.fixed = 0.5 s exceeds the stable bound");
}

TEST_F(Preflight, BodyTooSmallToHoldAPoint) {
  json scene = tiny_block();
  scene["bodies"].push_back(
      {{"name", "speck"}, {"material", "cap"}, {"rectangle", {{"min", {3.5, 2}}, {"max", {3.55, 2.05}}}}});
  expect_refused(write_scene("speck", scene), "bodies[2] (speck): no point falls inside it");
}

TEST_F(Preflight, PathsThatAreFiles) {
  json scene = tiny_block();
  scene["output"]["frame_interval"] = 0;  // needs no ffmpeg
  const fs::path file = write_scene("plain", scene);
  const fs::path not_a_dir = root_ / "a-file";
  std::ofstream(not_a_dir) << "x";
  expect_refused(file, "--state-cache " + not_a_dir.string() + ": is a file",
                 {"--state-cache", not_a_dir.string()});
  for (const fs::path& out : {not_a_dir, not_a_dir / "below"}) {
    const Result c = landslide({"check", file.string(), "--out", out.string()});
    const Result r = landslide({"run", file.string(), "--out", out.string()});
    EXPECT_EQ(c.status, 2);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(c.error().find("--out " + out.string() + ": "), std::string::npos) << c.err;
    EXPECT_NE(c.error().find("is a file"), std::string::npos) << c.err;
    EXPECT_EQ(c.error(), r.error());
  }
}

TEST_F(Preflight, UnwritableOutputFolder) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anywhere";
  json scene = tiny_block();
  scene["output"]["frame_interval"] = 0;
  const fs::path file = write_scene("plain", scene);
  fs::create_directories(root_ / "locked");
  fs::permissions(root_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  const std::string out = (root_ / "locked" / "out").string();
  const Result c = landslide({"check", file.string(), "--out", out});
  const Result r = landslide({"run", file.string(), "--out", out});
  fs::permissions(root_ / "locked", fs::perms::owner_all);
  EXPECT_EQ(c.status, 2);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(c.error().find("is not writable"), std::string::npos) << c.err;
  EXPECT_EQ(c.error(), r.error());
}

// The values that used to run for hours (or forever) without a word: each
// passes a limit of the estimate, which names it; --allow-long gets past.
TEST_F(Preflight, EstimatesPastTheLimitsAreRefused) {
  struct Case {
    std::string name, expected;
    void (*edit)(json&);
  };
  const std::vector<Case> cases = {
      {"huge-modulus", "steps (first dt = ",
       [](json& s) { s["materials"]["soil"]["youngs_modulus"] = 1e30; }},
      {"tiny-density", "steps (first dt = ",
       [](json& s) {
         s["materials"]["soil"]["density"] = 1e-30;
         s["materials"]["soil"]["critical_density"] = 1e-30;
       }},
      {"incompressible", "steps (first dt = ",
       [](json& s) { s["materials"]["soil"]["poisson_ratio"] = 0.4999999; }},
      // 40 s / 100000 frames: output.frame_interval's lower limit.
      {"many-frames", "frames per field", [](json& s) { s["output"]["frame_interval"] = 0.0004; }},
  };
  for (const Case& k : cases) {
    if (k.name == "many-frames" && !painting_) continue;
    json scene = shipped_slope();
    k.edit(scene);
    const fs::path file = write_scene(k.name, scene);
    expect_refused(file, k.expected);
    const Result c = landslide({"check", file.string(), "--threads", "1"});
    EXPECT_NE(c.out.find("estimate: "), std::string::npos) << "the refusal shows the estimate";
    const Result allowed = landslide({"check", file.string(), "--threads", "1", "--allow-long"});
    EXPECT_EQ(allowed.status, 0) << allowed.err;
    EXPECT_NE(allowed.err.find("warning: "), std::string::npos) << allowed.err;
  }
}

// check prints the estimate run prints at its start: the same counts
// (only the measured wall time may differ).
TEST_F(Preflight, CheckPrintsTheEstimateRunStartsWith) {
  json scene = tiny_block();
  scene["output"]["frame_interval"] = 0;
  const fs::path file = write_scene("plain", scene);
  const Result c = landslide({"check", file.string(), "--threads", "1"});
  ASSERT_EQ(c.status, 0) << c.err;
  const Result r = landslide({"run", file.string(), "--out", (root_ / "run").string(), "--threads", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string counts = c.out.substr(0, c.out.find("  disk:"));
  EXPECT_NE(counts.find(" points, "), std::string::npos) << c.out;
  EXPECT_NE(counts.find("steps: settle "), std::string::npos) << c.out;
  EXPECT_EQ(r.err.find(counts), 0u) << r.err;
  for (const char* line : {"  series rows: ", "  memory: about ", "  wall time: about "})
    EXPECT_NE(c.out.find(line), std::string::npos) << c.out;
}

TEST_F(Preflight, EarlierOutputsAreRefusedUnlessOverwrite) {
  json scene = tiny_block();
  scene["output"]["frame_interval"] = 0;
  scene["output"]["vtk"] = "stage-end";
  const fs::path file = write_scene("plain", scene);
  const fs::path out = root_ / "out";
  fs::create_directories(out / "frames" / "velocity");
  fs::create_directories(out / "vtk");
  std::ofstream(out / "frames" / "velocity" / "000099.png") << "stale";
  std::ofstream(out / "frames" / "velocity" / "notes.txt") << "not ours";
  std::ofstream(out / "vtk" / "frame-000099.vtu") << "stale";
  std::ofstream(out / "velocity.mp4") << "stale";
  std::ofstream(out / "summary.json") << "{}";
  const Result c = landslide({"check", file.string(), "--out", out.string()});
  const Result r = landslide({"run", file.string(), "--out", out.string()});
  EXPECT_EQ(c.status, 2);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(c.error().find("holds an earlier run's outputs (frames, summary.json, velocity.mp4, "
                           "vtk): expected a new or empty folder, or --overwrite"),
            std::string::npos)
      << c.err;
  EXPECT_EQ(c.error(), r.error());
  EXPECT_EQ(read_text(out / "summary.json"), "{}") << "a refused run leaves the folder as it was";
  // check --overwrite accepts the folder and removes nothing; run --overwrite
  // removes the earlier outputs, and only those.
  EXPECT_EQ(landslide({"check", file.string(), "--out", out.string(), "--overwrite"}).status, 0);
  EXPECT_TRUE(fs::exists(out / "velocity.mp4"));
  const Result o = landslide({"run", file.string(), "--out", out.string(), "--overwrite"});
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_FALSE(fs::exists(out / "frames" / "velocity" / "000099.png"));
  EXPECT_FALSE(fs::exists(out / "vtk" / "frame-000099.vtu"));
  EXPECT_FALSE(fs::exists(out / "velocity.mp4"));
  EXPECT_TRUE(fs::exists(out / "frames" / "velocity" / "notes.txt"));
  EXPECT_TRUE(fs::exists(out / "vtk" / "settle-end.vtu"));
  EXPECT_NE(read_text(out / "summary.json"), "{}");
  // A folder with none of the run's outputs is used as it is.
  fs::create_directories(root_ / "mine");
  std::ofstream(root_ / "mine" / "notes.txt") << "mine";
  EXPECT_EQ(landslide({"run", file.string(), "--out", (root_ / "mine").string()}).status, 0);
}

}  // namespace

namespace {

// The figure of check's "memory: about N unit" line, in bytes.
double memory_estimate(const std::string& out) {
  const std::string key = "memory: about ";
  const std::size_t at = out.find(key);
  if (at == std::string::npos) return -1;
  std::istringstream line(out.substr(at + key.size()));
  double value = 0;
  std::string unit;
  line >> value >> unit;
  const std::vector<std::string> units = {"B", "kB", "MB", "GB", "TB"};
  for (std::size_t u = 0; u < units.size(); ++u, value *= 1000)
    if (unit == units[u]) return value;
  return -1;
}

// A Mohr-Coulomb square filling its 10 m domain, two points a cell each way:
// (10 m / (cell_size / 2))^2 points. Its trigger sets the friction angle
// to a number, and it paints no frames.
json square_scene(double cell_size) {
  json scene = json::parse(R"({
    "name": "square", "domain": {"min": [0, 0], "max": [10, 10]},
    "grid": {"padding_cells": 2, "points_per_cell": 2},
    "gravity": [0, -9.81], "time_step": {"courant": 0.5},
    "boundaries": {"left": "roller", "right": "roller", "bottom": "fixed", "top": "free"},
    "materials": {"soil": {"model": "mohr-coulomb", "density": 2000, "youngs_modulus": 2e7,
                  "poisson_ratio": 0.25, "cohesion": 1e4, "friction_angle": 25,
                  "dilation_angle": 0, "critical_density": 1900}},
    "bodies": [{"name": "b", "material": "soil", "rectangle": {"min": [0, 0], "max": [10, 10]}}],
    "stages": [{"name": "trigger", "type": "material-change", "material": "soil",
                "set": {"friction_angle": 25}},
               {"name": "fall", "type": "dynamic", "duration": 0.001}],
    "output": {"frame_interval": 0}})");
  scene["grid"]["cell_size"] = cell_size;
  return scene;
}

// What check's memory estimate adds when stage `stage` of `scene` sets a
// random friction angle instead of its number; `scene_with_field` is the
// scene as read with the field.
class FieldMemory : public Preflight {
 protected:
  double added_by_field(json scene, int stage, sim::Scenario& scene_with_field) {
    const fs::path plain = write_scene("plain", scene);
    const double mean = scene["stages"][stage]["set"]["friction_angle"];
    scene["stages"][stage]["set"]["friction_angle"] = {
        {"random_field",
         {{"distribution", "truncated-normal"}, {"mean", mean}, {"cov", 0.15},
          {"lower", mean - 8}, {"upper", mean + 8}, {"scale_of_fluctuation", {20, 2}},
          {"seed", 7}}}};
    const fs::path field = write_scene("field", scene);
    const Result without = landslide({"check", plain.string(), "--threads", "1"});
    const Result with = landslide({"check", field.string(), "--threads", "1"});
    EXPECT_EQ(without.status, 0) << without.err;
    EXPECT_EQ(with.status, 0) << with.err;
    scene_with_field = sim::load_scenario(field.string());
    return memory_estimate(with.out) - memory_estimate(without.out);
  }
};

}  // namespace

// A stage's random field costs memory: its draw, or the points' own
// strengths after it, whichever is larger (sim/scene/memory_budget.hpp). The
// estimate adds that to the same scene's without the field.
TEST_F(FieldMemory, ARandomFieldCountsItsDraw) {
  sim::Scenario s;
  const fs::path slope = fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios/paper-slope-phi20-n66787.json";
  const double added = added_by_field(json::parse(read_text(slope)), 1, s);
  const double draw = sim::field_draw_peak_bytes(sim::field_lattice(s));
  ASSERT_GT(draw, sim::kBytesPerPointWithField * 66787) << "this scene's draw is the larger part";
  // Both figures are printed to three digits.
  EXPECT_NEAR(added, draw, 1.5e6);
}

// Where the soil fills the domain, the lattice has about as many nodes as
// there are points, and the points' own strengths, not the draw, are what a
// field adds.
TEST_F(FieldMemory, ARandomFieldOnEveryLatticeNodeCountsItsStrengths) {
  sim::Scenario s;
  const double added = added_by_field(square_scene(0.05), 0, s);
  const double points = 400.0 * 400.0;  // (10 m / (0.05 m / 2))^2
  const double strengths = sim::kBytesPerPointWithField * points;
  ASSERT_LT(sim::field_draw_peak_bytes(sim::field_lattice(s)), strengths)
      << "this scene's strengths are the larger part";
  EXPECT_NEAR(added, strengths, 1.5e6);
  // No less than a run measured: 198.5 B per point above the same run
  // without a field, for 4 M points of this square (memory_budget.hpp).
  EXPECT_GE(added, 198.5 * points - 1.5e6);
}

// Painting frames costs memory per point and per field painted
// (sim/scene/memory_budget.hpp): check adds it to the estimate of the same
// scene without frames, and no less than a run was measured to take.
TEST_F(Preflight, PaintedFramesCountTheirMemoryPerPointAndField) {
  json scene = square_scene(0.025);
  const double points = 800.0 * 800.0;
  double added[2] = {};
  const std::vector<std::vector<std::string>> fields = {
      {"displacement-x"}, {"displacement-x", "relative-yield", "velocity"}};
  const Result without = landslide({"check", write_scene("unpainted", scene).string()});
  ASSERT_EQ(without.status, 0) << without.err;
  for (int k = 0; k < 2; ++k) {
    scene["output"] = {{"frame_interval", 0.0005}, {"fields", fields[k]}};
    const Result with = landslide({"check", write_scene("painted", scene).string()});
    ASSERT_EQ(with.status, 0) << with.err;
    added[k] = memory_estimate(with.out) - memory_estimate(without.out);
    const double counted = sim::kBytesPerPaintedPoint +
                           sim::kBytesPerPaintedFieldPoint * double(fields[k].size());
    EXPECT_NEAR(added[k], counted * points, 1.5e6) << fields[k].size() << " fields";
  }
  // Measured for 4 M points of this square, 6 frames: 72.4 and 90.0 B per
  // point above the same run without frames, with one and three fields.
  EXPECT_GE(added[0], 72.4 * points - 1.5e6);
  EXPECT_GE(added[1], 90.0 * points - 1.5e6);
}

// Painting time grows with the points painted, by no less than the 61-63 ns
// per point, frame and field measured (app/estimate.hpp), whatever the pixels.
TEST_F(Preflight, PaintingTimeCountsThePointsPainted) {
  double painting[2] = {};
  const double cells[2] = {0.05, 0.025}, points[2] = {400.0 * 400.0, 800.0 * 800.0};
  for (int k = 0; k < 2; ++k) {
    json scene = square_scene(cells[k]);
    scene["output"] = {{"frame_interval", 0.0005}, {"fields", {"displacement-x"}}};
    const sim::Simulation sim(sim::parse_scenario(scene.dump(), "square"));
    const app::Estimate e = app::estimate_run(sim, 640, 640, fs::path(), 1);
    ASSERT_EQ(e.points, std::size_t(points[k]));
    ASSERT_EQ(e.frames, 3);  // 0, 0.5 and 1 ms
    painting[k] = e.wall_seconds - e.point_steps / e.point_steps_per_second;
  }
  EXPECT_GE(painting[1] - painting[0], 3 * (points[1] - points[0]) * 61e-9);
}
