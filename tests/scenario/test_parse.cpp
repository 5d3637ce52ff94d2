// A valid scenario lands field by field in sim::Scenario.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sim/scene/scenario.hpp"
#include "tests/scenario/example.hpp"

namespace {

using scenario_test::example_json;
using scenario_test::kExample;
using sim::Vec2;

constexpr double kPi = 3.14159265358979323846;
double rad(double degrees) { return degrees * kPi / 180; }

sim::Scenario parse(const nlohmann::json& doc) { return sim::parse_scenario(doc.dump(), "scn.json"); }

TEST(ScenarioParse, TopLevelDomainGridGravityBoundaries) {
  const sim::Scenario s = sim::parse_scenario(kExample, "scn.json");
  EXPECT_EQ(s.name, "full-example");
  EXPECT_EQ(s.description, "Every key of the format.");
  EXPECT_EQ(s.source_path, "scn.json");
  EXPECT_EQ(s.domain_min, (Vec2{0, 0}));
  EXPECT_EQ(s.domain_max, (Vec2{80, 20}));
  EXPECT_EQ(s.cell_size, 1.0);
  EXPECT_EQ(s.padding_cells, 3);
  EXPECT_EQ(s.points_per_cell, 2);
  EXPECT_EQ(s.gravity, (Vec2{0.5, -9.81}));
  EXPECT_EQ(s.boundaries.left.kind, sim::BoundaryKind::Roller);
  EXPECT_EQ(s.boundaries.right.kind, sim::BoundaryKind::Free);
  EXPECT_EQ(s.boundaries.bottom.kind, sim::BoundaryKind::Fixed);
  EXPECT_EQ(s.boundaries.top.kind, sim::BoundaryKind::Free);
}

TEST(ScenarioParse, TransferIsTheFlipUpdateUnlessApicIsAsked) {
  nlohmann::json doc = nlohmann::json::parse(kExample);
  EXPECT_EQ(parse(doc).transfer, sim::TransferScheme::Flip);
  doc["transfer"] = "apic";
  EXPECT_EQ(parse(doc).transfer, sim::TransferScheme::Apic);
  doc["transfer"] = "flip";
  EXPECT_EQ(parse(doc).transfer, sim::TransferScheme::Flip);
}

TEST(ScenarioParse, FrictionWallKeepsItsCoefficient) {
  nlohmann::json doc = nlohmann::json::parse(kExample);
  doc["boundaries"]["bottom"] = {{"friction", 0.35}};
  doc["boundaries"]["right"] = {{"friction", 0}};
  const sim::Scenario s = parse(doc);
  EXPECT_EQ(s.boundaries.bottom.kind, sim::BoundaryKind::Friction);
  EXPECT_EQ(s.boundaries.bottom.friction, 0.35);
  EXPECT_EQ(s.boundaries.right.kind, sim::BoundaryKind::Friction);
  EXPECT_EQ(s.boundaries.right.friction, 0.0);
  EXPECT_EQ(s.boundaries.left.kind, sim::BoundaryKind::Roller);
}

TEST(ScenarioParse, MaterialsInKeyOrderWithAnglesInRadians) {
  const sim::Scenario s = sim::parse_scenario(kExample, "scn.json");
  ASSERT_EQ(s.materials.size(), 3u);
  // nlohmann keeps object keys sorted, so the indices follow the names.
  EXPECT_EQ(s.materials[0].name, "bedrock");
  EXPECT_EQ(s.materials[1].name, "house");
  EXPECT_EQ(s.materials[2].name, "soil");

  const sim::MaterialSpec& rock = s.materials[0];
  EXPECT_EQ(rock.model, sim::MaterialModel::LinearElastic);
  EXPECT_EQ(rock.density, 2600);
  EXPECT_EQ(rock.youngs_modulus, 1e9);
  EXPECT_EQ(rock.poisson_ratio, 0.2);
  EXPECT_EQ(rock.cohesion, 0);
  EXPECT_EQ(rock.friction_angle, 0);

  const sim::MaterialSpec& soil = s.materials[2];
  EXPECT_EQ(soil.model, sim::MaterialModel::MohrCoulomb);
  EXPECT_EQ(soil.density, 2000);
  EXPECT_EQ(soil.youngs_modulus, 2e7);
  EXPECT_EQ(soil.poisson_ratio, 0.25);
  EXPECT_EQ(soil.cohesion, 40000);
  EXPECT_DOUBLE_EQ(soil.friction_angle, rad(30));
  EXPECT_DOUBLE_EQ(soil.dilation_angle, rad(10));
  EXPECT_EQ(soil.critical_density, 1900.0);
}

TEST(ScenarioParse, BodiesAreCounterClockwisePolygons) {
  const sim::Scenario s = sim::parse_scenario(kExample, "scn.json");
  ASSERT_EQ(s.bodies.size(), 3u);
  EXPECT_EQ(s.bodies[0].name, "base");
  EXPECT_EQ(s.bodies[0].material, 0);
  EXPECT_EQ(s.bodies[0].polygon, (std::vector<Vec2>{{0, 0}, {80, 0}, {80, 2}, {0, 2}}));
  // Given clockwise, stored reversed.
  EXPECT_EQ(s.bodies[1].name, "slope");
  EXPECT_EQ(s.bodies[1].material, 2);
  EXPECT_EQ(s.bodies[1].polygon, (std::vector<Vec2>{{52, 2}, {40, 12}, {0, 12}, {0, 2}}));
  EXPECT_EQ(s.bodies[2].name, "house");
  EXPECT_EQ(s.bodies[2].material, 1);
  EXPECT_EQ(s.bodies[2].polygon, (std::vector<Vec2>{{30, 12}, {36, 12}, {36, 16}, {30, 16}}));
}

TEST(ScenarioParse, CounterClockwisePolygonKeptAsGiven) {
  nlohmann::json doc = example_json();
  doc["bodies"][1]["polygon"] = {{52, 2}, {40, 12}, {0, 12}, {0, 2}};
  const sim::Scenario s = parse(doc);
  EXPECT_EQ(s.bodies[1].polygon, (std::vector<Vec2>{{52, 2}, {40, 12}, {0, 12}, {0, 2}}));
}

TEST(ScenarioParse, TimeStep) {
  const sim::Scenario fixed = sim::parse_scenario(kExample, "scn.json");
  EXPECT_EQ(fixed.time_step.mode, sim::TimeStepSpec::Mode::Fixed);
  EXPECT_EQ(fixed.time_step.fixed_dt, 0.001);
  nlohmann::json doc = example_json();
  doc["time_step"] = {{"courant", 0.4}};
  const sim::Scenario courant = parse(doc);
  EXPECT_EQ(courant.time_step.mode, sim::TimeStepSpec::Mode::Courant);
  EXPECT_EQ(courant.time_step.courant, 0.4);
}

TEST(ScenarioParse, StagesAndMaterialChanges) {
  const sim::Scenario s = sim::parse_scenario(kExample, "scn.json");
  ASSERT_EQ(s.stages.size(), 3u);
  const sim::StageSpec& settle = s.stages[0];
  EXPECT_EQ(settle.type, sim::StageType::Gravity);
  EXPECT_EQ(settle.name, "settle");
  EXPECT_EQ(settle.duration, 4);
  EXPECT_EQ(settle.ramp_fraction, 0.5);
  EXPECT_EQ(settle.damping, 0.01);
  EXPECT_TRUE(settle.rest.enabled);
  EXPECT_EQ(settle.rest.kinetic_ratio, 1e-5);
  EXPECT_EQ(settle.rest.min_time, 3);
  EXPECT_TRUE(settle.changes.empty());

  const sim::StageSpec& trigger = s.stages[1];
  EXPECT_EQ(trigger.type, sim::StageType::MaterialChange);
  EXPECT_EQ(trigger.name, "trigger");
  EXPECT_FALSE(trigger.rest.enabled);
  // Applied in key order, angles in radians.
  ASSERT_EQ(trigger.changes.size(), 5u);
  const std::vector<std::string> properties = {"cohesion", "dilation_angle", "friction_angle",
                                               "poisson_ratio", "youngs_modulus"};
  const std::vector<double> values = {0, rad(5), rad(20), 0.3, 1e7};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(trigger.changes[i].material, 2) << i;
    EXPECT_EQ(trigger.changes[i].property, properties[i]) << i;
    EXPECT_DOUBLE_EQ(trigger.changes[i].value, values[i]) << i;
  }
  // The materials keep their initial values; the stage carries the change.
  EXPECT_EQ(s.materials[2].cohesion, 40000);

