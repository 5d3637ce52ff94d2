// Terms of the wall-time estimate (app/estimate.hpp) that a run pays per
// point besides the step.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/estimate.hpp"
#include "block_scene.hpp"
#include "sim/run/simulation.hpp"
#include "sim/scene/scenario.hpp"

namespace {

app::Estimate estimate_with_vtk(const char* vtk) {
  nlohmann::json scene = nlohmann::json::parse(kSlumpingBlock);
  scene["output"]["vtk"] = vtk;
  const sim::Simulation sim(sim::parse_scenario(scene.dump(), "block"));
  return app::estimate_run(sim, 160, 90, {}, 1);
}

// Each VTK state costs no less than the 1.3 us per point measured for a
// 4 M-point state (ASCII .vtu, 244 bytes a point).
TEST(EstimateTerms, VtkStatesCountTheirTimePerPoint) {
  const app::Estimate without = estimate_with_vtk("none");
  const app::Estimate with = estimate_with_vtk("stage-end");
  EXPECT_EQ(without.states, 0);
  ASSERT_EQ(with.states, 2);  // the settling and the slump
  EXPECT_GE(with.wall_seconds - without.wall_seconds, 2 * double(with.points) * 1.3e-6);
}

}  // namespace
