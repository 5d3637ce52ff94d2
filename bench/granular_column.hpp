// The granular column of issue 6 (CB-Geo MPM's comparison case), shared by
// the throughput benches: a 0.2 m x 0.4 m Mohr-Coulomb column (phi = 30 deg,
// c = 0) against the left wall of a 1.0 m x 0.45 m fixed-wall box, 2x2
// points per cell. `refine` divides the cell: 25,538 points at 1, about
// refine^2 times as many at finer cells (issue 17's size sweep).
#pragma once

#include <cmath>
#include <string>

#include "sim/scene/scenario.hpp"

namespace bench {

inline sim::Scenario load_scene(const std::string& name) {
  return sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/" + name + ".json");
}

inline sim::Scenario granular_column(int refine = 1) {
  sim::Scenario s = load_scene("elastic-column");
  s.name = "granular-column";
  // (0.2 / h) (0.4 / h) 4 points = 25,600 gives h = 0.2 / sqrt(3200) = 3.536 mm.
  s.cell_size = 0.2 / std::sqrt(3200.0) / refine;
  s.domain_min = {0, 0};
  s.domain_max = {1.0, 0.45};
  const sim::Wall fixed{sim::BoundaryKind::Fixed, 0.0}, free{sim::BoundaryKind::Free, 0.0};
  s.boundaries = {fixed, fixed, fixed, free};
  sim::MaterialSpec m;
  m.name = "sand";
  m.model = sim::MaterialModel::MohrCoulomb;
  m.density = 2650;
  m.youngs_modulus = 0.84e6;
  m.poisson_ratio = 0.3;
  m.friction_angle = 30 * M_PI / 180;
  m.critical_density = m.density;  // the granular regime on, as in the shipped scenes
  s.materials = {m};
  s.bodies[0].material = 0;
  s.bodies[0].polygon = {{0, 0}, {0.2, 0}, {0.2, 0.4}, {0, 0.4}};
  return s;
}

}  // namespace bench
