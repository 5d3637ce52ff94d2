// GIMP weighting functions (paper Eqs. 12 and 13) for the uGIMP variant of
// Bardenhagen & Kober (2004): the particle characteristic function is a box
// of half-width l_p that keeps its initial size (method notes, section 1).
//
// In 2D the weight is the product of two 1D weights, S_ip = Sx * Sy, and its
// gradient is (Sx' Sy, Sx Sy'). With l_p <= h/2 a particle touches at most
// three nodes per axis, so one particle's weights fit a fixed 3x3 stencil.
#pragma once

#include <cmath>

namespace sim {

// 1D uGIMP weight S(xi) and its derivative dS/dxi, xi = x_p - x_i
// (method notes, section 1 table). The derivative equals the particle-averaged
// shape-function gradient of Eq. (13) divided by the particle volume.
inline void gimp_weight_1d(double xi, double h, double lp, double& S, double& dS) {
  const double a = std::fabs(xi);
  const double sign = xi < 0 ? -1.0 : 1.0;
  if (a <= lp) {  // particle domain straddles the node
    S = 1.0 - (xi * xi + lp * lp) / (2.0 * h * lp);
    dS = -xi / (h * lp);
  } else if (a <= h - lp) {  // domain inside one cell: linear hat
    S = 1.0 - a / h;
    dS = -sign / h;
  } else if (a < h + lp) {  // domain straddles the far node of the cell
    const double r = h + lp - a;
    S = r * r / (4.0 * h * lp);
    dS = -sign * r / (2.0 * h * lp);
  } else {
    S = 0.0;
    dS = 0.0;
  }
}

// One particle's 3x3 stencil: nodes (base_i + a, base_j + b), a, b in 0..2.
struct Stencil {
  int base_i = 0, base_j = 0;
  double wx[3], wy[3];  // 1D weights per axis
  double dx[3], dy[3];  // 1D weight derivatives per axis
};

// First node index (per axis) that can carry a non-zero weight: nodes with
// x_i > x_p - h - l_p, i.e. floor((x_p - l_p - origin) / h).
inline int gimp_base_node(double xp, double origin, double h, double lp) {
  return static_cast<int>(std::floor((xp - lp - origin) / h));
}

// Fills the stencil of a particle at (xp, yp) on a grid with the given origin
// and cell size h.
inline void gimp_stencil(double xp, double yp, double origin_x, double origin_y, double h,
                         double lp, Stencil& st) {
  st.base_i = gimp_base_node(xp, origin_x, h, lp);
  st.base_j = gimp_base_node(yp, origin_y, h, lp);
  for (int a = 0; a < 3; ++a) {
    gimp_weight_1d(xp - (origin_x + (st.base_i + a) * h), h, lp, st.wx[a], st.dx[a]);
    gimp_weight_1d(yp - (origin_y + (st.base_j + a) * h), h, lp, st.wy[a], st.dy[a]);
  }
}

}  // namespace sim
