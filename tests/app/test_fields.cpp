// Output fields on a hand-built world, their colour ranges, the frame window.
#include <gtest/gtest.h>

#include <cmath>

#include "output/frames.hpp"
#include "sim/physics/material.hpp"
#include "sim/physics/mohr_coulomb.hpp"
#include "sim/physics/point_strength.hpp"

namespace {

using app::Field;

sim::MaterialSpec soil() {
  sim::MaterialSpec m;
  m.name = "soil";
  m.model = sim::MaterialModel::MohrCoulomb;
  m.density = 2000;
  m.youngs_modulus = 20e6;
  m.poisson_ratio = 0.25;
  m.cohesion = 10e3;
  m.friction_angle = 30 * M_PI / 180;
  m.dilation_angle = 0;
  return m;
}

sim::MaterialSpec house() {
  sim::MaterialSpec m;
  m.name = "house";
  m.density = 500;
  m.youngs_modulus = 20e6;
  m.poisson_ratio = 0.25;
  return m;
}

// Four points: 0 soil at rest, hydrostatic; 1 soil moving, sheared; 2 soil
// that yielded; 3 house (linear elastic), sheared.
sim::World tiny_world() {
  sim::World w;
  w.material_specs = {soil(), house()};
  for (const auto& m : w.material_specs) w.materials.push_back(sim::make_material_constants(m));
  sim::Particles& p = w.points;
  p.resize(4);
  const double x[] = {1, 2, 3, 4}, y[] = {5, 6, 7, 8};
  const double rx[] = {1, 1.5, 3.25, 3}, ry[] = {5, 7, 7, 8.5};
  for (int i = 0; i < 4; ++i) {
    p.x[i] = p.x0[i] = x[i];
    p.y[i] = p.y0[i] = y[i];
    p.ref_x[i] = rx[i];
    p.ref_y[i] = ry[i];
    p.mass[i] = 2;
    p.density[i] = 0.5;  // volume 4, half size 1
    p.sxx[i] = p.syy[i] = p.szz[i] = -100e3;
  }
  p.vx[1] = 3;
  p.vy[1] = -4;
  p.sxx[1] = -150e3;
  p.syy[1] = -50e3;
  p.sxy[1] = 20e3;
  p.yielded[2] = 1;
  p.sxy[3] = 80e3;
  p.material = {0, 0, 0, 1};
  return w;
}

TEST(Fields, DisplacementIsPositionMinusReference) {
  const sim::World w = tiny_world();
  const auto ux = app::field_values(Field::DisplacementX, w);
  const auto uy = app::field_values(Field::DisplacementY, w);
  const double ex[] = {0, 0.5, -0.25, 1}, ey[] = {0, -1, 0, -0.5};
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(ux[i], ex[i]) << i;
    EXPECT_DOUBLE_EQ(uy[i], ey[i]) << i;
  }
}

TEST(Fields, VelocityIsTheSpeed) {
  const auto v = app::field_values(Field::Velocity, tiny_world());
  EXPECT_DOUBLE_EQ(v[0], 0);
  EXPECT_DOUBLE_EQ(v[1], 5);
}

TEST(Fields, StressYyInKiloPascal) {
  const auto s = app::field_values(Field::StressYY, tiny_world());
  EXPECT_DOUBLE_EQ(s[0], -100);
  EXPECT_DOUBLE_EQ(s[1], -50);
}

TEST(Fields, MaterialIsTheIndex) {
  const auto m = app::field_values(Field::Material, tiny_world());
  EXPECT_EQ(m, (std::vector<double>{0, 0, 0, 1}));
}

TEST(Fields, RelativeYieldEq32YieldedTwoElasticZero) {
  const sim::World w = tiny_world();
  const auto f = app::field_values(Field::RelativeYield, w);
  EXPECT_NEAR(f[0], 0.0, 1e-12);  // hydrostatic
  const sim::Stress s1{-150e3, -50e3, 20e3, -100e3};
  EXPECT_DOUBLE_EQ(f[1], sim::relative_yield(w.materials[0].mohr_coulomb, s1));
  EXPECT_GT(f[1], 0.0);
  EXPECT_LT(f[1], 1.0);
  EXPECT_EQ(f[2], 2.0);  // yielded in the last step (Figure 10)
  EXPECT_EQ(f[3], 0.0);  // linear elastic: no yield surface
}

TEST(Fields, RelativeYieldOfUnknownMaterialIsNan) {
  sim::World w = tiny_world();
  w.points.material[0] = 7;
  EXPECT_TRUE(std::isnan(app::field_values(Field::RelativeYield, w)[0]));
}

