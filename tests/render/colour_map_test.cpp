#include <gtest/gtest.h>

#include <cmath>

#include "render/colour_map.hpp"
#include "render/error.hpp"

namespace render {
namespace {

// Within 1/255 of a published colour (channels 0..1).
void expect_colour(const Rgba& c, double r, double g, double b) {
  EXPECT_NEAR(c.r / 255.0, r, 1.0 / 255.0);
  EXPECT_NEAR(c.g / 255.0, g, 1.0 / 255.0);
  EXPECT_NEAR(c.b / 255.0, b, 1.0 / 255.0);
  EXPECT_EQ(c.a, 255);
}

TEST(ColourMap, ViridisMatchesPublishedEndsAndMiddle) {
  const ColourMap m = ColourMap::viridis();
  expect_colour(m.map(0.0, 0.0, 1.0), 0.267004, 0.004874, 0.329415);
  expect_colour(m.map(0.5, 0.0, 1.0), 0.127568, 0.566949, 0.550556);
  expect_colour(m.map(1.0, 0.0, 1.0), 0.993248, 0.906157, 0.143936);
  expect_colour(m.map(25.0, 0.0, 100.0), 0.229739, 0.322361, 0.545706);  // entry 64
}

TEST(ColourMap, JetMatchesPublishedEndsAndMiddle) {
  const ColourMap m = ColourMap::jet();
  expect_colour(m.map(-3.0, -3.0, 3.0), 0.0, 0.0, 0.5);
  // matplotlib jet(0.5): entry 128 of its 256-entry table.
  expect_colour(m.map(0.0, -3.0, 3.0), 0.490196, 1.0, 0.477546);
  expect_colour(m.map(3.0, -3.0, 3.0), 0.5, 0.0, 0.0);
  expect_colour(m.at(0.125), 0.0, 0.0, 1.0);   // pure blue shoulder
  expect_colour(m.at(0.75), 1.0, 0.581699, 0.0);  // entry 192, orange
}

TEST(ColourMap, ClampsOutsideTheRange) {
  for (const auto& name : ColourMap::names()) {
    if (name == "categorical") continue;
    const ColourMap m = ColourMap::by_name(name);
    EXPECT_EQ(m.map(-1e9, 2.0, 4.0), m.map(2.0, 2.0, 4.0)) << name;
    EXPECT_EQ(m.map(1e9, 2.0, 4.0), m.map(4.0, 2.0, 4.0)) << name;
    EXPECT_EQ(m.map(INFINITY, 2.0, 4.0), m.at(1.0)) << name;
    EXPECT_EQ(m.map(NAN, 2.0, 4.0), m.nan_colour()) << name;
  }
}

TEST(ColourMap, CategoricalCyclesByIntegerId) {
  const ColourMap m = ColourMap::by_name("categorical");
  EXPECT_TRUE(m.is_categorical());
  EXPECT_EQ(m.map(0, 0, 1), (Rgba{31, 119, 180, 255}));
  EXPECT_EQ(m.map(1.2, 0, 1), (Rgba{255, 127, 14, 255}));
  EXPECT_EQ(m.map(10, 0, 1), m.map(0, 0, 1));
  EXPECT_EQ(m.map(-1, 0, 1), m.map(9, 0, 1));
  EXPECT_NE(m.map(2, 0, 1), m.map(3, 0, 1));
}

TEST(ColourMap, UnknownNameAndBadRangeThrow) {
  try {
    ColourMap::by_name("rainbow2");
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("rainbow2"), std::string::npos);
  }
  EXPECT_THROW(validate_range(1.0, 1.0), InvalidArgument);
  EXPECT_THROW(validate_range(0.0, NAN), InvalidArgument);
  EXPECT_NO_THROW(validate_range(-1.0, 1.0));
}

}  // namespace
}  // namespace render
