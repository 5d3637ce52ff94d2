// The GIMP step as a list of phases (paper Section 5). Each phase is a free
// function over the World; only the first (locate.cpp) allocates, and only
// when the number of points or the touched window grows.
#include "sim/physics/step.hpp"

#include <omp.h>

#include <algorithm>
#include <cstring>
#include <type_traits>

#include "sim/physics/apic.hpp"
#include "sim/physics/bands.hpp"
#include "sim/physics/wall_friction.hpp"

namespace sim {

// The whole step is one parallel region: a thread keeps its bands of points
// and rows of nodes from phase to phase (sim/physics/bands.hpp). Locate's
// phases are separated by barriers; from the reset of the grid on, every
// phase needs only the bands beside its own, and waits for the marks those
// bands leave (sim/physics/bands.hpp) instead of for every thread. The transfers
// are the paper's (FLIP-like increments) or APIC's (sim/physics/apic.hpp), chosen
// once per step. The team has no more threads than there are free cores
// (sim/physics/team.hpp).
void step(World& w, const StepInput& in, StepReport& report) {
  prepare_locate(w);
  const bool apic = w.transfer == TransferScheme::Apic;
#pragma omp parallel num_threads(team_size(w.team))
  {
    if (locate_and_sort(w)) {  // false on every thread if a point left the grid
      reset_grid(w);  // marks its bands: P2G waits for those above its own
      points_to_grid(w);
      enforce_walls_on_momentum(w);  // marks its bands: the stress phase waits for those it reads
      update_stress_and_forces(w, in);
      update_nodal_momentum(w, in.dt);  // marks its bands: G2P waits for those it reads
      if (apic) grid_to_points_apic(w, in); else grid_to_points(w, in);
    }
  }
  if (w.bad_point < static_cast<int>(w.points.size())) throw_point_left_grid(w);
  report = sum_step_report(w);
}

namespace {

// Whether later phases read every nodal value the holds and the update
// make: friction walls read and change p_i, a_i and f_i at their nodes, and
// APIC sums the grid's kinetic energy from p_i. Without them the phases
// below store only what G2P and the stress phase read, and only on the
// nodes points weight.
bool all_nodal_values_read(const World& w) {
  return !w.grid.friction_walls.empty() || w.transfer == TransferScheme::Apic;
}

// The nodes of rows [first, last) that the reset, the walls and the nodal
// update visit. Node row j is weighted by the points of base rows j - 2 to j:
// from the first base node of those rows to three past the last. The rest
// of the window is air: no point reads it but with a zero weight (the fourth
// lane of a stencil row, gimp.hpp), so it is neither reset nor updated. On
// the 66,787-point slope the spans hold 68 % of the window's nodes at rest;
// with friction walls or APIC, which visit the whole window, a span is the
// window's row.
void set_row_spans(World& w, int first, int last) {
  Grid& g = w.grid;
  const bool all = all_nodal_values_read(w);
  const int base_rows = g.j_end - 2 - g.j_begin;
  for (int j = first; j < last; ++j) {
    const int r = j - g.j_begin;
    int lo = g.i_end, hi = g.i_begin - 3;
    for (int b = std::max(0, r - 2); b <= std::min(r, base_rows - 1); ++b) {
      const int* base = &w.base_row_span[2 * b];
      if (base[0] > base[1]) continue;  // no points
      lo = std::min(lo, base[0]);
      hi = std::max(hi, base[1]);
    }
    int* span = g.span_of_row(j);
    span[0] = all ? g.i_begin : lo;
    span[1] = all ? g.i_end : std::max(lo, hi + 3);
  }
}

}  // namespace

void reset_grid(World& w) {
  WorkClock clock(w);
  Grid& g = w.grid;
  int first, last;
  own_rows(w, first, last);
  set_row_spans(w, first, last);
  // An array at a time: the five stores of a node in one loop were compiled
  // to scalar stores (the arrays might overlap, as far as the compiler
  // knows), and perf put 3.7 % of a 66,787-point run on them.
  for (int j = first; j < last; ++j) {
    const int* span = g.span_of_row(j);
    const int k = g.node(span[0], j), n = g.node(span[1], j) - k;  // fill_n: none if n <= 0
    for (auto* a : {&g.mass, &g.px, &g.py, &g.fx, &g.fy})
      std::fill_n(a->data() + k, n, 0.0);
  }
  if (!g.friction_walls.empty()) reset_wall_gaps(g, first, last);
  clock.finish();
  mark_own_bands(w, BandMark::Reset);
}

namespace {

// One band's points to their nodes with the paper's transfer.
void map_band(World& w, int band) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  double* const arrays[3] = {g.mass.data(), g.px.data(), g.py.data()};
  const StencilWeights* const weights = w.weights.data();
  scatter_band_in_runs(w, band, arrays, [&](int p, Lane4(&rows)[3][3]) {
    const StencilWeights& st = weights[p];
    const double m = pts.mass[p], mvx = m * pts.vx[p], mvy = m * pts.vy[p];
    for (int b = 0; b < 3; ++b) {
      const Lane4 S = x_weights(st) * st.wy[b];  // S_ip, Eq. (12)
      rows[0][b] = fused(S, m, rows[0][b]);      // Eq. (26)
      rows[1][b] = fused(S, mvx, rows[1][b]);    // Eq. (27)
      rows[2][b] = fused(S, mvy, rows[2][b]);
    }
  });
}

}  // namespace