TEST(Fields, CaptureKeepsPositionsHalfSizesAndEachField) {
  const sim::World w = tiny_world();
  const app::Frame fr =
      app::capture_frame(w, {Field::Velocity, Field::DisplacementX}, 12, 1.5, "slide");
  EXPECT_EQ(fr.number, 12);
  EXPECT_EQ(fr.time, 1.5);
  EXPECT_EQ(fr.stage, "slide");
  ASSERT_EQ(fr.x.size(), 4u);
  EXPECT_FLOAT_EQ(fr.x[3], 4.0f);
  EXPECT_FLOAT_EQ(fr.y[3], 8.0f);
  for (const float h : fr.half) EXPECT_FLOAT_EQ(h, 1.0f);  // sqrt(2 / 0.5) / 2
  ASSERT_EQ(fr.values.size(), 2u);
  EXPECT_FLOAT_EQ(fr.values[0][1], 5.0f);
  EXPECT_FLOAT_EQ(fr.values[1][1], 0.5f);
}

// The world's points as write_vtu saves them (displacement from ref_x, ref_y).
sim::PointState saved_state(const sim::World& w) {
  sim::PointState s;
  const sim::Particles& p = w.points;
  s.x = p.x;
  s.y = p.y;
  for (std::size_t i = 0; i < p.size(); ++i) {
    s.ux.push_back(p.x[i] - p.ref_x[i]);
    s.uy.push_back(p.y[i] - p.ref_y[i]);
    s.volume.push_back(p.volume(i));
    s.material.push_back(p.material[i]);
    s.yielded.push_back(p.yielded[i]);
  }
  s.vx = p.vx;
  s.vy = p.vy;
  s.sxx = p.sxx;
  s.syy = p.syy;
  s.sxy = p.sxy;
  s.szz = p.szz;
  s.density = p.density;
  s.cohesion = w.strength.cohesion;
  s.friction_angle = w.strength.friction_angle;
  return s;
}

TEST(Fields, SavedStateGivesTheSameValues) {
  const sim::World w = tiny_world();
  const sim::PointState s = saved_state(w);
  for (const Field f : {Field::DisplacementX, Field::DisplacementY, Field::RelativeYield,
                        Field::StressYY, Field::Velocity, Field::Material})
    EXPECT_EQ(app::field_values(f, s, w.materials), app::field_values(f, w))
        << app::field_name(f);
}

// Equal, NaN where the other is NaN (points painted grey).
void expect_same_values(const std::vector<double>& a, const std::vector<double>& b,
                        const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i])) EXPECT_TRUE(std::isnan(b[i])) << what << " point " << i;
    else EXPECT_EQ(a[i], b[i]) << what << " point " << i;
  }
}

TEST(Fields, StrengthIsEachPointsOwnWhereARandomFieldSetIt) {
  sim::World w = tiny_world();
  const std::vector<double> fields[] = {app::field_values(Field::FrictionAngle, w),
                                        app::field_values(Field::Cohesion, w)};
  for (int i = 0; i < 3; ++i) {  // the material's own values, house grey
    EXPECT_NEAR(fields[0][i], 30, 1e-12);
    EXPECT_EQ(fields[1][i], 10);
  }
  EXPECT_TRUE(std::isnan(fields[0][3]) && std::isnan(fields[1][3]));
  const double deg = M_PI / 180;
  sim::set_point_strength(w, 0, "friction_angle", {20 * deg, 25 * deg, 35 * deg, 99});
  const std::vector<double> phi = app::field_values(Field::FrictionAngle, w);
  EXPECT_NEAR(phi[0], 20, 1e-12);
  EXPECT_NEAR(phi[1], 25, 1e-12);
  EXPECT_NEAR(phi[2], 35, 1e-12);
  EXPECT_TRUE(std::isnan(phi[3]));  // the house is not soil: its value is not read
  // Point 1 is judged against its own surface, not the material's 30 degrees.
  const sim::Stress st{w.points.sxx[1], w.points.syy[1], w.points.sxy[1], w.points.szz[1]};
  const double own = sim::relative_yield(sim::point_mohr_coulomb(w, 1), st);
  EXPECT_EQ(app::field_values(Field::RelativeYield, w)[1], own);
  EXPECT_GT(own, sim::relative_yield(w.materials[0].mohr_coulomb, st) + 0.01);
}

TEST(Fields, SavedStateWithARandomFieldGivesTheSameValues) {
  sim::World w = tiny_world();
  sim::set_point_strength(w, 0, "cohesion", {5e3, 20e3, 1e3, 0});
  const sim::PointState s = saved_state(w);
  ASSERT_EQ(s.cohesion.size(), 4u);
  for (const Field f : {Field::RelativeYield, Field::Cohesion, Field::FrictionAngle})
    expect_same_values(app::field_values(f, s, w.materials), app::field_values(f, w),
                       app::field_name(f));
  EXPECT_EQ(app::field_values(Field::Cohesion, s, w.materials)[1], 20);
}

