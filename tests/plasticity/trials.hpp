// Shared by the plasticity tests: an independent model of the Mohr-Coulomb
// material (built from the angles, not from sim::MohrCoulomb's constants), a
// deterministic set of trial stresses around the yield surface, and a
// brute-force active-set solution of the return to check the closed forms.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "sim/physics/mohr_coulomb.hpp"

namespace plasticity_test {

constexpr double kE = 20e6, kNu = 0.25;  // the paper's soil and house stiffness
constexpr double kPi = 3.14159265358979323846;
constexpr int kTrialsPerCase = 10000;

inline double deg(double d) { return d * kPi / 180.0; }

struct Case {
  double phi_deg = 0, psi_deg = 0, cohesion = 0;
};

// Friction 10..40 degrees, dilation 0, phi/2, phi, cohesion 40 kPa and 0.
inline std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const double phi : {10.0, 20.0, 30.0, 40.0})
    for (const double share : {0.0, 0.5, 1.0})
      for (const double c : {40e3, 0.0}) cases.push_back({phi, share * phi, c});
  return cases;
}

// Independent model in unsorted principal space: the six planes
// f_ij = k s_i - s_j - sigma_c (i != j) and their potential gradients
// b_ij = m e_i - e_j, so the brute force below needs no sorting.
struct Model {
  double k = 0, m = 0, sigma_c = 0, apex = 0;
  Eigen::Matrix3d D, D_inv;
  std::array<Eigen::Vector3d, 6> a, b, Db;
  sim::MohrCoulomb mc;
};

inline Model model_of(const Case& c) {
  Model md;
  const double sp = std::sin(deg(c.phi_deg)), ss = std::sin(deg(c.psi_deg));
  md.k = (1 + sp) / (1 - sp);
  md.m = (1 + ss) / (1 - ss);
  md.sigma_c = 2 * c.cohesion * std::sqrt(md.k);
  md.apex = md.sigma_c / (md.k - 1);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), shear = kE / (2 * (1 + kNu));
  md.D = lambda * Eigen::Matrix3d::Ones() + 2 * shear * Eigen::Matrix3d::Identity();
  md.D_inv = md.D.inverse();
  int n = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      md.a[n] = md.k * Eigen::Vector3d::Unit(i) - Eigen::Vector3d::Unit(j);
      md.b[n] = md.m * Eigen::Vector3d::Unit(i) - Eigen::Vector3d::Unit(j);
      md.Db[n] = md.D * md.b[n];
      ++n;
    }
  md.mc = sim::MohrCoulomb::make(kE, kNu, c.cohesion, deg(c.phi_deg), deg(c.psi_deg));
  return md;
}

// Gradients of the sorted potential g = m s1 - s3 and of the two planes that
// meet it on each edge: b13 everywhere, b23 on s1 = s2, b12 on s2 = s3.
inline Eigen::Vector3d b13(double m) { return {m, 0, -1}; }
inline Eigen::Vector3d b23(double m) { return {0, m, -1}; }
inline Eigen::Vector3d b12(double m) { return {m, -1, 0}; }

inline double yield_sorted(const Model& md, const Eigen::Vector3d& s) {
  return md.k * s.maxCoeff() - s.minCoeff() - md.sigma_c;
}

inline Eigen::Vector3d sorted_desc(Eigen::Vector3d v) {
  std::sort(v.data(), v.data() + 3, [](double x, double y) { return x > y; });
  return v;
}

inline sim::Principal3 to_p3(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }
inline Eigen::Vector3d to_vec(const sim::Principal3& v) { return {v[0], v[1], v[2]}; }

// sigma_ref for the tolerances: the largest trial component or c, whichever
// is larger (every trial here has components of order 1e4..1e6 Pa).
inline double sigma_ref(const Eigen::Vector3d& trial, double cohesion) {
  return std::max(trial.cwiseAbs().maxCoeff(), cohesion);
}

// Plane-strain stress with sorted principal values s, sigma_zz in slot
// zz_slot and the larger in-plane value along (cos theta, sin theta).
inline sim::Stress stress_of(const Eigen::Vector3d& s, int zz_slot, double theta) {
  const int a = zz_slot == 0 ? 1 : 0, b = zz_slot == 2 ? 1 : 2;
  const double c = std::cos(theta), n = std::sin(theta);
  return sim::Stress{s[a] * c * c + s[b] * n * n, s[a] * n * n + s[b] * c * c, (s[a] - s[b]) * c * n,
                     s[zz_slot]};
}

// Principal values of a Stress by a general eigen-solver, sorted descending.
inline Eigen::Vector3d eigen_principal(const sim::Stress& s) {
  Eigen::Matrix2d m;
  m << s.xx, s.xy, s.xy, s.yy;
  const Eigen::Vector2d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(m).eigenvalues();
  return sorted_desc({e[0], e[1], s.zz});
}

enum class Kind { Box, Tension, Plane, Edge1, Edge2, Apex, Inside };

