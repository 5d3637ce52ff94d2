// Bad scenarios, each made by changing one thing in the valid example: the
// message names the file, the JSON path and what was expected.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "sim/scene/scenario.hpp"
#include "tests/scenario/example.hpp"

namespace {

using Json = nlohmann::json;

struct BadCase {
  const char* name;
  std::function<void(Json&)> mutate;
  std::vector<std::string> expected;  // substrings of what(), after the label
};

// Sets a placeholder number and swaps it for text JSON cannot hold as a double.
constexpr const char* kPlaceholder = "0.123456789";

const std::vector<BadCase>& bad_cases() {
  static const std::vector<BadCase> cases = {
      {"StringForNumber", [](Json& d) { d["grid"]["cell_size"] = "1.0"; },
       {"grid.cell_size = \"1.0\": expected a number in (0, inf)"}},
      {"PoissonRatio07", [](Json& d) { d["materials"]["soil"]["poisson_ratio"] = 0.7; },
       {"materials.soil.poisson_ratio = 0.7: expected a number in [0, 0.5)"}},
      {"PoissonRatio05", [](Json& d) { d["materials"]["house"]["poisson_ratio"] = 0.5; },
       {"materials.house.poisson_ratio = 0.5: expected a number in [0, 0.5)"}},
      {"NegativeDensity", [](Json& d) { d["materials"]["soil"]["density"] = -2000; },
       {"materials.soil.density = -2000: expected a number in (0, inf)"}},
      {"ZeroCellSize", [](Json& d) { d["grid"]["cell_size"] = 0; },
       {"grid.cell_size = 0: expected a number in (0, inf)"}},
      {"FractionalPadding", [](Json& d) { d["grid"]["padding_cells"] = 2.5; },
       {"grid.padding_cells = 2.5: expected an integer in [2, 100]"}},
      {"PaddingOne", [](Json& d) { d["grid"]["padding_cells"] = 1; },
       {"grid.padding_cells = 1: expected an integer in [2, 100]"}},
      {"NinePointsPerCell", [](Json& d) { d["grid"]["points_per_cell"] = 9; },
       {"grid.points_per_cell = 9: expected an integer in [1, 8]"}},
      {"UnknownTopLevelKey", [](Json& d) { d["colour"] = "red"; },
       {"colour: unknown key (allowed: name, description, domain, grid, gravity, boundaries, "
        "materials, bodies, time_step, transfer, stages, output)"}},
      {"UnknownTransfer", [](Json& d) { d["transfer"] = "pic"; },
       {"transfer = \"pic\": expected one of \"flip\", \"apic\""}},
      {"UnknownMaterialKey", [](Json& d) { d["materials"]["house"]["cohesion"] = 10; },
       {"materials.house.cohesion: unknown key for a linear-elastic material (allowed: model, "
        "density, youngs_modulus, poisson_ratio)"}},
      {"UnknownBodyKey", [](Json& d) { d["bodies"][1]["colour"] = "brown"; },
       {"bodies[1].colour: unknown key (allowed: name, material, rectangle, polygon)"}},
      {"UnknownStageKey", [](Json& d) { d["stages"][2]["ramp_fraction"] = 0.5; },
       {"stages[2].ramp_fraction: unknown key for a dynamic stage (allowed: name, type, duration, "
        "damping, stop_at_rest)"}},
      {"UnknownOutputKey", [](Json& d) { d["output"]["format"] = "png"; },
       {"output.format: unknown key (allowed: frame_interval, frame_stages, fields, colour_map, "
        "ranges, displacement_reference, vtk, vtk_interval, image_size, view)"}},
      {"ViewMaxBelowMin",
       [](Json& d) { d["output"]["view"] = {{"min", {10, 0}}, {"max", {5, 20}}}; },
       {"output.view.max = [5,20]: expected max > min in x and y"}},
      {"ViewMissingMax", [](Json& d) { d["output"]["view"] = {{"min", {10, 0}}}; },
       {"output.view.max: missing (required)"}},
      {"ViewUnknownKey",
       [](Json& d) { d["output"]["view"] = {{"min", {0, 0}}, {"max", {5, 5}}, {"zoom", 2}}; },
       {"output.view.zoom: unknown key (allowed: min, max)"}},
      {"ViewNotAPoint",
       [](Json& d) { d["output"]["view"] = {{"min", {0, 0}}, {"max", {5}}}; },
       {"output.view.max = [5]: expected"}},
      {"ImageHeightWord", [](Json& d) { d["output"]["image_size"] = {1280, "tall"}; },
       {"output.image_size[1] = \"tall\": expected an integer in [64, 8192] or \"auto\""}},
      {"ImageWidthAuto", [](Json& d) { d["output"]["image_size"] = {"auto", 720}; },
       {"output.image_size[0] = \"auto\": expected an integer in [64, 8192]"}},
      {"ImageTooSmall", [](Json& d) { d["output"]["image_size"] = {1280, 32}; },
       {"output.image_size[1] = 32: expected an integer in [64, 8192] or \"auto\""}},
      {"ImageOneSide", [](Json& d) { d["output"]["image_size"] = {1280}; },
       {"output.image_size = [1280]: expected [width, height] or [width, \"auto\"] in pixels"}},
      {"VtkIntervalMissing", [](Json& d) { d["output"]["vtk"] = "interval"; },
       {"output.vtk_interval: missing (required when vtk is \"interval\")"}},
      {"VtkIntervalZero",
       [](Json& d) {
         d["output"]["vtk"] = "interval";
         d["output"]["vtk_interval"] = 0;
       },
       {"output.vtk_interval = 0: expected a number in (0, inf)"}},
      {"VtkIntervalTooSmall",
       [](Json& d) {
         d["output"]["vtk"] = "interval";
         d["output"]["vtk_interval"] = 1e-5;
       },
       {"output.vtk_interval = 1e-05: expected at least the longest stage / 100000 s"}},
      {"VtkIntervalWithoutInterval",
       [](Json& d) {
         d["output"]["vtk"] = "stage-end";
         d["output"]["vtk_interval"] = 0.5;
       },
       {"output.vtk_interval = 0.5: expected no vtk_interval unless vtk is \"interval\""}},
      {"RangeLowNotBelowHigh", [](Json& d) { d["output"]["ranges"] = {{"velocity", {2, 2}}}; },
       {"output.ranges.velocity = [2,2]: expected [low, high], low < high"}},
      {"RangeOfCategoricalField",
       [](Json& d) { d["output"]["ranges"] = {{"material", {0, 1}}}; },
       {"output.ranges.material: unknown key (allowed: displacement-x, displacement-y, "
        "relative-yield, stress-yy, velocity, cohesion, friction-angle)"}},
      {"RangeNotANumber", [](Json& d) { d["output"]["ranges"] = {{"stress-yy", {"-1e5", 0}}}; },
       {"output.ranges.stress-yy[0] = \"-1e5\": expected a finite number"}},
      {"GravityOfBooleans", [](Json& d) { d["gravity"] = {true, -9.81}; },
       {"gravity[0] = true: expected a finite number"}},
      {"UnknownBoundary", [](Json& d) { d["boundaries"]["left"] = "slip"; },
       {"boundaries.left = \"slip\": expected one of \"fixed\", \"roller\", \"free\", or "
        "{\"friction\": mu} with mu >= 0"}},
      {"NegativeWallFriction", [](Json& d) { d["boundaries"]["bottom"] = {{"friction", -0.1}}; },
       {"boundaries.bottom.friction = -0.1: expected a number in [0, inf)"}},
      {"WallFrictionNotANumber",
       [](Json& d) { d["boundaries"]["bottom"] = {{"friction", "0.4"}}; },
       {"boundaries.bottom.friction = \"0.4\": expected a number in [0, inf)"}},
      {"WallFrictionMissing", [](Json& d) { d["boundaries"]["top"] = Json::object(); },
       {"boundaries.top.friction: missing (the Coulomb coefficient mu)"}},
      {"UnknownWallKey", [](Json& d) { d["boundaries"]["left"] = {{"friction", 0.3}, {"mu", 1}}; },
       {"boundaries.left.mu: unknown key for a friction wall (allowed: friction)"}},
      {"WallOfANumber", [](Json& d) { d["boundaries"]["right"] = 0.3; },
       {"boundaries.right = 0.3: expected one of \"fixed\", \"roller\", \"free\", or "
        "{\"friction\": mu} with mu >= 0"}},
      {"OverlapOfDifferentMaterials",
       [](Json& d) { d["bodies"][2]["rectangle"]["min"] = {30, 10}; },
       {"bodies[2] (house) overlaps bodies[1] (slope) of a different material"}},
      {"BowTiePolygon",
       [](Json& d) { d["bodies"][1]["polygon"] = {{0, 2}, {52, 12}, {52, 2}, {0, 12}}; },
       {"bodies[1].polygon = [[0,2],[52,12],[52,2],[0,12]]: expected a simple polygon (edges 0-1 "
        "and 2-3 cross or touch"}},
      {"ClosedPolygon",
       [](Json& d) { d["bodies"][1]["polygon"] = {{0, 2}, {0, 12}, {40, 12}, {52, 2}, {0, 2}}; },
       {"bodies[1].polygon = [[0,2],[0,12],[40,12],[52,2],[0,2]]: expected a simple polygon (the "
        "last vertex repeats the first; it is closed already)"}},
      {"RepeatedVertex",
       [](Json& d) { d["bodies"][1]["polygon"] = {{0, 2}, {0, 12}, {0, 12}, {40, 12}, {52, 2}}; },
       {"expected a simple polygon (vertices 1-2 are the same point)"}},
      {"BodyOutsideDomain", [](Json& d) { d["bodies"][2]["rectangle"]["max"] = {36, 25}; },
       {"bodies[2].rectangle.max = [36,25]: expected a point inside the domain [0, 80] x [0, 20]"}},
      {"PolygonVertexOutsideDomain",
       [](Json& d) { d["bodies"][1]["polygon"][3] = {52, -0.5}; },
       {"bodies[1].polygon[3] = [52,-0.5]: expected a point inside the domain [0, 80] x [0, 20]"}},
      {"RectangleMaxBelowMin", [](Json& d) { d["bodies"][2]["rectangle"]["max"] = {36, 11}; },
       {"bodies[2].rectangle.max = [36,11]: expected max > min in x and y"}},
      {"GravityWithoutDuration", [](Json& d) { d["stages"][0].erase("duration"); },
       {"stages[0].duration: missing (required for a gravity stage)"}},
      {"GravityWithoutRampFraction", [](Json& d) { d["stages"][0].erase("ramp_fraction"); },
       {"stages[0].ramp_fraction: missing (required for a gravity stage)"}},
      {"GravityWithoutDamping", [](Json& d) { d["stages"][0].erase("damping"); },
       {"stages[0].damping: missing (required for a gravity stage)"}},
      {"ChangeWithoutMaterial", [](Json& d) { d["stages"][1].erase("material"); },
       {"stages[1].material: missing (required for a material-change stage)"}},
      {"ChangeWithoutSet", [](Json& d) { d["stages"][1].erase("set"); },
       {"stages[1].set: missing (required for a material-change stage)"}},
      {"ChangeOfUnknownProperty", [](Json& d) { d["stages"][1]["set"]["density"] = 1000; },
       {"stages[1].set.density: unknown key for mohr-coulomb material \"soil\" (allowed: cohesion, "
        "friction_angle, dilation_angle, youngs_modulus, poisson_ratio)"}},
      {"ChangeOfCohesionOfElasticMaterial",
       [](Json& d) {
         d["stages"][1]["material"] = "house";
         d["stages"][1]["set"] = {{"cohesion", 0}};
       },
       {"stages[1].set.cohesion: unknown key for linear-elastic material \"house\" (allowed: "
        "youngs_modulus, poisson_ratio)"}},
      {"UnknownStageType", [](Json& d) { d["stages"][2]["type"] = "quake"; },
       {"stages[2].type = \"quake\": expected one of \"gravity\", \"material-change\", "
        "\"dynamic\""}},
      {"UnknownMaterialInBody", [](Json& d) { d["bodies"][1]["material"] = "clay"; },
       {"bodies[1].material = \"clay\": expected the name of a material in materials "
        "(defined: \"bedrock\", \"house\", \"soil\")"}},
      {"UnknownMaterialInStage", [](Json& d) { d["stages"][1]["material"] = "clay"; },
       {"stages[1].material = \"clay\": expected the name of a material in materials "
        "(defined: \"bedrock\", \"house\", \"soil\")"}},
      {"DuplicateStageName", [](Json& d) { d["stages"][2]["name"] = "settle"; },
       {"stages[2].name = \"settle\": expected a name no other stage has (stages[0] has it)"}},
      {"DuplicateBodyName", [](Json& d) { d["bodies"][2]["name"] = "slope"; },
       {"bodies[2].name = \"slope\": expected a name no other body has (bodies[1] has it)"}},
      {"CriticalDensityMissing", [](Json& d) { d["materials"]["soil"].erase("critical_density"); },
       {"materials.soil.critical_density: missing (required for a mohr-coulomb material)"}},
      {"CriticalDensityAboveDensity",
       [](Json& d) { d["materials"]["soil"]["critical_density"] = 2100; },
       {"materials.soil.critical_density = 2100: expected a number in (0, 2000]"}},
      {"CriticalDensityZero", [](Json& d) { d["materials"]["soil"]["critical_density"] = 0; },
       {"materials.soil.critical_density = 0: expected a number in (0, 2000]"}},
      {"CriticalDensityOfElasticMaterial",
       [](Json& d) { d["materials"]["house"]["critical_density"] = 450; },
       {"materials.house.critical_density: unknown key for a linear-elastic material (allowed: "
        "model, density, youngs_modulus, poisson_ratio)"}},
      {"DilationAboveFriction", [](Json& d) { d["materials"]["soil"]["dilation_angle"] = 35; },
       {"materials.soil.dilation_angle = 35: expected a number in [0, 30]"}},
      {"DilationAboveFrictionAfterChange",
       [](Json& d) { d["stages"][1]["set"]["friction_angle"] = 3; },
       {"stages[1] (trigger) leaves materials.soil with dilation_angle 5 > friction_angle 3: "
        "expected dilation_angle <= friction_angle"}},
      {"CourantAndFixed", [](Json& d) { d["time_step"]["courant"] = 0.5; },
       {"time_step = ", "expected exactly one of \"courant\" or \"fixed\""}},
      {"CourantTooLarge", [](Json& d) { d["time_step"] = {{"courant", 0.8}}; },
       {"time_step.courant = 0.8: expected a number in (0, 0.5]"}},
      {"InfiniteNumber", [](Json& d) { d["time_step"] = {{"courant", 0.123456789}}; },
       {"time_step.courant = 1e999: expected a finite number"}},
      {"UnknownField",
       [](Json& d) { d["output"]["fields"] = {"displacement-x", "pressure"}; },
       {"output.fields[1] = \"pressure\": expected one of \"displacement-x\""}},
      {"FrameStageMissing", [](Json& d) { d["output"]["frame_stages"] = {"landslide"}; },
       {"output.frame_stages[0] = \"landslide\": expected the name of a gravity or dynamic "
        "stage"}},
      {"FrameStageIsMaterialChange", [](Json& d) { d["output"]["frame_stages"] = {"trigger"}; },
       {"output.frame_stages[0] = \"trigger\": expected the name of a gravity or dynamic stage"}},
      {"FrameStageTwice", [](Json& d) { d["output"]["frame_stages"] = {"slide", "settle", "slide"}; },
       {"output.frame_stages[2] = \"slide\": expected each stage once"}},
      {"OverPointBudget",
       [](Json& d) {
         d["grid"]["cell_size"] = 0.01;
         d["grid"]["points_per_cell"] = 4;
       },
       {"grid = ", "expected at most 37000000 points (body area / (cell_size / points_per_cell)^2); "
                   "the bodies need about 103040000"}},
      {"HugeCoordinatesOverPointBudget",
       [](Json& d) {
         // About 1.6e9 points, though the area in square metres overflows.
         d["domain"]["max"] = {1e200, 1e200};
         d["grid"] = {{"cell_size", 2e196}, {"padding_cells", 2}, {"points_per_cell", 8}};
         d["bodies"] = {{{"name", "all"}, {"material", "soil"},
                         {"rectangle", {{"min", {0, 0}}, {"max", {1e200, 1e200}}}}}};
       },
       {"grid = ", "expected at most 37000000 points"}},
      {"OverGridBudget", [](Json& d) { d["grid"]["cell_size"] = 0.001; },
       {"grid.cell_size = 0.001: expected a grid of at most 50000000 nodes; this domain, cell size "
        "and padding need about 1600"}},
      {"MinTimeAfterDuration", [](Json& d) { d["stages"][2]["stop_at_rest"]["min_time"] = 31; },
       {"stages[2].stop_at_rest.min_time = 31: expected a number in [0, 30]"}},
      {"MaterialNotAnObject", [](Json& d) { d["materials"]["soil"] = "sand"; },
       {"materials.soil = \"sand\": expected an object"}},
  };
  return cases;
}

class ScenarioErrors : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ScenarioErrors, NameFilePathAndExpectation) {
  const BadCase& c = bad_cases()[GetParam()];
  Json doc = scenario_test::example_json();
  c.mutate(doc);
  std::string text = doc.dump();
  if (std::string(c.name) == "InfiniteNumber")
    text.replace(text.find(kPlaceholder), std::string(kPlaceholder).size(), "1e999");
  try {
    sim::parse_scenario(text, "scn.json");
    FAIL() << c.name << ": accepted";
  } catch (const sim::ScenarioError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("scn.json: ", 0), 0u) << what;
    for (const std::string& part : c.expected)
      EXPECT_NE(what.find(part), std::string::npos) << "expected \"" << part << "\" in\n" << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Table, ScenarioErrors, ::testing::Range<std::size_t>(0, bad_cases().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           return std::string(bad_cases()[info.param].name);
                         });