  const sim::StageSpec& slide = s.stages[2];
  EXPECT_EQ(slide.type, sim::StageType::Dynamic);
  EXPECT_EQ(slide.duration, 30);
  EXPECT_EQ(slide.damping, 0.001);
  EXPECT_EQ(slide.ramp_fraction, 0);
  EXPECT_TRUE(slide.rest.enabled);
  EXPECT_EQ(slide.rest.kinetic_ratio, 1e-4);
  EXPECT_EQ(slide.rest.min_time, 2);
}

TEST(ScenarioParse, OptionalStageKeysDefault) {
  nlohmann::json doc = example_json();
  doc["stages"][0].erase("stop_at_rest");
  doc["stages"][2].erase("stop_at_rest");
  doc["stages"][2].erase("damping");
  const sim::Scenario s = parse(doc);
  EXPECT_FALSE(s.stages[0].rest.enabled);
  EXPECT_FALSE(s.stages[2].rest.enabled);
  EXPECT_EQ(s.stages[2].damping, 0);
}

TEST(ScenarioParse, OutputGiven) {
  const sim::Scenario s = sim::parse_scenario(kExample, "scn.json");
  EXPECT_EQ(s.output.frame_interval, 0.5);
  EXPECT_EQ(s.output.frame_stages, (std::vector<std::string>{"slide"}));
  EXPECT_EQ(s.output.fields,
            (std::vector<std::string>{"displacement-x", "relative-yield", "material"}));
  EXPECT_EQ(s.output.colour_map, "jet");
  EXPECT_EQ(s.output.displacement_reference, "stage-start");
  EXPECT_EQ(s.output.vtk, "frames");
  EXPECT_EQ(s.output.image_size, (std::array<int, 2>{640, 360}));
}

