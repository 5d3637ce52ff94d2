// End to end: a short run of a tiny scene paints numbered PNGs per field and
// videos; `landslide render` re-paints its VTK states into the same pixels;
// `landslide panel` composes frames; nothing half-written is left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "app/commands.hpp"
#include "tests/app/tiny_block.hpp"
#include "output/frames.hpp"
#include "render/image_diff.hpp"
#include "render/png_io.hpp"
#include "render/video.hpp"
#include "sim/physics/team.hpp"

namespace {

namespace fs = std::filesystem;

// A soil block and an elastic cap settling, then slumping (tiny_block.hpp).
const char* const kScene = apptest::kTinyBlock;

const std::vector<std::string> kFields = {"displacement-y", "relative-yield", "velocity",
                                          "material"};
constexpr int kFrames = 5 + 3;  // settle: 0 .. 0.2 s, slump: 0 .. 0.1 s

std::string frame_name(int i) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.png", i);
  return name;
}

int numbered_pngs(const fs::path& dir) {
  static const std::regex numbered(R"(\d{6}\.png)");
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (std::regex_match(e.path().filename().string(), numbered)) ++n;
  return n;
}

std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp") != std::string::npos || name.find(".part") != std::string::npos)
      found.push_back(e.path().string());
  }
  return found;
}

class RunFrames : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("landslide-app-test-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    scenario_ = root_ / "tiny-block.json";
    std::ofstream(scenario_) << kScene;
    out_ = root_ / "out";
    ffmpeg_ = render::ffmpeg_available(nullptr);
    if (!ffmpeg_) return;
    // Left by an "earlier run" with more frames: must not join this run's video.
    fs::create_directories(out_ / "frames" / "velocity");
    std::ofstream(out_ / "frames" / "velocity" / frame_name(kFrames)) << "stale";
    std::ofstream(out_ / "frames" / "velocity" / "notes.txt") << "not ours";
    app::RunOptions o;
    o.scenario = scenario_.string();
    o.out_dir = out_.string();
    o.threads = 1;
    o.overwrite = true;  // without it the earlier frames are refused (test_preflight.cpp)
    status_ = app::run_command(o);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  void SetUp() override {
    if (!ffmpeg_) GTEST_SKIP() << "ffmpeg (with libx264, gif, palettegen) is not available";
    ASSERT_EQ(status_, app::kExitOk);
  }

  static fs::path root_, scenario_, out_;
  static bool ffmpeg_;
  static int status_;
};

fs::path RunFrames::root_, RunFrames::scenario_, RunFrames::out_;
bool RunFrames::ffmpeg_ = false;
int RunFrames::status_ = -1;

TEST_F(RunFrames, NumberedPngsPerFieldAtTheImageSize) {
  for (const std::string& field : kFields) {
    const fs::path dir = out_ / "frames" / field;
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    EXPECT_EQ(numbered_pngs(dir), kFrames) << dir;
    for (int i = 0; i < kFrames; ++i) {
      const render::Image img = render::read_png((dir / frame_name(i)).string());
      EXPECT_EQ(img.width(), 320);
      EXPECT_EQ(img.height(), 180);
    }
  }
}

TEST_F(RunFrames, StaleFramesOfAnEarlierRunAreRemoved) {
  EXPECT_FALSE(fs::exists(out_ / "frames" / "velocity" / frame_name(kFrames)));
  EXPECT_TRUE(fs::exists(out_ / "frames" / "velocity" / "notes.txt"));
}

TEST_F(RunFrames, FramesChangeWhileTheBlockMoves) {
  const fs::path dir = out_ / "frames" / "velocity";
  const render::Image first = render::read_png((dir / frame_name(0)).string());
  const render::Image later = render::read_png((dir / frame_name(2)).string());
  EXPECT_GT(render::diff_images(later, first).differing_pixels, 0u);
}

TEST_F(RunFrames, Mp4AndGifPerField) {
  for (const std::string& field : kFields) {
    for (const char* ext : {".mp4", ".gif"}) {
      const fs::path p = out_ / (field + ext);
      ASSERT_TRUE(fs::is_regular_file(p)) << p;
      EXPECT_GT(fs::file_size(p), 100u) << p;
    }
  }
}

TEST_F(RunFrames, StatesJsonNamesStageAndFrame) {
  std::ifstream in(out_ / "vtk" / "states.json");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\"frame-000007.vtu\""), std::string::npos);
  EXPECT_NE(text.str().find("\"slump\""), std::string::npos);
}

TEST_F(RunFrames, NothingHalfWritten) {
  EXPECT_EQ(temporaries(root_), std::vector<std::string>{});
  EXPECT_FALSE(fs::exists(out_ / ".frames-pending")) << "the spilled frames outlive the run";
}

