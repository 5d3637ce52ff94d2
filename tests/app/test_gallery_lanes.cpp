// The gallery's two lanes (gallery/src/gallery_lanes.hpp) when a run fails:
// the other lane's run stops at its next step and the failed run's error is
// the one reported. Here the second lane's second scene cannot be built (its
// house holds no point) while the first lane's scene has 10 minutes of
// slide to simulate: without the stop it ran to its end, 62 s on 2 threads
// of an AMD EPYC, printed its wall time, and the test failed.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "gallery/src/gallery_lanes.hpp"
#include "sim/scene/scenario.hpp"

namespace {

namespace fs = std::filesystem;

// The committed phi = 20 slope at cell size h, with `slide` s of slide and no rest test.
sim::Scenario slope(double h, double slide) {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20.json");
  s.cell_size = h;
  for (sim::StageSpec& stage : s.stages)
    if (stage.type == sim::StageType::Dynamic) {
      stage.duration = slide;
      stage.rest.enabled = false;
    }
  return s;
}

TEST(GalleryLanes, AFailedRunStopsTheOtherLane) {
  const fs::path out = fs::temp_directory_path() / ("landslide-lanes-" + std::to_string(::getpid()));
  fs::remove_all(out);
  fs::create_directories(out);
  app::gallery::Gallery g(LANDSLIDE_SOURCE_DIR "/scenarios", out, false);
  sim::Scenario finest = slope(0.8, 600), small = slope(1.0, 10), broken = slope(1.0, 10);
  finest.name = "finest";
  small.name = "small";
  broken.name = "broken";
  ASSERT_EQ(broken.bodies.at(1).name, "house");
  broken.bodies[1].polygon = {{36.01, 10.01}, {36.02, 10.01}, {36.02, 10.02}, {36.01, 10.02}};
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  testing::internal::CaptureStderr();
  std::string error;
  try {
    app::gallery::run_in_lanes(g, {{finest}, {small}, {broken}});
  } catch (const sim::ScenarioError& e) {
    error = e.what();
  }
  const std::string log = testing::internal::GetCapturedStderr();
  omp_set_num_threads(threads);
  EXPECT_NE(error.find("no point falls inside it"), std::string::npos) << error;
  EXPECT_NE(log.find("running finest"), std::string::npos) << log;
  EXPECT_NE(log.find("finest: stopped at t = "), std::string::npos) << log;
  EXPECT_EQ(log.find("finest: the run failed"), std::string::npos) << log;
  EXPECT_NE(log.find("small: "), std::string::npos) << log;  // it ran before the broken one
  fs::remove_all(out);
}

}  // namespace
