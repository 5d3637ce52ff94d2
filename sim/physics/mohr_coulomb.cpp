// Mohr-Coulomb return in principal stress space after Clausen, Damkilde &
// Andersen (2006, associated; 2007, non-associated flow). The yield function
// (paper Eq. 20) and the plastic potential (Eq. 23) are linear in the sorted
// principal stresses, so within each region of the trial-stress space the
// return (Eqs. 21, 22 over a finite step) is one linear map: no iteration and
// no tolerance. Formulas and region order: method notes, section 2.
#include "sim/physics/mohr_coulomb.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sim {

namespace {

double dot(const Principal3& a, const Principal3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

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

namespace {

// Mohr's circle of the in-plane stress: half the difference of the normal
// stresses and the radius.
double half_difference(const Stress& s) { return 0.5 * (s.xx - s.yy); }
double circle_radius(const Stress& s) {
  const double half = half_difference(s);
  return std::sqrt(half * half + s.xy * s.xy);
}

// The principal values alone, sorted; the directions (a division) are left
// to principal_directions, which only a plastic return needs.
void principal_values(const Stress& s, double radius, PrincipalStress& p) {
  const double centre = 0.5 * (s.xx + s.yy);
  const double hi = centre + radius, lo = centre - radius, zz = s.zz;
  // Plane strain: sigma_zz is a principal stress too and may sort anywhere.
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
}

void principal_directions(const Stress& s, double radius, PrincipalStress& p) {
  if (radius > 0) {
    const double inverse = 1 / radius;
    p.cos2 = half_difference(s) * inverse;
    p.sin2 = s.xy * inverse;
  }
}

}  // namespace

PrincipalStress principal_stresses(const Stress& s) {
  // Closed-form 2x2 eigenpair (Mohr's circle): this runs for every point in
  // every step, where a general eigen-solver would cost far more.
  PrincipalStress p;
  const double radius = circle_radius(s);
  principal_values(s, radius, p);
  principal_directions(s, radius, p);
  return p;
}

Stress from_principal(const PrincipalStress& p, const Principal3& v) {
  // The first non-zz slot holds the value on the (cos theta, sin theta)
  // direction, the second the one on the perpendicular direction. Writing
  // v_a n n^T + v_b t t^T in double-angle form holds whichever of the two is
  // larger, so the slots need no reordering.
  const int a = p.zz_slot == 0 ? 1 : 0;
  const int b = p.zz_slot == 2 ? 1 : 2;
  const double centre = 0.5 * (v[a] + v[b]), half = 0.5 * (v[a] - v[b]);
  return Stress{centre + half * p.cos2, centre - half * p.cos2, half * p.sin2, v[p.zz_slot]};
}

double yield_function(const MohrCoulomb& mc, const Principal3& s) {
  return mc.k * s[0] - s[2] - mc.sigma_c;
}

double yield_function(const MohrCoulomb& mc, const Stress& s) {
  return yield_function(mc, principal_stresses(s).s);
}

namespace {

// Clausen et al. (2007) regions for a sorted trial with f = f(s) > 0, tested
// in the method notes' order; `s` becomes s_C.
ReturnRegion plastic_return(const MohrCoulomb& mc, Principal3& s, double f) {
  const Principal3 d{s[0] - mc.apex, s[1] - mc.apex, s[2] - mc.apex};  // s_B - s_a
  // t_i is where the edge-i return would land; t_i >= 0 for both edges means
  // either would land at or past the apex: the trial lies in the cone of
  // return directions from the apex. With psi = 0 the gradients are
  // deviatoric, the return keeps the mean stress, and no point of the
  // surface has a mean above the apex: then t1 and t2 are positive multiples
  // of (mean - apex) and this test sends exactly those trials to the apex
  // (a tension cut-off; the only case without a plastic-flow solution).
  const double t1 = dot(mc.project1, d), t2 = dot(mc.project2, d);
  if (t1 >= 0 && t2 >= 0) {
    s = {mc.apex, mc.apex, mc.apex};
    return ReturnRegion::Apex;
  }
  // Between the two boundary planes the plane return stays sorted
  // (s1 >= s2 >= s3), i.e. on the facet between the edges.
  const double p1 = dot(mc.side1, d), p2 = dot(mc.side2, d);
  if (p1 >= 0 && p2 <= 0) {
    for (int i = 0; i < 3; ++i) s[i] -= f * mc.plane_corrector[i];
    return ReturnRegion::Plane;
  }
  // s_a + t l puts the returned values exactly on the edge (s1 == s2 or
  // s2 == s3 bit for bit) and exactly on the surface up to round-off in t.
  if (p1 < 0) {
    for (int i = 0; i < 3; ++i) s[i] = mc.apex + t1 * mc.edge1[i];
    return ReturnRegion::EdgeS1EqS2;
  }
  for (int i = 0; i < 3; ++i) s[i] = mc.apex + t2 * mc.edge2[i];
  return ReturnRegion::EdgeS2EqS3;
}

}  // namespace

ReturnRegion mohr_coulomb_return_principal(const MohrCoulomb& mc, Principal3& s) {
  const double f = yield_function(mc, s);
  if (f <= 0) return ReturnRegion::Elastic;
  return plastic_return(mc, s, f);
}

ReturnRegion mohr_coulomb_return(const MohrCoulomb& mc, Stress& s) {
  PrincipalStress p;
  const double radius = circle_radius(s);
  principal_values(s, radius, p);
  const double f = yield_function(mc, p.s);
  if (f <= 0) return ReturnRegion::Elastic;  // untouched: no round trip through p
  principal_directions(s, radius, p);
  const ReturnRegion region = plastic_return(mc, p.s, f);
  // Isotropic elasticity and isotropic f, g: the return changes principal
  // values only, so they go back on the trial's principal directions.
  s = from_principal(p, p.s);
  return region;
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
