// Particle-to-grid and grid-to-particle transfers (Eqs. 26-30).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "sim/scene/seed.hpp"
#include "sim/physics/step.hpp"
#include "support.hpp"

namespace {

TEST(Transfer, PointsToGridKeepsMassAndMomentum) {
  sim::World w = sim::make_world(
      simtest::block_scenario({1.0, 1.0}, {3.0, 2.5}, 0.25, 2, {0, 0}, {5, 4}));
  ASSERT_EQ(w.points.size(), 8u * 6u * 4u);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  double mass = 0, px = 0, py = 0;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    w.points.x[p] += 0.05 * u(rng);  // off the lattice
    w.points.vx[p] = u(rng);
    w.points.vy[p] = u(rng);
    mass += w.points.mass[p];
    px += w.points.mass[p] * w.points.vx[p];
    py += w.points.mass[p] * w.points.vy[p];
  }
  sim::locate_points(w);
  sim::reset_grid(w);
  sim::points_to_grid(w);
  double gm = 0, gpx = 0, gpy = 0;
  for (std::size_t k = 0; k < w.grid.mass.size(); ++k) {
    gm += w.grid.mass[k];
    gpx += w.grid.px[k];
    gpy += w.grid.py[k];
  }
  EXPECT_NEAR(gm, mass, 1e-12 * mass);
  EXPECT_NEAR(gpx, px, 1e-10 * mass);
  EXPECT_NEAR(gpy, py, 1e-10 * mass);
}

// The reset, the walls and the nodal update visit each node row's span only
// (step.cpp): every node a point weights must lie in its row's span, and
// beside a step in the soil's outline a row is narrower than the window.
TEST(Transfer, RowSpansHoldEveryNodeAPointWeights) {
  sim::World w = sim::make_world(
      simtest::block_scenario({1.0, 1.0}, {3.0, 2.5}, 0.25, 2, {0, 0}, {5, 4}));
  for (std::size_t p = 0; p < w.points.size(); ++p)
    if (w.points.y[p] > 1.75) w.points.x[p] += 1.1;  // the upper half moved right
  sim::locate_points(w);
  sim::reset_grid(w);
  const sim::Grid& g = w.grid;
  const auto span = [&](int j) { return g.span_of_row(j); };
  int narrower = 0;
  for (int j = g.j_begin; j < g.j_end; ++j)
    narrower += span(j)[0] > g.i_begin || span(j)[1] < g.i_end;
  EXPECT_GE(narrower, 4);
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    const sim::StencilWeights& st = w.weights[p];
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        const int* s = span(st.base_j + b);
        EXPECT_GE(st.base_i + a, s[0]) << "point " << p << ", row " << st.base_j + b;
        EXPECT_LT(st.base_i + a, s[1]) << "point " << p << ", row " << st.base_j + b;
      }
  }
}

// Friction walls and APIC read nodal values all over the window
// (wall_friction.cpp, apic.cpp): with either, every row's span is the
// window's row, the staircase of the test above notwithstanding.
TEST(Transfer, RowSpansAreTheWindowWithFrictionWallsOrApic) {
  for (const bool apic : {false, true}) {
    sim::Scenario s = simtest::block_scenario({1.0, 1.0}, {3.0, 2.5}, 0.25, 2, {0, 0}, {5, 4});
    if (apic)
      s.transfer = sim::TransferScheme::Apic;
    else
      s.boundaries.bottom = {sim::BoundaryKind::Friction, 0.3};
    sim::World w = sim::make_world(s);
    for (std::size_t p = 0; p < w.points.size(); ++p)
      if (w.points.y[p] > 1.75) w.points.x[p] += 1.1;
    sim::locate_points(w);
    sim::reset_grid(w);
    const sim::Grid& g = w.grid;
    for (int j = g.j_begin; j < g.j_end; ++j) {
      EXPECT_EQ(g.span_of_row(j)[0], g.i_begin) << (apic ? "APIC" : "friction") << ", row " << j;
      EXPECT_EQ(g.span_of_row(j)[1], g.i_end) << (apic ? "APIC" : "friction") << ", row " << j;
    }
  }
}

// In a scene of kMemoryBoundFrom points or more, locate writes the stencils
// as whole cache lines with streaming stores (sim/physics/stencil_stores.hpp)
// and P2G fetches them ahead (bands.hpp). Lowered to 0, the same scene must
// get the same stencils, bit for bit, and step to the same points: 140
// points, so that the last block of eight is partial and stored point by
// point.
TEST(Transfer, StreamedStencilsAreTheStoredOnes) {
  const sim::Scenario s = simtest::block_scenario({1.0, 1.0}, {2.75, 2.25}, 0.25, 2, {0, 0}, {5, 4});
  sim::World stored = sim::make_world(s);
  ASSERT_EQ(stored.points.size(), 140u);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (std::size_t p = 0; p < stored.points.size(); ++p) {
    stored.points.x[p] += u(rng);
    stored.points.y[p] += u(rng);
  }
  sim::World streamed = stored;
  streamed.memory_bound_from = 0;
  sim::locate_points(stored);
  sim::locate_points(streamed);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(streamed.weights.data()) % 64, 0u);
  for (std::size_t p = 0; p < stored.points.size(); ++p)
    EXPECT_EQ(std::memcmp(&stored.weights[p], &streamed.weights[p], sizeof(sim::StencilWeights)), 0)
        << "point " << p;
  sim::StepReport report;
  for (int k = 0; k < 5; ++k) {
    sim::step(stored, sim::StepInput{1e-3, {0, -9.81}, 0}, report);
    sim::step(streamed, sim::StepInput{1e-3, {0, -9.81}, 0}, report);
  }
  EXPECT_EQ(stored.points.x, streamed.points.x);
  EXPECT_EQ(stored.points.y, streamed.points.y);
  EXPECT_EQ(stored.points.sxx, streamed.points.sxx);
}

