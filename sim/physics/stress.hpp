// Plane-strain stress at one point: in-plane components and the out-of-plane
// normal stress sigma_zz, which plane strain keeps non-zero. Tension positive.
//
// Templates on the number type: T = double for one point, T = Lane8
// (lanes.hpp) for eight points whose stress is updated at once
// (sim/physics/point_update.cpp). The formulas that take them are written once
// for both.
#pragma once

namespace sim {

template <class T>
struct StressOf {
  T xx{}, yy{}, xy{}, zz{};
};
using Stress = StressOf<double>;

// Strain increment in the plane (tensor shear: xy = (du/dy + dv/dx) / 2).
template <class T>
struct StrainOf {
  T xx{}, yy{}, xy{};
};
using StrainIncrement = StrainOf<double>;

}  // namespace sim
