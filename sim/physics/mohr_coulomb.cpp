// Mohr-Coulomb return in principal stress space after Clausen, Damkilde &
// Andersen (2006, associated; 2007, non-associated flow). The yield function
// (paper Eq. 20) and the plastic potential (Eq. 23) are linear in the sorted
// principal stresses, so within each region of the trial-stress space the
// return (Eqs. 21, 22 over a finite step) is one linear map: no iteration and
// no tolerance. Formulas and region order: method notes, section 2.
#include "sim/physics/mohr_coulomb.hpp"

#include "sim/physics/mohr_coulomb_return.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sim {

namespace {

using mc_return::dot;

Principal3 cross(const Principal3& a, const Principal3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Principal3 scaled(const Principal3& v, double factor) {
  return {v[0] * factor, v[1] * factor, v[2] * factor};
}

// Isotropic elasticity in principal space, D = lambda 1 1^T + 2 G I: the
// principal directions are shared by stress and elastic strain, so the 6x6
// (here 4x4) matrix reduces to this 3x3 one (Clausen et al. 2006).
Principal3 apply_d(double lambda, double shear, const Principal3& v) {
  const double tr = lambda * (v[0] + v[1] + v[2]);
  return {tr + 2 * shear * v[0], tr + 2 * shear * v[1], tr + 2 * shear * v[2]};
}

Principal3 apply_d_inverse(double lambda, double shear, const Principal3& v) {
  const double tr = lambda / (2 * shear + 3 * lambda) * (v[0] + v[1] + v[2]);
  return {(v[0] - tr) / (2 * shear), (v[1] - tr) / (2 * shear), (v[2] - tr) / (2 * shear)};
}

void reject(const std::string& what) {
  throw std::invalid_argument("Mohr-Coulomb material: " + what);
}

}  // namespace

MohrCoulomb MohrCoulomb::make(double E, double nu, double c, double phi, double psi) {
  const double half_pi = 2 * std::atan(1.0);
  if (!(E > 0) || !std::isfinite(E)) reject("Young's modulus must be positive");
  if (!(nu > -1 && nu < 0.5)) reject("Poisson's ratio must be in (-1, 0.5)");
  if (!(c >= 0) || !std::isfinite(c)) reject("cohesion must be >= 0");
  if (!(phi > 0 && phi < half_pi)) reject("friction angle must be in (0, 90) degrees");
  if (!(psi >= 0 && psi <= phi)) reject("dilation angle must be in [0, friction angle]");

  MohrCoulomb mc;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), shear = E / (2 * (1 + nu));
  const double sin_psi = std::sin(psi);
  mc.cohesion = c;
  mc.friction_angle = phi;
  mc.dilation_angle = psi;
  mc.youngs_modulus = E;
  mc.poisson_ratio = nu;
  mc.sin_phi = std::sin(phi);
  mc.cos_phi = std::cos(phi);
  // Eq. (20) times 2 / (1 - sin phi) gives f = k s1 - s3 - sigma_c; Eq. (23)
  // the same way gives g = m s1 - s3: one slope each, so every gradient below
  // is a constant vector.
  mc.k = (1 + mc.sin_phi) / (1 - mc.sin_phi);
  mc.m = (1 + sin_psi) / (1 - sin_psi);
  mc.sigma_c = 2 * c * std::sqrt(mc.k);
  // All three principal stresses equal: (k - 1) s = sigma_c, i.e. c cot(phi).
  mc.apex = c * mc.cos_phi / mc.sin_phi;

  // Plane: s_C = s_B - dlambda D b with f(s_C) = 0, and f linear, gives
  // dlambda = f(s_B) / (a^T D b) (Clausen et al. 2007).
  const Principal3 a{mc.k, 0, -1}, b{mc.m, 0, -1};
  const Principal3 db = apply_d(lambda, shear, b);
  mc.plane_corrector = scaled(db, 1 / dot(a, db));

  // Edges as lines through the apex; t < 0 walks down towards compression.
  mc.edge1 = {1, 1, mc.k};
  mc.edge2 = {1, mc.k, mc.k};
  // A trial whose plane return lands exactly on edge i lies on the plane
  // through that edge spanned by r_p; its normal r_p x l_i tells the sides.
  mc.side1 = cross(mc.plane_corrector, mc.edge1);
  mc.side2 = cross(mc.plane_corrector, mc.edge2);