// Each band by the scene's transfer, then the friction walls' gaps of its
// points, whatever the transfer: the APIC mapping once had a scatter of its
// own without the gaps, and a block fell through a friction floor.
void points_to_grid(World& w) {
  const bool apic = w.transfer == TransferScheme::Apic;
  const bool walls = !w.grid.friction_walls.empty();
  scatter_own_bands(w, BandMark::Mass, BandMark::Reset, [&](int band) {
    if (apic) map_band_apic(w, band); else map_band(w, band);
    if (walls) scatter_wall_gaps(w, band);
  });
}

namespace {

// The nodal phases below take a row's nodes eight at a time (V = Lane8, a
// node a lane, M = Int8) and its last ones one at a time (V = double,
// M = bool), each by one formula written for both. g++ 12 vectorized
// neither loop written node by node ("no vectype" for the loads of the
// grid's arrays), and the slope's window is mostly air whose nodes cost the
// same as the soil's. Lanes and single nodes round alike, so the bits are
// those of a node at a time.
template <class V>
V at(const NodeArray<double>& a, int k) {
  if constexpr (std::is_same_v<V, double>)
    return a[k];
  else
    return load8(&a[k]);
}
template <class V>
void put(NodeArray<double>& a, int k, const V& v) {
  std::memcpy(&a[k], &v, sizeof v);
}
// Whether a wall holds the component at node k (and the seven after it).
template <class M>
M held(const NodeArray<std::uint8_t>& fix, int k) {
  if constexpr (std::is_same_v<M, bool>) {
    return fix[k] != 0;
  } else {
    Bytes8 bytes;
    std::memcpy(&bytes, &fix[k], sizeof bytes);
    return __builtin_convertvector(bytes != 0, M);  // -1 or 0, widened with its sign
  }
}
// Row j's span, eight nodes at a time while eight remain, then one by one.
template <class Eight, class One>
void along_row(const Grid& g, int j, Eight eight, One one) {
  const int* span = g.span_of_row(j);
  int k = g.node(span[0], j);
  const int end = g.node(span[1], j);
  for (; k + 8 <= end; k += 8) eight(k);
  for (; k < end; ++k) one(k);
}

// 1 / m_i, or 0 at a node without mass.
template <class V>
V inverse_mass(const V& m) {
  return m > 0.0 ? 1.0 / m : V{};
}

// Whether a wall holds a component at any of the nodes.
inline bool any_held(bool hx, bool hy) { return hx || hy; }
inline bool any_held(const Int8& hx, const Int8& hy) { return !every((hx | hy) == 0); }

// Where the nodal phases read a component back: at a held one, or
// everywhere where friction walls or APIC (`all`) may have set it.
inline bool held_or_all(bool h, bool all) { return h || all; }
inline Int8 held_or_all(const Int8& h, bool all) { return all ? Int8{} - 1 : h; }

// Walls hold nodal momentum components at zero (paper Section 6). Nodal
// velocity v_i = p_i / m_i is what the strain increment of Eq. (31) reads.
// The velocity a wall takes away is kept (in ax, ay) and handed to the points
// with the step's acceleration: with the incremental update of Eq. (30) a
// point would otherwise keep the speed a no-slip wall stopped, and a deposit
// against a wall would never come to rest. Returns p_i . dv_i / 2 at each
// node: the kinetic energy m_i |dv_i|^2 / 2 the holds take, negated.
//
// A component no wall holds keeps its p_i and takes no a_i: without
// friction walls and APIC, which read and change them here (`all`), they
// are stored only where a wall holds a component of a node, and the nodal
// update reads a_i only where one is held (update_momentum).
template <class V, class M>
V hold_momentum(Grid& g, int k, bool all) {
  const M hx = held<M>(g.fix_x, k), hy = held<M>(g.fix_y, k);
  const V inv = inverse_mass(at<V>(g.mass, k));
  const V px = at<V>(g.px, k), py = at<V>(g.py, k);
  const V ax = hx ? -px * inv : V{}, ay = hy ? -py * inv : V{};
  const V kept_x = hx ? V{} : px, kept_y = hy ? V{} : py;
  if (all || any_held(hx, hy)) {
    put(g.ax, k, ax);
    put(g.ay, k, ay);
    put(g.px, k, kept_x);
    put(g.py, k, kept_y);
  }
  put(g.vx, k, kept_x * inv);
  put(g.vy, k, kept_y * inv);
  return 0.5 * (px * ax + py * ay);
}

// Eq. (28): p_i^{k+1} = p_i^k + dt f_i, with the force normal to a wall
// taken away. The nodal acceleration handed to the points (Eq. 30) is the
// whole velocity change of the step: force plus what the wall took away.
//
// G2P reads a_i and v_i^{k+1}, and held_a_i near the walls. The updated
// f_i and p_i are read only by friction walls and APIC's kinetic sums
// (`all`); without them they are not stored. held_a_i is a_i at a held
// component and 0 elsewhere, and the grid's arrays start at 0
// (node_array.hpp), so without friction walls (which write it at nodes no
// wall holds) it is stored only where a wall holds a component. Six of ten
// stores a node fewer, the same values read.
template <class V, class M>
void update_momentum(Grid& g, int k, double dt, double inv_dt, bool all) {
  const M hx = held<M>(g.fix_x, k), hy = held<M>(g.fix_y, k);
  const V inv = inverse_mass(at<V>(g.mass, k));
  const V fx = hx ? V{} : at<V>(g.fx, k), fy = hy ? V{} : at<V>(g.fy, k);
  const V px = fused(fx, dt, at<V>(g.px, k)), py = fused(fy, dt, at<V>(g.py, k));
  const V taken_x = held_or_all(hx, all) ? at<V>(g.ax, k) : V{};  // by hold_momentum
  const V taken_y = held_or_all(hy, all) ? at<V>(g.ay, k) : V{};
  const V ax = fused(fx, inv, taken_x * inv_dt);
  const V ay = fused(fy, inv, taken_y * inv_dt);
  put(g.ax, k, ax);
  put(g.ay, k, ay);
  put(g.vx, k, px * inv);
  put(g.vy, k, py * inv);
  if (all) {
    put(g.fx, k, fx);
    put(g.fy, k, fy);
    put(g.px, k, px);
    put(g.py, k, py);
  }
  if (all || any_held(hx, hy)) {
    put(g.held_ax, k, hx ? ax : V{});
    put(g.held_ay, k, hy ? ay : V{});
  }
}

}  // namespace

