// Mohr-Coulomb plasticity with non-associated flow (paper Eqs. 20-23),
// returned to the yield surface in principal stress space by the method of
// Clausen, Damkilde & Andersen (2006, 2007): one closed-form projection per
// region (plane, two edges, apex), no iteration. Method notes, section 2.
//
// Convention: tension positive, principal stresses s1 >= s2 >= s3. The
// paper's Eq. (20) orders them the other way round; the surface is the same.
#pragma once

#include <array>

#include "sim/stress.hpp"

namespace sim {

using Vec3 = std::array<double, 3>;

enum class ReturnRegion : unsigned char { Elastic, Plane, EdgeS1EqS2, EdgeS2EqS3, Apex };

struct MohrCoulomb {
  double cohesion = 0, sin_phi = 0, cos_phi = 1;
  double k = 1;        // (1 + sin phi) / (1 - sin phi)
  double m = 1;        // (1 + sin psi) / (1 - sin psi)
  double sigma_c = 0;  // 2 c sqrt(k), uniaxial compressive strength
  double apex = 0;     // c cot(phi): the apex is (apex, apex, apex)
  Vec3 plane_corrector{};  // r_p = D b / (a^T D b)
  Vec3 edge1{}, edge2{};   // l1 = (1, 1, k), l2 = (1, k, k)
  Vec3 normal1{}, normal2{};    // r_p x l1, r_p x l2: which side of the plane region
  Vec3 project1{}, project2{};  // r_i / (r_i . l_i): edge parameter t from s_B - apex

  static MohrCoulomb make(double youngs_modulus, double poisson_ratio, double cohesion,
                          double friction_angle, double dilation_angle);
};

// Principal stresses of a plane-strain stress and where they came from.
struct Principal {
  Vec3 s{};           // s1 >= s2 >= s3
  int zz_slot = 0;    // which of s[0..2] is sigma_zz
  double cos2 = 1, sin2 = 0;  // in-plane direction of the larger in-plane value (2 theta)
};

Principal principal_stresses(const Stress& s);
// Puts principal values (in the slots of `p`) back on p's directions.
Stress from_principal(const Principal& p, const Vec3& values);

// f = k s1 - s3 - sigma_c: negative inside, zero on the surface.
double yield_function(const MohrCoulomb& mc, const Vec3& s);
double yield_function(const MohrCoulomb& mc, const Stress& s);

// Returns a trial stress to the yield surface in place; leaves it untouched
// (bit for bit) when it is inside.
ReturnRegion mohr_coulomb_return(const MohrCoulomb& mc, Stress& s);
// The same in principal space (for tests): returns s_C for trial s_B.
ReturnRegion mohr_coulomb_return_principal(const MohrCoulomb& mc, Vec3& s);

// Relative yield of the paper's Eq. (32): 0 hydrostatic, 1 on the surface;
// 1 where the mean stress is at or beyond the apex.
double relative_yield(const MohrCoulomb& mc, const Stress& s);

}  // namespace sim
