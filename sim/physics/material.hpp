// Constants the step needs for each material, derived once from the scenario
// (and again after a material-change stage) so the hot loop does no trig.
#pragma once

#include <string>
#include <vector>

#include "sim/physics/mohr_coulomb.hpp"
#include "sim/physics/spec.hpp"

namespace sim {

struct MaterialConstants {
  bool plastic = false;     // Mohr-Coulomb: run the return mapping
  double lambda = 0;        // Lame's first parameter
  double shear = 0;         // shear modulus G
  double wave_speed = 0;    // P-wave speed at the initial density (method notes, section 4)
  // Below it a point carries no stress (sim/physics/granular.hpp); 0 for materials
  // that never lose contact (linear elastic).
  double critical_density = 0;
  MohrCoulomb mohr_coulomb; // valid when plastic
};

MaterialConstants make_material_constants(const MaterialSpec& spec);

// Applies a material-change stage's property to a spec (angles in radians).
void apply_material_change(MaterialSpec& spec, const std::string& property, double value);

}  // namespace sim
