// The Bui et al. (2008) comparison of `landslide validate`
// (validation/bui_experiment.hpp): the committed experiment curves read back as
// their source gives them, a broken curve file is refused with a message
// naming file, line, value and what is allowed, and each measure returns the
// known answer on a made-up state whose answer is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "validation/bui_experiment.hpp"
#include "sim/scene/scenario.hpp"

namespace {

const std::string kData = std::string(LANDSLIDE_SOURCE_DIR) + "/scenarios/validation/data/";

// Adds a block of points of side `s` filling [x_min, x_max] x [0, height],
// at rest where they started.
void add_block(sim::Particles& p, double x_min, double x_max, double height, double s) {
  const int nx = static_cast<int>(std::lround((x_max - x_min) / s));
  const int ny = static_cast<int>(std::lround(height / s));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      p.x.push_back(x_min + (i + 0.5) * s);
      p.y.push_back((j + 0.5) * s);
      p.density.push_back(2650);
      p.mass.push_back(2650 * s * s);  // volume s^2: a square of side s
    }
  p.x0 = p.x;
  p.y0 = p.y;
}

sim::Particles block(double x_min, double x_max, double height, double s) {
  sim::Particles p;
  add_block(p, x_min, x_max, height, s);
  return p;
}

std::string message_of_reading(const std::string& text, std::size_t min_points = 2) {
  const auto path = std::filesystem::temp_directory_path() / "landslide-test-curve.csv";
  std::ofstream(path) << text;
  try {
    app::read_curve(path.string(), min_points);
  } catch (const sim::ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(ValidationData, CommittedCurvesReadAsTheirSourceGivesThem) {
  // End points as in LandslideSIM/MaterialPointSolver.jl at 932e6c7 (the files' headers).
  const app::Curve surface = app::read_curve(kData + "bui2008-experiment-surface.csv", 2);
  ASSERT_EQ(surface.x.size(), 23u);
  EXPECT_DOUBLE_EQ(surface.x.front(), 0.00012288);
  EXPECT_DOUBLE_EQ(surface.y.front(), 0.099231753);
  EXPECT_DOUBLE_EQ(surface.x.back(), 0.442348498);
  EXPECT_DOUBLE_EQ(surface.y.back(), 0.001519511);
  const app::Curve failure = app::read_curve(kData + "bui2008-experiment-failure.csv", 3);
  ASSERT_EQ(failure.x.size(), 9u);
  EXPECT_DOUBLE_EQ(failure.x.front(), 0.021159264);
  EXPECT_DOUBLE_EQ(failure.y.back(), 0.000460549);
}

TEST(ValidationData, BrokenCurveFileIsRefusedNamingFileLineValueAndWhatIsAllowed) {
  std::string m = message_of_reading("# header\n0,0.1\n0.1,abc\n");
  EXPECT_NE(m.find("landslide-test-curve.csv: line 3: y 'abc' is not a finite number"),
            std::string::npos) << m;
  EXPECT_NE(m.find("expected y as a number of metres in [-1, 10]"), std::string::npos) << m;
  m = message_of_reading("0,0.1\n0.1,50\n");
  EXPECT_NE(m.find("line 2: y 50 is out of range"), std::string::npos) << m;
  m = message_of_reading("0.2,0.1\n0.1,0.05\n");
  EXPECT_NE(m.find("line 2: x 0.1 is less than the previous point's 0.2"), std::string::npos) << m;
  m = message_of_reading("0,0.1,3\n");
  EXPECT_NE(m.find("line 1: '0,0.1,3' is not one pair x,y"), std::string::npos) << m;
  m = message_of_reading("0,0.1\n0.1,0.05\n", 3);
  EXPECT_NE(m.find("2 points; expected at least 3"), std::string::npos) << m;
  EXPECT_EQ(message_of_reading("# a comment\n\n0,0.1\r\n0.1,0.05\n"), "");
  try {
    app::read_curve(kData + "no-such-file.csv", 2);
    ADD_FAILURE() << "a missing file was read";
  } catch (const sim::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-file.csv: cannot read file"), std::string::npos);
  }
}

TEST(ValidationMeasures, CurveToeIsWhereTheSurfaceFallsBelowTheHeight) {
  const app::Curve c{{0.0, 0.1, 0.2}, {0.1, 0.05, 0.0}};
  EXPECT_NEAR(app::curve_toe(c, 0.025), 0.15, 1e-12);  // halfway down the second segment
  EXPECT_DOUBLE_EQ(app::curve_toe(c, 0.0), 0.2);       // never below: the last point
}

TEST(ValidationMeasures, SurfaceOfABlockOfPoints) {
  const sim::Particles p = block(0.0, 0.3, 0.02, 0.002);
  EXPECT_NEAR(app::surface_height(p, 0.15, 0.005), 0.02, 1e-12);
  EXPECT_NEAR(app::surface_height(p, 0.0, 0.005), 0.02, 1e-12);
  EXPECT_EQ(app::surface_height(p, 0.4, 0.005), 0.0);
  const app::Curve flat{{0.05, 0.1, 0.25}, {0.02, 0.02, 0.02}};
  EXPECT_NEAR(app::rms_surface_difference(p, flat, 0.005), 0.0, 1e-12);
  const app::Curve lower{{0.05, 0.1, 0.25}, {0.015, 0.015, 0.015}};
  EXPECT_NEAR(app::rms_surface_difference(p, lower, 0.005), 0.005, 1e-12);
}

// Points beyond a plane through (0.18, 0) at angle theta moved 10 mm to the
// right: the boundary of those that did not move lies on the plane.
void check_failure_line(double theta_deg) {
  const double s = 0.001, x_base = 0.18, t = std::tan(theta_deg * M_PI / 180);
  sim::Particles p = block(0.0, 0.2, 0.1, s);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x0[i] > x_base - p.y0[i] / t) p.x[i] += 0.01;
  const app::Marks m = app::unmoved_boundary(p, s, 0.01, 0.09, 0.001);
  ASSERT_EQ(m.x.size(), 80u);
  EXPECT_NEAR(app::line_angle_deg(m), theta_deg, 0.5);
  const app::Curve plane{{x_base - 0.1 / t, x_base}, {0.1, 0.0}};
  EXPECT_LT(app::rms_offset_x(m, plane), s);
  // Nothing moved: no marks, no angle.
  EXPECT_TRUE(std::isnan(app::line_angle_deg(app::unmoved_boundary(block(0, 0.2, 0.1, s), s, 0.01,
                                                                   0.09, 0.001))));
}

TEST(ValidationMeasures, UnmovedBoundaryFindsAPlanarFailureLine) {
  check_failure_line(35.0);
  check_failure_line(54.9);  // Coulomb's 45 + phi / 2 for phi = 19.8
}

TEST(ValidationMeasures, CurveXAtHeightAndOffsets) {
  const app::Curve line{{0.02, 0.1, 0.18}, {0.1, 0.05, 0.0}};
  EXPECT_NEAR(app::curve_x_at_height(line, 0.025), 0.14, 1e-12);
  EXPECT_DOUBLE_EQ(app::curve_x_at_height(line, 0.2), 0.02);  // clamped to the top point
  const app::Marks shifted{{0.15, 0.11}, {0.025, 0.05}};      // 10 mm right of the line
  EXPECT_NEAR(app::rms_offset_x(shifted, line), 0.01, 1e-12);
  const app::Marks band = app::curve_band(line, 0.01, 0.09);
  ASSERT_EQ(band.x.size(), 1u);
  EXPECT_DOUBLE_EQ(band.y[0], 0.05);
}

}  // namespace
