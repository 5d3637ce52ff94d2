// A random field in a material-change stage's "set" (scenarios/README.md,
// "Random fields"): read into RandomFieldSpec in SI units, and every value the
// generator could not use refused before step 0, naming the JSON path.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "sim/scene/scenario.hpp"
#include "tests/scenario/example.hpp"

namespace {

using Json = nlohmann::json;
constexpr double kDeg = 3.14159265358979323846 / 180;

// The example's trigger (stages[1]) with friction_angle drawn from a field.
Json with_friction_field() {
  Json d = scenario_test::example_json();
  d["stages"][1]["set"]["friction_angle"] = {
      {"random_field",
       {{"distribution", "truncated-normal"}, {"mean", 20}, {"cov", 0.15}, {"lower", 10},
        {"upper", 30}, {"scale_of_fluctuation", {20, 2}}, {"seed", 7}}}};
  return d;
}

Json& field_of(Json& d) { return d["stages"][1]["set"]["friction_angle"]["random_field"]; }

TEST(RandomFieldKeys, TruncatedNormalFrictionAngleIsReadInRadians) {
  const sim::Scenario s = sim::parse_scenario(with_friction_field().dump(), "scn.json");
  const sim::MaterialChange* field = nullptr;
  for (const sim::MaterialChange& c : s.stages[1].changes)
    if (c.property == "friction_angle") field = &c;
  ASSERT_NE(field, nullptr);
  ASSERT_TRUE(field->has_field);
  EXPECT_EQ(field->field.distribution, sim::RandomFieldSpec::Distribution::TruncatedNormal);
  EXPECT_DOUBLE_EQ(field->field.mean, 20 * kDeg);
  EXPECT_DOUBLE_EQ(field->value, 20 * kDeg);  // the material's spec holds the mean
  EXPECT_DOUBLE_EQ(field->field.lower, 10 * kDeg);
  EXPECT_DOUBLE_EQ(field->field.upper, 30 * kDeg);
  EXPECT_EQ(field->field.cov, 0.15);
  EXPECT_EQ(field->field.theta_x, 20);
  EXPECT_EQ(field->field.theta_y, 2);
  EXPECT_EQ(field->field.seed, 7u);
  for (const sim::MaterialChange& c : s.stages[1].changes) {
    if (c.property != "friction_angle") {
      EXPECT_FALSE(c.has_field) << c.property;
    }
  }
}

TEST(RandomFieldKeys, LogNormalCohesionIsReadInPascals) {
  Json d = scenario_test::example_json();
  d["stages"][1]["set"]["cohesion"] = {
      {"random_field",
       {{"distribution", "lognormal"}, {"mean", 5000}, {"cov", 0.3},
        {"scale_of_fluctuation", {10, 1}}, {"seed", 9007199254740991ULL}}}};
  const sim::Scenario s = sim::parse_scenario(d.dump(), "scn.json");
  for (const sim::MaterialChange& c : s.stages[1].changes)
    if (c.property == "cohesion") {
      ASSERT_TRUE(c.has_field);
      EXPECT_EQ(c.field.distribution, sim::RandomFieldSpec::Distribution::LogNormal);
      EXPECT_EQ(c.field.mean, 5000);
      EXPECT_EQ(c.field.seed, 9007199254740991ULL);
    }
}

struct BadField {
  const char* name;
  std::function<void(Json&)> mutate;
  std::string expected;
};

const std::vector<BadField>& bad_fields() {
  const std::string at = "stages[1].set.friction_angle.random_field";
  static const std::vector<BadField> cases = {
      {"LogNormalFriction", [](Json& d) { field_of(d)["distribution"] = "lognormal"; },
       at + ".distribution = \"lognormal\": expected \"truncated-normal\" for a friction angle"},
      {"UnknownDistribution", [](Json& d) { field_of(d)["distribution"] = "uniform"; },
       at + ".distribution = \"uniform\": expected one of \"lognormal\", \"truncated-normal\""},
      {"LowerBelowDilation", [](Json& d) { field_of(d)["lower"] = 4; },
       at + ".lower = 4: expected a number in [5, 90)"},
      {"UpperAt90", [](Json& d) { field_of(d)["upper"] = 90; },
       at + ".upper = 90: expected a number in (10, 90)"},
      {"BoundsOutOfReach", [](Json& d) { field_of(d)["lower"] = 80, field_of(d)["upper"] = 89; },
       at + ".upper = 89: expected bounds [80, 89] holding at least 1e-9 of the parent normal"},
      {"ZeroCov", [](Json& d) { field_of(d)["cov"] = 0; },
       at + ".cov = 0: expected a number in (0, 10]"},
      {"MissingSeed", [](Json& d) { field_of(d).erase("seed"); }, at + ".seed: missing"},
      {"FractionalSeed", [](Json& d) { field_of(d)["seed"] = 1.5; },
       at + ".seed = 1.5: expected a whole number in [0, 2^53 - 1]"},
      {"NegativeSeed", [](Json& d) { field_of(d)["seed"] = -1; },
       at + ".seed = -1: expected a whole number in [0, 2^53 - 1]"},
      {"ThetaNotAPair", [](Json& d) { field_of(d)["scale_of_fluctuation"] = 5; },
       at + ".scale_of_fluctuation = 5: expected [theta_x, theta_y] in m"},
      {"ThetaZero", [](Json& d) { field_of(d)["scale_of_fluctuation"] = {0, 2}; },
       at + ".scale_of_fluctuation[0] = 0: expected a number in (0, 500000]"},
      {"UnknownFieldKey", [](Json& d) { field_of(d)["correlation"] = "markov"; },
       at + ".correlation: unknown key for a truncated-normal field"},
      {"LowerOnALogNormal",
       [](Json& d) {
         d["stages"][1]["set"]["cohesion"] = {
             {"random_field",
              {{"distribution", "lognormal"}, {"mean", 1000}, {"cov", 0.3}, {"lower", 0},
               {"scale_of_fluctuation", {10, 1}}, {"seed", 1}}}};
       },
       "stages[1].set.cohesion.random_field.lower: unknown key for a lognormal field"},
      {"NotWrapped",
       [](Json& d) { d["stages"][1]["set"]["friction_angle"] = {{"mean", 20}}; },
       "stages[1].set.friction_angle.mean: unknown key (allowed: random_field)"},
      {"FieldOfAnElasticMaterial",
       [](Json& d) {
         d["stages"][1]["material"] = "house";
         d["stages"][1]["set"] = {{"friction_angle", {{"random_field", Json::object()}}}};
       },
       "stages[1].set.friction_angle: unknown key for linear-elastic material \"house\""},
      {"FieldOfYoungsModulus",
       [](Json& d) {
         d["stages"][1]["set"]["youngs_modulus"] = {{"random_field", Json::object()}};
       },
       "stages[1].set.youngs_modulus = {\"random_field\":{}}: expected a number in (0, inf)"},
      {"FieldInTheMaterials",
       [](Json& d) { d["materials"]["soil"]["cohesion"] = {{"random_field", Json::object()}}; },
       "materials.soil.cohesion = {\"random_field\":{}}: expected a number (a random field of it "
       "is set by a material-change stage's \"set\""},
      {"DilationAboveTheFieldsLowerBound",
       [](Json& d) {
         d["stages"].insert(d["stages"].begin() + 2, Json{{"name", "dilate"},
                                                          {"type", "material-change"},
                                                          {"material", "soil"},
                                                          {"set", {{"dilation_angle", 15}}}});
       },
       "leaves materials.soil with dilation_angle 15 > friction_angle 10 (its field's lower "
       "bound)"},
  };
  return cases;
}

class RandomFieldErrors : public ::testing::TestWithParam<std::size_t> {};

TEST_P(RandomFieldErrors, NameThePathAndWhatIsAllowed) {
  const BadField& c = bad_fields()[GetParam()];
  Json d = with_friction_field();
  d["stages"][1]["set"]["dilation_angle"] = 5;
  c.mutate(d);
  try {
    sim::parse_scenario(d.dump(), "scn.json");
    FAIL() << c.name << ": accepted";
  } catch (const sim::ScenarioError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("scn.json: ", 0), 0u) << what;
    EXPECT_NE(what.find(c.expected), std::string::npos)
        << "expected \"" << c.expected << "\" in\n" << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Table, RandomFieldErrors,
                         ::testing::Range<std::size_t>(0, bad_fields().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           return std::string(bad_fields()[info.param].name);
                         });

}  // namespace