TEST(ScenarioParse, OutputDefaultsWhenEmpty) {
  nlohmann::json doc = example_json();
  doc["output"] = nlohmann::json::object();
  doc.erase("description");
  const sim::Scenario s = parse(doc);
  EXPECT_EQ(s.description, "");
  EXPECT_EQ(s.output.frame_interval, 0);
  // Every gravity and dynamic stage, in order; never a material change.
  EXPECT_EQ(s.output.frame_stages, (std::vector<std::string>{"settle", "slide"}));
  EXPECT_EQ(s.output.fields, (std::vector<std::string>{"displacement-x"}));
  EXPECT_EQ(s.output.colour_map, "viridis");
  EXPECT_EQ(s.output.displacement_reference, "initial");
  EXPECT_EQ(s.output.vtk, "none");
  EXPECT_EQ(s.output.vtk_interval, 0);
  // The height follows the view: "auto".
  EXPECT_EQ(s.output.image_size, (std::array<int, 2>{1280, sim::kAutoHeight}));
  EXPECT_FALSE(s.output.has_view);
}

TEST(ScenarioParse, ViewAutoHeightAndVtkInterval) {
  nlohmann::json doc = example_json();
  doc["output"]["view"] = {{"min", {5, -1}}, {"max", {45.5, 16}}};
  doc["output"]["image_size"] = {960, "auto"};
  doc["output"]["vtk"] = "interval";
  doc["output"]["vtk_interval"] = 0.25;
  const sim::Scenario s = parse(doc);
  EXPECT_TRUE(s.output.has_view);
  EXPECT_EQ(s.output.view_min, (sim::Vec2{5, -1}));
  EXPECT_EQ(s.output.view_max, (sim::Vec2{45.5, 16}));
  EXPECT_EQ(s.output.image_size, (std::array<int, 2>{960, sim::kAutoHeight}));
  EXPECT_EQ(s.output.vtk, "interval");
  EXPECT_EQ(s.output.vtk_interval, 0.25);
}

TEST(ScenarioParse, SameMaterialBodiesMayOverlap) {
  nlohmann::json doc = example_json();
  doc["bodies"].push_back({{"name", "mound"}, {"material", "soil"},
                           {"rectangle", {{"min", {10, 8}}, {"max", {20, 14}}}}});
  const sim::Scenario s = parse(doc);
  EXPECT_EQ(s.bodies.size(), 4u);
  EXPECT_EQ(s.bodies[3].material, 2);
}

