// GIMP weights (Eqs. 12, 13; method notes section 1): partition of unity,
// gradients that sum to zero, and a gradient that is the weight's derivative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "sim/physics/gimp.hpp"
#include "sim/physics/slope_lanes.hpp"

namespace {

constexpr double kH = 0.5;

TEST(GimpWeights, SumToOneAndGradientsToZeroAtRandomPositions) {
  std::mt19937_64 rng(7);
  for (const int ppc : {1, 2, 3, 4}) {
    const double lp = kH / (2.0 * ppc);
    std::uniform_real_distribution<double> pos(2.0, 8.0);
    for (int k = 0; k < 20000; ++k) {
      sim::StencilWeights st;
      sim::StencilSlopes d;
      sim::gimp_stencil(pos(rng), pos(rng), -1.0, -1.0, sim::GimpShape(kH, lp), st, d);
      double sum = 0, gx = 0, gy = 0;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          sum += st.wx[a] * st.wy[b];
          gx += d.dx[a] * st.wy[b];
          gy += st.wx[a] * d.dy[b];
          EXPECT_GE(st.wx[a] * st.wy[b], 0.0);
        }
      ASSERT_NEAR(sum, 1.0, 1e-13) << "ppc " << ppc;
      ASSERT_NEAR(gx, 0.0, 1e-11);
      ASSERT_NEAR(gy, 0.0, 1e-11);
    }
  }
}

TEST(GimpWeights, DerivativeMatchesFiniteDifferenceAndWeightIsContinuous) {
  const sim::GimpShape k(kH, kH / 4);
  for (double xi = -1.3 * kH; xi <= 1.3 * kH; xi += 0.0137 * kH) {
    double s, ds, sp, dsp, sm, dsm;
    sim::gimp_weight_1d(xi, k, s, ds);
    const double e = 1e-7;
    sim::gimp_weight_1d(xi + e, k, sp, dsp);
    sim::gimp_weight_1d(xi - e, k, sm, dsm);
    EXPECT_NEAR((sp - sm) / (2 * e), ds, 1e-5) << "xi = " << xi;
    EXPECT_NEAR(sp, sm, 1e-6) << "weight jumps at xi = " << xi;
  }
}

TEST(GimpWeights, ReproducesLinearFields) {
  // sum_i S_ip x_i = x_p: GIMP interpolates a linear field exactly, which is
  // why a rigid motion produces no strain.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(1.0, 4.0);
  const double lp = kH / 4, ox = -0.3, oy = 0.2;
  for (int k = 0; k < 1000; ++k) {
    const double xp = pos(rng), yp = pos(rng);
    sim::StencilWeights st;
    sim::StencilSlopes d;
    sim::gimp_stencil(xp, yp, ox, oy, sim::GimpShape(kH, lp), st, d);
    double x = 0, y = 0, dxdx = 0, dydy = 0;
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        const double xi = ox + (st.base_i + a) * kH, yi = oy + (st.base_j + b) * kH;
        x += st.wx[a] * st.wy[b] * xi;
        y += st.wx[a] * st.wy[b] * yi;
        dxdx += d.dx[a] * st.wy[b] * xi;
        dydy += st.wx[a] * d.dy[b] * yi;
      }
    EXPECT_NEAR(x, xp, 1e-12);
    EXPECT_NEAR(y, yp, 1e-12);
    EXPECT_NEAR(dxdx, 1.0, 1e-12);
    EXPECT_NEAR(dydy, 1.0, 1e-12);
  }
}

TEST(GimpWeights, StencilMatchesTheWeightAtEveryNode) {
  // The stencil picks each node's piece of the weight without branching; it
  // must give what the region test of gimp_weight_1d gives, at every node,
  // including positions on the region edges.
  std::mt19937_64 rng(5);
  for (const int ppc : {1, 2, 3, 4}) {
    const sim::GimpShape k(kH, kH / (2.0 * ppc));
    std::uniform_real_distribution<double> pos(0.0, 4.0);
    for (int n = 0; n < 20000; ++n) {
      // Every fourth position sits on a node or a region edge.
      double xp = pos(rng);
      if (n % 4 == 0) xp = std::round(xp / k.lp) * k.lp;
      sim::StencilWeights st;
      sim::StencilSlopes d;
      sim::gimp_stencil(xp, xp, -1.0, -1.0, k, st, d);
      for (int a = 0; a < 3; ++a) {
        double s, ds;
        sim::gimp_weight_1d(xp - (-1.0 + (st.base_i + a) * kH), k, s, ds);
        ASSERT_NEAR(st.wx[a], s, 1e-14) << "ppc " << ppc << ", x = " << xp << ", node " << a;
        ASSERT_NEAR(d.dx[a], ds, 1e-12) << "ppc " << ppc << ", x = " << xp << ", node " << a;
      }
      double beyond, d_beyond;  // the node past the stencil carries nothing
      sim::gimp_weight_1d(xp - (-1.0 + (st.base_i + 3) * kH), k, beyond, d_beyond);
      ASSERT_EQ(beyond, 0.0) << "x = " << xp;
    }
  }
}

