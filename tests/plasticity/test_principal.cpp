// Plane-strain side of the return: principal decomposition, in-plane
// rotation, the relative yield of Eq. (32), the yield function against
// Eq. (20), and the material's input checks.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "trials.hpp"

namespace {

using namespace plasticity_test;
using sim::ReturnRegion;

TEST(PrincipalStress, DecomposesSortsAndRebuilds) {
  // In-plane (-20, -300) kPa at 0.4 rad, zz in each of the three slots.
  for (const double zz : {50e3, -100e3, -500e3}) {
    const Eigen::Vector3d s = sorted_desc({-20e3, -300e3, zz});
    const int slot = zz == 50e3 ? 0 : zz == -100e3 ? 1 : 2;
    const sim::Stress stress = stress_of(s, slot, 0.4);
    const sim::PrincipalStress p = sim::principal_stresses(stress);
    EXPECT_EQ(p.zz_slot, slot);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.s[i], s[i], 1e-9);
    EXPECT_NEAR(p.cos2, std::cos(0.8), 1e-14);
    EXPECT_NEAR(p.sin2, std::sin(0.8), 1e-14);
    const sim::Stress back = sim::from_principal(p, p.s);
    EXPECT_NEAR(back.xx, stress.xx, 1e-9);
    EXPECT_NEAR(back.yy, stress.yy, 1e-9);
    EXPECT_NEAR(back.xy, stress.xy, 1e-9);
    EXPECT_EQ(back.zz, stress.zz);
  }
}

// The first `count` trials of a material that reach `region` (principal path).
std::vector<Trial> trials_in(const Model& md, ReturnRegion region, int count) {
  std::vector<Trial> out;
  for (const Trial& t : make_trials(md, seed_of(99))) {
    sim::Principal3 p = to_p3(t.s_b);
    if (sim::mohr_coulomb_return_principal(md.mc, p) == region) out.push_back(t);
    if (static_cast<int>(out.size()) == count) break;
  }
  return out;
}

TEST(MohrCoulombReturn, InPlaneRotationKeepsPrincipalValuesAndDirections) {
  const double angles[] = {0.0, 0.3, 1.1, kPi / 2, 2.5, -0.7, -kPi / 4};
  int checked = 0;
  for (const Case& c : {Case{30, 15, 40e3}, Case{20, 0, 0}, Case{40, 40, 40e3}}) {
    const Model md = model_of(c);
    for (const ReturnRegion region : {ReturnRegion::Plane, ReturnRegion::EdgeS1EqS2,
                                      ReturnRegion::EdgeS2EqS3, ReturnRegion::Apex}) {
      const std::vector<Trial> some = trials_in(md, region, 20);
      ASSERT_FALSE(some.empty());
      for (const Trial& t : some) {
        sim::Principal3 p = to_p3(t.s_b);
        sim::mohr_coulomb_return_principal(md.mc, p);
        const Eigen::Vector3d s_c = to_vec(p);
        const double ref = sigma_ref(t.s_b, c.cohesion);
        for (const double theta : angles)
          for (int slot = 0; slot < 3; ++slot) {
            const sim::Stress trial = stress_of(t.s_b, slot, theta);
            sim::Stress s = trial;
            // The region itself may flip for trials on a region boundary
            // (psi = 0 trials built at the apex); the values may not.
            ASSERT_NE(sim::mohr_coulomb_return(md.mc, s), ReturnRegion::Elastic);
            // Same principal values whatever the rotation or zz slot...
            ASSERT_LT((eigen_principal(s) - s_c).cwiseAbs().maxCoeff() / ref, 1e-10);
            // ...each on the trial's own direction: zz keeps its slot's value
            // and the in-plane ones go back on the rotated axes.
            const sim::Stress want = stress_of(s_c, slot, theta);
            ASSERT_NEAR(s.xx, want.xx, 1e-10 * ref);
            ASSERT_NEAR(s.yy, want.yy, 1e-10 * ref);
            ASSERT_NEAR(s.xy, want.xy, 1e-10 * ref);
            ASSERT_NEAR(s.zz, want.zz, 1e-10 * ref);
            // Coaxial with the trial: the in-plane tensors commute.
            const double commutator =
                trial.xy * (s.xx - s.yy) - s.xy * (trial.xx - trial.yy);
            ASSERT_LT(std::fabs(commutator) / (ref * ref), 1e-10);
            ++checked;
          }
      }
    }
    // Equal in-plane values: any in-plane direction is principal.
    for (const double zz : {-900e3, 400e3}) {
      sim::Stress s{-100e3, -100e3, 0, zz};
      ASSERT_NE(sim::mohr_coulomb_return(md.mc, s), ReturnRegion::Elastic);
      EXPECT_EQ(s.xx, s.yy);
      EXPECT_EQ(s.xy, 0.0);
      EXPECT_LT(std::fabs(yield_sorted(md, eigen_principal(s))) / 900e3, 1e-10);
    }
  }
  std::printf("rotation: %d returns checked\n", checked);
}