// Throws ScenarioError; returns its message.
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const sim::ScenarioError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ScenarioError";
  return "";
}

TEST(ScenarioErrorsText, InvalidJsonSyntax) {
  const std::string what =
      message_of([] { sim::parse_scenario("{\"name\": \"x\",}", "scn.json"); });
  EXPECT_EQ(what, "scn.json: invalid JSON at line 1, column 14: syntax error while parsing object "
                  "key - unexpected '}'; expected string literal");
  // Lines and columns count from 1, as editors do.
  const std::string third = message_of([] {
    sim::parse_scenario("{\n  \"name\": \"x\",\n  \"grid\" 2\n}", "scn.json");
  });
  EXPECT_EQ(third.rfind("scn.json: invalid JSON at line 3, column 10: ", 0), 0u) << third;
}

TEST(ScenarioErrorsText, OverflowingNumberNamesItsPath) {
  // nlohmann refuses numbers beyond a double; the reader says where they are.
  std::string text = scenario_test::example_json().dump();
  const std::string vertex = "[40,12]";
  text.replace(text.find(vertex), vertex.size(), "[40,-1e999]");
  EXPECT_EQ(message_of([&] { sim::parse_scenario(text, "scn.json"); }),
            "scn.json: bodies[1].polygon[2][1] = -1e999: expected a finite number (this one is "
            "too large for a double)");
  EXPECT_EQ(message_of([] { sim::parse_scenario("1e400", "scn.json"); }),
            "scn.json: (top level) = 1e400: expected a finite number (this one is too large for "
            "a double)");
}

