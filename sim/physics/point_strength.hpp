// Mohr-Coulomb strength point by point, for soil whose cohesion or friction
// angle a random field sets (issue 16; the field itself is drawn in
// sim/scene/random_field.hpp). Random MPM (Wang, Hicks & Vardon 2016,
// Geotechnique Letters 6(2):113-118) gives each material point its own strength from the
// field at its position; the yield surface and plastic flow are the paper's
// Eqs. (20)-(23) with that point's c and phi, returned by the same Clausen
// return (sim/physics/mohr_coulomb.hpp).
//
// A scene without a field never builds these arrays; the step sets a pointer
// to them once per step, null without a field (point_update.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "sim/physics/mohr_coulomb.hpp"
#include "sim/physics/spec.hpp"

namespace sim {

struct World;

// The constants of each point's return that the step reads (the members of
// MohrCoulombLanes, mohr_coulomb_return.hpp), one array of doubles each, so
// that eight points stored one after another load each as one vector and
// the sort moves them through its scratch array of doubles. As one
// 256-byte MohrCoulomb a point, the step gathered 144 doubles from eight
// structs for every group, and the sort held a second copy of them all
// (bench/README.md, issue 17's twenty-second pass).
struct SurfaceArrays {
  std::vector<double> k, sigma_c, apex;
  std::array<std::vector<double>, 3> plane_corrector, side1, side2, project1, project2;
};

struct PointStrength {
  // Empty until a field is set; then one entry per point. Points of a
  // material without a field hold its own values; linear-elastic points
  // hold zeros and a default surface that is never used.
  std::vector<double> cohesion;        // Pa
  std::vector<double> friction_angle;  // rad
  SurfaceArrays surfaces;
  bool active() const { return !cohesion.empty(); }
};

// Calls f(a.c, b.c) for each of the 18 constants c the step reads, by the
// names that MohrCoulomb, MohrCoulombLanes and SurfaceArrays share: one list
// of them for every copy from one form to another.
template <class A, class B, class F>
void pair_surface_constants(A& a, B& b, F f) {
  f(a.k, b.k);
  f(a.sigma_c, b.sigma_c);
  f(a.apex, b.apex);
  for (int i = 0; i < 3; ++i) {
    f(a.plane_corrector[i], b.plane_corrector[i]);
    f(a.side1[i], b.side1[i]);
    f(a.side2[i], b.side2[i]);
    f(a.project1[i], b.project1[i]);
    f(a.project2[i], b.project2[i]);
  }
}

// Visits the arrays of `s` (SurfaceArrays or const SurfaceArrays).
template <class S, class Visit>
void for_each_surface_array(S& s, Visit visit) {
  static_assert(sizeof(SurfaceArrays) == 18 * sizeof(std::vector<double>),
                "an array was added to SurfaceArrays: visit it here");
  pair_surface_constants(s, s, [&](auto& v, auto&) { visit(v); });
}

// Sets `property` ("cohesion" or "friction_angle") of every point of
// `material` to values[p] (one value per point; others are not read), and
// rebuilds their returns. The material's spec keeps the field's mean.
void set_point_strength(World& w, int material, const std::string& property,
                        const std::vector<double>& values);

// After a material's spec changed by a number (world.material_specs): its
// points follow the spec for `property` again (a cohesion or friction angle
// given as a number replaces the field), and their returns are rebuilt with
// its new stiffness or dilation. Nothing to do where no field was set.
void follow_material_change(World& w, int material, const std::string& property);

// Rebuilds every plastic point's return from the per-point values and the
// specs (after a state with per-point values was restored).
void rebuild_point_strength(World& w);

// The Mohr-Coulomb surface of point p: its own where a field is set, else
// its material's. Made again from the point's strength, so by value.
MohrCoulomb point_mohr_coulomb(const World& w, std::size_t p);

}  // namespace sim
