// The stress phase of the step: the grid -> point strain increment, the
// constitutive model, and the point -> grid internal and body forces. The
// velocity and position update is in grid_to_points.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "sim/physics/bands.hpp"
#include "sim/physics/constitutive.hpp"
#include "sim/physics/exp_lanes.hpp"
#include "sim/physics/granular.hpp"
#include "sim/physics/mohr_coulomb_return.hpp"
#include "sim/physics/point_lanes.hpp"
#include "sim/physics/slope_lanes.hpp"
#include "sim/physics/step.hpp"

namespace sim {

namespace {

// The constants of eight points' materials, one lane each (the eight-point
// form of MaterialConstants for constitutive.hpp and granular.hpp).
struct MaterialLanes {
  Lane8 lambda, shear, critical_density;
  Int8 plastic;  // all bits set where the point's material is Mohr-Coulomb
  MohrCoulombLanes mohr_coulomb;
};

// The materials' constants are remade only when the group of eight points q
// has other materials than the group before: a scene of one soil makes them
// once. The materials are compared as one word of their eight indices
// (`materials`, the points' bytes), without looking them up: in turns with
// cb17895 the column's stress phase went from 23.1 to 21.6 ns per point on
// one thread (issue 17, eleventh pass). Surfaces of the points' own (a
// random field's) are loaded for every group.
struct MaterialLanesCache {
  MaterialLanes lanes;
  std::uint64_t kinds = 0;  // the materials the lanes hold, one byte each
  bool held = false;

  const MaterialLanes& get(const World& w, const Bytes8& materials, const int q[8], bool run,
                           const SurfaceArrays* own) {
    std::uint64_t now;
    std::memcpy(&now, &materials, sizeof now);
    if (!held || now != kinds) fill(w, now, own);
    const auto own_lanes = [&](const std::vector<double>& a) {
      return lanes_at<Lane8>(a.data(), q, run);
    };
    if (own) lanes.mohr_coulomb = surface_lanes(*own, own_lanes);
    return lanes;
  }

  // Out of line and marked cold: inlined into update_eight_stresses it
  // shaped that function's registers, and 1,105 of its 3,317 instructions
  // moved to or from the stack; without it 566 of 2,468 (objdump). Stress
  // and forces, one thread, least/median of 8 in turns (issue 17,
  // thirty-eighth pass): slope 26.5/27.1 -> 25.5/25.9 ns a point, column
  // 29.8/30.1 -> 29.1/29.6; a random field's 36.0/37.1 -> 36.1/37.4.
  //
  // It runs once a band, and again wherever the group's materials differ
  // from the group before: on the 8,370-point slope with its house, for 3.1
  // % of the groups of a whole `landslide run` (733,664 of 23.9 M, 59 % of
  // them of one material), where perf put 3.6 % of the run in it while it
  // put every lane's 21 constants in one by one. Built from broadcasts, the
  // first lane's material everywhere and then each other material where its
  // points are, a lane holds the same double either way.
  __attribute__((noinline, cold)) void fill(const World& w, std::uint64_t now,
                                            const SurfaceArrays* own) {
    kinds = now;
    held = true;
    Bytes8 bytes;
    std::memcpy(&bytes, &now, sizeof bytes);
    const Int8 of = __builtin_convertvector(bytes, Int8);
    set_where(Int8{} - 1, w.materials[bytes[0]], own);
    for (int l = 1; l < 8; ++l) {
      bool first = true;  // the first lane of its material
      for (int k = 0; k < l; ++k) first = first && bytes[k] != bytes[l];
      if (first) set_where(of == bytes[l], w.materials[bytes[l]], own);
    }
  }

