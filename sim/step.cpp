// The GIMP step as a list of phases (paper Section 5). Each phase is a free
// function over the World; only locate_points and the step's partial sums
// allocate, and only when the number of points or the touched window grows.
#include "sim/step.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/bands.hpp"

namespace sim {

// The whole step is one parallel region: a thread keeps its bands of points
// and rows of nodes from phase to phase (sim/bands.hpp), and the phases are
// separated by barriers, not by starting new teams of threads.
void step(World& w, const StepInput& in, StepReport& report) {
  locate_points(w);
  w.band_sums.assign((w.band_start.size() - 1) * kBandSums, 0.0);
  w.grid.row_sums.assign(static_cast<std::size_t>(w.grid.j_end - w.grid.j_begin), 0.0);
#pragma omp parallel
  {
#pragma omp single
    partition_bands(w, omp_get_num_threads());
    reset_grid(w);
#pragma omp barrier
    points_to_grid(w);
    enforce_walls_on_momentum(w);
#pragma omp barrier
    update_stress_and_forces(w, in);
    update_nodal_momentum(w, in.dt);
#pragma omp barrier
    grid_to_points(w, in);
  }
  report = sum_step_report(w);
}

namespace {

[[noreturn]] void point_left_grid(const World& w, int p) {
  std::ostringstream msg;
  msg.precision(6);
  msg << "point " << p << " (material '" << w.material_specs[w.points.material[p]].name
      << "') at (" << w.points.x[p] << ", " << w.points.y[p] << ") m ";
  if (!std::isfinite(w.points.x[p]) || !std::isfinite(w.points.y[p]))
    msg << "has a non-finite position";
  else
    msg << "left the grid [" << w.grid.origin_x << ", "
        << w.grid.origin_x + (w.grid.nx - 1) * w.grid.h << "] x [" << w.grid.origin_y << ", "
        << w.grid.origin_y + (w.grid.ny - 1) * w.grid.h << "]";
  throw SimulationError(msg.str());
}

// Stable counting sort of the points by base node, then cut into bands of
// kBandRows node rows. Sorting keeps neighbours close in memory and fixes the
// order in which each node's sums are taken. The bins cover only the base
// nodes of this step's window (row-major, as the grid), so a scene pays for
// the nodes near its material, not for the whole mesh.
void sort_into_bands(World& w) {
  Grid& g = w.grid;
  const int n = static_cast<int>(w.points.size());
  const int width = g.i_end - 2 - g.i_begin;  // base nodes per row in the window
  const int base_rows = g.j_end - 2 - g.j_begin;
  const std::size_t bins = static_cast<std::size_t>(std::max(width, 0)) * std::max(base_rows, 0);
  w.bin_count.assign(bins + 1, 0);
  for (int p = 0; p < n; ++p) {
    const Stencil& st = w.stencils[p];
    w.bin_key[p] = (st.base_j - g.j_begin) * width + (st.base_i - g.i_begin);
    ++w.bin_count[w.bin_key[p] + 1];
  }
  for (std::size_t b = 0; b < bins; ++b) w.bin_count[b + 1] += w.bin_count[b];
  const int rows = g.j_end - g.j_begin;
  const int bands = (rows + kBandRows - 1) / kBandRows;
  w.band_start.resize(static_cast<std::size_t>(bands) + 1);
  for (int b = 0; b <= bands; ++b)
    w.band_start[b] = w.bin_count[static_cast<std::size_t>(std::min(b * kBandRows, base_rows)) * width];
  w.order.resize(n);
  for (int p = 0; p < n; ++p) w.order[w.bin_count[w.bin_key[p]]++] = p;
}

}  // namespace

void locate_points(World& w) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  const int n = static_cast<int>(pts.size());
  w.stencils.resize(n);
  w.bin_key.resize(n);
  int bad = n, i_lo = g.nx, i_hi = -1, j_lo = g.ny, j_hi = -1;
  const int blocks = (n + 7) / 8;
  // Eight points at a time (Lane8, gimp.hpp); the last block repeats its
  // last point where the points run out.
#pragma omp parallel for schedule(static) reduction(min : bad, i_lo, j_lo) reduction(max : i_hi, j_hi)
  for (int blk = 0; blk < blocks; ++blk) {
    const int first = 8 * blk, count = std::min(8, n - first);
    Lane8 x, y;
    for (int l = 0; l < 8; ++l) {
      x[l] = pts.x[first + std::min(l, count - 1)];
      y[l] = pts.y[first + std::min(l, count - 1)];
    }
    Int8 base_i, base_j;
    Lane8 wx[3], dx[3], wy[3], dy[3];
    gimp_axis(x, g.origin_x, w.gimp, base_i, wx, dx);
    gimp_axis(y, g.origin_y, w.gimp, base_j, wy, dy);
    for (int l = 0; l < count; ++l) {
      const int p = first + l;
      Stencil& st = w.stencils[p];
      st.base_i = static_cast<int>(base_i[l]);
      st.base_j = static_cast<int>(base_j[l]);
      st.wx = Lane4{wx[0][l], wx[1][l], wx[2][l], 0.0};
      st.dx = Lane4{dx[0][l], dx[1][l], dx[2][l], 0.0};
      for (int a = 0; a < 3; ++a) {
        st.wy[a] = wy[a][l];
        st.dy[a] = dy[a][l];
      }
      const bool inside = std::isfinite(x[l]) && std::isfinite(y[l]) && st.base_i >= 0 &&
                          st.base_j >= 0 && st.base_i + 2 < g.nx && st.base_j + 2 < g.ny;
      if (!inside) {
        bad = std::min(bad, p);
        continue;
      }
      i_lo = std::min(i_lo, st.base_i);
      i_hi = std::max(i_hi, st.base_i);
      j_lo = std::min(j_lo, st.base_j);
      j_hi = std::max(j_hi, st.base_j);
    }
  }
  if (bad < n) point_left_grid(w, bad);
  if (n == 0) i_lo = i_hi = j_lo = j_hi = 0;
  g.i_begin = i_lo;
  g.i_end = i_hi + 3;
  g.j_begin = j_lo;
  g.j_end = j_hi + 3;
  sort_into_bands(w);
}

