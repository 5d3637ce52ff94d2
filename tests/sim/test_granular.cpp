// The disconnected state of Dunatunga & Kamrin (2015), sim/physics/granular.hpp: a
// Mohr-Coulomb block pulled apart below its critical density carries no
// stress; pushed back together past it, it carries stress again.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/scene/seed.hpp"
#include "sim/physics/step.hpp"
#include "support.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

sim::World sand_block(double critical_ratio) {
  sim::Scenario s = simtest::block_scenario({1.0, 1.0}, {2.0, 2.0}, 0.125, 2, {0, 0}, {3, 3});
  sim::MaterialSpec& m = s.materials[0];
  m.model = sim::MaterialModel::MohrCoulomb;
  m.friction_angle = 30 * kPi / 180;
  m.critical_density = critical_ratio * m.density;
  return sim::make_world(s);
}

// Every point moves with the uniform dilation rate `rate` about (1.5, 1.5).
void set_dilation(sim::World& w, double rate) {
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    w.points.vx[p] = rate * (w.points.x[p] - 1.5);
    w.points.vy[p] = rate * (w.points.y[p] - 1.5);
  }
}

double mean_density(const sim::World& w) {
  double sum = 0;
  for (double rho : w.points.density) sum += rho;
  return sum / w.points.size();
}

TEST(Granular, TornSoilCarriesNoStressUntilPackedAgain) {
  sim::World w = sand_block(0.95);
  const double rho0 = w.material_specs[0].density, critical = 0.95 * rho0;
  sim::StepReport report;
  const sim::StepInput in{1e-4, {0, 0}, 0};
  // Pulled apart to a mean density of 0.9 rho0.
  while (mean_density(w) > 0.9 * rho0) {
    set_dilation(w, 1.0);
    sim::step(w, in, report);
  }
  int below = 0;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    if (w.points.density[p] >= critical) continue;
    ++below;
    EXPECT_EQ(w.points.sxx[p], 0.0) << "point " << p;
    EXPECT_EQ(w.points.syy[p], 0.0) << "point " << p;
    EXPECT_EQ(w.points.sxy[p], 0.0) << "point " << p;
    EXPECT_EQ(w.points.szz[p], 0.0) << "point " << p;
    EXPECT_EQ(w.points.yielded[p], 1) << "point " << p;
  }
  EXPECT_GT(below, static_cast<int>(w.points.size()) / 2);
  // Pushed back together: once past the critical density the soil carries
  // a compressive stress again, built from zero.
  while (mean_density(w) < 1.02 * critical) {
    set_dilation(w, -1.0);
    sim::step(w, in, report);
  }
  int packed = 0;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    if (w.points.density[p] < 1.005 * critical) continue;
    ++packed;
    EXPECT_LT(w.points.sxx[p] + w.points.syy[p], 0.0) << "point " << p;
  }
  EXPECT_GT(packed, static_cast<int>(w.points.size()) / 2);
}

TEST(Granular, ElasticMaterialNeverDisconnects) {
  sim::Scenario s = simtest::block_scenario({1.0, 1.0}, {2.0, 2.0}, 0.125, 2, {0, 0}, {3, 3});
  sim::World w = sim::make_world(s);
  sim::StepReport report;
  while (mean_density(w) > 0.9 * w.material_specs[0].density) {
    set_dilation(w, 1.0);
    sim::step(w, sim::StepInput{1e-4, {0, 0}, 0}, report);
  }
  for (std::size_t p = 0; p < w.points.size(); ++p)
    EXPECT_GT(w.points.sxx[p] + w.points.syy[p], 0.0) << "point " << p << " lost its tension";
}

}  // namespace
