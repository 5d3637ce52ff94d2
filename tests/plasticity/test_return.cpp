// The Mohr-Coulomb return (method notes section 2, Clausen et al. 2007) on
// 240,000 deterministic trial stresses: 10,000 for each combination of
// friction angle (10..40 deg), dilation (0, phi/2, phi) and cohesion (40 kPa,
// 0), i.e. 60,000 per friction angle.
// Tolerances are relative to sigma_ref = max(largest |trial principal|, c).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "trials.hpp"

namespace {

using namespace plasticity_test;
using sim::ReturnRegion;

const char* kRegionNames[5] = {"elastic", "plane", "edge s1=s2", "edge s2=s3", "apex"};

// Region counts of every case, printed as one table.
void print_counts(const char* title, const std::vector<Case>& cases,
                  const std::vector<std::array<int, 5>>& counts) {
  std::printf("%s\n  phi  psi   c[kPa]  %8s %8s %10s %10s %8s\n", title, kRegionNames[0],
              kRegionNames[1], kRegionNames[2], kRegionNames[3], kRegionNames[4]);
  for (std::size_t i = 0; i < cases.size(); ++i)
    std::printf("  %3.0f %4.1f %8.0f  %8d %8d %10d %10d %8d\n", cases[i].phi_deg, cases[i].psi_deg,
                cases[i].cohesion / 1e3, counts[i][0], counts[i][1], counts[i][2], counts[i][3],
                counts[i][4]);
}

// Full plane-strain path: random in-plane rotation and sigma_zz slot.
TEST(MohrCoulombReturn, TrialsLandOnTheSurfaceAndElasticOnesAreUntouched) {
  const std::vector<Case> cases = all_cases();
  std::vector<std::array<int, 5>> counts(cases.size(), std::array<int, 5>{});
  double worst_f = 0, worst_match = 0;
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Model md = model_of(cases[ci]);
    for (const Trial& t : make_trials(md, seed_of(static_cast<int>(ci)))) {
      const sim::Stress trial = stress_of(t.s_b, t.zz_slot, t.theta);
      sim::Stress s = trial;
      const ReturnRegion region = sim::mohr_coulomb_return(md.mc, s);
      ++counts[ci][static_cast<int>(region)];
      const double ref = sigma_ref(t.s_b, cases[ci].cohesion);
      if (region == ReturnRegion::Elastic) {
        ASSERT_EQ(std::memcmp(&s, &trial, sizeof s), 0) << "elastic trial changed";
        ASSERT_LE(yield_sorted(md, eigen_principal(trial)) / ref, 1e-12);
        continue;
      }
      const Eigen::Vector3d s_c = eigen_principal(s);
      const double f = std::fabs(yield_sorted(md, s_c)) / ref;
      worst_f = std::max(worst_f, f);
      ASSERT_LT(f, 1e-10) << "phi " << cases[ci].phi_deg << " region " << int(region);
      // Same answer as the principal-space return of the same trial.
      sim::Principal3 p = to_p3(t.s_b);
      sim::mohr_coulomb_return_principal(md.mc, p);
      const double match = (s_c - to_vec(p)).cwiseAbs().maxCoeff() / ref;
      worst_match = std::max(worst_match, match);
      ASSERT_LT(match, 1e-10);
    }
  }
  print_counts("plane-strain path, regions per case:", cases, counts);
  std::printf("worst |f(s_C)| / sigma_ref %.2e; worst plane-strain vs principal %.2e\n", worst_f,
              worst_match);
  for (std::size_t ci = 0; ci < cases.size(); ++ci)
    for (int r = 0; r < 5; ++r)
      EXPECT_GT(counts[ci][r], 0) << kRegionNames[r] << " never reached, phi " << cases[ci].phi_deg
                                  << " psi " << cases[ci].psi_deg << " c " << cases[ci].cohesion;
}

// Independent closed form of each region, solved here from the active
// planes' consistency conditions; throws nothing, returns s_C and whether
// the multipliers are non-negative.
struct ClosedForm {
  Eigen::Vector3d s_c;
  bool multipliers_non_negative = true;
};

