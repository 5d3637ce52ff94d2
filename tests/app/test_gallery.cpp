// `landslide gallery` end to end, on a coarse copy of the committed phi = 20
// scene (h = 2 m, about 500 points, at most 4.5 s of slide) and the studies'
// sweep files over it: the friction-angle study as shipped, the resolution
// study at coarse cell sizes. Every figure and both animations are written,
// the 2x2 figures have four panels, the side-by-side animation has a page
// every 0.5 s of the longest slide (when ffprobe is there to count them), and
// nothing temporary is left. The folder holds no other scene, so the
// figures of the studies can only come from the sweep files. What the
// figures show at the paper's resolutions is looked at in gallery/README.md,
// not here; their physics is what tests/regression/ guards.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "gallery/src/gallery_studies.hpp"
#include "output/frames.hpp"
#include "render/png_io.hpp"
#include "render/subprocess.hpp"
#include "render/video.hpp"
#include "sim/io/file_bytes.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kSlide = 4.5;  // s; the longest slide of the copies
const char* const kSideBySide = "anim-friction-angles-displacement-x";
const char* const kResolutions = "sweeps/fig11-resolutions.json";
const char* const kFrictionAngles = "sweeps/fig12-friction-angles.json";

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// paper-slope-phi20.json at h = 2 m with at most kSlide s of slide, and the
// shipped sweep files, the resolution study's cell sizes made coarse.
fs::path write_coarse_scenarios(const fs::path& root) {
  const fs::path source = fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios", dir = root / "scenarios";
  fs::create_directories(dir / "sweeps");
  json s = read_json(source / "paper-slope-phi20.json");
  s["grid"]["cell_size"] = 2.0;
  for (json& stage : s["stages"])
    if (stage["type"] == "dynamic") {
      stage["duration"] = kSlide;
      stage["stop_at_rest"]["min_time"] = 2.0;
    }
  std::ofstream(dir / "paper-slope-phi20.json") << s.dump(1);
  json resolutions = read_json(source / kResolutions);
  resolutions["axes"][0]["values"] = {2.6, 2.4, 2.2, 2.0};
  std::ofstream(dir / kResolutions) << resolutions.dump(1);
  fs::copy_file(source / kFrictionAngles, dir / kFrictionAngles);
  return dir;
}

// write_coarse_scenarios with the friction-angle study's sweep file edited.
fs::path with_friction_study(const fs::path& root, const std::function<void(json&)>& edit) {
  const fs::path scenarios = write_coarse_scenarios(root);
  json study = read_json(scenarios / kFrictionAngles);
  edit(study);
  std::ofstream(scenarios / kFrictionAngles) << study.dump(1);
  return scenarios;
}

// An empty folder for one test's files.
fs::path fresh_root(const std::string& test) {
  const fs::path root =
      fs::temp_directory_path() / ("landslide-gallery-" + test + "-" + std::to_string(::getpid()));
  fs::remove_all(root);
  return root;
}

// Frames of an mp4 as ffprobe counts them; -1 without ffprobe.
int mp4_frames(const fs::path& mp4) {
  const render::ProcessResult r = render::run_process(
      {"ffprobe", "-v", "error", "-select_streams", "v:0", "-count_packets", "-show_entries",
       "stream=nb_read_packets", "-of", "csv=p=0", mp4.string()});
  if (!r.ok()) return -1;
  return std::stoi(r.output);
}

// Seconds a GIF plays, as ffprobe reads it; -1 without ffprobe.
double gif_seconds(const fs::path& gif) {
  const render::ProcessResult r = render::run_process(
      {"ffprobe", "-v", "error", "-show_entries", "format=duration", "-of", "csv=p=0", gif.string()});
  if (!r.ok()) return -1;
  return std::stod(r.output);
}

