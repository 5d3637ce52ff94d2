// Material points as a structure of arrays. The step touches the "hot" arrays
// every phase; the "cold" ones are read only for output and diagnostics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sim/physics/gimp.hpp"

namespace sim {

struct Particles {
  // Hot: position, velocity, mass, density, Cauchy stress (plane strain).
  std::vector<double> x, y;
  std::vector<double> vx, vy;
  std::vector<double> mass;
  std::vector<double> density;  // current; volume = mass / density
  std::vector<double> sxx, syy, sxy, szz;
  std::vector<std::uint8_t> material;
  // APIC only (sim/physics/apic.hpp), empty otherwise: the affine velocity C_p.
  std::vector<double> cxx, cxy, cyx, cyy;

  // Cold: where each point started, where its displacement is measured from,
  // and whether it yielded in the last step (painted as 2 in Eq. 32's field).
  std::vector<double> x0, y0;
  std::vector<double> ref_x, ref_y;
  std::vector<std::uint8_t> yielded;

  std::size_t size() const { return x.size(); }
  // Current volume per unit thickness, V_p = m_p / rho_p (mass is conserved,
  // density follows Eq. 25).
  double volume(std::size_t p) const { return mass[p] / density[p]; }
  void resize(std::size_t n);
};

inline void Particles::resize(std::size_t n) {
  for (auto* v : {&x, &y, &vx, &vy, &mass, &density, &sxx, &syy, &sxy, &szz, &x0, &y0, &ref_x,
                  &ref_y})
    v->assign(n, 0.0);
  material.assign(n, 0);
  yielded.assign(n, 0);
}

}  // namespace sim