  // On an edge two potentials are active, so s_B - s_C lies in
  // span(D b_i, D b_j). r = D^-1 (b_i x b_j) is orthogonal to both (D is
  // symmetric), so r . (s_B - s_a - t l) = 0 fixes t. b_i x b_j is (1, 1, m)
  // for s1 = s2 (b = (m,0,-1), (0,m,-1)) and (1, m, m) for s2 = s3
  // (b = (m,0,-1), (m,-1,0)): the potential's own edge directions.
  const Principal3 r1 = apply_d_inverse(lambda, shear, {1, 1, mc.m});
  const Principal3 r2 = apply_d_inverse(lambda, shear, {1, mc.m, mc.m});
  mc.project1 = scaled(r1, 1 / dot(r1, mc.edge1));
  mc.project2 = scaled(r2, 1 / dot(r2, mc.edge2));
  return mc;
}

// The one-point forms of the select-form templates (mohr_coulomb_return.hpp).

namespace {

PrincipalStress to_principal(const mc_return::Sorted<double>& sorted, double cos2, double sin2) {
  PrincipalStress p;
  p.s = sorted.s;
  p.zz_slot = sorted.zz_first ? 0 : (sorted.zz_at_least_second ? 1 : 2);
  p.cos2 = cos2;
  p.sin2 = sin2;
  return p;
}

mc_return::Sorted<double> to_sorted(const PrincipalStress& p) {
  return {p.s, p.zz_slot == 0, p.zz_slot <= 1};
}

ReturnRegion region_of(const mc_return::Regions<double>& r) {
  if (r.apex) return ReturnRegion::Apex;
  if (r.plane) return ReturnRegion::Plane;
  return r.edge_s1_s2 ? ReturnRegion::EdgeS1EqS2 : ReturnRegion::EdgeS2EqS3;
}

}  // namespace

PrincipalStress principal_stresses(const Stress& s) {
  // Closed-form 2x2 eigenpair (Mohr's circle): this runs for every point in
  // every step, where a general eigen-solver would cost far more.
  const double radius = mc_return::circle_radius(s);
  double cos2, sin2;
  mc_return::principal_directions(s, radius, cos2, sin2);
  return to_principal(mc_return::principal_values(s, radius), cos2, sin2);
}

Stress from_principal(const PrincipalStress& p, const Principal3& v) {
  return mc_return::from_principal(to_sorted(p), p.cos2, p.sin2, v);
}

double yield_function(const MohrCoulomb& mc, const Principal3& s) {
  return mc_return::yield_function<double>(mc, s);
}

double yield_function(const MohrCoulomb& mc, const Stress& s) {
  return yield_function(mc, principal_stresses(s).s);
}

ReturnRegion mohr_coulomb_return_principal(const MohrCoulomb& mc, Principal3& s) {
  const double f = yield_function(mc, s);
  if (f <= 0) return ReturnRegion::Elastic;
  return region_of(mc_return::plastic_return(mc, s, f));
}

ReturnRegion mohr_coulomb_return(const MohrCoulomb& mc, Stress& s) {
  mc_return::Regions<double> regions;
  if (mc_return::return_in_place(mc, s, regions)) return ReturnRegion::Elastic;
  return region_of(regions);
}

double relative_yield(const MohrCoulomb& mc, const Stress& s) {
  const Principal3 p = principal_stresses(s).s;
  // Eq. (32): largest shear over the shear strength at that mean stress.
  // c cos(phi) - mean sin(phi) is written sin(phi) (apex - mean), which is
  // the same number but exactly 0 at the apex stress: the two terms would
  // leave a round-off residue there, and 0 / residue would paint a point
  // returned to the apex as hydrostatic.
  const double shear = 0.5 * (p[0] - p[2]);
  const double strength = mc.sin_phi * (mc.apex - 0.5 * (p[0] + p[2]));
  // At or beyond the apex (strength <= 0) and on or outside the surface: 1.
  if (shear >= strength) return 1.0;
  return shear / strength;
}

}  // namespace sim