  // Material m's constants in the lanes `where` is set.
  void set_where(const Int8& where, const MaterialConstants& m, const SurfaceArrays* own) {
    const auto put = [&](Lane8& lanes, double v) { lanes = where ? splat<Lane8>(v) : lanes; };
    put(lanes.lambda, m.lambda);
    put(lanes.shear, m.shear);
    put(lanes.critical_density, m.critical_density);
    lanes.plastic = where ? Int8{} - (m.plastic ? 1 : 0) : lanes.plastic;
    if (!own) pair_surface_constants(lanes.mohr_coulomb, m.mohr_coulomb, put);
  }
};

// Velocity gradients L_ab = sum_i v_ia dS_ip/dx_b of points 2k and 2k + 1
// (p and q), one point in each half of a Lane8; L = {xx, xy, yx, yy}, as
// {xx_a, xx_c, xy_a, xy_c, yx_a, yx_c, yy_a, yy_c}.
// S_ip is a product of an x and a y weight (Eq. 12), so a node column's
// velocities are summed down its three rows first, by the y weights and by
// their slopes, and the column sums then times the x slopes and weights:
// L_xx = sum_col Sx'_col sum_row Sy_row v_x. Formed node by node (until issue
// 17's thirty-seventh pass) each row took two products more and kept the x
// factors live across the loop; see scatter_point_force for what it gained.
// Out of line, as is update_eight_stresses (see there).
template <int k>
__attribute__((noinline)) Lane8 velocity_gradients(const World& w, int p, int q,
                                                   const SlopeLanes& d) {
  const Grid& g = w.grid;
  const StencilWeights &a = w.weights[p], &c = w.weights[q];
  Lane8 vx_wy{}, vx_dy{}, vy_wy{}, vy_dy{};  // column sums of v by Sy and by Sy'
  const int base_a = g.node(a.base_i, a.base_j), base_c = g.node(c.base_i, c.base_j);
  for (int b = 0; b < 3; ++b) {
    const int ra = base_a + b * g.stride, rc = base_c + b * g.stride;
    const Lane8 wy = join4(splat4(a.wy[b]), splat4(c.wy[b])), dy = pair_halves<k>(d.dy[b]);
    const Lane8 vx = load4x2(g.vx.data(), ra, rc);
    const Lane8 vy = load4x2(g.vy.data(), ra, rc);
    vx_wy = fused(vx, wy, vx_wy);
    vx_dy = fused(vx, dy, vx_dy);
    vy_wy = fused(vy, wy, vy_wy);
    vy_dy = fused(vy, dy, vy_dy);
  }
  const Lane8 x_slopes = d.x_rows[k], x_weights_ac = join4(x_weights(a), x_weights(c));
  return sum3_of_halves(vx_wy * x_slopes, vx_dy * x_weights_ac, vy_wy * x_slopes,
                        vy_dy * x_weights_ac);
}

// What the force scatter needs of eight points just updated, one lane each:
// their new stress, their volume after Eq. (25), their mass and their
// stencils' y derivatives, so the scatter reloads nothing and divides
// nothing. The scatter takes them a point at a time, so they are handed over
// as arrays, written once a group: held as vectors, each point's reads of
// its lanes were compiled to stores of the whole vectors to the stack and a
// load, eight vector stores a point (issue 17, thirty-third pass).
struct UpdatedLanes {
  alignas(64) double sxx[8], syy[8], sxy[8], volume[8], mass[8];
  alignas(64) double work[8];  // each point's stress work over the step (Eq. 3)
  alignas(64) double dy[3][8];
  SlopeLanes slopes;
};

// The stress update of points p[0..count), count <= 8, eight at a time
// (Eqs. 31, 24, 21-23, 25), one lane each: lanes past count repeat the last
// point and are not stored. `own`: each point's Mohr-Coulomb surface where a
// random field set them (sim/physics/point_strength.hpp), null otherwise.
//
// Eight at once because the return's regions (mohr_coulomb_return.hpp) are
// selects, not branches: the step took 45 ns per point in this phase one
// point at a time (stress and force, granular column, one thread), much of
// it on branches that a yielding soil takes at random.
//
// This and each pair's velocity_gradients are compiled as functions of
// their own (noinline). Inlined into the band's loop, clang scheduled the
// four pairs' gathers among the rest of the update, with more Lane8 values
// alive at once than AVX2's sixteen registers hold (a Lane8 takes two):
// about 1,750 of the phase's 4,300 instructions moved to or from the stack
// (objdump). Apart, the gathers touch the stack not at all and the phase
// has about 1,190 such moves of 3,770. Stress and forces, one thread,
// least/median ns a point in turns (issue 17, thirty-eighth pass, AMD
// EPYC): slope `bench/phases 1 200 --scene paper-slope-phi20-n66787`
// 29.6/32.3 -> 26.3/29.6 with the gradients alone out of line, 26.3/27.2 ->
// 25.8/26.6 with this too; column `1 300` 34.9/40.2 -> 30.2/31.4, then
// 29.8/30.1 -> 29.5/29.9. The same operations, so the same bits.
__attribute__((noinline)) void update_eight_stresses(World& w, const int* p, int count,
                                                     double dt, const SurfaceArrays* own,
                                                     MaterialLanesCache& cache,
                                                     UpdatedLanes& out) {
  Particles& pts = w.points;
  int q[8];
  Lane8 pairs[4], L[4];
  group_of_eight(p, count, q);
  const bool run = stored_in_a_run(q, count);
  out.slopes = slope_lanes(lanes_at<Lane8>(pts.x.data(), q, run),
                           lanes_at<Lane8>(pts.y.data(), q, run), w.grid, w.gimp);
  pairs[0] = velocity_gradients<0>(w, q[0], q[1], out.slopes);
  pairs[1] = velocity_gradients<1>(w, q[2], q[3], out.slopes);
  pairs[2] = velocity_gradients<2>(w, q[4], q[5], out.slopes);
  pairs[3] = velocity_gradients<3>(w, q[6], q[7], out.slopes);
  pairs_to_lanes(pairs, L);  // {xx, xy, yx, yy}
  const Bytes8 flags = lanes_at<Bytes8>(pts.yielded.data(), q, run);
  const Int8 was_yielded = __builtin_convertvector(flags, Int8);
  const MaterialLanes& m = cache.get(w, lanes_at<Bytes8>(pts.material.data(), q, run), q, run, own);
  const Lane8 &Lxx = L[0], &Lxy = L[1], &Lyx = L[2], &Lyy = L[3];
  const StrainOf<Lane8> de{dt * Lxx, dt * Lyy, 0.5 * dt * (Lxy + Lyx)};  // Eq. (31)
  const StressOf<Lane8> before{
      lanes_at<Lane8>(pts.sxx.data(), q, run), lanes_at<Lane8>(pts.syy.data(), q, run),
      lanes_at<Lane8>(pts.sxy.data(), q, run), lanes_at<Lane8>(pts.szz.data(), q, run)};
  const Lane8 m_p = lanes_at<Lane8>(pts.mass.data(), q, run);
  const Lane8 rho = lanes_at<Lane8>(pts.density.data(), q, run);
  const Lane8 volume = m_p / rho;  // at the start of the step
  StressOf<Lane8> s = before;
  jaumann_rotate(s, 0.5 * dt * (Lxy - Lyx));  // Eq. (24)
  elastic_predictor(s, de, m);                // Eq. (21)
  Int8 yielded = was_yielded;
  // Eqs. (20)-(23), soil only: a group of house points skips the return.
  if (!every(m.plastic == 0)) {
    StressOf<Lane8> returned = s;
    mc_return::Regions<Lane8> regions;
    const Int8 elastic = mc_return::return_in_place(m.mohr_coulomb, returned, regions);
    s = {m.plastic ? returned.xx : s.xx, m.plastic ? returned.yy : s.yy,
         m.plastic ? returned.xy : s.xy, m.plastic ? returned.zz : s.zz};
    yielded = m.plastic ? (elastic ? Int8{} : Int8{} + 1) : was_yielded;
  }
  const Lane8 rho_after = rho * exp_lanes(-(de.xx + de.yy));  // Eq. (25)
  // Torn or loosened soil below its critical density carries no stress
  // (Dunatunga & Kamrin 2015): it counts as yielded, flowing freely.
  yielded = disconnect_below_critical_density(rho_after, m, s) ? Int8{} + 1 : yielded;
  // Stress power of Eq. (3) over the step, midpoint stress.
  put_lanes(out.work, volume * 0.5 * ((before.xx + s.xx) * de.xx + (before.yy + s.yy) * de.yy +
                                      2.0 * (before.xy + s.xy) * de.xy));
  store_lanes(pts.sxx.data(), q, count, run, s.xx);
  store_lanes(pts.syy.data(), q, count, run, s.yy);
  store_lanes(pts.sxy.data(), q, count, run, s.xy);
  store_lanes(pts.szz.data(), q, count, run, s.zz);
  store_lanes(pts.density.data(), q, count, run, rho_after);
  store_lanes(pts.yielded.data(), q, count, run, __builtin_convertvector(yielded, Bytes8));
  put_lanes(out.sxx, s.xx);
  put_lanes(out.syy, s.yy);
  put_lanes(out.sxy, s.xy);
  put_lanes(out.volume, m_p / rho_after);  // Particles::volume, lane by lane
  put_lanes(out.mass, m_p);
  for (int b = 0; b < 3; ++b) put_lanes(out.dy[b], out.slopes.dy[b]);
}

// Adds the internal and body forces of point p, lane l of `u`, to its nodes,
// Eqs. (16), (17): `sums` holds the rows of fx (low halves) and fy (high
// halves) at p's base node, so each line below is both components at once.
// f_int = -V_p sigma_p . grad S_ip and f_ext = m_p b S_ip with S_ip = Sx Sy
// (Eq. 12) are, row by row, Sy (m_p b Sx - V_p sigma_.x Sx') + Sy' (-V_p
// sigma_.y Sx): the two bracketed factors are formed once a point, and a row
// adds two products. Formed node by node (until issue 17's thirty-seventh
// pass), a row took five products and the held rows spilled to the stack;
// with the velocity gradients' column sums, the stress phase went from
// 34.4/35.8 to 29.7/30.6 ns a point on the 66,787-point slope (one thread,
// least/median of 8 in turns; the force scatter alone 32.3/34.5). Rounded
// otherwise, so the bits changed (bench/README.md).
void scatter_point_force(const StencilWeights& st, const UpdatedLanes& u, int l,
                         const Vec2& gravity, NodeSumsSideBySide& sums) {
  const double V = u.volume[l];
  const double sxx = u.sxx[l], syy = u.syy[l], sxy = u.sxy[l];
  const double mgx = u.mass[l] * gravity[0], mgy = u.mass[l] * gravity[1];
  const auto halves = [](double lo, double hi) { return Lane8{lo, lo, lo, lo, hi, hi, hi, hi}; };
  const Lane8 first = halves(sxx, sxy), second = halves(sxy, syy), mg = halves(mgx, mgy);
  // The x rows in both halves once a point, not each product joined a row.
  const Lane8& rows = u.slopes.x_rows[l / 2];
  const Lane8 wx = twice(x_weights(st)), dx = twice(l % 2 ? high4(rows) : low4(rows));
  const Lane8 along_wy = fused(first * dx, -V, wx * mg), along_dy = (-V * second) * wx;
  sums.hold(node_index(st.base_i, st.base_j, sums.stride));
  for (int b = 0; b < 3; ++b)
    sums.rows[b] = fused(along_wy, st.wy[b], fused(along_dy, u.dy[b][l], sums.rows[b]));
}

const SurfaceArrays* own_strength(const World& w) {
  return w.strength.active() ? &w.strength.surfaces : nullptr;
}

}  // namespace

double update_stress(World& w, double dt) {
  const SurfaceArrays* own = own_strength(w);
  MaterialLanesCache cache;
  const int n = static_cast<int>(w.points.size());
  double total = 0;
  for (int first = 0; first < n; first += 8) {
    int p[8];
    const int count = std::min(8, n - first);
    for (int l = 0; l < count; ++l) p[l] = first + l;
    UpdatedLanes updated;
    update_eight_stresses(w, p, count, dt, own, cache, updated);
    for (int l = 0; l < count; ++l) total += updated.work[l];
  }
  return total;
}

// One pass over the points for both: a group of points' new stress goes to
// their nodes while their stencils and stresses are still in cache. The
// nodal velocities the stress update reads do not change in this phase, so
// grouping the points changes no result: each point's force is still added
// in the band's order, and its work summed in that order.
void update_stress_and_forces(World& w, const StepInput& in) {
  const SurfaceArrays* own = own_strength(w);
  scatter_own_bands(w, BandMark::Forces, BandMark::Walls, [&](int band) {
    MaterialLanesCache cache;
    NodeSumsSideBySide forces{w.grid.fx.data(), w.grid.fy.data(), w.grid.stride};
    // Locals, not read through w: after the stress update's call and the
    // scatter's stores clang read the order, the stencils and the grid's
    // stride again at every point (the scatter's loop 84.7 -> 81.1
    // instructions a point-step on the 8,370-point slope, bench/instructions.sh,
    // issue 17, forty-third pass).
    const int* const order = w.order.data();
    const StencilWeights* const weights = w.weights.data();
    double total = 0;
    const int end = w.band_start[band + 1];
    for (int s = w.band_start[band]; s < end; s += 8) {
      const int count = std::min(8, end - s);
      UpdatedLanes updated;
      update_eight_stresses(w, &order[s], count, in.dt, own, cache, updated);
      for (int l = 0; l < count; ++l) {
        total += updated.work[l];
        scatter_point_force(weights[order[s + l]], updated, l, in.gravity, forces);
      }
    }
    forces.flush();
    w.band_sums[band * kBandSums + kInternalWork] = total;
  });
}

}  // namespace sim
