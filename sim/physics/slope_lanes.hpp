// The derivatives of eight points' GIMP stencils (Eq. 13), one point a lane,
// made from their positions in the stress phase (sim/physics/point_update.cpp)
// rather than stored by locate and read back: at 6.5 M points those 48 B a
// point came from memory, where x and y are 16 B (issue 17, eighteenth pass,
// bench/README.md). gimp_axis_slopes is locate's own arithmetic, so the bits
// are the same.
#pragma once

#include "sim/physics/gimp.hpp"
#include "sim/physics/grid.hpp"

namespace sim {

// The derivatives dS/dx, dS/dy of eight points' stencils as the gathers and
// the scatter take them: x_rows[k] holds the x derivatives of points 2k and
// 2k + 1 as two stencil rows {dx0, dx1, dx2, 0} side by side, dy[b] those of
// row b, one point a lane.
struct SlopeLanes {
  Lane8 x_rows[4];
  Lane8 dy[3];
};

// {v[2k] four times, v[2k + 1] four times}: points 2k and 2k + 1's lanes, one
// a half.
template <int k>
inline Lane8 pair_halves(const Lane8& v) {
  return __builtin_shufflevector(v, v, 2 * k, 2 * k, 2 * k, 2 * k, 2 * k + 1, 2 * k + 1,
                                 2 * k + 1, 2 * k + 1);
}
// {d0, d1, d2, 0} of point 2k, then of point 2k + 1, from lanes of d[0..2].
template <int k>
inline Lane8 pair_rows(const Lane8 d[3]) {
  const Lane8 d01 = __builtin_shufflevector(d[0], d[1], 2 * k, 8 + 2 * k, 2 * k + 1, 9 + 2 * k,
                                            0, 0, 0, 0);
  const Lane8 d2 = __builtin_shufflevector(d[2], Lane8{}, 2 * k, 8, 2 * k + 1, 8, 0, 0, 0, 0);
  return __builtin_shufflevector(d01, d2, 0, 1, 8, 9, 2, 3, 10, 11);
}

// The derivatives of the stencils of points at (x, y), one point a lane, on
// grid g.
inline SlopeLanes slope_lanes(const Lane8& x, const Lane8& y, const Grid& g, const GimpShape& k) {
  Lane8 dx[3];
  SlopeLanes s;
  gimp_axis_slopes<Lane8, Int32x8>(x, g.origin_x, k, dx);
  gimp_axis_slopes<Lane8, Int32x8>(y, g.origin_y, k, s.dy);
  s.x_rows[0] = pair_rows<0>(dx);
  s.x_rows[1] = pair_rows<1>(dx);
  s.x_rows[2] = pair_rows<2>(dx);
  s.x_rows[3] = pair_rows<3>(dx);
  return s;
}

}  // namespace sim
