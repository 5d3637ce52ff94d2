// The granular regime of torn and deposited soil: the disconnected state of
// Dunatunga & Kamrin (2015), "Continuum modelling and simulation of granular
// flows through their many phases", J. Fluid Mech. 779:483-513. In their
// model, material whose free volume exceeds a critical level has separated
// and is stress-free; denser material is an elasto-plastic solid.
//
// A granular material denser than its critical density rho_c is a connected
// packing and follows its constitutive law (here Mohr-Coulomb, Eqs. 20-23 of
// the paper). Below rho_c the grains are out of contact: the material is
// "disconnected", carries no stress (sigma = 0, all of its deformation is
// free, plastic motion) and moves under gravity and contact alone. Once it is
// compacted past rho_c again, by landing on the deposit or being caught by
// the flow, it carries stress again, built up elastically from zero. The
// density is the one the step tracks, rho := rho exp(-tr d eps) (paper
// Eq. 25), which the disconnected motion keeps updating.
//
// rho_c also ends dilation: Mohr-Coulomb with psi > 0 dilates for as long as
// it flows, and a shear band that loosens past rho_c stops carrying stress
// until gravity and its neighbours pack it again, so rho_c plays the part of
// the critical-state density at which dilatancy stops.
#pragma once

#include "sim/physics/material.hpp"
#include "sim/physics/stress.hpp"

namespace sim {

// Dunatunga & Kamrin's rule, applied after the density update of the step:
// a point below its material's critical density carries no stress. T is
// double or Lane8 (stress.hpp), M MaterialConstants or its eight-point form;
// returns where the point is disconnected (a bool, or a lane mask).
template <class T, class M>
auto disconnect_below_critical_density(const T& density, const M& m, StressOf<T>& s) {
  const auto disconnected = density < m.critical_density;
  s = {disconnected ? T{} : s.xx, disconnected ? T{} : s.yy, disconnected ? T{} : s.xy,
       disconnected ? T{} : s.zz};
  return disconnected;
}

}  // namespace sim