TEST(Transfer, RigidTranslationIsReproduced) {
  // A free block moving at constant velocity without gravity: no strain, no
  // stress, every point moves by v t and keeps its velocity.
  sim::World w = sim::make_world(
      simtest::block_scenario({1.0, 1.0}, {2.0, 1.5}, 0.25, 2, {0, 0}, {6, 4}));
  const double vx = 3.0, vy = -1.0, dt = 1e-3;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    w.points.vx[p] = vx;
    w.points.vy[p] = vy;
  }
  sim::StepReport report;
  const int steps = 200;
  for (int k = 0; k < steps; ++k) sim::step(w, sim::StepInput{dt, {0, 0}, 0}, report);
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    EXPECT_NEAR(w.points.x[p], w.points.x0[p] + vx * dt * steps, 1e-11);
    EXPECT_NEAR(w.points.y[p], w.points.y0[p] + vy * dt * steps, 1e-11);
    EXPECT_NEAR(w.points.vx[p], vx, 1e-11);
    EXPECT_NEAR(w.points.vy[p], vy, 1e-11);
    EXPECT_NEAR(w.points.sxx[p], 0.0, 1e-3);
    EXPECT_NEAR(w.points.syy[p], 0.0, 1e-3);
    EXPECT_NEAR(w.points.sxy[p], 0.0, 1e-3);
    EXPECT_NEAR(w.points.density[p], 2000.0, 1e-9);
  }
  const double mass = w.points.mass[0] * w.points.size();
  EXPECT_NEAR(report.kinetic_energy, 0.5 * mass * (vx * vx + vy * vy), 1e-9 * mass);
}

TEST(Transfer, WallTransferLossClosesTheKineticEnergyOfAStoppedStep) {
  // A block resting on a no-slip floor, moving down and sideways, with no
  // stiffness to speak of: the only change of the step is what the floor
  // takes. The grid loses wall_loss; the points, which take the interpolated
  // change (Eq. 30), lose wall_loss + transfer_loss, transfer_loss > 0.
  sim::Scenario s = simtest::block_scenario({1.0, 0.0}, {2.0, 1.0}, 0.25, 2, {0, 0}, {4, 3});
  s.boundaries.bottom = {sim::BoundaryKind::Fixed, 0.0};
  s.materials[0].youngs_modulus = 1e-3;  // forces negligible next to the wall's change
  sim::World w = sim::make_world(s);
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    w.points.vx[p] = 1.0;
    w.points.vy[p] = -0.5;
  }
  const double before = 0.5 * w.points.mass[0] * w.points.size() * 1.25;
  sim::StepReport report;
  sim::step(w, sim::StepInput{1e-4, {0, 0}, 0}, report);
  const double after = report.kinetic_energy + report.damping_loss;
  EXPECT_GT(report.wall_loss, 0.01 * before);
  EXPECT_GT(report.transfer_loss, 0.1 * report.wall_loss);
  EXPECT_NEAR(before - after, report.wall_loss + report.transfer_loss, 1e-7 * before);
  EXPECT_GT(before - after - report.wall_loss, 0.1 * report.wall_loss)
      << "wall_loss alone does not close the step";
}

TEST(Transfer, PointLeavingTheGridIsAClearError) {
  sim::World w = sim::make_world(
      simtest::block_scenario({1.0, 1.0}, {2.0, 1.5}, 0.25, 2, {0, 0}, {3, 2}));
  w.points.x[5] = 50.0;
  try {
    sim::locate_points(w);
    FAIL() << "no error for a point outside the grid";
  } catch (const sim::SimulationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("point 5"), std::string::npos) << what;
    EXPECT_NE(what.find("left the grid"), std::string::npos) << what;
    EXPECT_NE(what.find("50"), std::string::npos) << what;
  }
  w.points.x[5] = std::nan("");
  EXPECT_THROW(sim::locate_points(w), sim::SimulationError);
}

// Locate takes eight points' base nodes in 32-bit lanes: a point whose base
// node index is at or past the end of int's range, in either direction,
// must still be off the grid (an index + 2 would wrap round to a negative
// one, inside).
TEST(Transfer, PointAtTheEndOfTheIndexRangeLeavesTheGrid) {
  sim::World w = sim::make_world(
      simtest::block_scenario({1.0, 1.0}, {2.0, 1.5}, 0.25, 2, {0, 0}, {3, 2}));
  const double x0 = w.points.x[5], y0 = w.points.y[5];
  const sim::Grid& g = w.grid;
  const auto at_base = [&](double origin, double base) {
    return origin + w.gimp.lp + (base + 0.5) * g.h;
  };
  for (double base : {2147483645.0, 2147483646.0, 2147483647.0, 2147483648.0, -2147483648.0,
                      -2147483649.0, 1e300}) {
    for (int axis = 0; axis < 2; ++axis) {
      w.points.x[5] = axis == 0 ? at_base(g.origin_x, base) : x0;
      w.points.y[5] = axis == 1 ? at_base(g.origin_y, base) : y0;
      try {
        sim::locate_points(w);
        ADD_FAILURE() << "no error for a point with base index " << base << " on axis " << axis;
      } catch (const sim::SimulationError& e) {
        EXPECT_NE(std::string(e.what()).find("left the grid"), std::string::npos) << e.what();
      }
    }
  }
}

}  // namespace