TEST(ScenarioParse, HouseTouchingThePaperSlopeIsAccepted) {
  const sim::Scenario s = sim::load_scenario(std::string(LANDSLIDE_SOURCE_DIR) +
                                             "/scenarios/paper-slope-phi20.json");
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_NE(s.bodies[0].material, s.bodies[1].material);
  EXPECT_EQ(s.materials[s.bodies[1].material].name, "house");
  // Touching at a vertex only is accepted as well.
  nlohmann::json doc = example_json();
  doc["bodies"][2]["rectangle"] = {{"min", {52, 0.5}}, {"max", {60, 2}}};
  doc["bodies"][0]["rectangle"] = {{"min", {0, 0}}, {"max", {52, 0.5}}};
  EXPECT_NO_THROW(parse(doc));
}

TEST(ScenarioParse, DilationMayEqualFriction) {
  for (int degrees = 1; degrees < 90; ++degrees) {
    for (double frac : {0.0, 0.1, 0.25, 0.3, 0.7}) {
      const double angle = degrees + frac;
      nlohmann::json doc = example_json();
      doc["materials"]["soil"]["friction_angle"] = angle;
      doc["materials"]["soil"]["dilation_angle"] = angle;
      doc["stages"][1]["set"] = {{"friction_angle", angle}, {"dilation_angle", angle}};
      EXPECT_NO_THROW(parse(doc)) << angle;
    }
  }
}

TEST(ScenarioParse, LoadScenarioReadsEveryCommittedScene) {
  for (const char* name : {"elastic-column", "paper-slope-phi10", "paper-slope-phi15",
                           "paper-slope-phi20", "paper-slope-phi25", "paper-slope-phi20-n1661",
                           "paper-slope-phi20-n28711", "paper-slope-phi20-n66787"}) {
    const std::string path = std::string(LANDSLIDE_SOURCE_DIR) + "/scenarios/" + name + ".json";
    const sim::Scenario s = sim::load_scenario(path);
    EXPECT_EQ(s.name, name);
    EXPECT_EQ(s.source_path, path);
  }
}

TEST(ScenarioParse, ReadmeExampleIsValid) {
  // The complete example in scenarios/README.md is the first json block.
  std::ifstream in(LANDSLIDE_SOURCE_DIR "/scenarios/README.md");
  std::stringstream readme;
  readme << in.rdbuf();
  const std::string text = readme.str();
  const std::size_t begin = text.find("```json\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = text.find("```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  const sim::Scenario s = sim::parse_scenario(text.substr(begin + 8, end - begin - 8), "README.md");
  EXPECT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.bodies.size(), 3u);
  EXPECT_EQ(s.stages.size(), 3u);
}

TEST(ScenarioParse, RoundOffOverlapOfDifferentMaterialsCountsAsTouching) {
  // The house computed 1e-12 m into the slope's top is still standing on it;
  // 1e-6 m into it is an overlap (the domain is 80 m: round-off is 8e-8 m).
  nlohmann::json doc = example_json();
  doc["bodies"][2]["rectangle"]["min"] = {30, 12 - 1e-12};
  EXPECT_NO_THROW(parse(doc));
  doc["bodies"][2]["rectangle"]["min"] = {30, 12 - 1e-6};
  EXPECT_THROW(parse(doc), sim::ScenarioError);
}

TEST(ScenarioParse, OutputRanges) {
  nlohmann::json doc = example_json();
  doc["output"]["ranges"] = {{"stress-yy", {-2e5, 0}}, {"velocity", {0, 3.5}}};
  const sim::Scenario s = parse(doc);
  ASSERT_EQ(s.output.ranges.size(), 2u);
  EXPECT_EQ(s.output.ranges.at("stress-yy"), (std::array<double, 2>{-2e5, 0}));
  EXPECT_EQ(s.output.ranges.at("velocity"), (std::array<double, 2>{0, 3.5}));
  EXPECT_TRUE(sim::parse_scenario(kExample, "scn.json").output.ranges.empty());
}

}  // namespace