// Eq. (32) written the brief's way: 0.5 (s_max - s_min) over
// c cos(phi) - 0.5 (s_max + s_min) sin(phi).
double eq32(const Case& c, const Eigen::Vector3d& s) {
  const double phi = deg(c.phi_deg);
  return 0.5 * (s.maxCoeff() - s.minCoeff()) /
         (c.cohesion * std::cos(phi) - 0.5 * (s.maxCoeff() + s.minCoeff()) * std::sin(phi));
}

TEST(RelativeYield, ZeroHydrostaticOneOnTheSurfaceBetweenInside) {
  double worst_surface = 0;
  int inside = 0, surface = 0;
  for (const Case& c : all_cases()) {
    const Model md = model_of(c);
    for (const double p : {-1e6, -1e3, md.apex - 1e3})
      EXPECT_EQ(sim::relative_yield(md.mc, sim::Stress{p, p, 0, p}), 0.0);
    // At and beyond the apex the denominator is <= 0: 1.
    for (const double p : {md.mc.apex, md.mc.apex + 1e3})
      EXPECT_EQ(sim::relative_yield(md.mc, sim::Stress{p, p, 0, p}), 1.0);
    int n = 0;
    for (const Trial& t : make_trials(md, seed_of(7))) {
      if (++n > 2000) break;
      sim::Stress s = stress_of(t.s_b, t.zz_slot, t.theta);
      const double before = sim::relative_yield(md.mc, s);
      const ReturnRegion region = sim::mohr_coulomb_return(md.mc, s);
      const double after = sim::relative_yield(md.mc, s);
      if (region == ReturnRegion::Elastic) {
        ASSERT_GE(before, 0.0);
        ASSERT_LT(before, 1.0);
        if (t.s_b.maxCoeff() + t.s_b.minCoeff() < 2 * md.apex) {
          ASSERT_NEAR(before, eq32(c, t.s_b), 1e-9);
        }
        ++inside;
        continue;
      }
      EXPECT_EQ(before, 1.0);  // outside the surface: clamped
      const Eigen::Vector3d s_c = eigen_principal(s);
      // Near the apex both numerator and denominator shrink; round-off in
      // the stress is relative to sigma_ref, so scale the tolerance.
      const double gap = std::max((s_c - Eigen::Vector3d::Constant(md.apex)).norm(), 1e-300);
      const double ref = sigma_ref(t.s_b, c.cohesion);
      worst_surface = std::max(worst_surface, std::fabs(after - 1) * gap / ref);
      ASSERT_LE(std::fabs(after - 1), 1e-10 * ref / gap);
      // Shrinking the shear at a fixed s1 + s3 scales Eq. (32) linearly.
      const double mid = 0.5 * (s_c[0] + s_c[2]);
      for (const double share : {0.0, 0.25, 0.5, 0.9}) {
        const Eigen::Vector3d q = Eigen::Vector3d::Constant(mid) + share * (s_c.array() - mid).matrix();
        if (mid >= md.apex) break;
        ASSERT_NEAR(sim::relative_yield(md.mc, stress_of(q, t.zz_slot, t.theta)), share,
                    1e-9 * ref / gap);
      }
      ++surface;
    }
  }
  std::printf("relative yield: %d inside, %d returned; worst |f_rel - 1| * |s_C - s_a| / "
              "sigma_ref %.2e\n", inside, surface, worst_surface);
}

TEST(YieldFunction, IsEq20TimesTwoOverOneMinusSinPhi) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-500e3, 100e3);
  for (const Case& c : all_cases()) {
    const Model md = model_of(c);
    const double phi = deg(c.phi_deg);
    for (int n = 0; n < 200; ++n) {
      const sim::Stress s{u(rng), u(rng), 0.3 * u(rng), u(rng)};
      const Eigen::Vector3d p = eigen_principal(s);
      // Paper's ordering sigma_1 <= sigma_3: sigma_1 = p.min, sigma_3 = p.max.
      const double s1 = p.minCoeff(), s3 = p.maxCoeff();
      const double eq20 =
          0.5 * (s3 - s1) + 0.5 * (s1 + s3) * std::sin(phi) - c.cohesion * std::cos(phi);
      ASSERT_NEAR(sim::yield_function(md.mc, s), 2 / (1 - std::sin(phi)) * eq20, 1e-9 * 500e3);
    }
  }
}

TEST(MohrCoulombMake, RejectsOutOfRangeMaterials) {
  using sim::MohrCoulomb;
  EXPECT_NO_THROW(MohrCoulomb::make(kE, kNu, 0, deg(30), deg(30)));
  EXPECT_NO_THROW(MohrCoulomb::make(kE, 0.0, 40e3, deg(10), 0));
  EXPECT_THROW(MohrCoulomb::make(kE, kNu, 40e3, 0, 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb::make(kE, kNu, 40e3, deg(90), 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb::make(kE, kNu, 40e3, deg(30), deg(31)), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb::make(kE, kNu, 40e3, deg(30), -0.01), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb::make(kE, kNu, -1, deg(30), 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb::make(kE, 0.5, 40e3, deg(30), 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb::make(0, kNu, 40e3, deg(30), 0), std::invalid_argument);
}

}  // namespace
