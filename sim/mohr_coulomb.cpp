#include "sim/mohr_coulomb.hpp"

#include <algorithm>
#include <cmath>

namespace sim {

namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Principal elastic matrix D = lambda 1 1^T + 2 G I applied to v, and its inverse.
Vec3 apply_d(double lambda, double shear, const Vec3& v) {
  const double tr = lambda * (v[0] + v[1] + v[2]);
  return {tr + 2 * shear * v[0], tr + 2 * shear * v[1], tr + 2 * shear * v[2]};
}

Vec3 apply_d_inverse(double lambda, double shear, const Vec3& v) {
  const double tr = lambda / (2 * shear + 3 * lambda) * (v[0] + v[1] + v[2]);
  return {(v[0] - tr) / (2 * shear), (v[1] - tr) / (2 * shear), (v[2] - tr) / (2 * shear)};
}

}  // namespace

MohrCoulomb MohrCoulomb::make(double E, double nu, double c, double phi, double psi) {
  MohrCoulomb mc;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), shear = E / (2 * (1 + nu));
  mc.cohesion = c;
  mc.sin_phi = std::sin(phi);
  mc.cos_phi = std::cos(phi);
  mc.k = (1 + mc.sin_phi) / (1 - mc.sin_phi);
  mc.m = (1 + std::sin(psi)) / (1 - std::sin(psi));
  mc.sigma_c = 2 * c * std::sqrt(mc.k);
  mc.apex = c * mc.cos_phi / mc.sin_phi;
  // Plane: yield normal a = (k, 0, -1), potential gradient b = (m, 0, -1).
  const Vec3 a{mc.k, 0, -1}, b{mc.m, 0, -1};
  const Vec3 db = apply_d(lambda, shear, b);
  const double adb = dot(a, db);
  mc.plane_corrector = {db[0] / adb, db[1] / adb, db[2] / adb};
  mc.edge1 = {1, 1, mc.k};
  mc.edge2 = {1, mc.k, mc.k};
  mc.normal1 = cross(mc.plane_corrector, mc.edge1);
  mc.normal2 = cross(mc.plane_corrector, mc.edge2);
  // Edges: the return direction follows the potential's edge directions.
  const Vec3 r1 = apply_d_inverse(lambda, shear, {1, 1, mc.m});
  const Vec3 r2 = apply_d_inverse(lambda, shear, {1, mc.m, mc.m});
  const double n1 = dot(r1, mc.edge1), n2 = dot(r2, mc.edge2);
  mc.project1 = {r1[0] / n1, r1[1] / n1, r1[2] / n1};
  mc.project2 = {r2[0] / n2, r2[1] / n2, r2[2] / n2};
  return mc;
}

Principal principal_stresses(const Stress& s) {
  Principal p;
  const double centre = 0.5 * (s.xx + s.yy);
  const double half = 0.5 * (s.xx - s.yy);
  const double radius = std::sqrt(half * half + s.xy * s.xy);
  if (radius > 0) {
    p.cos2 = half / radius;
    p.sin2 = s.xy / radius;
  }
  const double hi = centre + radius, lo = centre - radius, zz = s.zz;
  // Slots: in-plane larger, in-plane smaller and zz, sorted descending.
  if (zz >= hi) {
    p.s = {zz, hi, lo};
    p.zz_slot = 0;
  } else if (zz >= lo) {
    p.s = {hi, zz, lo};
    p.zz_slot = 1;
  } else {
    p.s = {hi, lo, zz};
    p.zz_slot = 2;
  }
  return p;
}

Stress from_principal(const Principal& p, const Vec3& v) {
  // The in-plane values keep their order of slots: the larger in-plane value
  // sits in the first non-zz slot.
  const int a = p.zz_slot == 0 ? 1 : 0;
  const int b = p.zz_slot == 2 ? 1 : 2;
  const double hi = v[a], lo = v[b];
  const double centre = 0.5 * (hi + lo), half = 0.5 * (hi - lo);
  return Stress{centre + half * p.cos2, centre - half * p.cos2, half * p.sin2, v[p.zz_slot]};
}

double yield_function(const MohrCoulomb& mc, const Vec3& s) {
  return mc.k * s[0] - s[2] - mc.sigma_c;
}

double yield_function(const MohrCoulomb& mc, const Stress& s) {
  return yield_function(mc, principal_stresses(s).s);
}

ReturnRegion mohr_coulomb_return_principal(const MohrCoulomb& mc, Vec3& s) {
  const double f = yield_function(mc, s);
  if (f <= 0) return ReturnRegion::Elastic;
  const Vec3 d{s[0] - mc.apex, s[1] - mc.apex, s[2] - mc.apex};  // s_B - s_a
  const double t1 = dot(mc.project1, d), t2 = dot(mc.project2, d);
  if (t1 >= 0 && t2 >= 0) {
    s = {mc.apex, mc.apex, mc.apex};
    return ReturnRegion::Apex;
  }
  const double p1 = dot(mc.normal1, d), p2 = dot(mc.normal2, d);
  if (p1 >= 0 && p2 <= 0) {
    for (int i = 0; i < 3; ++i) s[i] -= f * mc.plane_corrector[i];
    return ReturnRegion::Plane;
  }
  if (p1 < 0) {
    for (int i = 0; i < 3; ++i) s[i] = mc.apex + t1 * mc.edge1[i];
    return ReturnRegion::EdgeS1EqS2;
  }
  for (int i = 0; i < 3; ++i) s[i] = mc.apex + t2 * mc.edge2[i];
  return ReturnRegion::EdgeS2EqS3;
}

ReturnRegion mohr_coulomb_return(const MohrCoulomb& mc, Stress& s) {
  Principal p = principal_stresses(s);
  if (yield_function(mc, p.s) <= 0) return ReturnRegion::Elastic;
  const ReturnRegion region = mohr_coulomb_return_principal(mc, p.s);
  s = from_principal(p, p.s);
  return region;
}

double relative_yield(const MohrCoulomb& mc, const Stress& s) {
  const Vec3 p = principal_stresses(s).s;
  // Eq. (32): max shear over the shear strength at this mean stress.
  const double strength = mc.cohesion * mc.cos_phi - 0.5 * (p[0] + p[2]) * mc.sin_phi;
  if (strength <= 0) return 1.0;
  return std::min(1.0, 0.5 * (p[0] - p[2]) / strength);
}

}  // namespace sim
