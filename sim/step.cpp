// The GIMP step as a list of phases (paper Section 5). Each phase is a free
// function over the World; only locate_points allocates, and only when the
// number of points or the touched window grows.
#include "sim/step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sim {

void step(World& w, const StepInput& in, StepReport& report) {
  locate_points(w);
  reset_grid(w.grid);
  points_to_grid(w);
  report = StepReport{};
  report.wall_loss = enforce_walls_on_momentum(w.grid);
  report.internal_work = update_stress(w, in.dt);
  grid_forces(w, in.gravity);
  update_nodal_momentum(w.grid, in.dt);
  grid_to_points(w, in, report);
  report.transfer_loss = report.wall_loss - report.wall_change_on_points;
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

// Runs add(p) for every point, band by band: even bands in parallel, then odd
// bands. No two bands running at once touch the same node, and each node
// receives its contributions in the same order whatever the thread count.
template <class Add>
void scatter_by_bands(const World& w, Add add) {
  const int bands = static_cast<int>(w.band_start.size()) - 1;
  for (int parity = 0; parity < 2; ++parity) {
#pragma omp parallel for schedule(dynamic, 1)
    for (int b = parity; b < bands; b += 2)
      for (int s = w.band_start[b]; s < w.band_start[b + 1]; ++s) add(w.order[s]);
  }
}

}  // namespace

void locate_points(World& w) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  const int n = static_cast<int>(pts.size());
  w.stencils.resize(n);
  w.bin_key.resize(n);
  int bad = n, i_lo = g.nx, i_hi = -1, j_lo = g.ny, j_hi = -1;
#pragma omp parallel for schedule(static) reduction(min : bad, i_lo, j_lo) reduction(max : i_hi, j_hi)
  for (int p = 0; p < n; ++p) {
    Stencil& st = w.stencils[p];
    gimp_stencil(pts.x[p], pts.y[p], g.origin_x, g.origin_y, g.h, w.half_width, st);
    const bool inside = std::isfinite(pts.x[p]) && std::isfinite(pts.y[p]) && st.base_i >= 0 &&
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
  if (bad < n) point_left_grid(w, bad);
  if (n == 0) i_lo = i_hi = j_lo = j_hi = 0;
  g.i_begin = i_lo;
  g.i_end = i_hi + 3;
  g.j_begin = j_lo;
  g.j_end = j_hi + 3;
  sort_into_bands(w);
}

void reset_grid(Grid& g) {
#pragma omp parallel for schedule(static)
  for (int j = g.j_begin; j < g.j_end; ++j) {
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
  scatter_by_bands(w, [&](int p) {
    const Stencil& st = w.stencils[p];
    const double m = pts.mass[p], mvx = m * pts.vx[p], mvy = m * pts.vy[p];
    for (int b = 0; b < 3; ++b) {
      const int row = g.node(st.base_i, st.base_j + b);
      for (int a = 0; a < 3; ++a) {
        const double S = st.wx[a] * st.wy[b];  // S_ip, Eq. (12)
        g.mass[row + a] += S * m;              // Eq. (26)
        g.px[row + a] += S * mvx;              // Eq. (27)
        g.py[row + a] += S * mvy;
        g.points[row + a] += S > 0.0;
      }
    }
  });
}

// Walls hold nodal momentum components at zero (paper Section 6). Nodal
// velocity v_i = p_i / m_i is what the strain increment of Eq. (31) reads.
// The velocity a wall takes away is kept (in ax, ay) and handed to the points
// with the step's acceleration: with the incremental update of Eq. (30) a
// point would otherwise keep the speed a no-slip wall stopped, and a deposit
// against a wall would never come to rest.
double enforce_walls_on_momentum(Grid& g) {
  g.row_sums.assign(static_cast<std::size_t>(g.j_end - g.j_begin), 0.0);
#pragma omp parallel for schedule(static)
  for (int j = g.j_begin; j < g.j_end; ++j) {
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
  double removed = 0;  // row by row, in a fixed order
  for (const double row : g.row_sums) removed += row;
  return removed;
}

void grid_forces(World& w, const Vec2& gravity) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  scatter_by_bands(w, [&](int p) {
    const Stencil& st = w.stencils[p];
    const double V = pts.mass[p] / pts.density[p];
    const double sxx = pts.sxx[p], syy = pts.syy[p], sxy = pts.sxy[p];
    const double mgx = pts.mass[p] * gravity[0], mgy = pts.mass[p] * gravity[1];
    for (int b = 0; b < 3; ++b) {
      const int row = g.node(st.base_i, st.base_j + b);
      for (int a = 0; a < 3; ++a) {
        const double S = st.wx[a] * st.wy[b];
        const double gx = st.dx[a] * st.wy[b], gy = st.wx[a] * st.dy[b];  // grad S_ip
        // f_int = -sigma_p . grad S_ip V_p, Eq. (16); f_ext = m_p b S_ip, Eq. (17).
        g.fx[row + a] += -V * (sxx * gx + sxy * gy) + S * mgx;
        g.fy[row + a] += -V * (sxy * gx + syy * gy) + S * mgy;
      }
    }
  });
}

// Eq. (28): p_i^{k+1} = p_i^k + dt f_i. Walls take the force normal to them.
// The nodal acceleration handed to the points (Eq. 30) is the whole velocity
// change of the step: force plus what the wall took away.
void update_nodal_momentum(Grid& g, double dt) {
  const double inv_dt = 1.0 / dt;
#pragma omp parallel for schedule(static)
  for (int j = g.j_begin; j < g.j_end; ++j) {
    for (int i = g.i_begin; i < g.i_end; ++i) {
      const int k = g.node(i, j);
      if (g.fix_x[k]) g.fx[k] = 0.0;
      if (g.fix_y[k]) g.fy[k] = 0.0;
      g.px[k] += dt * g.fx[k];
      g.py[k] += dt * g.fy[k];
      const double inv = g.mass[k] > 0.0 ? 1.0 / g.mass[k] : 0.0;
      g.ax[k] = g.ax[k] * inv_dt + g.fx[k] * inv;
      g.ay[k] = g.ay[k] * inv_dt + g.fy[k] * inv;
      g.vx[k] = g.px[k] * inv;
      g.vy[k] = g.py[k] * inv;
    }
  }
}

}  // namespace sim
