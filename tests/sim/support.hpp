// Small scenes built in code for the solver's unit tests.
#pragma once

#include <cstdint>

#include "sim/physics/particles.hpp"
#include "sim/scene/scenario.hpp"

namespace simtest {

inline std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t bytes) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

// A 64-bit hash of every value a step changes: equal hashes, equal states.
inline std::uint64_t state_hash(const sim::Particles& p) {
  std::uint64_t h = 1469598103934665603ull;
  for (const auto* v : {&p.x, &p.y, &p.vx, &p.vy, &p.density, &p.sxx, &p.syy, &p.sxy, &p.szz,
                        &p.ref_x, &p.ref_y})
    h = fnv1a(h, v->data(), v->size() * sizeof(double));
  return fnv1a(h, p.yielded.data(), p.yielded.size());
}

// One linear-elastic rectangle body on a padded grid, walls free unless set.
inline sim::Scenario block_scenario(sim::Vec2 lo, sim::Vec2 hi, double h, int ppc,
                                    sim::Vec2 domain_lo, sim::Vec2 domain_hi) {
  sim::Scenario s;
  s.name = "block";
  s.domain_min = domain_lo;
  s.domain_max = domain_hi;
  s.cell_size = h;
  s.padding_cells = 2;
  s.points_per_cell = ppc;
  sim::MaterialSpec m;
  m.name = "elastic";
  m.density = 2000;
  m.youngs_modulus = 20e6;
  m.poisson_ratio = 0.25;
  s.materials.push_back(m);
  sim::BodySpec b;
  b.name = "block";
  b.material = 0;
  b.polygon = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  s.bodies.push_back(b);
  s.time_step.courant = 0.5;
  return s;
}

}  // namespace simtest
