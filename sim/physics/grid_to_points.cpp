// The velocity and position update (grid -> point, Eqs. 29 and 30) with the
// paper's FLIP-like increments, and the band sums it takes on the way: the
// gravity work, the kinetic energies, what the damping of the gravity stage
// and the walls take, and the signal speed that sets the next time step.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "sim/physics/bands.hpp"
#include "sim/physics/point_lanes.hpp"
#include "sim/physics/step.hpp"

namespace sim {

namespace {

// What G2P writes and reads of the points, as raw pointers: the band's sums
// stay in registers instead of being reloaded after every store to a point
// array.
struct PointArrays {
  double *x, *y, *vx, *vy;
  const double* mass;
  const std::uint8_t* material;
};

// The walls' share of a point's velocity change, w = sum_i S_ip held_a_i, as
// |w|^2; only for points whose stencil a wall acts on. Out of line and cold,
// as is FastestByMaterial::add_mixed: the few points they are for do not
// shape the registers of G2P's loop. With both inlined, G2P took 12.4/13.4
// ns a point on the 66,787-point slope and 12.5/13.3 on the column, with
// both out of line 12.1/12.6 and 12.1/12.6 (`bench/phases`, one thread,
// least/median of 8 and 6 in turns; issue 17, thirty-eighth pass).
__attribute__((noinline, cold)) double walled_squared(const Grid& g,
                                                      const StencilWeights& st) {
  Lane4 swx{}, swy{};
  for (int b = 0; b < 3; ++b) {
    const int row = g.node(st.base_i, st.base_j + b);
    const Lane4 S = x_weights(st) * st.wy[b];
    swx = fused(S, load4(&g.held_ax[row]), swx);
    swy = fused(S, load4(&g.held_ay[row]), swy);
  }
  const double wx = sum3(swx), wy = sum3(swy);
  return wx * wx + wy * wy;
}

// The base node of the run of points being gathered (points come in runs of
// one base node, locate.cpp), and whether a wall acts on a node of its
// stencil (Grid::reaches_walls): tested once a run, not a point at a time
// from its stencil in the band sums' loop.
struct RunBase {
  int node = -1;
  bool walled = false;

  void move_to(const Grid& g, const StencilWeights& st) {
    const int at = g.node(st.base_i, st.base_j);
    if (at == node) return;
    node = at;
    walled = g.reaches_walls(st.base_i, st.base_j);
  }
};

// One point's sums S_ip a_i (low halves of `accel`) and S_ip v_i (of
// `velocity`), before the three nodes of a row are added; bit `bit` of
// `walled` set where a wall acts on its stencil. The nodes are read at every
// point, as the FMAs' memory operands. Held in registers through a run of
// one base node (from the twenty-ninth pass of issue 17), they took twelve
// of AVX2's sixteen and the loop moved others to and from the stack: G2P
// went from 130.3 to 116.9 instructions a point-step on the 66,787-point
// slope without them (bench/instructions.sh, forty-fourth pass).
__attribute__((always_inline)) inline void gather_one(const Grid& g, const StencilWeights& st,
                                                      RunBase& base, Lane8& accel,
                                                      Lane8& velocity, unsigned& walled,
                                                      int bit) {
  base.move_to(g, st);
  walled |= unsigned(base.walled) << bit;
  const Lane8 wx = twice(x_weights(st));
  accel = velocity = Lane8{};
  for (int b = 0; b < 3; ++b) {
    const Lane8 S = wx * st.wy[b];
    const int row = base.node + b * g.stride;
    accel = fused(S, load4x2_of(g.ax.data(), g.ay.data(), row), accel);
    velocity = fused(S, load4x2_of(g.vx.data(), g.vy.data(), row), velocity);
  }
}

// Each material's largest |v_p|^2 over a band's points, for its signal
// speed. A group of eight points of one material (most groups) takes a
// lane-by-lane maximum, folded into its material's when the material
// changes: written point by point, each maximum waited for the store of the
// one before, and perf put a fifth of G2P's samples there. A maximum is
// exact and these skip a NaN |v_p|^2 as std::max(largest, NaN) does, so the
// order does not change the result.
struct FastestByMaterial {
  double largest[256];
  Lane8 lanes = Lane8{} - 1.0;
  int material = -1;  // whose maximum `lanes` holds; -1 for none

