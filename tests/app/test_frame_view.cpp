// The view a run paints and how much of it is kept in memory: the material's
// extent plus a margin, the image height that follows it, the default
// scene's slope at a readable size, frames spilled to disk as they are
// captured, and VTK states at an interval without any painting.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "output/frames.hpp"
#include "tests/app/tiny_block.hpp"
#include "render/png_io.hpp"
#include "sim/run/simulation.hpp"

namespace {

namespace fs = std::filesystem;

// The tiny block (a 2 m x 1 m soil block and a 1 m x 0.5 m cap on it, in a
// 4 m x 3 m box), both stages painted, at 320 px wide and the view's aspect.
std::string scene_text(const nlohmann::json& output) {
  nlohmann::json scene = nlohmann::json::parse(apptest::kTinyBlock);
  scene["output"] = output;
  return scene.dump();
}

const nlohmann::json kOutput = {{"frame_interval", 0.05},
                                {"fields", {"velocity", "material"}},
                                {"image_size", {320, "auto"}}};
const std::string kScene = scene_text(kOutput);

fs::path scratch(const std::string& what) {
  const fs::path p =
      fs::temp_directory_path() / ("landslide-view-" + what + "-" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

int count_files(const fs::path& dir, const std::string& pattern) {
  if (!fs::is_directory(dir)) return 0;
  const std::regex re(pattern);
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (std::regex_match(e.path().filename().string(), re)) ++n;
  return n;
}

TEST(View, DefaultIsTheMaterialExtentPlusAMargin) {
  const sim::Scenario s = sim::parse_scenario(kScene, "view-block.json");
  const sim::Simulation sim(s);
  app::Extent extent;
  extent.add(app::capture_frame(sim.world(), {app::Field::Velocity}, 0, 0, "settle"));
  // Points sit at the centres of 0.25 m squares filling the bodies; painted
  // squares are kSquareFill times their size, so they reach past the bodies'
  // edges (x 1 .. 3, y 0 .. 1.5) by 0.125 * (kSquareFill - 1).
  const double over = 0.125 * (app::kSquareFill - 1);
  EXPECT_NEAR(extent.x0, 1 - over, 1e-6);
  EXPECT_NEAR(extent.x1, 3 + over, 1e-6);
  EXPECT_NEAR(extent.y0, 0 - over, 1e-6);
  EXPECT_NEAR(extent.y1, 1.5 + over, 1e-6);
  // 5 % of the larger side is 0.1 m, less than one cell: the margin is 0.5 m;
  // below the floor the view stops at the domain's window (0.5 m below y = 0).
  const app::Window v = app::view_window(s, extent);
  EXPECT_NEAR(v.x0, extent.x0 - 0.5, 1e-9);
  EXPECT_NEAR(v.x1, extent.x1 + 0.5, 1e-9);
  EXPECT_NEAR(v.y0, -0.5, 1e-9);
  EXPECT_NEAR(v.y1, extent.y1 + 0.5, 1e-9);
  // Nothing captured: the domain's window.
  const app::Window d = app::view_window(s, app::Extent{});
  const app::Window f = app::frame_window(s);
  EXPECT_EQ(d.x0, f.x0);
  EXPECT_EQ(d.y1, f.y1);
}

TEST(View, TheScenariosViewWins) {
  nlohmann::json output = kOutput;
  output["view"] = {{"min", {-1, -2}}, {"max", {7, 2}}};
  const sim::Scenario s = sim::parse_scenario(scene_text(output), "view-block.json");
  app::Extent extent;
  extent.add(app::capture_frame(sim::Simulation(s).world(), {app::Field::Velocity}, 0, 0, ""));
  const app::Window v = app::view_window(s, extent);
  EXPECT_EQ(v.x0, -1);
  EXPECT_EQ(v.x1, 7);
  EXPECT_EQ(v.y0, -2);
  EXPECT_EQ(v.y1, 2);
}

TEST(View, AutoHeightFollowsTheViewAndFixedSizesStay) {
  sim::Scenario s = sim::parse_scenario(kScene, "view-block.json");
  render::Font font;
  const app::FrameView wide = app::frame_view(s, app::Window{0, 8, 0, 1}, font);
  const app::FrameView tall = app::frame_view(s, app::Window{0, 8, 0, 4}, font);
  EXPECT_EQ(wide.width, 320);
  EXPECT_LT(wide.height, tall.height);
  s.output.image_size = {320, 200};
  const app::FrameView fixed = app::frame_view(s, app::Window{0, 8, 0, 4}, font);
  EXPECT_EQ(fixed.height, 200);
}

// A captured frame goes to disk at once: memory holds one frame however
// many are captured, and painting leaves no spilled file behind.
TEST(FrameRecorder, HoldsOneFrameInMemoryHoweverManyAreCaptured) {
  const fs::path out = scratch("spill");
  const sim::Scenario s = sim::parse_scenario(kScene, "view-block.json");
  const sim::Simulation sim(s);
  app::FrameRecorder recorder(s, out);
  recorder.start();
  const std::size_t one_frame =
      app::capture_frame(sim.world(), recorder.fields(), 0, 0, "settle").bytes();
  std::size_t after_few = 0;
  for (int n = 0; n < 40; ++n) {
    recorder.capture(sim.world(), 0.05 * n, n, n < 20 ? "settle" : "slump");
    if (n == 4) after_few = recorder.bytes_in_memory();
  }
  EXPECT_EQ(recorder.pending(), 40u);
  // The frame and its bytes as written (the frame, its header and checksum),
  // after 5 captures as after 40.
  for (const std::size_t held : {after_few, recorder.bytes_in_memory()}) {
    EXPECT_GE(held, 2 * one_frame);
    EXPECT_LE(held, 2 * one_frame + 4096);
  }
  EXPECT_EQ(count_files(recorder.spill_dir(), R"(\d{6}\.frame)"), 40);

  EXPECT_EQ(recorder.paint_pending(), 80);
  EXPECT_EQ(recorder.bytes_in_memory(), 0u);  // nor while it paints
  EXPECT_FALSE(fs::exists(recorder.spill_dir()));
  const fs::path velocity = recorder.frames_dir(app::Field::Velocity);
  EXPECT_EQ(count_files(velocity, R"(\d{6}\.png)"), 40);
  // The image takes the view's aspect: the frame is as wide as image_size
  // asks and as tall as frame_view() says for the material's view.
  app::Extent extent;
  extent.add(app::capture_frame(sim.world(), recorder.fields(), 0, 0, ""));
  render::Font font;
  const app::FrameView view = app::frame_view(s, app::view_window(s, extent), font);
  const render::Image png = render::read_png((velocity / "000039.png").string());
  EXPECT_EQ(png.width(), 320);
  EXPECT_EQ(png.height(), view.height);
  fs::remove_all(out);
}

// The default scene (./run.sh) at 1280 px wide: the 10 m slope is at least
// 200 px tall in its frames (issue 14).
TEST(View, DefaultSceneShowsTheSlopeAtLeast200PxTall) {
  const sim::Scenario s =
      sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json");
  const sim::Simulation sim(s);
  const app::Frame frame = app::capture_frame(sim.world(), {app::Field::DisplacementX}, 0, 0, "slide");
  app::Extent extent;
  extent.add(frame);
  app::FramePainter painter(s.output.image_size[0], 64);
  const app::FrameView view = app::frame_view(s, app::view_window(s, extent), painter.font());
  const app::FieldStyle style = app::field_style(app::Field::DisplacementX, s);
  painter.paint(app::frame_spec(s, style, s.output.colour_map, app::Range{-1, 20}, frame, view),
                frame, 0);
  const double slope_px = painter.last_layout().map.scale() * 10.0;
  RecordProperty("slope_px", std::to_string(slope_px));
  RecordProperty("image", std::to_string(view.width) + "x" + std::to_string(view.height));
  EXPECT_EQ(view.width, 1280);
  EXPECT_GE(slope_px, 200.0) << "image " << view.width << " x " << view.height;
}

// VTK states at an interval need neither frames nor ffmpeg.
TEST(VtkInterval, StatesAtEveryIntervalWithoutPaintingOrFfmpeg) {
  const fs::path root = scratch("vtk");
  std::ofstream(root / "vtk-only.json")
      << scene_text({{"vtk", "interval"}, {"vtk_interval", 0.05}});
  fs::create_directories(root / "empty-bin");
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", (root / "empty-bin").c_str(), 1);
  app::RunOptions o;
  o.scenario = (root / "vtk-only.json").string();
  o.out_dir = (root / "out").string();
  o.threads = 1;
  const int status = app::run_command(o);
  ::setenv("PATH", saved.c_str(), 1);
  ASSERT_EQ(status, app::kExitOk);
  // settle: 0, 0.05 .. 0.2 s; slump: 0, 0.05, 0.1 s.
  EXPECT_EQ(count_files(root / "out" / "vtk", R"(state-\d{6}\.vtu)"), 5 + 3);
  EXPECT_TRUE(fs::is_regular_file(root / "out" / "vtk" / "points.pvd"));
  EXPECT_FALSE(fs::exists(root / "out" / "frames"));
  fs::remove_all(root);
}

}  // namespace
