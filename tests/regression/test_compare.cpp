// The number comparison the regression scenes rely on: a failure must say
// which number changed, from what to what, and nothing may slip through.
#include <gtest/gtest.h>

#include "tests/regression/regression.hpp"

namespace {

using nlohmann::json;

json summary(double runout, const json& slope = 12.5) {
  return {{"points", 1661},
          {"stages",
           {{{"name", "gravity"}, {"ended_at_rest", false}},
            {{"name", "slide"},
             {"metrics",
              {{"runout_m", runout},
               {"deposit_slope_deg", slope},
               {"materials", {{{"material", "house"}, {"mean_ux_m", 1.0}}}}}}}}}};
}

TEST(CompareNumbers, ChangeBeyondToleranceNamesThePathAndBothValues) {
  const auto lines = regression::compare_numbers(summary(15.0), summary(15.3), {1e-3, 0});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "stages[1] (slide).metrics.runout_m: expected 15, got 15.3 (relative change "
            "2.00e-02, tolerance 1e-03)");
}

TEST(CompareNumbers, ChangeWithinToleranceIsEqual) {
  EXPECT_TRUE(regression::compare_numbers(summary(15.0), summary(15.01), {1e-3, 0}).empty());
  EXPECT_EQ(regression::compare_numbers(summary(15.0), summary(15.02), {1e-3, 0}).size(), 1u);
}

TEST(CompareNumbers, AbsoluteFloorCoversNumbersNearZero) {
  EXPECT_TRUE(regression::compare_numbers(summary(0.0), summary(-1e-12), {1e-3, 1e-9}).empty());
  EXPECT_EQ(regression::compare_numbers(summary(0.0), summary(1e-6), {1e-3, 1e-9}).size(), 1u);
}

TEST(CompareNumbers, BooleansAndNullsAreExactAndMaterialsAreNamed) {
  json a = summary(15.0), b = summary(15.0, nullptr);
  b["stages"][0]["ended_at_rest"] = true;
  b["stages"][1]["metrics"]["materials"][0]["mean_ux_m"] = 2.0;
  const auto lines = regression::compare_numbers(a, b, {1e-3, 0});
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "stages[0] (gravity).ended_at_rest: expected false, got true");
  EXPECT_EQ(lines[1], "stages[1] (slide).metrics.deposit_slope_deg: expected 12.5, got null");
  EXPECT_EQ(lines[2],
            "stages[1] (slide).metrics.materials[0] (house).mean_ux_m: expected 1, got 2 "
            "(relative change 1.00e+00, tolerance 1e-03)");
}

TEST(CompareNumbers, MissingEntriesFailAndNewOnesAreNotes) {
  json a = summary(15.0), b = summary(15.0);
  a["stages"][1]["metrics"].erase("runout_m");
  b["stages"][1]["metrics"]["front_x_m"] = 70.0;
  const auto lines = regression::compare_numbers(b, a, {1e-3, 0});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "stages[1] (slide).metrics.front_x_m: expected 70, missing");
  EXPECT_EQ(lines[1], "stages[1] (slide).metrics.runout_m: expected 15, missing");
  EXPECT_EQ(regression::new_entries(a, b),
            (std::vector<std::string>{"stages[1] (slide).metrics.front_x_m: 70",
                                      "stages[1] (slide).metrics.runout_m: 15"}));
  EXPECT_TRUE(regression::new_entries(b, a).empty());
}

TEST(StableNumbers, DropsWhatDiffersBetweenIdenticalRuns) {
  json s = {{"wall_time_s", 3.0}, {"threads", 2}, {"version", "v"}, {"scenario_file", "f"},
            {"points", 10},       {"stages", {{{"name", "slide"}, {"wall_time_s", 1.0}, {"steps", 5}}}}};
  const json kept = regression::stable_numbers(s);
  EXPECT_EQ(kept, json({{"points", 10}, {"stages", {{{"name", "slide"}, {"steps", 5}}}}}));
}

}  // namespace
