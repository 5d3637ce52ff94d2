// The stress update of one point, split in the steps the paper names:
// Jaumann rotation (Eq. 24), elastic predictor (Eq. 21) and, for soil, the
// Mohr-Coulomb return (Eqs. 20-23, Clausen et al.). T is double or Lane8
// (stress.hpp); M is MaterialConstants or its eight-point form.
#pragma once

#include "sim/physics/lanes.hpp"
#include "sim/physics/material.hpp"
#include "sim/physics/stress.hpp"

namespace sim {

// Objective stress rate: the stress rotates with the material spin,
// sigma += Omega sigma - sigma Omega, Omega = W dt with W_xy = spin / dt.
// The paper calls its rate the Jaumann rate (Eq. 24); the spin terms are what
// make it objective, so a rigidly spinning body keeps its principal stresses.
// `spin` is W_xy dt = (dvx/dy - dvy/dx) dt / 2. sigma_zz does not rotate.
template <class T>
void jaumann_rotate(StressOf<T>& s, const T& spin) {
  const T xx = s.xx, yy = s.yy, xy = s.xy, twice_spin = 2.0 * spin;
  s.xx = fused(twice_spin, xy, xx);
  s.yy = fused(-twice_spin, xy, yy);
  s.xy = fused(spin, yy - xx, xy);
}

// Hooke's law in plane strain on a strain increment (Eq. 21 without the
// plastic part): d sigma = lambda tr(d eps) I + 2 G d eps, d eps_zz = 0.
template <class T, class M>
void elastic_predictor(StressOf<T>& s, const StrainOf<T>& de, const M& m) {
  const T volumetric = m.lambda * (de.xx + de.yy);
  s.xx += fused(de.xx, 2.0 * m.shear, volumetric);
  s.yy += fused(de.yy, 2.0 * m.shear, volumetric);
  s.xy += 2.0 * m.shear * de.xy;
  s.zz += volumetric;
}

}  // namespace sim