ClosedForm closed_form(const Model& md, const Eigen::Vector3d& s_b, ReturnRegion region,
                       double ref) {
  const double m = md.m, k = md.k;
  const Eigen::Vector3d a13(k, 0, -1), a23(0, k, -1), a12(k, -1, 0);
  std::vector<Eigen::Vector3d> a, b;
  switch (region) {
    case ReturnRegion::Plane: a = {a13}; b = {b13(m)}; break;
    case ReturnRegion::EdgeS1EqS2: a = {a13, a23}; b = {b13(m), b23(m)}; break;
    case ReturnRegion::EdgeS2EqS3: a = {a13, a12}; b = {b13(m), b12(m)}; break;
    default: return {Eigen::Vector3d::Constant(md.apex), true};
  }
  const int n = static_cast<int>(a.size());
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd rhs(n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) M(r, c) = a[r].dot(md.D * b[c]);
    rhs(r) = a[r].dot(s_b) - md.sigma_c;
  }
  const Eigen::VectorXd lam = M.fullPivLu().solve(rhs);
  ClosedForm out{s_b, true};
  for (int c = 0; c < n; ++c) {
    out.s_c -= lam(c) * md.D * b[c];
    if (lam(c) * (md.D * b[c]).norm() < -1e-9 * ref) out.multipliers_non_negative = false;
  }
  return out;
}

TEST(MohrCoulombReturn, EachRegionMatchesItsClosedFormAndTheActiveSetSolution) {
  const std::vector<Case> cases = all_cases();
  std::vector<std::array<int, 5>> counts(cases.size(), std::array<int, 5>{});
  int several = 0, none = 0, built = 0;
  double worst_closed = 0, worst_brute = 0, worst_built = 0;
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Model md = model_of(cases[ci]);
    for (const Trial& t : make_trials(md, seed_of(static_cast<int>(ci)))) {
      sim::Principal3 p = to_p3(t.s_b);
      const ReturnRegion region = sim::mohr_coulomb_return_principal(md.mc, p);
      ++counts[ci][static_cast<int>(region)];
      const Eigen::Vector3d s_c = to_vec(p);
      const double ref = sigma_ref(t.s_b, cases[ci].cohesion);
      if (t.kind == Kind::Inside) {
        ASSERT_EQ(region, ReturnRegion::Elastic);
      }
      if (region == ReturnRegion::Elastic) {
        ASSERT_LE(yield_sorted(md, t.s_b), 0.0);
        continue;
      }
      ASSERT_GT(yield_sorted(md, t.s_b), 0.0);
      // The region's own formula, derived here independently.
      const ClosedForm cf = closed_form(md, t.s_b, region, ref);
      const double closed = (s_c - cf.s_c).cwiseAbs().maxCoeff() / ref;
      worst_closed = std::max(worst_closed, closed);
      ASSERT_LT(closed, 1e-10) << "region " << int(region);
      ASSERT_TRUE(cf.multipliers_non_negative) << "region " << int(region);
      // s_a + t l: exactly on the edge, bit for bit.
      if (region == ReturnRegion::EdgeS1EqS2) {
        ASSERT_EQ(s_c[0], s_c[1]);
      }
      if (region == ReturnRegion::EdgeS2EqS3) {
        ASSERT_EQ(s_c[1], s_c[2]);
      }
      // Every admissible return found by enumerating active sets.
      const std::vector<Eigen::Vector3d> admissible = admissible_returns(md, t.s_b, ref);
      if (admissible.empty()) {
        // Only psi = 0 beyond the apex: the flow keeps the mean stress and
        // no surface point has a mean above the apex; the return cuts off
        // at the apex (see mohr_coulomb.cpp).
        ++none;
        ASSERT_EQ(cases[ci].psi_deg, 0.0);
        ASSERT_EQ(region, ReturnRegion::Apex);
        ASSERT_GE(t.s_b.mean() - md.apex, -1e-12 * ref);
        continue;
      }
      if (admissible.size() > 1) ++several;
      double best = 1e300;
      for (const auto& s : admissible) best = std::min(best, (s - s_c).cwiseAbs().maxCoeff() / ref);
      worst_brute = std::max(worst_brute, best);
      ASSERT_LT(best, 1e-8) << "region " << int(region) << " trial " << t.s_b.transpose();
      if (t.has_expected) {
        ++built;
        const double e = (t.expected - s_c).cwiseAbs().maxCoeff() / ref;
        worst_built = std::max(worst_built, e);
        ASSERT_LT(e, 1e-8) << "built trial, kind " << int(t.kind) << " region " << int(region);
      }
    }
  }
  print_counts("principal path, regions per case:", cases, counts);
  std::printf("worst vs closed form %.2e, vs brute force %.2e, vs built answer %.2e (%d built)\n"
              "trials with several admissible returns %d, with none (psi = 0 tension) %d\n",
              worst_closed, worst_brute, worst_built, built, several, none);
  EXPECT_EQ(several, 0) << "the return is not unique for some trials";
  for (std::size_t ci = 0; ci < cases.size(); ++ci)
    for (int r = 1; r < 5; ++r) EXPECT_GT(counts[ci][r], 0) << kRegionNames[r];
}

