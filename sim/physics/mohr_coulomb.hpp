// Mohr-Coulomb plasticity with non-associated flow (paper Eqs. 20-23),
// returned to the yield surface in principal stress space by the method of
// Clausen, Damkilde & Andersen (2006, 2007): one closed-form projection per
// region (plane, two edges, apex), no iteration. Method notes, section 2.
//
// Convention: tension positive, principal stresses sorted s1 >= s2 >= s3.
// The paper's Eq. (20) orders them the other way round (sigma_1 <= sigma_3);
// the surface and the flow are the same.
#pragma once

#include <array>

#include "sim/physics/stress.hpp"

namespace sim {

// Principal values, or a direction in principal stress space.
using Principal3 = std::array<double, 3>;

enum class ReturnRegion : unsigned char { Elastic, Plane, EdgeS1EqS2, EdgeS2EqS3, Apex };

// Everything the return needs for one material, computed once by make() so
// the per-point return does no trigonometry and no allocation.
struct MohrCoulomb {
  double cohesion = 0, sin_phi = 0, cos_phi = 1;
  double k = 1;        // (1 + sin phi) / (1 - sin phi): slope of the yield plane
  double m = 1;        // (1 + sin psi) / (1 - sin psi): slope of the potential
  double sigma_c = 0;  // 2 c sqrt(k), uniaxial compressive strength
  double apex = 0;     // c cot(phi): the apex is (apex, apex, apex)
  Principal3 plane_corrector{};   // r_p = D b / (a^T D b)
  Principal3 edge1{}, edge2{};    // l1 = (1, 1, k) (s1 = s2), l2 = (1, k, k) (s2 = s3)
  Principal3 side1{}, side2{};    // r_p x l1, r_p x l2: p_I, p_II bound the plane region
  Principal3 project1{}, project2{};  // r_i / (r_i . l_i): edge parameter t_i from s_B - s_a
  // What it was made from, read only to show it or to make another surface
  // of the same soil (sim/physics/point_strength.hpp, painted fields).
  double friction_angle = 0, dilation_angle = 0, youngs_modulus = 0, poisson_ratio = 0;

  // Angles in radians: friction in (0, pi/2), dilation in [0, friction];
  // cohesion >= 0 (0 puts the apex at the origin); E > 0, nu in (-1, 0.5).
  // Throws std::invalid_argument otherwise.
  static MohrCoulomb make(double youngs_modulus, double poisson_ratio, double cohesion,
                          double friction_angle_rad, double dilation_angle_rad);
  // The same soil (stiffness, dilation) with another cohesion and friction angle.
  MohrCoulomb with_strength(double cohesion, double friction_angle_rad) const {
    return make(youngs_modulus, poisson_ratio, cohesion, friction_angle_rad, dilation_angle);
  }
};

// Principal decomposition of a plane-strain stress: the three values sorted,
// which of them is sigma_zz, and the in-plane direction of the larger
// in-plane value as (cos 2 theta, sin 2 theta), theta measured from x.
struct PrincipalStress {
  Principal3 s{};             // s1 >= s2 >= s3
  int zz_slot = 0;            // index of sigma_zz in s
  double cos2 = 1, sin2 = 0;  // (1, 0) when the in-plane values are equal
};

PrincipalStress principal_stresses(const Stress& s);
// Puts new values for the slots of `p` back on p's principal directions.
Stress from_principal(const PrincipalStress& p, const Principal3& values);

// f = k s1 - s3 - sigma_c (method notes' convention, s sorted descending):
// negative inside, zero on the surface. It is 2 / (1 - sin phi) times the
// paper's Eq. (20), so both vanish on the same surface.
double yield_function(const MohrCoulomb& mc, const Principal3& sorted);
double yield_function(const MohrCoulomb& mc, const Stress& s);

// Returns the elastic trial stress to the yield surface in place and says
// which region it went through. Elastic trials are left untouched bit for bit.
// With psi = 0 (no plastic volume change) a trial whose mean stress is at or
// beyond the apex has no admissible return; it goes to the apex (see .cpp).
ReturnRegion mohr_coulomb_return(const MohrCoulomb& mc, Stress& s);
// The same in principal space: `sorted` is s_B on entry, s_C on exit.
ReturnRegion mohr_coulomb_return_principal(const MohrCoulomb& mc, Principal3& sorted);

// Relative yield of the paper's Eq. (32) over the three principal stresses:
// 0 hydrostatic, 1 on the yield surface, in [0, 1) inside; 1 where the mean
// of s1 and s3 is at or beyond the apex and clamped to 1 outside the surface.
double relative_yield(const MohrCoulomb& mc, const Stress& s);

}  // namespace sim
