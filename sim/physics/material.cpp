#include "sim/physics/material.hpp"

#include <cmath>
#include <stdexcept>

namespace sim {

MaterialConstants make_material_constants(const MaterialSpec& m) {
  MaterialConstants c;
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  c.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  c.shear = E / (2 * (1 + nu));
  // Constrained (P-wave) modulus M = lambda + 2G; c_p = sqrt(M / rho).
  c.wave_speed = std::sqrt((c.lambda + 2 * c.shear) / m.density);
  c.plastic = m.model == MaterialModel::MohrCoulomb;
  c.critical_density = c.plastic ? m.critical_density : 0.0;
  if (c.plastic)
    c.mohr_coulomb = MohrCoulomb::make(E, nu, m.cohesion, m.friction_angle, m.dilation_angle);
  return c;
}

void apply_material_change(MaterialSpec& spec, const std::string& property, double value) {
  if (property == "cohesion") spec.cohesion = value;
  else if (property == "friction_angle") spec.friction_angle = value;
  else if (property == "dilation_angle") spec.dilation_angle = value;
  else if (property == "youngs_modulus") spec.youngs_modulus = value;
  else if (property == "poisson_ratio") spec.poisson_ratio = value;
  else throw std::logic_error("material change of unknown property '" + property +
                              "' passed validation");
}

}  // namespace sim
