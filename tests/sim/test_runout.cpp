// The one definition of the runout (sim/run/runout.hpp) on blocks of soil points
// moved by hand: the toe follows the material, a detached clod or a film
// thinner than 1.5 % of the initial height does not carry it on.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/run/runout.hpp"
#include "sim/scene/seed.hpp"
#include "support.hpp"

namespace {

// A soil block 0.3 m long and 0.1 m high on a 5 mm grid, 2 x 2 points per
// cell: points 2.5 mm apart, the toe threshold 1.5 mm.
sim::World soil_block() {
  sim::Scenario s = simtest::block_scenario({0.0, 0.0}, {0.3, 0.1}, 0.005, 2, {0, 0}, {1, 0.2});
  s.materials[0].model = sim::MaterialModel::MohrCoulomb;
  s.materials[0].friction_angle = 0.5;  // rad
  s.materials[0].critical_density = s.materials[0].density;
  return sim::make_world(s);
}

TEST(Runout, ZeroAtTheStartAndTheShiftOfAMovedBlock) {
  sim::World w = soil_block();
  const sim::Runout r = sim::measure_runout(w);
  EXPECT_NEAR(r.threshold, 0.0015, 1e-12);
  EXPECT_NEAR(r.initial_toe, 0.3, 0.003);  // within half a window and a bin of the edge
  EXPECT_EQ(r.runout, 0.0);
  for (double& x : w.points.x) x += 0.1;
  const sim::Runout moved = sim::measure_runout(w);
  EXPECT_EQ(moved.initial_toe, r.initial_toe);
  EXPECT_NEAR(moved.runout, 0.1, 1e-9);
}

TEST(Runout, ADetachedClodDoesNotCarryTheToe) {
  sim::World w = soil_block();
  for (double& x : w.points.x) x += 0.05;
  const double block = sim::measure_runout(w).toe;
  // The last column of points thrown 0.2 m further: a gap ends the deposit,
  // so the toe is that of the block without them, a point spacing back.
  for (std::size_t p = 0; p < w.points.size(); ++p)
    if (w.points.x0[p] > 0.3 - 0.0025) w.points.x[p] += 0.2;
  EXPECT_NEAR(sim::measure_runout(w).toe, block - 0.0025, 0.001);
}

TEST(Runout, AFilmThinnerThanTheThresholdDoesNotCount) {
  // The top row of points laid out ahead of the block: one point thick
  // (2.5 mm) it carries the toe; spread to one point every 5 mm (1.25 mm of
  // material) it does not.
  for (const double gap : {0.0025, 0.005}) {
    sim::World w = soil_block();
    double x = 0.3 + 0.5 * gap;
    for (std::size_t p = 0; p < w.points.size(); ++p) {
      if (w.points.y0[p] < 0.1 - 0.0025) continue;
      w.points.y[p] = 0.00125;
      w.points.x[p] = x;
      x += gap;
    }
    const sim::Runout r = sim::measure_runout(w);
    if (gap == 0.0025)
      EXPECT_NEAR(r.toe, x - 0.5 * gap, 0.0025) << "one point thick";
    else
      EXPECT_LT(r.runout, 0.0025) << "scattered";
  }
}

}  // namespace