// One test: ctest runs each test in a process of its own, and the gallery
// is the expensive part.
TEST(Gallery, EveryFigureAndBothAnimationsFromCoarseScenes) {
  if (!render::ffmpeg_available(nullptr))
    GTEST_SKIP() << "ffmpeg (with libx264, gif, palettegen) is not available";
  const fs::path root = fresh_root("test");
  const fs::path scenarios = write_coarse_scenarios(root);
  const fs::path out = root / "gallery";
  app::GalleryOptions o;
  o.out = out.string();
  o.scenarios = scenarios.string();
  ASSERT_EQ(app::gallery_command(o), app::kExitOk);

  // Panels are 960 px wide: one column, or two.
  for (const char* one : {"fig05-vertical-stress.png", "fig06-horizontal-displacement.png",
                          "fig10-relative-yield-3s.png"}) {
    const render::Image img = render::read_png((out / one).string());
    EXPECT_GT(img.width(), 960) << one;
    EXPECT_LT(img.width(), 2 * 960) << one << ": not one panel wide";
  }
  for (const char* four :
       {"fig09-slide.png", "fig11-resolutions.png", "fig12-friction-angles.png"}) {
    const render::Image img = render::read_png((out / four).string());
    EXPECT_GT(img.width(), 2 * 960) << four << ": not two panels wide";
    EXPECT_GT(img.height(), img.width() / 4) << four << ": not two panels high";
  }
  const render::Image series = render::read_png((out / "series-paper-slope-phi20.png").string());
  EXPECT_GT(series.width(), 1280) << "the frame with its series beside it";

  for (const std::string base : {"anim-paper-slope-phi20-displacement-x", kSideBySide})
    for (const char* ext : {".mp4", ".gif"}) {
      const fs::path p = out / (base + ext);
      ASSERT_TRUE(fs::is_regular_file(p)) << p;
      EXPECT_GT(fs::file_size(p), 1000u) << p;
    }
  // A page every 0.5 s of slide, shown 4 a second (twice the simulated
  // speed) and each repeated to play at 25 fps.
  const int played = mp4_frames(out / (std::string(kSideBySide) + ".mp4"));
  if (played >= 0) {
    const int pages = int(kSlide / 0.5) + 1;
    EXPECT_NEAR(played, pages * double(app::kPlayFps) / 4, 1.0) << "frames of the side-by-side mp4";
    // The GIF shows every page, each for 25 cs, without repeats.
    EXPECT_NEAR(gif_seconds(out / (std::string(kSideBySide) + ".gif")), pages / 4.0, 0.05);
  }

  EXPECT_FALSE(fs::exists(out / ".work"));
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << e.path();
    EXPECT_EQ(name.find(".part"), std::string::npos) << e.path();
  }
  fs::remove_all(root);
}

// The runs on two lanes (gallery_lanes.hpp) paint what they paint on one:
// every figure and GIF byte for byte (an mp4's bytes differ from run to run
// of one binary). On 2 threads the finest scene and the friction-angle
// study, which share its gravity stage, run beside the other resolutions;
// on 1 thread every run takes its turn.
TEST(Gallery, TwoLanesPaintWhatOneLanePaints) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "ffmpeg is not available";
  const fs::path root = fresh_root("lanes");
  const fs::path scenarios = write_coarse_scenarios(root);
  const auto gallery_on = [&](int threads, const char* expected) {
    omp_set_num_threads(threads);
    app::GalleryOptions o;
    o.out = (root / std::to_string(threads)).string();
    o.scenarios = scenarios.string();
    testing::internal::CaptureStdout();
    const int status = app::gallery_command(o);
    const std::string printed = testing::internal::GetCapturedStdout();
    EXPECT_EQ(status, app::kExitOk);
    EXPECT_NE(printed.find(expected), std::string::npos) << printed;
    EXPECT_NE(printed.find("); processor time "), std::string::npos) << printed;
  };
  const int threads = omp_get_max_threads();
  gallery_on(1, "(one lane)");
  gallery_on(2, "(two lanes: h = 2.000 m");
  omp_set_num_threads(threads);
  int compared = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(root / "1")) {
    const std::string ext = e.path().extension().string();
    if (ext != ".png" && ext != ".gif") continue;
    EXPECT_EQ(sim::read_file_bytes(e.path(), "missing"),
              sim::read_file_bytes(root / "2" / e.path().filename(), "missing"))
        << e.path().filename();
    ++compared;
  }
  EXPECT_EQ(compared, 9);  // 7 figures, 2 GIFs
  fs::remove_all(root);
}