struct Trial {
  Eigen::Vector3d s_b;           // sorted trial
  Kind kind = Kind::Box;
  bool has_expected = false;     // built as s_C + D (sum of lambda_i b_i), lambda_i >= 0
  Eigen::Vector3d expected{0, 0, 0};
  int zz_slot = 0;
  double theta = 0;
};

// Deterministic trials for one case: 40 % uniform in a box around the cone,
// 10 % in tension beyond the apex, 50 % built from a point on the plane, an
// edge, the apex or inside, plus a random admissible plastic step.
inline std::vector<Trial> make_trials(const Model& md, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double R = 200e3, a = md.apex;
  std::vector<Trial> trials(kTrialsPerCase);
  for (int n = 0; n < kTrialsPerCase; ++n) {
    Trial& t = trials[n];
    const int mode = n % 10;
    Eigen::Vector3d s;
    if (mode < 4) {
      t.kind = Kind::Box;
      for (int i = 0; i < 3; ++i) s[i] = a + R * (-3 + 3.5 * u01(rng));
    } else if (mode == 4) {
      t.kind = Kind::Tension;
      const Eigen::Vector3d dev(normal(rng), normal(rng), normal(rng));
      s = Eigen::Vector3d::Constant(a + R * u01(rng)) +
          0.5 * R * (dev - Eigen::Vector3d::Constant(dev.mean()));
    } else {
      t.kind = static_cast<Kind>(mode - 5 + static_cast<int>(Kind::Plane));
      // On the surface: s1 = a + u, s3 = a + k u (u <= 0), s2 between.
      const double u = t.kind == Kind::Apex ? 0.0 : -R * 3 * u01(rng);
      const double w = t.kind == Kind::Edge1 ? 1.0 : t.kind == Kind::Edge2 ? 0.0 : u01(rng);
      const double s1 = a + u, s3 = a + md.k * u;
      const Eigen::Vector3d on(s1, s3 + w * (s1 - s3), s3);
      Eigen::Vector3d flow = Eigen::Vector3d::Zero();
      auto add = [&](const Eigen::Vector3d& g) {
        const Eigen::Vector3d dg = md.D * g;
        flow += u01(rng) * 2 * R / dg.norm() * dg;
      };
      if (t.kind == Kind::Inside) {
        flow = -R * u01(rng) * Eigen::Vector3d::Ones();  // lowers f by (k - 1) R u
      } else {
        add(b13(md.m));
        if (t.kind == Kind::Edge1 || t.kind == Kind::Apex) add(b23(md.m));
        if (t.kind == Kind::Edge2 || t.kind == Kind::Apex) add(b12(md.m));
      }
      s = on + flow;
      // The return commutes with permuting the principal axes: sort s_B and
      // apply the same permutation to the expected s_C.
      std::array<int, 3> order{0, 1, 2};
      std::sort(order.begin(), order.end(), [&](int i, int j) { return s[i] > s[j]; });
      t.has_expected = true;
      for (int i = 0; i < 3; ++i) t.expected[i] = t.kind == Kind::Inside ? s[order[i]] : on[order[i]];
    }
    t.s_b = sorted_desc(s);
    t.zz_slot = static_cast<int>(rng() % 3);
    t.theta = kPi * (2 * u01(rng) - 1);
  }
  return trials;
}

inline std::uint64_t seed_of(int case_index) { return 0x5eedULL * 1000003ULL + case_index; }

// Every stress s_C = s_B - D sum(lambda_i b_i) with lambda_i >= 0 over an
// active set of up to three of the six planes, all planes satisfied:
// the discrete consistency conditions, solved by enumeration.
inline std::vector<Eigen::Vector3d> admissible_returns(const Model& md, const Eigen::Vector3d& s_b,
                                                       double scale) {
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
  using SmallVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
  std::vector<Eigen::Vector3d> found;
  for (int mask = 1; mask < 64; ++mask) {
    int idx[6], n = 0;
    for (int i = 0; i < 6; ++i)
      if (mask >> i & 1) idx[n++] = i;
    if (n > 3) continue;
    Small M(n, n);
    SmallVec rhs(n);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) M(r, c) = md.a[idx[r]].dot(md.Db[idx[c]]);
      rhs(r) = md.a[idx[r]].dot(s_b) - md.sigma_c;
    }
    const Eigen::FullPivLU<Small> lu(M);
    if (lu.rank() < n) continue;
    const SmallVec lam = lu.solve(rhs);
    if ((M * lam - rhs).norm() > 1e-12 * scale * (1 + md.k)) continue;
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    bool ok = true;
    for (int c = 0; c < n; ++c) {
      step += lam(c) * md.Db[idx[c]];
      if (lam(c) * md.Db[idx[c]].norm() < -1e-9 * scale) ok = false;
    }
    const Eigen::Vector3d s_c = s_b - step;
    for (int i = 0; i < 6 && ok; ++i)
      if (md.a[i].dot(s_c) - md.sigma_c > 1e-9 * scale) ok = false;
    if (!ok) continue;
    bool seen = false;
    for (const auto& f : found) seen = seen || (f - s_c).norm() < 1e-7 * scale;
    if (!seen) found.push_back(s_c);
  }
  return found;
}

}  // namespace plasticity_test
