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

#include <cstddef>
#include <string>
#include <vector>

#include "sim/physics/mohr_coulomb.hpp"
#include "sim/physics/spec.hpp"

namespace sim {

struct World;

struct PointStrength {
  // Empty until a field is set; then one entry per point. Points of a
  // material without a field hold its own values; linear-elastic points
  // hold zeros and a default return that is never used.
  std::vector<double> cohesion;        // Pa
  std::vector<double> friction_angle;  // rad
  std::vector<MohrCoulomb> mohr_coulomb;
  bool active() const { return !mohr_coulomb.empty(); }
};

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

// The Mohr-Coulomb return of point p: its own where a field is set, else its material's.
const MohrCoulomb& point_mohr_coulomb(const World& w, std::size_t p);

}  // namespace sim