TEST(ScenarioErrorsText, NanAndInfinityAreNotJson) {
  // What Python's json module writes for float("nan") and float("inf"): the
  // message says JSON has no such number, where it is, and what is allowed.
  std::string text = scenario_test::example_json().dump();
  const std::string vertex = "[40,12]";
  const std::size_t at = text.find(vertex);
  for (const char* bad : {"NaN", "-Infinity", "Infinity", "nan", "inf"}) {
    std::string t = text;
    t.replace(at, vertex.size(), std::string("[40,\n") + bad + "]");
    const std::string what = message_of([&] { sim::parse_scenario(t, "scn.json"); });
    EXPECT_EQ(what, std::string("scn.json: bodies[1].polygon[2][1] = ") + bad +
                        " at line 2, column 1: expected a finite number (JSON has no NaN or "
                        "Infinity; every number of a scenario must be finite)")
        << bad;
  }
  // A misspelt word that is not a number stays a syntax error.
  std::string t = text;
  t.replace(at, vertex.size(), "[40,Nope]");
  const std::string what = message_of([&] { sim::parse_scenario(t, "scn.json"); });
  EXPECT_EQ(what.rfind("scn.json: invalid JSON at line 1, column ", 0), 0u) << what;
}

TEST(ScenarioErrorsText, KeyGivenTwice) {
  // A repeated key would otherwise keep only its last value, silently.
  std::string text = scenario_test::example_json().dump();
  const std::string cohesion = "\"cohesion\":40000";
  text.replace(text.find(cohesion), cohesion.size(), cohesion + ",\"cohesion\":0");
  EXPECT_EQ(message_of([&] { sim::parse_scenario(text, "scn.json"); }),
            "scn.json: materials.soil.cohesion: key given twice in one object (each key at most "
            "once)");
  // The same key in two different objects is fine.
  EXPECT_NO_THROW(sim::parse_scenario(scenario_test::kExample, "scn.json"));
}

