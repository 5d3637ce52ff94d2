// What the step is built from: the materials, the walls and the transfer
// scheme. A scenario (sim/scene/scenario.hpp) holds them as it reads them
// from JSON; the step sees only these, never the reader.
// Angles are in radians here; the JSON gives degrees.
#pragma once

#include <array>
#include <string>

namespace sim {

using Vec2 = std::array<double, 2>;

enum class MaterialModel { LinearElastic, MohrCoulomb };

struct MaterialSpec {
  std::string name;
  MaterialModel model = MaterialModel::LinearElastic;
  double density = 0;         // kg/m^3, initial
  double youngs_modulus = 0;  // Pa
  double poisson_ratio = 0;   // [0, 0.5)
  // Mohr-Coulomb only.
  double cohesion = 0;        // Pa
  double friction_angle = 0;  // rad
  double dilation_angle = 0;  // rad
  // Below this density the grains lose contact and carry no stress
  // (Dunatunga & Kamrin 2015, sim/physics/granular.hpp), kg/m^3, in (0, density].
  double critical_density = 0;
};

// What a wall holds: both velocity components (fixed, no slip), the one
// normal to it (roller), nothing (free), or Coulomb friction: no velocity
// into the wall, separation allowed, sliding resisted by friction * the
// normal impulse (sim/physics/wall_friction.hpp).
enum class BoundaryKind { Fixed, Roller, Free, Friction };
struct Wall {
  BoundaryKind kind = BoundaryKind::Free;
  double friction = 0;  // Coulomb coefficient mu of a Friction wall, >= 0
};
struct Boundaries {
  Wall left, right, bottom, top;
};

// How velocities go from the grid back to the points: the paper's FLIP-like
// increments (Eq. 30, "mapping only the changes"), or the affine
// particle-in-cell transfer of Jiang et al. (2015), sim/physics/apic.hpp.
enum class TransferScheme { Flip, Apic };

}  // namespace sim
