// The Mohr-Coulomb return (method notes section 2): every trial stress lands
// on the yield surface, every region is reached, and the plastic strain
// increment D^-1 (s_B - s_C) is a non-negative combination of the gradients
// of the active plastic potentials (non-associated flow, Eqs. 22, 23).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/mohr_coulomb.hpp"

namespace {

constexpr double kE = 20e6, kNu = 0.25;
const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kShear = kE / (2 * (1 + kNu));

double deg(double d) { return d * M_PI / 180.0; }

sim::Vec3 strain_of(const sim::Vec3& ds) {  // D^-1 ds
  const double tr = kLambda / (2 * kShear + 3 * kLambda) * (ds[0] + ds[1] + ds[2]);
  return {(ds[0] - tr) / (2 * kShear), (ds[1] - tr) / (2 * kShear), (ds[2] - tr) / (2 * kShear)};
}

// Least-squares multipliers of e = l1 g1 + l2 g2; returns the residual norm.
double fit_two(const sim::Vec3& e, const sim::Vec3& g1, const sim::Vec3& g2, double& l1,
               double& l2) {
  auto dot = [](const sim::Vec3& a, const sim::Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  const double a11 = dot(g1, g1), a12 = dot(g1, g2), a22 = dot(g2, g2);
  const double b1 = dot(g1, e), b2 = dot(g2, e), det = a11 * a22 - a12 * a12;
  l1 = (a22 * b1 - a12 * b2) / det;
  l2 = (a11 * b2 - a12 * b1) / det;
  double r = 0;
  for (int i = 0; i < 3; ++i) r += std::pow(e[i] - l1 * g1[i] - l2 * g2[i], 2);
  return std::sqrt(r);
}

struct Case {
  double phi, psi_share, cohesion;
};

TEST(MohrCoulomb, RandomTrialsReturnOntoTheSurfaceWithTheFlowOfThePotential) {
  std::mt19937_64 rng(2024);
  int regions[5] = {0, 0, 0, 0, 0};
  double worst_f = 0;
  for (const double phi : {10.0, 20.0, 30.0, 40.0}) {
    for (const double share : {0.0, 0.5, 1.0}) {
      for (const double c : {40e3, 0.0}) {
        const sim::MohrCoulomb mc =
            sim::MohrCoulomb::make(kE, kNu, c, deg(phi), deg(share * phi));
        const double ref = std::max(c, 100e3);
        std::uniform_real_distribution<double> u(-4 * ref, 1.5 * ref);
        for (int n = 0; n < 10000 / 6 + 1; ++n) {
          sim::Vec3 s{u(rng), u(rng), u(rng)};
          std::sort(s.begin(), s.end(), std::greater<double>());
          const sim::Vec3 trial = s;
          const sim::ReturnRegion r = sim::mohr_coulomb_return_principal(mc, s);
          ++regions[static_cast<int>(r)];
          if (r == sim::ReturnRegion::Elastic) {
            EXPECT_EQ(s, trial);
            continue;
          }
          const double scale = std::max({std::fabs(trial[0]), std::fabs(trial[2]), ref});
          const double f = std::fabs(sim::yield_function(mc, s)) / scale;
          worst_f = std::max(worst_f, f);
          ASSERT_LT(f, 1e-10) << "phi " << phi << " region " << int(r);
          EXPECT_GE(s[0], s[1] - 1e-9 * scale);
          EXPECT_GE(s[1], s[2] - 1e-9 * scale);
          const sim::Vec3 e = strain_of({trial[0] - s[0], trial[1] - s[1], trial[2] - s[2]});
          const double m = mc.m;
          double l1 = 0, l2 = 0, res = 0;
          const double norm = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
          switch (r) {
            case sim::ReturnRegion::Plane:
              res = fit_two(e, {m, 0, -1}, {0, 0, 1e-30}, l1, l2);  // single gradient
              l2 = 0;
              break;
            case sim::ReturnRegion::EdgeS1EqS2:
              res = fit_two(e, {m, 0, -1}, {0, m, -1}, l1, l2);
              EXPECT_NEAR(s[0], s[1], 1e-9 * scale);
              break;
            case sim::ReturnRegion::EdgeS2EqS3:
              res = fit_two(e, {m, 0, -1}, {m, -1, 0}, l1, l2);
              EXPECT_NEAR(s[1], s[2], 1e-9 * scale);
              break;
            case sim::ReturnRegion::Apex:
              EXPECT_NEAR(s[0], mc.apex, 1e-9 * scale);
              EXPECT_NEAR(s[2], mc.apex, 1e-9 * scale);
              continue;
            default: break;
          }
          EXPECT_LT(res, 1e-8 * norm) << "flow not along the potential, region " << int(r);
          EXPECT_GE(l1, -1e-8 * norm);
          EXPECT_GE(l2, -1e-8 * norm);
        }
      }
    }
  }
  std::printf("regions: elastic %d, plane %d, edge s1=s2 %d, edge s2=s3 %d, apex %d; "
              "worst |f|/sigma_ref %.2e\n",
              regions[0], regions[1], regions[2], regions[3], regions[4], worst_f);
  for (int r = 0; r < 5; ++r) EXPECT_GT(regions[r], 0) << "region " << r << " never reached";
}

TEST(MohrCoulomb, PlaneStrainReturnKeepsPrincipalDirections) {
  const sim::MohrCoulomb mc = sim::MohrCoulomb::make(kE, kNu, 10e3, deg(30), deg(10));
  for (const double angle : {0.0, 0.3, 1.1, 2.5}) {
    const double c = std::cos(angle), s = std::sin(angle);
    // Principal (-300, -20) kPa in plane, rotated by angle; zz in between.
    const double a = -20e3, b = -300e3;
    sim::Stress t{a * c * c + b * s * s, a * s * s + b * c * c, (a - b) * s * c, -100e3};
    const sim::ReturnRegion r = sim::mohr_coulomb_return(mc, t);
    EXPECT_NE(r, sim::ReturnRegion::Elastic);
    const double theta = 0.5 * std::atan2(2 * t.xy, t.xx - t.yy);
    EXPECT_NEAR(std::remainder(theta - angle, M_PI), 0.0, 1e-9);
    EXPECT_NEAR(sim::yield_function(mc, t) / 300e3, 0.0, 1e-10);
    EXPECT_NEAR(sim::relative_yield(mc, t), 1.0, 1e-9);
  }
}

TEST(MohrCoulomb, RelativeYieldIsZeroWhenHydrostaticAndBelowOneInside) {
  const sim::MohrCoulomb mc = sim::MohrCoulomb::make(kE, kNu, 40e3, deg(20), deg(10));
  EXPECT_NEAR(sim::relative_yield(mc, sim::Stress{-50e3, -50e3, 0, -50e3}), 0.0, 1e-15);
  const sim::Stress inside{-60e3, -40e3, 5e3, -50e3};
  const double fr = sim::relative_yield(mc, inside);
  EXPECT_GT(fr, 0.0);
  EXPECT_LT(fr, 1.0);
  EXPECT_LT(sim::yield_function(mc, inside), 0.0);
  sim::Stress copy = inside;
  EXPECT_EQ(sim::mohr_coulomb_return(mc, copy), sim::ReturnRegion::Elastic);
  EXPECT_EQ(copy.xx, inside.xx);
  EXPECT_EQ(copy.xy, inside.xy);
}

}  // namespace