// D^-1 (s_B - s_C) is the plastic strain increment (Eqs. 21, 22): a
// non-negative combination of the gradients of the active potentials.
TEST(MohrCoulombReturn, PlasticStrainIncrementFollowsThePotential) {
  const std::vector<Case> cases = all_cases();
  double worst_residual = 0;
  int checked[5] = {0, 0, 0, 0, 0};
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Model md = model_of(cases[ci]);
    const double m = md.m;
    for (const Trial& t : make_trials(md, seed_of(static_cast<int>(ci)))) {
      sim::Principal3 p = to_p3(t.s_b);
      const ReturnRegion region = sim::mohr_coulomb_return_principal(md.mc, p);
      if (region == ReturnRegion::Elastic) continue;
      const Eigen::Vector3d e = md.D_inv * (t.s_b - to_vec(p));
      if (e.norm() == 0) continue;
      Eigen::MatrixXd G;
      if (region == ReturnRegion::Plane) {
        // Parallel to b = (m, 0, -1) and pointing the same way.
        const double cross = e.cross(b13(m)).norm() / (e.norm() * b13(m).norm());
        worst_residual = std::max(worst_residual, cross);
        ASSERT_LT(cross, 1e-9);
        ASSERT_GT(e.dot(b13(m)), 0.0);
        ++checked[1];
        continue;
      }
      if (region == ReturnRegion::Apex && cases[ci].psi_deg == 0) {
        ASSERT_GE(t.s_b.mean() - md.apex, -1e-12 * sigma_ref(t.s_b, cases[ci].cohesion));
        continue;  // tension cut-off, no flow solution exists
      }
      if (region == ReturnRegion::EdgeS1EqS2) G = (Eigen::MatrixXd(3, 2) << b13(m), b23(m)).finished();
      if (region == ReturnRegion::EdgeS2EqS3) G = (Eigen::MatrixXd(3, 2) << b13(m), b12(m)).finished();
      if (region == ReturnRegion::Apex) {
        // All six planes meet at the apex, and near-hydrostatic trials need
        // gradients beyond b13, b23, b12: some three of the six must do.
        bool spanned = false;
        for (int i = 0; i < 6 && !spanned; ++i)
          for (int j = i + 1; j < 6 && !spanned; ++j)
            for (int l = j + 1; l < 6 && !spanned; ++l) {
              Eigen::Matrix3d B;
              B << md.b[i], md.b[j], md.b[l];
              if (std::fabs(B.determinant()) < 1e-12) continue;
              const Eigen::Vector3d lam = B.partialPivLu().solve(e);
              spanned = (lam.array() >= -1e-9 * e.norm()).all();
            }
        ASSERT_TRUE(spanned) << "apex: flow outside the cone of the six gradients";
        ++checked[4];
        continue;
      }
      const Eigen::VectorXd lam = G.colPivHouseholderQr().solve(e);
      const double residual = (G * lam - e).norm() / e.norm();
      worst_residual = std::max(worst_residual, residual);
      ASSERT_LT(residual, 1e-9) << "region " << int(region);
      for (int c = 0; c < lam.size(); ++c)
        ASSERT_GE(lam(c) * G.col(c).norm(), -1e-9 * e.norm()) << "region " << int(region);
      ++checked[static_cast<int>(region)];
    }
  }
  std::printf("flow checked: plane %d, edge s1=s2 %d, edge s2=s3 %d, apex (psi > 0) %d; "
              "worst relative residual %.2e\n",
              checked[1], checked[2], checked[3], checked[4], worst_residual);
  for (int r = 1; r < 5; ++r) EXPECT_GT(checked[r], 0) << kRegionNames[r];
}

}  // namespace
