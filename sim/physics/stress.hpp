// Plane-strain stress at one point: in-plane components and the out-of-plane
// normal stress sigma_zz, which plane strain keeps non-zero. Tension positive.
#pragma once

namespace sim {

struct Stress {
  double xx = 0, yy = 0, xy = 0, zz = 0;
};

// Strain increment in the plane (tensor shear: xy = (du/dy + dv/dx) / 2).
struct StrainIncrement {
  double xx = 0, yy = 0, xy = 0;
};

}  // namespace sim
