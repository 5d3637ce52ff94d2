// `landslide gallery` end to end, on coarse copies of the seven committed
// paper-slope scenes (h = 2 m, about 500 points, 4.5 s of slide; phi = 25
// stops after 2 s so the side-by-side animation holds its last frame): every
// figure and both animations are written, the 2x2 figures have four panels,
// the side-by-side animation has a page every 0.5 s of the longest slide
// (when ffprobe is there to count them), and nothing temporary is left. What
// the figures show at the paper's resolutions is looked at in
// gallery/README.md, not here; their physics is what tests/regression/ guards.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "output/frames.hpp"
#include "render/png_io.hpp"
#include "render/subprocess.hpp"
#include "render/video.hpp"

namespace {

namespace fs = std::filesystem;

const char* const kScenes[] = {"paper-slope-phi20.json",        "paper-slope-phi25.json",
                               "paper-slope-phi15.json",        "paper-slope-phi10.json",
                               "paper-slope-phi20-n1661.json",  "paper-slope-phi20-n28711.json",
                               "paper-slope-phi20-n66787.json"};
constexpr double kSlide = 4.5;  // s; the longest slide of the copies
const char* const kSideBySide = "anim-friction-angles-displacement-x";

void write_coarse_copy(const std::string& name, const fs::path& dir) {
  std::ifstream in(fs::path(LANDSLIDE_SOURCE_DIR) / "scenarios" / name);
  nlohmann::json s = nlohmann::json::parse(in);
  s["grid"]["cell_size"] = 2.0;
  for (nlohmann::json& stage : s["stages"])
    if (stage["type"] == "dynamic") {
      stage["duration"] = name == "paper-slope-phi25.json" ? 2.0 : kSlide;
      stage["stop_at_rest"]["min_time"] = 2.0;
    }
  std::ofstream(dir / name) << s.dump(1);
}

// Frames of an mp4 as ffprobe counts them; -1 without ffprobe.
int mp4_frames(const fs::path& mp4) {
  const render::ProcessResult r = render::run_process(
      {"ffprobe", "-v", "error", "-select_streams", "v:0", "-count_packets", "-show_entries",
       "stream=nb_read_packets", "-of", "csv=p=0", mp4.string()});
  if (!r.ok()) return -1;
  return std::stoi(r.output);
}

// One test: ctest runs each test in a process of its own, and the gallery
// is the expensive part.
TEST(Gallery, EveryFigureAndBothAnimationsFromCoarseScenes) {
  if (!render::ffmpeg_available(nullptr))
    GTEST_SKIP() << "ffmpeg (with libx264, gif, palettegen) is not available";
  const fs::path root =
      fs::temp_directory_path() / ("landslide-gallery-test-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "scenarios");
  for (const char* name : kScenes) write_coarse_copy(name, root / "scenarios");
  const fs::path out = root / "gallery";
  app::GalleryOptions o;
  o.out = out.string();
  o.scenarios = (root / "scenarios").string();
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
  }

  EXPECT_FALSE(fs::exists(out / ".work"));
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << e.path();
    EXPECT_EQ(name.find(".part"), std::string::npos) << e.path();
  }
  fs::remove_all(root);
}

// A scene that fails at its first step (a fixed time step 100 times the
// stable one) leaves no state at all: its panels are empty plots captioned
// FAILED, every figure is still written, and the command exits 1.
TEST(Gallery, ARunThatFailsBeforeAnyStateStillGivesEveryFigure) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "ffmpeg is not available";
  const fs::path root =
      fs::temp_directory_path() / ("landslide-gallery-failed-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "scenarios");
  for (const char* name : kScenes) write_coarse_copy(name, root / "scenarios");
  const fs::path phi10 = root / "scenarios" / "paper-slope-phi10.json";
  std::ifstream in(phi10);
  nlohmann::json s = nlohmann::json::parse(in);
  in.close();
  s["time_step"] = {{"fixed", 0.5}};
  std::ofstream(phi10) << s.dump(1);
  app::GalleryOptions o;
  o.out = (root / "gallery").string();
  o.scenarios = (root / "scenarios").string();
  EXPECT_EQ(app::gallery_command(o), app::kExitFailed);
  for (const char* fig : {"fig05-vertical-stress.png", "fig06-horizontal-displacement.png",
                          "fig09-slide.png", "fig10-relative-yield-3s.png",
                          "fig11-resolutions.png", "fig12-friction-angles.png"})
    EXPECT_TRUE(fs::is_regular_file(root / "gallery" / fig)) << fig;
  fs::remove_all(root);
}

// A scenarios folder without the seven scenes: exit 2 before anything runs.
TEST(GalleryCommand, MissingScenesAreBadInputAndNothingIsWritten) {
  const fs::path root =
      fs::temp_directory_path() / ("landslide-gallery-bad-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "scenarios");
  app::GalleryOptions o;
  o.out = (root / "gallery").string();
  o.scenarios = (root / "scenarios").string();
  EXPECT_EQ(app::gallery_command(o), app::kExitBadInput);
  EXPECT_FALSE(fs::exists(root / "gallery"));
  fs::remove_all(root);
}

}  // namespace