TEST_F(RunFrames, RenderReproducesEveryFrameOfEveryField) {
  for (const std::string& field : kFields) {
    app::RenderOptions o;
    o.input = out_.string();
    o.scenario = scenario_.string();
    o.field = field;
    o.out = (root_ / "render" / field).string();
    ASSERT_EQ(app::render_command(o), app::kExitOk) << field;
    for (int i = 0; i < kFrames; ++i) {
      const render::Image run = render::read_png((out_ / "frames" / field / frame_name(i)).string());
      const render::Image again = render::read_png((root_ / "render" / field / frame_name(i)).string());
      const render::DiffResult d = render::diff_images(again, run);
      EXPECT_TRUE(d.passed) << field << " frame " << i << ": " << d.summary();
    }
  }
  EXPECT_EQ(temporaries(root_), std::vector<std::string>{});
}

TEST_F(RunFrames, RenderOneVtuToAPngWithAFixedRange) {
  app::RenderOptions o;
  o.input = (out_ / "vtk" / "frame-000003.vtu").string();
  o.scenario = scenario_.string();
  o.field = "stress-yy";  // not among the run's fields: any field can be re-painted
  o.colour_map = "jet";
  o.range = std::make_pair(-40.0, 0.0);
  o.out = (root_ / "one" / "stress.png").string();
  ASSERT_EQ(app::render_command(o), app::kExitOk);
  const render::Image img = render::read_png(o.out);
  EXPECT_EQ(img.width(), 320);
  EXPECT_EQ(img.height(), 180);
}

TEST_F(RunFrames, RenderRefusesBadArguments) {
  app::RenderOptions good;
  good.input = out_.string();
  good.scenario = scenario_.string();
  good.field = "velocity";
  good.out = (root_ / "bad").string();
  auto status = [&](auto change) {
    app::RenderOptions o = good;
    change(o);
    return app::render_command(o);
  };
  EXPECT_EQ(status([](app::RenderOptions& o) { o.field = "pressure"; }), app::kExitBadInput);
  EXPECT_EQ(status([](app::RenderOptions& o) { o.input += "/nowhere"; }), app::kExitBadInput);
  EXPECT_EQ(status([](app::RenderOptions& o) { o.scenario += ".missing"; }),
            app::kExitBadInput);
  EXPECT_EQ(status([](app::RenderOptions& o) { o.colour_map = "rainbow"; }),
            app::kExitBadInput);
  EXPECT_EQ(status([](app::RenderOptions& o) { o.range = std::make_pair(1.0, 1.0); }),
            app::kExitBadInput);
  // Eight states cannot go into one PNG file.
  EXPECT_EQ(status([&](app::RenderOptions& o) { o.out = (root_ / "bad.png").string(); }),
            app::kExitBadInput);
  // A directory without vtk/points.pvd.
  EXPECT_EQ(status([&](app::RenderOptions& o) { o.input = (out_ / "frames").string(); }),
            app::kExitBadInput);
  EXPECT_FALSE(fs::exists(root_ / "bad"));
  EXPECT_FALSE(fs::exists(root_ / "bad.png"));
}

// Determinism: the same scene with two threads paints byte-identical PNGs.
// Another scene's states would be painted under its title, in its domain.
TEST_F(RunFrames, RenderRefusesAnotherScenarioAndOtherImageTypes) {
  auto refusal = [&](const std::string& scene, const std::string& out) {
    const fs::path file = root_ / "other.json";
    std::ofstream(file) << scene;
    app::RenderOptions o;
    o.input = out_.string();
    o.scenario = file.string();
    o.field = "velocity";
    o.out = (root_ / out).string();
    testing::internal::CaptureStderr();
    const int status = app::render_command(o);
    const std::string text = testing::internal::GetCapturedStderr();
    EXPECT_EQ(status, app::kExitBadInput) << text;
    EXPECT_FALSE(fs::exists(o.out)) << o.out;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    return text;
  };
  auto changed = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  const std::string renamed = changed(kScene, R"("tiny-block")", R"("other-block")");
  EXPECT_NE(refusal(renamed, "renamed").find("states.json: states of scenario \"tiny-block\", "
                                             "but --scenario " + (root_ / "other.json").string() +
                                             " is \"other-block\""),
            std::string::npos);
  // Same name, other points (a states.json of an older run has no name):
  // 2 x 2 points in each of 8 + 2 cells, 3 x 3 in the denser scene.
  const std::string denser = changed(kScene, R"("points_per_cell": 2)", R"("points_per_cell": 3)");
  const std::string text = refusal(denser, "denser");
  EXPECT_NE(text.find("frame-000000.vtu: 40 points, but --scenario"), std::string::npos) << text;
  EXPECT_NE(text.find(" seeds 90 points: give the scenario the run was made with"),
            std::string::npos)
      << text;
  for (const char* out : {"x.jpg", "x.JPEG", "x.gif", "x.mp4"})
    EXPECT_NE(refusal(kScene, out).find(": landslide render writes PNG only"), std::string::npos)
        << out;
}