  explicit FastestByMaterial(int kinds) { std::fill(largest, largest + kinds, -1.0); }
  void add(const std::uint8_t* materials, const int q[8], bool run, const Lane8& v2) {
    const Bytes8 m = lanes_at<Bytes8>(materials, q, run);
    std::uint64_t word;
    std::memcpy(&word, &m, sizeof word);
    if (word != m[0] * 0x0101010101010101ull) {  // of several materials: point by point
      add_mixed(m, v2);
      return;
    }
    if (m[0] != material) {
      fold();
      material = m[0];
    }
    lanes = lanes < v2 ? v2 : lanes;
  }
  // A group of several materials, point by point (see walled_squared).
  __attribute__((noinline, cold)) void add_mixed(const Bytes8& m, const Lane8& v2) {
    for (int l = 0; l < 8; ++l) largest[m[l]] = std::max(largest[m[l]], v2[l]);
  }
  void fold() {
    if (material < 0) return;
    for (int l = 0; l < 8; ++l) largest[material] = std::max(largest[material], lanes[l]);
    lanes = Lane8{} - 1.0;
  }
};

// The band's sums of four terms, `sums` = {a, b, c, d}, each added point by
// point in the band's order: points q[0..count) of a group, their terms
// a..d one a lane. Each point's four terms are put side by side (two
// unpacks and a lane swap a pair of points), so one addition a point
// does the four sums' additions in the order they had one by one. Added
// from four arrays a point at a time, with the walls' test of each point
// beside them (now RunBase's), that loop took 22 instructions a point; G2P
// went from 135.5 to 130.3 instructions a point-step on the 66,787-point
// slope (bench/instructions.sh, issue 17, forty-fourth pass).
__attribute__((always_inline)) inline void add_in_point_order(Lane4& sums, int count,
                                                              const Lane8& a, const Lane8& b,
                                                              const Lane8& c, const Lane8& d) {
  const Lane8 ab_even = __builtin_shufflevector(a, b, 0, 8, 2, 10, 4, 12, 6, 14);
  const Lane8 ab_odd = __builtin_shufflevector(a, b, 1, 9, 3, 11, 5, 13, 7, 15);
  const Lane8 cd_even = __builtin_shufflevector(c, d, 0, 8, 2, 10, 4, 12, 6, 14);
  const Lane8 cd_odd = __builtin_shufflevector(c, d, 1, 9, 3, 11, 5, 13, 7, 15);
  const Lane4 point[8] = {
      __builtin_shufflevector(ab_even, cd_even, 0, 1, 8, 9),
      __builtin_shufflevector(ab_odd, cd_odd, 0, 1, 8, 9),
      __builtin_shufflevector(ab_even, cd_even, 2, 3, 10, 11),
      __builtin_shufflevector(ab_odd, cd_odd, 2, 3, 10, 11),
      __builtin_shufflevector(ab_even, cd_even, 4, 5, 12, 13),
      __builtin_shufflevector(ab_odd, cd_odd, 4, 5, 12, 13),
      __builtin_shufflevector(ab_even, cd_even, 6, 7, 14, 15),
      __builtin_shufflevector(ab_odd, cd_odd, 6, 7, 14, 15)};
  for (int l = 0; l < 8; ++l)
    if (l < count) sums += point[l];
}

// The sums of two points, as {ax_a, ax_c, ay_a, ay_c, vx_a, vx_c, vy_a, vy_c}:
// each lane the same products added in the same order as a node at a time.
__attribute__((always_inline)) inline Lane8 gather_two(const Grid& g, RunBase& base,
                                                       const StencilWeights& a,
                                                       const StencilWeights& c,
                                                       unsigned& walled, int bit) {
  Lane8 accel_a, velocity_a, accel_c, velocity_c;
  gather_one(g, a, base, accel_a, velocity_a, walled, bit);
  gather_one(g, c, base, accel_c, velocity_c, walled, bit + 1);
  const Lane8 sums = sum3_of_halves(accel_a, accel_c, velocity_a, velocity_c);
  return __builtin_shufflevector(sums, sums, 0, 2, 1, 3, 4, 6, 5, 7);
}

// The new velocities and positions of eight points q[0..count) of a band
// (point_lanes.hpp), one a lane, from their sums S_ip a_i and S_ip v_i
// (`sums`: ax, ay, vx, vy), and their terms of the band's sums `t`, added
// point by point in the band's order, and each material's largest |v_p|^2.
// Eight at a time rather than two (until issue 17's twenty-ninth pass), a
// group stored in a run is read and written as vectors: G2P took 11.6 ns a
// point on the 66,787-point slope, 11.1 in eight lanes (one thread, the
// least of 14 runs in turns).
__attribute__((always_inline)) inline void update_eight(const World& w, const PointArrays& a,
                                                        const StepInput& in, double keep,
                                                        const int q[8], int count,
                                                        const Lane8 sums[4], unsigned walled,
                                                        Lane4& terms, PointSums& t,
                                                        FastestByMaterial& fastest) {
  const bool run = stored_in_a_run(q, count);
  const Lane8 &ax = sums[0], &ay = sums[1], &vx = sums[2], &vy = sums[3];
  const Lane8 dx = in.dt * vx, dy = in.dt * vy;                      // Eq. (29)
  const Lane8 ux = fused(ax, in.dt, lanes_at<Lane8>(a.vx, q, run));  // Eq. (30)
  const Lane8 uy = fused(ay, in.dt, lanes_at<Lane8>(a.vy, q, run));
  const Lane8 kx = ux * keep, ky = uy * keep;  // damping of the gravity stage
  const Lane8 m = lanes_at<Lane8>(a.mass, q, run);
  const Lane8 v2 = kx * kx + ky * ky;
  add_in_point_order(terms, count, m * (in.gravity[0] * dx + in.gravity[1] * dy),
                     0.5 * m * v2, 0.5 * m * (vx * vx + vy * vy),
                     0.5 * m * (ux * ux + uy * uy - v2));
  store_lanes(a.x, q, count, run, lanes_at<Lane8>(a.x, q, run) + dx);
  store_lanes(a.y, q, count, run, lanes_at<Lane8>(a.y, q, run) + dy);
  store_lanes(a.vx, q, count, run, kx);
  store_lanes(a.vy, q, count, run, ky);
  // Zero, and not added, for a point whose stencil no wall acts on.
  for (int l = 0; walled >> l != 0 && l < count; ++l)
    if (walled >> l & 1)
      t.walled += 0.5 * m[l] * in.dt * in.dt * walled_squared(w.grid, w.weights[q[l]]);
  fastest.add(a.material, q, run, v2);
}

}  // namespace

// The points of each band eight by eight, in the band's order.
void grid_to_points(World& w, const StepInput& in) {
  const double keep = 1.0 / (1.0 + in.damping);  // v := v / (1 + theta)
  Particles& pts = w.points;
  const PointArrays a{pts.x.data(),  pts.y.data(),    pts.vx.data(),
                      pts.vy.data(), pts.mass.data(), pts.material.data()};
  const int kinds = static_cast<int>(w.materials.size());
  gather_own_bands(w, [&](int band) {
    PointSums t{};
    // The band's signal speed max_p (c_p + |v_p|) from the largest |v_p|^2 of
    // each material: sqrt and + round correctly, so they keep order, and
    // c + sqrt(max v^2) is the largest c + sqrt(v^2) bit for bit, at one
    // square root per material instead of one per point.
    FastestByMaterial fastest(kinds);
    const int end = w.band_start[band + 1];
    RunBase base;
    Lane4 terms{};  // the sums of gravity work, kinetic, moving and damped energy
    for (int s = w.band_start[band]; s < end; s += 8) {
      const int count = std::min(8, end - s);
      int q[8];
      group_of_eight(&w.order[s], count, q);
      Lane8 pairs[4], sums[4];
      unsigned walled = 0;  // bit l: a wall acts on point q[l]'s stencil
      for (int k = 0; k < 4; ++k)
        pairs[k] = gather_two(w.grid, base, w.weights[q[2 * k]], w.weights[q[2 * k + 1]],
                              walled, 2 * k);
      pairs_to_lanes(pairs, sums);  // {ax, ay, vx, vy}
      update_eight(w, a, in, keep, q, count, sums, walled, terms, t, fastest);
    }
    t.gravity_work = terms[0];
    t.kinetic = terms[1];
    t.moving = terms[2];
    t.damped = terms[3];
    fastest.fold();
    for (int k = 0; k < kinds; ++k)
      if (fastest.largest[k] >= 0)
        t.signal = std::max(t.signal, w.materials[k].wave_speed + std::sqrt(fastest.largest[k]));
    store_point_sums(w, band, t);
  });
}

double max_signal_speed(const World& w) {
  const Particles& pts = w.points;
  double signal = 0;
  for (std::size_t p = 0; p < pts.size(); ++p)
    signal = std::max(signal, w.materials[pts.material[p]].wave_speed +
                                  std::hypot(pts.vx[p], pts.vy[p]));
  return signal;
}

}  // namespace sim
