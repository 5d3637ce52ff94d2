// Every shipped scene of up to the 8370-point slopes runs to its end, with the
// same steps as `landslide run` (frame times included: the time loop lands on
// them), and every stage that may stop at rest does so. The finer slopes
// (n28711, n66787) run in `landslide validate --finest`. A change of bits can
// break a chaotic slide that no test runs; this one runs them all.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "sim/run/simulation.hpp"

namespace {

class ShippedScene : public testing::TestWithParam<const char*> {};

TEST_P(ShippedScene, RunsToItsEnd) {
  const std::string file = std::string(LANDSLIDE_SOURCE_DIR "/scenarios/") + GetParam() + ".json";
  const sim::Scenario s = sim::load_scenario(file);
  sim::Simulation simulation(s);
  sim::Observer quiet;
  ASSERT_NO_THROW(simulation.run(quiet)) << file;
  ASSERT_EQ(simulation.results().size(), s.stages.size());
  for (std::size_t k = 0; k < s.stages.size(); ++k) {
    const sim::StageSpec& stage = s.stages[k];
    const sim::StageResult& r = simulation.results()[k];
    if (stage.type == sim::StageType::MaterialChange) continue;
    const sim::StageMetrics& m = r.metrics;
    std::printf("%s %s: %ld steps, %.2f s%s, runout %.3f m, packed %.4f, slope %.1f deg, "
                "energy %+.3f %%\n",
                s.name.c_str(), stage.name.c_str(), r.steps, r.simulated_time,
                r.ended_at_rest ? " (at rest)" : "", m.runout, m.packed_fraction,
                m.deposit_slope_deg, 100 * r.energy.relative_error);
    if (stage.type == sim::StageType::Dynamic && stage.rest.enabled) {
      EXPECT_TRUE(r.ended_at_rest) << stage.name << " still moving at its end";
    }
    EXPECT_TRUE(std::isfinite(r.energy.relative_error));
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene,
                         testing::Values("elastic-column", "paper-slope-phi25", "paper-slope-phi20",
                                         "paper-slope-phi15", "paper-slope-phi10",
                                         "paper-slope-phi20-n1661", "validation/bui2008-column"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-' || c == '/' || c == '.') c = '_';
                           return name;
                         });

}  // namespace