void reset_grid(World& w) {
  Grid& g = w.grid;
  int first, last;
  own_rows(w, first, last);
  for (int j = first; j < last; ++j) {
    for (int i = g.i_begin; i < g.i_end; ++i) {
      const int k = g.node(i, j);
      g.mass[k] = g.px[k] = g.py[k] = g.fx[k] = g.fy[k] = 0.0;
      g.points[k] = 0;
    }
  }
}

void points_to_grid(World& w) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  scatter_own_bands(w, [&](int band) {
    for (int s = w.band_start[band]; s < w.band_start[band + 1]; ++s) {
      const int p = w.order[s];
      const Stencil& st = w.stencils[p];
      const double m = pts.mass[p], mvx = m * pts.vx[p], mvy = m * pts.vy[p];
      for (int b = 0; b < 3; ++b) {
        const int row = g.node(st.base_i, st.base_j + b);
        const Lane4 S = st.wx * st.wy[b];                   // S_ip, Eq. (12)
        store4(&g.mass[row], load4(&g.mass[row]) + S * m);  // Eq. (26)
        store4(&g.px[row], load4(&g.px[row]) + S * mvx);    // Eq. (27)
        store4(&g.py[row], load4(&g.py[row]) + S * mvy);
        for (int a = 0; a < 3; ++a) g.points[row + a] += S[a] > 0.0;
      }
    }
  });
}

// Walls hold nodal momentum components at zero (paper Section 6). Nodal
// velocity v_i = p_i / m_i is what the strain increment of Eq. (31) reads.
// The velocity a wall takes away is kept (in ax, ay) and handed to the points
// with the step's acceleration: with the incremental update of Eq. (30) a
// point would otherwise keep the speed a no-slip wall stopped, and a deposit
// against a wall would never come to rest. The kinetic energy taken goes to
// row_sums, row by row.
void enforce_walls_on_momentum(World& w) {
  Grid& g = w.grid;
  int first, last;
  own_rows(w, first, last);
  for (int j = first; j < last; ++j) {
    double removed = 0;
    for (int i = g.i_begin; i < g.i_end; ++i) {
      const int k = g.node(i, j);
      const double inv = g.mass[k] > 0.0 ? 1.0 / g.mass[k] : 0.0;
      g.ax[k] = g.fix_x[k] ? -g.px[k] * inv : 0.0;
      g.ay[k] = g.fix_y[k] ? -g.py[k] * inv : 0.0;
      removed -= 0.5 * (g.px[k] * g.ax[k] + g.py[k] * g.ay[k]);
      if (g.fix_x[k]) g.px[k] = 0.0;
      if (g.fix_y[k]) g.py[k] = 0.0;
      g.vx[k] = g.px[k] * inv;
      g.vy[k] = g.py[k] * inv;
    }
    g.row_sums[j - g.j_begin] = removed;
  }
}

// Eq. (28): p_i^{k+1} = p_i^k + dt f_i. Walls take the force normal to them.
// The nodal acceleration handed to the points (Eq. 30) is the whole velocity
// change of the step: force plus what the wall took away.
void update_nodal_momentum(World& w, double dt) {
  Grid& g = w.grid;
  const double inv_dt = 1.0 / dt;
  int first, last;
  own_rows(w, first, last);
  for (int j = first; j < last; ++j) {
    for (int i = g.i_begin; i < g.i_end; ++i) {
      const int k = g.node(i, j);
      if (g.fix_x[k]) g.fx[k] = 0.0;
      if (g.fix_y[k]) g.fy[k] = 0.0;
      g.px[k] += dt * g.fx[k];
      g.py[k] += dt * g.fy[k];
      const double inv = g.mass[k] > 0.0 ? 1.0 / g.mass[k] : 0.0;
      g.ax[k] = g.ax[k] * inv_dt + g.fx[k] * inv;
      g.ay[k] = g.ay[k] * inv_dt + g.fy[k] * inv;
      g.held_ax[k] = g.fix_x[k] ? g.ax[k] : 0.0;
      g.held_ay[k] = g.fix_y[k] ? g.ay[k] : 0.0;
      g.vx[k] = g.px[k] * inv;
      g.vy[k] = g.py[k] * inv;
    }
  }
}

// The step's sums, band by band (row by row for the walls) in a fixed order.
StepReport sum_step_report(const World& w) {
  StepReport r;
  for (const double row : w.grid.row_sums) r.wall_loss += row;
  for (std::size_t b = 0; b + 1 < w.band_start.size(); ++b) {
    const double* sums = &w.band_sums[b * kBandSums];
    r.internal_work += sums[0];
    r.gravity_work += sums[1];
    r.kinetic_energy += sums[2];
    r.moving_kinetic_energy += sums[3];
    r.damping_loss += sums[4];
    r.max_signal = std::max(r.max_signal, sums[5]);
    r.wall_change_on_points += sums[6];
  }
  r.transfer_loss = r.wall_loss - r.wall_change_on_points;
  return r;
}

}  // namespace sim