// x_weights reads four doubles of the stencil: lanes 0..2 are the row itself
// and lane 3 is +0.0, whatever the next member holds.
TEST(GimpWeights, XRowsHoldTheRowAndAZeroFourthLane) {
  sim::StencilWeights st;
  sim::StencilSlopes slopes;
  sim::gimp_stencil(3.1, 4.7, -1.0, -1.0, sim::GimpShape(kH, kH / 4), st, slopes);
  st.wy[0] = 2.5;  // the double after wx
  const sim::Lane4 w = sim::x_weights(st);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(w[a], st.wx[a]);
  EXPECT_EQ(w[3], 0.0);
  EXPECT_FALSE(std::signbit(w[3]));
  const sim::Lane8 both = sim::twice(w);
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(both[l], w[l]);
    EXPECT_EQ(both[l + 4], w[l]);
  }
}

// The stress phase makes the derivatives again from the positions with
// gimp_axis_slopes; each lane must be, bit for bit, what locate's one-point
// stencil gives, including positions on nodes and region edges.
TEST(GimpWeights, SlopesMadeAgainAreTheStencilsBitForBit) {
  std::mt19937_64 rng(11);
  for (const int ppc : {1, 2, 3, 4}) {
    const sim::GimpShape k(kH, kH / (2.0 * ppc));
    std::uniform_real_distribution<double> pos(0.0, 4.0);
    for (int n = 0; n < 2000; ++n) {
      sim::Lane8 x;
      for (int l = 0; l < 8; ++l) {
        x[l] = pos(rng);
        if (l % 4 == 0) x[l] = std::round(x[l] / k.lp) * k.lp;
      }
      sim::Lane8 d[3];
      sim::gimp_axis_slopes<sim::Lane8, sim::Int32x8>(x, -1.0, k, d);
      for (int l = 0; l < 8; ++l) {
        sim::StencilWeights st;
        sim::StencilSlopes one;
        sim::gimp_stencil(x[l], x[l], -1.0, -1.0, k, st, one);
        for (int a = 0; a < 3; ++a) {
          std::uint64_t made, stored;
          const double lane = d[a][l];  // clang takes no address of a vector's lane
          std::memcpy(&made, &lane, sizeof made);
          std::memcpy(&stored, &one.dx[a], sizeof stored);
          ASSERT_EQ(made, stored) << "ppc " << ppc << ", x = " << x[l] << ", node " << a;
        }
      }
    }
  }
}

// slope_lanes hands them on as stencil rows of two points, {dx0, dx1, dx2,
// +0.0} each, and as one lane a point for dy.
TEST(GimpWeights, SlopeLanesHoldEachPointsRows) {
  sim::Grid g;
  g.origin_x = -1.0;
  g.origin_y = -2.0;
  const sim::GimpShape k(kH, kH / 4);
  const sim::Lane8 x{0.1, 0.37, 1.2, 2.05, 0.0, 3.3, 1.49, 0.77};
  const sim::Lane8 y{2.2, 0.4, 0.15, 1.9, 3.1, 0.0, 0.66, 2.5};
  const sim::SlopeLanes s = sim::slope_lanes(x, y, g, k);
  for (int l = 0; l < 8; ++l) {
    sim::StencilWeights st;
    sim::StencilSlopes one;
    sim::gimp_stencil(x[l], y[l], g.origin_x, g.origin_y, k, st, one);
    const sim::Lane8& rows = s.x_rows[l / 2];
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(rows[4 * (l % 2) + a], one.dx[a]) << "point " << l << ", node " << a;
      EXPECT_EQ(s.dy[a][l], one.dy[a]) << "point " << l << ", row " << a;
    }
    EXPECT_EQ(rows[4 * (l % 2) + 3], 0.0);
    EXPECT_FALSE(std::signbit(rows[4 * (l % 2) + 3]));
  }
}

}  // namespace