TEST_F(RunFrames, TwoThreadsPaintTheSamePngs) {
  app::RunOptions o;
  o.scenario = scenario_.string();
  o.out_dir = (root_ / "out-two-threads").string();
  o.threads = 2;
  sim::follow_free_cores(false);  // two threads even on a loaded machine
  ASSERT_EQ(app::run_command(o), app::kExitOk);
  auto bytes = [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const std::string& field : kFields)
    for (int i = 0; i < kFrames; ++i) {
      const fs::path one = out_ / "frames" / field / frame_name(i);
      const fs::path two = fs::path(o.out_dir) / "frames" / field / frame_name(i);
      const std::string a = bytes(one);
      EXPECT_FALSE(a.empty()) << one;
      EXPECT_EQ(a, bytes(two)) << one << " differs from " << two;
    }
}

TEST_F(RunFrames, PanelOfFourFrames) {
  app::PanelOptions o;
  o.out = (root_ / "panel" / "panel.png").string();
  o.title = "tiny block";
  o.cols = 2;
  for (const std::string& field : kFields) {
    o.items.push_back((out_ / "frames" / field / frame_name(4)).string());
    o.items.push_back(field);
  }
  ASSERT_EQ(app::panel_command(o), app::kExitOk);
  const render::Image panel = render::read_png(o.out);
  EXPECT_GT(panel.width(), 2 * 320);
  EXPECT_GT(panel.height(), 2 * 180);

  app::PanelOptions odd = o;
  odd.items.pop_back();  // an image without its caption
  EXPECT_EQ(app::panel_command(odd), app::kExitBadInput);
  app::PanelOptions missing = o;
  missing.items[0] = (root_ / "no-such.png").string();
  EXPECT_EQ(app::panel_command(missing), app::kExitBadInput);
}

// Without ffmpeg a run that paints refuses to start: exit 2, nothing written.
TEST(RunCommand, RefusesToPaintWithoutFfmpegBeforeSimulating) {
  const fs::path root =
      fs::temp_directory_path() / ("landslide-app-noffmpeg-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "empty-bin");
  const fs::path scenario = root / "tiny-block.json";
  std::ofstream(scenario) << kScene;
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", (root / "empty-bin").c_str(), 1);
  app::RunOptions o;
  o.scenario = scenario.string();
  o.out_dir = (root / "out").string();
  o.threads = 1;
  const int status = app::run_command(o);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(status, app::kExitBadInput);
  EXPECT_FALSE(fs::exists(root / "out"));
  fs::remove_all(root);
}

// A fixed time step a hair under the bound at rest passes the preflight and
// fails the second step, as the falling points raise the signal speed, after
// frame 0 was captured: that frame is still painted (one frame makes no video).
TEST(RunCommand, FailedRunStillPaintsWhatItCaptured) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "ffmpeg is not available";
  const fs::path root =
      fs::temp_directory_path() / ("landslide-app-failed-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  std::string scene = kScene;
  const std::string courant = R"("time_step": {"courant": 0.5})";
  // The cap's c_p = sqrt(E (1 - nu) / ((1 + nu) (1 - 2 nu)) / rho), Courant 0.5, h = 0.5 m.
  const double bound = 0.5 * 0.5 / std::sqrt(2e7 * 0.75 / (1.25 * 0.5) / 500);
  char fixed[80];
  std::snprintf(fixed, sizeof fixed, R"("time_step": {"fixed": %.17g})", bound * (1 - 1e-9));
  scene.replace(scene.find(courant), courant.size(), fixed);
  std::ofstream(root / "unstable.json") << scene;
  app::RunOptions o;
  o.scenario = (root / "unstable.json").string();
  o.out_dir = (root / "out").string();
  o.threads = 1;
  EXPECT_EQ(app::run_command(o), app::kExitFailed);
  EXPECT_TRUE(fs::is_regular_file(root / "out" / "frames" / "material" / frame_name(0)));
  EXPECT_FALSE(fs::exists(root / "out" / "material.mp4"));
  EXPECT_TRUE(fs::is_regular_file(root / "out" / "summary.json"));
  // The watchdog hands over the state from before the failure: here the
  // initial one.
  EXPECT_TRUE(fs::is_regular_file(root / "out" / "vtk" / "last-good.vtu"));
  EXPECT_FALSE(fs::exists(root / "out" / ".frames-pending"));
  EXPECT_EQ(temporaries(root), std::vector<std::string>{});
  fs::remove_all(root);
}

}  // namespace