TEST(ScenarioErrorsText, EmptyText) {
  const std::string what = message_of([] { sim::parse_scenario("", "scn.json"); });
  EXPECT_EQ(what.rfind("scn.json: invalid JSON at line 1, column 1: ", 0), 0u) << what;
}

TEST(ScenarioErrorsText, MissingFile) {
  const std::string path = "/nonexistent-landslide-dir/scn.json";
  const std::string what = message_of([&] { sim::load_scenario(path); });
  EXPECT_EQ(what.rfind(path + ": cannot read file: ", 0), 0u) << what;
  EXPECT_NE(what.find("No such file"), std::string::npos) << what;
}

TEST(ScenarioErrorsText, DirectoryInsteadOfFile) {
  const std::string what = message_of([] { sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios"); });
  EXPECT_EQ(what.rfind(LANDSLIDE_SOURCE_DIR "/scenarios: cannot read file: ", 0), 0u) << what;
}

TEST(ScenarioErrorsText, TopLevelNotAnObject) {
  for (const char* text : {"[1, 2]", "42", "\"scenario\"", "null"}) {
    const std::string what = message_of([&] { sim::parse_scenario(text, "scn.json"); });
    EXPECT_EQ(what.rfind("scn.json: (top level) = ", 0), 0u) << what;
    EXPECT_NE(what.find(": expected an object"), std::string::npos) << what;
  }
}

TEST(ScenarioErrorsText, MissingRequiredTopLevelKeys) {
  for (const char* key : {"name", "domain", "grid", "gravity", "boundaries", "materials", "bodies",
                          "time_step", "stages", "output"}) {
    Json doc = scenario_test::example_json();
    doc.erase(key);
    const std::string what = message_of([&] { sim::parse_scenario(doc.dump(), "scn.json"); });
    EXPECT_EQ(what, std::string("scn.json: ") + key + ": missing (required)");
  }
}

}  // namespace
