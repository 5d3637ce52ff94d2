// GIMP weighting functions (paper Eqs. 12 and 13) for the uGIMP variant of
// Bardenhagen & Kober (2004): the particle characteristic function is a box
// of half-width l_p that keeps its initial size (method notes, section 1).
//
// In 2D the weight is the product of two 1D weights, S_ip = Sx * Sy, and its
// gradient is (Sx' Sy, Sx Sy'). With l_p <= h/2 a particle touches at most
// three nodes per axis, so one particle's weights fit a fixed 3x3 stencil.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "sim/physics/lanes.hpp"

namespace sim {

// The grid's cell size h and the points' half-width l_p, with the
// reciprocals the weights use, so the step multiplies instead of divides.
struct GimpShape {
  double h = 0, lp = 0;
  double inv_h = 0, inv_hlp = 0, inv_2hlp = 0, inv_4hlp = 0;
  GimpShape() = default;
  GimpShape(double cell, double half_width)
      : h(cell),
        lp(half_width),
        inv_h(1.0 / cell),
        inv_hlp(1.0 / (cell * half_width)),
        inv_2hlp(0.5 / (cell * half_width)),
        inv_4hlp(0.25 / (cell * half_width)) {}
};

inline double abs_of(double x) { return x < 0 ? -x : x; }
inline Lane8 abs_of(const Lane8& x) { return x < 0 ? -x : x; }
// floor(t) as a double, exact: the base node's coordinate is computed from
// it, and its index converted from it. Without AVX-512 there is no vector
// conversion between doubles and 64-bit integers; the conversions of the
// base (there and back) were taken lane by lane, and perf put 11 % of the
// slope's step on them on an AMD EPYC (AVX2; issue 17, thirty-fifth pass).
// The rounding instruction and a conversion through 32-bit integers give
// the same values for any node index, so the same bits.
inline double floor_of(double t) { return std::floor(t); }
inline Lane8 floor_of(const Lane8& t) {
#if defined(__AVX512F__)
  return _mm512_roundscale_pd(t, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
#elif defined(__AVX__)
  return join4(_mm256_floor_pd(low4(t)), _mm256_floor_pd(high4(t)));
#else
  Lane8 f;
  for (int l = 0; l < 8; ++l) f[l] = std::floor(t[l]);
  return f;
#endif
}
// An integral f as an index. Past the range of int (a point far off the
// grid) the conversion gives INT_MIN, a negative index: off the grid.
inline int to_index(double f) { return static_cast<int>(f); }
inline Int32x8 to_index(const Lane8& f) { return __builtin_convertvector(f, Int32x8); }

// The three pieces of the 1D uGIMP weight S(xi) and its derivative dS/dxi,
// xi = x_p - x_i (method notes, section 1 table). The derivative equals the
// particle-averaged shape-function gradient of Eq. (13) divided by the
// particle volume.
//
// |xi| <= l_p: the particle's domain straddles the node.
template <class T>
void gimp_near(const T& xi, const GimpShape& k, T& S, T& dS) {
  S = fused(-fused(xi, xi, T{} + k.lp * k.lp), k.inv_2hlp, T{} + 1.0);
  dS = -xi * k.inv_hlp;
}
// l_p < |xi| <= h - l_p: the domain lies inside one cell, the linear hat.
template <class T>
void gimp_hat(const T& xi, const GimpShape& k, T& S, T& dS) {
  const T slope = T{} + k.inv_h;
  S = fused(-abs_of(xi), k.inv_h, T{} + 1.0);
  dS = xi < 0 ? slope : -slope;
}
// h - l_p < |xi| < h + l_p: the domain straddles the cell's far node.
template <class T>
void gimp_far(const T& xi, const GimpShape& k, T& S, T& dS) {
  const T reach = k.h + k.lp - abs_of(xi);
  const T r = reach > 0 ? reach : T{};  // zero beyond h + l_p
  S = r * r * k.inv_4hlp;
  const T slope = r * k.inv_2hlp;
  dS = xi < 0 ? slope : -slope;
}

// The 1D weight at any xi: the piece its region calls for.
inline void gimp_weight_1d(double xi, const GimpShape& k, double& S, double& dS) {
  const double a = std::fabs(xi);
  if (a <= k.lp) {
    gimp_near(xi, k, S, dS);
  } else if (a <= k.h - k.lp) {
    gimp_hat(xi, k, S, dS);
  } else if (a < k.h + k.lp) {
    gimp_far(xi, k, S, dS);
  } else {
    S = dS = 0.0;
  }
}

inline Lane4 load4(const double* p) {
  Lane4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store4(double* p, const Lane4& v) { std::memcpy(p, &v, sizeof v); }
inline Lane8 load8(const double* p) {
  Lane8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
// Lanes 0..2: a stencil row's three nodes; lane 3 is never part of a result.
inline double sum3(const Lane4& v) { return (v[0] + v[1]) + v[2]; }

// The sums of three of both halves of four Lane8 a, b, c, d, in this order:
// {sum3(low4(a)), sum3(high4(a)), sum3(low4(b)), ..., sum3(high4(d))}. The
// lanes are moved so that one vector addition adds all eight first terms to
// the eight second terms, and the next adds the third: each lane is still
// (v0 + v1) + v2, the same bits as sum3.
inline Lane8 sum3_of_halves(const Lane8& a, const Lane8& b, const Lane8& c, const Lane8& d) {
  const Lane8 ab = __builtin_shufflevector(a, b, 0, 4, 8, 12, 1, 5, 9, 13);
  const Lane8 cd = __builtin_shufflevector(c, d, 0, 4, 8, 12, 1, 5, 9, 13);
  const Lane8 ab2 = __builtin_shufflevector(a, b, 2, 6, 10, 14, 2, 6, 10, 14);
  const Lane8 cd2 = __builtin_shufflevector(c, d, 2, 6, 10, 14, 2, 6, 10, 14);
  const Lane8 first = __builtin_shufflevector(ab, cd, 0, 1, 2, 3, 8, 9, 10, 11);
  const Lane8 second = __builtin_shufflevector(ab, cd, 4, 5, 6, 7, 12, 13, 14, 15);
  const Lane8 third = __builtin_shufflevector(ab2, cd2, 0, 1, 2, 3, 8, 9, 10, 11);
  return (first + second) + third;
}
// Grid row `row_a` of `nodes` in the low half, `row_c` in the high half.
inline Lane8 load4x2(const double* nodes, int row_a, int row_c) {
  return join4(load4(nodes + row_a), load4(nodes + row_c));
}
// Grid row `row` of array `low` in the low half, of `high` in the high half.
inline Lane8 load4x2_of(const double* low, const double* high, int row) {
  return join4(load4(low + row), load4(high + row));
}
// A held stencil row moved one node along x: its first node is written back
// to row[0] and the node after its fourth, row[4], comes in as the fourth.
// The scatters' runs move so far more often than anywhere else (bands.hpp).
inline Lane4 slide_row(double* row, const Lane4& held) {
  row[0] = held[0];
  return __builtin_shufflevector(held, splat4(row[4]), 1, 2, 3, 4);
}

// One particle's 3x3 stencil: nodes (base_i + a, base_j + b), a, b in 0..2.
// The phases read a stencil row as one vector operation on three
// neighbouring nodes of a grid row: x_weights puts the x weights in lanes
// 0..2 of a Lane4 with lane 3 at 0 (the grid keeps a spare node at the end of
// every row for lane 3, see grid.hpp).
// Only the weights are stored, 56 B a point (World::weights): the transfers
// (P2G, G2P) read nothing else, and the stress phase makes the derivatives
// again from the positions (gimp_axis_slopes below). Stored apart from the
// weights, the derivatives were 48 B a point that locate wrote and the
// stress phase read back, from memory at 6.5 M points (issue 17, eighteenth
// pass, bench/README.md). The same values, so the same bits.
struct StencilWeights {
  double wx[3], wy[3];  // 1D weights along x and y
  int base_i = 0, base_j = 0;
};
struct StencilSlopes {  // its derivatives, for tests and benches (gimp_stencil)
  double dx[3], dy[3];
};

typedef std::int64_t Int4 __attribute__((vector_size(32)));

// Three doubles from `row` and a +0.0 lane, from one load of four and a
// mask: the fourth double read is the next member's (wy[0] after wx), part
// of the same struct. Built lane by lane, g++ took three loads and an insert
// for each row (issue 17, thirteenth pass); the lanes are the same bits
// either way.
inline Lane4 first_three(const double* row) {
  const Lane4 four = load4(row);
  return reinterpret_cast<Lane4>(reinterpret_cast<Int4>(four) & Int4{-1, -1, -1, 0});
}
inline Lane4 x_weights(const StencilWeights& st) {
  static_assert(offsetof(StencilWeights, wy) == 3 * sizeof(double), "wx is followed by wy");
  return first_three(st.wx);
}

// A Lane4 in both halves of a Lane8: one point's stencil row taken by a
// vector operation of eight lanes whose two halves are two components.
inline Lane8 twice(const Lane4& v) { return join4(v, v); }

// The rows of a base node's 3x3 nodes of two nodal arrays, held side by side
// while a scatter's points share that node: the first array's rows in the low
// halves of three Lane8 and the second's in the high halves, so one vector
// operation adds a point's terms to both (the force scatter's fx and fy).
// Each lane receives the same terms in the same order, so the same bits.
struct NodeSumsSideBySide {
  double* low;
  double* high;
  int stride = 0;
  int base = -1;  // grid index of the base node held, -1 for none
  Lane8 rows[3] = {};

  void hold(int at) {
    if (at == base) return;
    if (base >= 0 && at == base + 1) {  // the next node of the row: both arrays' rows slide
      for (int b = 0; b < 3; ++b) {
        double* lo = low + base + b * stride;
        double* hi = high + base + b * stride;
        lo[0] = rows[b][0];
        hi[0] = rows[b][4];
        const Lane8 entering = join4(splat4(lo[4]), splat4(hi[4]));
        rows[b] = __builtin_shufflevector(rows[b], entering, 1, 2, 3, 8, 5, 6, 7, 12);
      }
      base = at;
      return;
    }
    flush();
    base = at;
    for (int b = 0; b < 3; ++b) rows[b] = join4(load4(low + base + b * stride), load4(high + base + b * stride));
  }
  void flush() {
    if (base < 0) return;
    for (int b = 0; b < 3; ++b) {
      store4(low + base + b * stride, low4(rows[b]));
      store4(high + base + b * stride, high4(rows[b]));
    }
    base = -1;
  }
};

// One axis of the stencils of one point (T = double, I = int) or eight
// (T = Lane8, I = Int32x8). The base node is the first node that can carry a
// non-zero weight: x_i > x_p - h - l_p, i.e. floor((x_p - l_p - origin) / h).
// From it, xi lies in [l_p, h + l_p) for node 0, [l_p - h, l_p) for node 1
// and [l_p - 2h, l_p - h) for node 2, so each node has two candidate pieces;
// both are computed and a select keeps one.
// Always inlined: g++ called the eight-lane form out of line from locate and
// passed its twelve vectors through memory; inlined, locate takes about 1.6 ns
// less per point (bench/README.md, issue 17's eighth pass).
template <class T, class I>
__attribute__((always_inline)) inline void gimp_axis(const T& xp, double origin,
                                                     const GimpShape& k, I& base, T w[3],
                                                     T d[3]) {
  const T first = floor_of((xp - k.lp - origin) * k.inv_h);  // integral, so first + 1 is exact
  base = to_index(first);
  const T x0 = xp - fused(first, k.h, T{} + origin);
  const T x1 = xp - fused(first + 1.0, k.h, T{} + origin);
  const T x2 = xp - fused(first + 2.0, k.h, T{} + origin);
  T s_hat, d_hat, s_far, d_far, s_near, d_near;
  gimp_hat(x0, k, s_hat, d_hat);
  gimp_far(x0, k, s_far, d_far);
  const auto hat0 = x0 <= k.h - k.lp;
  w[0] = hat0 ? s_hat : s_far;
  d[0] = hat0 ? d_hat : d_far;
  gimp_near(x1, k, s_near, d_near);
  gimp_hat(x1, k, s_hat, d_hat);
  const auto near1 = x1 >= -k.lp;
  w[1] = near1 ? s_near : s_hat;
  d[1] = near1 ? d_near : d_hat;
  gimp_far(x2, k, w[2], d[2]);  // zero beyond h + l_p
}

// gimp_axis's derivatives alone, which the stress phase makes again from the
// points' positions rather than read back stored (the weights' arithmetic is
// left unused and dropped by the compiler): the same operations on the same
// positions, so the same bits as locate's.
template <class T, class I>
__attribute__((always_inline)) inline void gimp_axis_slopes(const T& xp, double origin,
                                                            const GimpShape& k, T d[3]) {
  I base;
  T w[3];
  gimp_axis(xp, origin, k, base, w, d);
}

// Fills the stencil of a particle at (xp, yp) on a grid with the given origin.
inline void gimp_stencil(double xp, double yp, double origin_x, double origin_y,
                         const GimpShape& k, StencilWeights& st, StencilSlopes& d) {
  gimp_axis(xp, origin_x, k, st.base_i, st.wx, d.dx);
  gimp_axis(yp, origin_y, k, st.base_j, st.wy, d.dy);
}

}  // namespace sim