TEST(Fields, HalfSizeIsHalfTheRootOfTheVolume) {
  EXPECT_DOUBLE_EQ(app::half_size(0.25), 0.25);
  EXPECT_TRUE(std::isnan(app::half_size(0)));
  EXPECT_TRUE(std::isnan(app::half_size(-1)));
}

TEST(Fields, NamesRoundTripAndUnknownNamesThrow) {
  for (const std::string& n : app::field_names())
    EXPECT_EQ(app::field_name(app::parse_field(n)), n);
  EXPECT_THROW(app::parse_field("pressure"), std::invalid_argument);
}

app::Frame values_frame(std::vector<float> v) {
  app::Frame f;
  f.values.push_back(std::move(v));
  return f;
}

TEST(FieldRange, PerFieldRules) {
  sim::Scenario s;
  s.materials = {soil(), house()};
  const std::vector<app::Frame> frames = {values_frame({1.0f, 2.0f}),
                                          values_frame({3.0f, NAN, 5.0f})};
  auto range = [&](Field f) { return app::field_range(app::field_style(f, s), frames, 0); };
  EXPECT_EQ(range(Field::RelativeYield).lo, 0);
  EXPECT_EQ(range(Field::RelativeYield).hi, 2);
  EXPECT_EQ(range(Field::DisplacementX).lo, 0);  // 0 kept in view
  EXPECT_EQ(range(Field::DisplacementX).hi, 5);
  EXPECT_EQ(range(Field::StressYY).lo, 1);  // [min, max]
  EXPECT_EQ(range(Field::Velocity).lo, 0);
  EXPECT_EQ(range(Field::Material).lo, 0);
  EXPECT_EQ(range(Field::Material).hi, 1);
  EXPECT_TRUE(app::field_style(Field::Material, s).categorical);
}

TEST(FieldRange, ScenarioRangesHoldForEveryFrame) {
  sim::Scenario s;
  s.materials = {soil(), house()};
  s.output.ranges["displacement-x"] = {-5.0, 30.0};
  s.output.ranges["stress-yy"] = {-200e3, 0.0};  // Pa in the scenario, painted in kPa
  const std::vector<app::Frame> frames = {values_frame({1.0f, 2.0f})};
  auto range = [&](Field f) { return app::field_range(app::field_style(f, s), frames, 0); };
  EXPECT_EQ(range(Field::DisplacementX).lo, -5.0);
  EXPECT_EQ(range(Field::DisplacementX).hi, 30.0);
  EXPECT_EQ(range(Field::StressYY).lo, -200.0);
  EXPECT_EQ(range(Field::StressYY).hi, 0.0);
  EXPECT_EQ(range(Field::Velocity).hi, 2.0);  // not given: range of the frames
}

TEST(FieldRange, EmptyOrFlatRangesAreWidened) {
  const sim::Scenario s;
  const app::FieldStyle disp = app::field_style(Field::DisplacementX, s);
  const app::Range zero = app::field_range(disp, {values_frame({0.0f, 0.0f})}, 0);
  EXPECT_EQ(zero.lo, 0);
  EXPECT_EQ(zero.hi, 1);
  const app::Range flat =
      app::field_range(app::field_style(Field::StressYY, s), {values_frame({-40.0f})}, 0);
  EXPECT_LT(flat.lo, -40);
  EXPECT_GT(flat.hi, -40);
  const app::Range none = app::field_range(disp, {values_frame({NAN})}, 0);
  EXPECT_LT(none.lo, none.hi);
}

TEST(FrameWindow, DomainPlusMargin) {
  sim::Scenario s;
  s.domain_min = {0, 0};
  s.domain_max = {100, 20};
  s.cell_size = 1;
  const app::Window w = app::frame_window(s);
  EXPECT_DOUBLE_EQ(w.x0, -3);
  EXPECT_DOUBLE_EQ(w.x1, 103);
  EXPECT_DOUBLE_EQ(w.y0, -3);
  EXPECT_DOUBLE_EQ(w.y1, 23);
}

TEST(Materials, ChangesOfEarlierStagesApply) {
  sim::Scenario s;
  s.materials = {soil()};
  sim::StageSpec gravity;
  gravity.name = "gravity";
  gravity.type = sim::StageType::Gravity;
  sim::StageSpec trigger;
  trigger.name = "trigger";
  trigger.type = sim::StageType::MaterialChange;
  trigger.changes = {sim::MaterialChange{0, "cohesion", 0.0, false, {}}};
  sim::StageSpec slide;
  slide.name = "slide";
  s.stages = {gravity, trigger, slide};
  EXPECT_EQ(app::materials_at_stage(s, "gravity")[0].mohr_coulomb.cohesion, 10e3);
  EXPECT_EQ(app::materials_at_stage(s, "slide")[0].mohr_coulomb.cohesion, 0);
  EXPECT_EQ(app::materials_at_stage(s, "")[0].mohr_coulomb.cohesion, 0);
}

}  // namespace
