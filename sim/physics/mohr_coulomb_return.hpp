// The Mohr-Coulomb return of mohr_coulomb.hpp written once for one point
// (T = double) and for eight (T = Lane8, lanes.hpp), with selects (?:) in
// place of branches: every region's result is computed and the trial's own
// region is kept. Each lane is bit for bit what the one-point form gives;
// the step runs the eight-point form (sim/physics/point_update.cpp), the tests
// and the painted fields the one-point form (mohr_coulomb.cpp).
//
// C is the surface's constants, MohrCoulomb itself or MohrCoulombLanes below:
// the same names, doubles or Lane8s.
#pragma once

#include <array>
#include <cmath>
#include <type_traits>

#include "sim/physics/gimp.hpp"
#include "sim/physics/mohr_coulomb.hpp"
#include "sim/physics/point_strength.hpp"

namespace sim {

template <class T>
using Principal3Of = std::array<T, 3>;

// The constants of eight points' surfaces, one lane each.
struct MohrCoulombLanes {
  Lane8 k, sigma_c, apex;
  Principal3Of<Lane8> plane_corrector, side1, side2, project1, project2;
};

// Lane l holds the constants of *surfaces[l].
inline MohrCoulombLanes surface_lanes(const MohrCoulomb* const surfaces[8]) {
  MohrCoulombLanes c;
  for (int l = 0; l < 8; ++l)
    pair_surface_constants(c, *surfaces[l], [l](Lane8& lanes, const double& v) { lanes[l] = v; });
  return c;
}

// The constants of eight points' own surfaces (point_strength.hpp): `load`
// gives the eight points' lanes of one of its arrays.
template <class Load>
MohrCoulombLanes surface_lanes(const SurfaceArrays& a, Load load) {
  MohrCoulombLanes c;
  pair_surface_constants(c, a,
                         [&](Lane8& lanes, const std::vector<double>& v) { lanes = load(v); });
  return c;
}

namespace mc_return {

inline double square_root(double x) { return std::sqrt(x); }
inline Lane8 square_root(const Lane8& x) {
  Lane8 r;
  for (int l = 0; l < 8; ++l) r[l] = std::sqrt(x[l]);  // one vsqrtpd: sqrt is exact in IEEE
  return r;
}

template <class T>
T dot(const Principal3Of<T>& a, const Principal3Of<T>& b) {
  return fused(a[2], b[2], fused(a[1], b[1], a[0] * b[0]));
}

// Mohr's circle of the in-plane stress: half the difference of the normal
// stresses and the radius.
template <class T>
T half_difference(const StressOf<T>& s) {
  return 0.5 * (s.xx - s.yy);
}
template <class T>
T squared_radius(const StressOf<T>& s) {
  const T half = half_difference(s);
  return fused(half, half, s.xy * s.xy);
}
template <class T>
T circle_radius(const StressOf<T>& s) {
  return square_root(squared_radius(s));
}

// Eight radii, each at least circle_radius's, from the processor's 14-bit
// estimate of 1 / sqrt (relative error below 2^-14) raised by 2^-12: the
// vector square root's latency held up the stress phase, and most groups of
// a slope at rest are inside the surface. Only where the build has an
// estimate; without one, return_in_place does not call this. q * rsqrt(q)
// is NaN at q = 0 (0 * inf) and at q = inf (inf * 0, a radius past 2^512):
// the radius is 0 at the one and infinite at the other. Without the second,
// an AMD EPYC with AVX-512 (Zen 5) gave NaN there, and
// MohrCoulombReturnLanes.RadiusEstimateBoundsTheRadius failed (issue 17,
// forty-fifth pass); a NaN radius failed the test of f as an infinite one
// does, so results were the same either way.
#if defined(__AVX512F__)
constexpr bool kRadiusEstimate = true;
inline Lane8 radius_above(const StressOf<Lane8>& s) {
  const Lane8 q = squared_radius(s);
  const Lane8 estimate =
      q < HUGE_VAL ? q * _mm512_rsqrt14_pd(q) * (1.0 + 0x1p-12) : Lane8{} + HUGE_VAL;
  return q > 0 ? estimate : Lane8{};
}
#elif defined(__AVX__)
// With AVX alone the estimate is single precision: q rounded to a float
// (relative error 2^-24), then rsqrtps (at most 1.5 * 2^-12 by the Intel
// and AMD manuals), so the radius is raised by 2^-10. Below the floats'
// normal range the estimate is infinite (rsqrt of 0), still a bound; above
// it, where rsqrt(inf) = 0 would not be, the radius is set infinite. On an
// AMD EPYC (AVX2), one thread, the stress phase went from 40.0 to 37.4 ns a
// point on the slope and from 44.7 to 40.8 on the column, least of 8 and 6
// rounds (issue 17, thirty-fifth pass).
constexpr bool kRadiusEstimate = true;
inline Lane8 radius_above(const StressOf<Lane8>& s) {
  const Lane8 q = squared_radius(s);
  const __m256 r =
      _mm256_rsqrt_ps(_mm256_set_m128(_mm256_cvtpd_ps(high4(q)), _mm256_cvtpd_ps(low4(q))));
  const Lane8 inverse = join4(_mm256_cvtps_pd(_mm256_castps256_ps128(r)),
                              _mm256_cvtps_pd(_mm256_extractf128_ps(r, 1)));
  const Lane8 estimate = q < 0x1p120 ? q * inverse * (1.0 + 0x1p-10) : Lane8{} + HUGE_VAL;
  return q > 0 ? estimate : Lane8{};
}
#else
constexpr bool kRadiusEstimate = false;
#endif

// The principal values sorted, s1 >= s2 >= s3, and where sigma_zz went:
// plane strain makes it a principal stress that may sort anywhere.
template <class T>
struct Sorted {
  Principal3Of<T> s;
  decltype(T{} < T{}) zz_first, zz_at_least_second;  // zz in slot 0; in slot 0 or 1
};

template <class T>
Sorted<T> principal_values(const StressOf<T>& s, const T& radius) {
  const T centre = 0.5 * (s.xx + s.yy);
  const T hi = centre + radius, lo = centre - radius, zz = s.zz;
  const auto first = zz >= hi, second = zz >= lo;
  return {{first ? zz : hi, first ? hi : (second ? zz : lo), first ? lo : (second ? lo : zz)},
          first,
          second};
}

// The in-plane direction of the larger in-plane value as (cos 2 theta,
// sin 2 theta), theta from x; (1, 0) when the in-plane values are equal.
template <class T>
void principal_directions(const StressOf<T>& s, const T& radius, T& cos2, T& sin2) {
  const T inverse = 1 / radius;  // infinite at radius 0, and then not kept
  const auto circle = radius > 0;
  cos2 = circle ? half_difference(s) * inverse : T{} + 1.0;
  sin2 = circle ? s.xy * inverse : T{};
}

// New values for the slots of `sorted` put back on its principal directions.
// The first non-zz slot holds the value on the (cos theta, sin theta)
// direction, the second the one on the perpendicular direction. Writing
// v_a n n^T + v_b t t^T in double-angle form holds whichever of the two is
// larger, so the slots need no reordering.
template <class T>
StressOf<T> from_principal(const Sorted<T>& sorted, const T& cos2, const T& sin2,
                           const Principal3Of<T>& v) {
  const T va = sorted.zz_first ? v[1] : v[0];
  const T vb = sorted.zz_first || sorted.zz_at_least_second ? v[2] : v[1];
  const T zz = sorted.zz_first ? v[0] : (sorted.zz_at_least_second ? v[1] : v[2]);
  const T centre = 0.5 * (va + vb), half = 0.5 * (va - vb);
  return {fused(half, cos2, centre), fused(-half, cos2, centre), half * sin2, zz};
}

// f = k s1 - s3 - sigma_c (mohr_coulomb.hpp): negative inside.
template <class T, class C>
T yield_function(const C& mc, const Principal3Of<T>& s) {
  return fused(mc.k, s[0], -s[2]) - mc.sigma_c;
}

template <class T>
struct Regions {
  decltype(T{} < T{}) apex, plane, edge_s1_s2;  // otherwise the s2 = s3 edge
};

// Clausen et al. (2007) regions for a sorted trial with f = f(s) > 0, tested
// in the method notes' order; `s` becomes s_C.
//
// t_i is where the edge-i return would land; t_i >= 0 for both edges means
// either would land at or past the apex: the trial lies in the cone of
// return directions from the apex. With psi = 0 the gradients are
// deviatoric, the return keeps the mean stress, and no point of the surface
// has a mean above the apex: then t1 and t2 are positive multiples of
// (mean - apex) and this test sends exactly those trials to the apex (a
// tension cut-off; the only case without a plastic-flow solution).
// Between the two boundary planes p_I, p_II the plane return stays sorted
// (s1 >= s2 >= s3), on the facet between the edges. s_a + t l puts the
// returned values exactly on an edge (s1 == s2 or s2 == s3 bit for bit) and
// on the surface up to round-off in t.
template <class T, class C>
Regions<T> plastic_return(const C& mc, Principal3Of<T>& s, const T& f) {
  const Principal3Of<T> d{s[0] - mc.apex, s[1] - mc.apex, s[2] - mc.apex};  // s_B - s_a
  const T t1 = dot(mc.project1, d), t2 = dot(mc.project2, d);
  const T p1 = dot(mc.side1, d), p2 = dot(mc.side2, d);
  const Regions<T> r{t1 >= 0 && t2 >= 0, p1 >= 0 && p2 <= 0, p1 < 0};
  // The edges' directions l1 = (1, 1, k), l2 = (1, k, k) (MohrCoulomb::edge1,
  // edge2), made from k here: eight points' surfaces then gather six
  // fewer vectors.
  const T one = T{} + 1.0;
  const Principal3Of<T> l1{one, one, mc.k}, l2{one, mc.k, mc.k};
  for (int i = 0; i < 3; ++i) {
    const T plane = fused(-f, mc.plane_corrector[i], s[i]);
    const T edge1 = fused(t1, l1[i], mc.apex), edge2 = fused(t2, l2[i], mc.apex);
    s[i] = r.apex ? T{} + mc.apex : (r.plane ? plane : (r.edge_s1_s2 ? edge1 : edge2));
  }
  return r;
}

// The return of a trial stress in place; the mask of the trials that were
// inside the surface, left untouched bit for bit (`regions` is set only
// where some trial was outside). Isotropic elasticity and
// isotropic f, g: the return changes principal values only, so they go back
// on the trial's principal directions.
//
// Where the build has radius_above, eight points first test f with it (with
// the radii themselves the test would be the exact one below, done twice).
// Every operation of principal_values and yield_function is correctly
// rounded, and so monotone, and f grows with the radius (k > 0): f <= 0 in every lane with
// radii at least the square roots means f <= 0 with the square roots. The
// trials are then left as they are without them: the same result, bit for
// bit (a lane whose k is not positive is a house point's, whose result the
// stress phase does not keep).
template <class T, class C>
auto return_in_place(const C& mc, StressOf<T>& s, Regions<T>& regions) {
  if constexpr (kRadiusEstimate && !std::is_same_v<T, double>) {
    const auto inside = yield_function<T>(mc, principal_values(s, radius_above(s)).s) <= 0;
    if (every(inside)) return inside;
  }
  const T radius = circle_radius(s);
  Sorted<T> sorted = principal_values(s, radius);
  const T f = yield_function<T>(mc, sorted.s);
  const auto elastic = f <= 0;
  // Inside the surface everywhere: the trials stay as they are. Groups the
  // estimate could not tell (or every group, without it) take this branch,
  // which selects alone never skip.
  if (every(elastic)) return elastic;
  T cos2, sin2;
  principal_directions(s, radius, cos2, sin2);
  regions = plastic_return(mc, sorted.s, f);
  const StressOf<T> back = from_principal(sorted, cos2, sin2, sorted.s);
  s = {elastic ? s.xx : back.xx, elastic ? s.yy : back.yy, elastic ? s.xy : back.xy,
       elastic ? s.zz : back.zz};
  return elastic;
}

}  // namespace mc_return
}  // namespace sim