// A scene that fails at its first step (a fixed time step 100 times the
// stable one), here the base of the friction-angle study, leaves no state at
// all: its panels are empty plots captioned FAILED, every figure is still
// written, and the command exits 1.
TEST(Gallery, ARunThatFailsBeforeAnyStateStillGivesEveryFigure) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "ffmpeg is not available";
  const fs::path root = fresh_root("failed");
  const fs::path scenarios =
      with_friction_study(root, [](json& study) { study["base"] = "../failing.json"; });
  json s = read_json(scenarios / "paper-slope-phi20.json");
  s["time_step"] = {{"fixed", 0.5}};
  std::ofstream(scenarios / "failing.json") << s.dump(1);
  app::GalleryOptions o;
  o.out = (root / "gallery").string();
  o.scenarios = scenarios.string();
  EXPECT_EQ(app::gallery_command(o), app::kExitFailed);
  for (const char* fig : {"fig05-vertical-stress.png", "fig06-horizontal-displacement.png",
                          "fig09-slide.png", "fig10-relative-yield-3s.png",
                          "fig11-resolutions.png", "fig12-friction-angles.png"})
    EXPECT_TRUE(fs::is_regular_file(root / "gallery" / fig)) << fig;
  fs::remove_all(root);
}

// The studies are what their sweep files say: edit a file, and the gallery's
// runs follow (values, their order, their number).
TEST(GalleryStudies, FollowTheSweepFiles) {
  const fs::path root = fresh_root("studies");
  const fs::path scenarios =
      with_friction_study(root, [](json& study) { study["axes"][0]["values"] = {30, 12.5}; });
  const app::gallery::Studies s = app::gallery::read_studies(scenarios);
  ASSERT_EQ(s.resolutions.sweep.members.size(), 4u);
  EXPECT_EQ(s.resolutions.sweep.members[0].scenario.cell_size, 2.6);
  EXPECT_EQ(s.resolutions.sweep.members[3].scenario.cell_size, 2.0);
  const std::vector<sweep::Member>& friction = s.friction_angles.sweep.members;
  ASSERT_EQ(friction.size(), 2u);
  EXPECT_EQ(app::gallery::scene_value(friction[1], s.friction_angles.path), "12.5");
  EXPECT_EQ(app::gallery::member_scenario(s.friction_angles, friction[1]).name,
            "fig12-friction-angles member 1 [stages.1.set.friction_angle = 12.5]");
  fs::remove_all(root);
}

// A study's sweep file over another axis than the figure's: exit 2, naming
// the file, the axis found and the one allowed, before anything runs.
TEST(GalleryCommand, AStudyOverAnotherAxisIsBadInput) {
  const fs::path root = fresh_root("axis");
  const fs::path scenarios = with_friction_study(root, [](json& study) {
    study["axes"][0] = {{"path", "stages.1.set.cohesion"}, {"values", {0, 1000}}};
  });
  try {
    app::gallery::read_studies(scenarios);
    ADD_FAILURE() << "a friction-angle study over the cohesion was read";
  } catch (const sweep::SweepError& e) {
    const std::string what = e.what();
    for (const char* named : {"fig12-friction-angles.json: axes", "stages.1.set.friction_angle",
                              "found: stages.1.set.cohesion"})
      EXPECT_NE(what.find(named), std::string::npos) << what;
  }
  app::GalleryOptions o;
  o.out = (root / "gallery").string();
  o.scenarios = scenarios.string();
  EXPECT_EQ(app::gallery_command(o), app::kExitBadInput);
  EXPECT_FALSE(fs::exists(root / "gallery"));
  fs::remove_all(root);
}

// A scenarios folder without the scene and the studies: exit 2 before anything runs.
TEST(GalleryCommand, MissingScenesAreBadInputAndNothingIsWritten) {
  const fs::path root = fresh_root("bad");
  fs::create_directories(root / "scenarios");
  app::GalleryOptions o;
  o.out = (root / "gallery").string();
  o.scenarios = (root / "scenarios").string();
  EXPECT_EQ(app::gallery_command(o), app::kExitBadInput);
  EXPECT_FALSE(fs::exists(root / "gallery"));
  fs::remove_all(root);
}

}  // namespace