// The holds above, row by row; the kinetic energy they take goes to
// row_sums, node by node in the row's order. Friction walls act after the
// holds.
void enforce_walls_on_momentum(World& w) {
  WorkClock clock(w);
  Grid& g = w.grid;
  int first, last;
  own_rows(w, first, last);
  if (w.transfer == TransferScheme::Apic) grid_kinetic_by_row(g, first, last, kRowGridKineticMapped);
  const bool all = all_nodal_values_read(w);
  for (int j = first; j < last; ++j) {
    double removed = 0;
    along_row(
        g, j,
        [&](int k) {
          const Lane8 taken = hold_momentum<Lane8, Int8>(g, k, all);
          for (int l = 0; l < 8; ++l) removed -= taken[l];
        },
        [&](int k) { removed -= hold_momentum<double, bool>(g, k, all); });
    // A held component's change is all it had: the grid loses what it takes.
    double* sums = &g.row_sums[(j - g.j_begin) * kRowSums];
    sums[kRowWallLoss] = removed;
    sums[kRowWallChangeOnGrid] = removed;
  }
  if (!g.friction_walls.empty()) friction_walls_on_momentum(g, first, last);
  clock.finish();
  mark_own_bands(w, BandMark::Walls);
}

// Eq. (28) on the thread's rows; friction walls then act on p_i^{k+1}.
void update_nodal_momentum(World& w, double dt) {
  WorkClock clock(w);
  Grid& g = w.grid;
  const double inv_dt = 1.0 / dt;
  const bool all = all_nodal_values_read(w);
  int first, last;
  own_rows(w, first, last);
  for (int j = first; j < last; ++j)
    along_row(
        g, j, [&](int k) { update_momentum<Lane8, Int8>(g, k, dt, inv_dt, all); },
        [&](int k) { update_momentum<double, bool>(g, k, dt, inv_dt, all); });
  if (!g.friction_walls.empty()) friction_walls_on_update(g, first, last, dt);
  if (w.transfer == TransferScheme::Apic) grid_kinetic_by_row(g, first, last, kRowGridKineticUpdated);
  clock.finish();
  mark_own_bands(w, BandMark::NodalUpdate);
}

