// The objective stress rate (Eq. 24): a rigid spin rotates the stress with the
// body and keeps its principal magnitudes.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/physics/constitutive.hpp"
#include "sim/scene/seed.hpp"
#include "sim/physics/step.hpp"
#include "support.hpp"

namespace {

struct Principal {
  double s1, s2, angle;  // in-plane principal values (s1 >= s2), direction of s1
};

Principal principal(double xx, double yy, double xy) {
  const double c = 0.5 * (xx + yy), r = std::hypot(0.5 * (xx - yy), xy);
  return {c + r, c - r, 0.5 * std::atan2(2 * xy, xx - yy)};
}

TEST(Jaumann, RigidSpinOnTheGridKeepsPrincipalStresses) {
  // Nodal velocities of a rigid counter-clockwise spin v = w x (x - c); the
  // strain increment of Eq. (31) is zero and the spin rotates the stress.
  sim::World w = sim::make_world(
      simtest::block_scenario({1.0, 1.0}, {2.0, 2.0}, 0.25, 2, {0, 0}, {3, 3}));
  const double omega = 2.0, dt = 5e-4;
  const int steps = 1000;  // one radian
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    w.points.sxx[p] = -100e3;
    w.points.syy[p] = -20e3;
    w.points.sxy[p] = 0;
    w.points.szz[p] = -40e3;
  }
  sim::locate_points(w);
  sim::Grid& g = w.grid;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.origin_x + i * g.h - 1.5, y = g.origin_y + j * g.h - 1.5;
      g.vx[g.node(i, j)] = -omega * y;
      g.vy[g.node(i, j)] = omega * x;
    }
  for (int k = 0; k < steps; ++k) sim::update_stress(w, dt);
  const double turned = omega * dt * steps;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    const Principal s = principal(w.points.sxx[p], w.points.syy[p], w.points.sxy[p]);
    // Incremental rotation is exact to first order: drift ~ angle * d(angle).
    EXPECT_NEAR(s.s1, -20e3, 100e3 * 2e-3);
    EXPECT_NEAR(s.s2, -100e3, 100e3 * 2e-3);
    EXPECT_NEAR(w.points.szz[p], -40e3, 1e-6);
    // s1 pointed along y (angle pi/2) and turns with the body.
    double diff = std::remainder(s.angle - (M_PI / 2 + turned), M_PI);
    EXPECT_NEAR(diff, 0.0, 2e-3) << "point " << p;
    EXPECT_NEAR(w.points.density[p], 2000.0, 1e-9);
  }
}

TEST(Jaumann, ZeroSpinLeavesStressAlone) {
  sim::Stress s{-1, -2, 0.5, -3};
  sim::jaumann_rotate(s, 0.0);
  EXPECT_EQ(s.xx, -1);
  EXPECT_EQ(s.yy, -2);
  EXPECT_EQ(s.xy, 0.5);
  EXPECT_EQ(s.zz, -3);
}

}  // namespace