// The step's sums, band by band (row by row for the walls) in a fixed order.
StepReport sum_step_report(const World& w) {
  StepReport r;
  double wall_change_on_grid = 0, grid_mapped = 0, grid_updated = 0, points_before = 0;
  for (std::size_t row = 0; row < w.grid.row_sums.size(); row += kRowSums) {
    const double* sums = &w.grid.row_sums[row];
    r.wall_loss += sums[kRowWallLoss];
    r.friction_work += sums[kRowFrictionWork];
    wall_change_on_grid += sums[kRowWallChangeOnGrid];
    grid_mapped += sums[kRowGridKineticMapped];
    grid_updated += sums[kRowGridKineticUpdated];
  }
  for (std::size_t b = 0; b + 1 < w.band_start.size(); ++b) {
    const double* sums = &w.band_sums[b * kBandSums];
    r.internal_work += sums[kInternalWork];
    r.gravity_work += sums[kGravityWork];
    r.kinetic_energy += sums[kKineticEnergy];
    r.moving_kinetic_energy += sums[kMovingKineticEnergy];
    r.damping_loss += sums[kDampingLoss];
    r.max_signal = std::max(r.max_signal, sums[kMaxSignal]);
    r.wall_change_on_points += sums[kWallChangeOnPoints];
    points_before += sums[kKineticBeforeGrid];
  }
  // FLIP: what the walls' change costs the points beyond what the walls took
  // (StepReport); APIC: both transfers' loss, measured (sim/physics/apic.hpp).
  r.transfer_loss = w.transfer == TransferScheme::Apic
                        ? (points_before - grid_mapped) + (grid_updated - r.moving_kinetic_energy)
                        : wall_change_on_grid - r.wall_change_on_points;
  return r;
}

}  // namespace sim
