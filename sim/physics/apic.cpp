#include "sim/physics/apic.hpp"

#include <algorithm>
#include <cmath>

#include "sim/physics/bands.hpp"

namespace sim {

namespace {

// x_a - x_p for the stencil's three columns (lane 3: the spare node).
Lane4 column_offsets(const Grid& g, const StencilWeights& st, double x) {
  const double first = g.origin_x + st.base_i * g.h - x;
  return Lane4{first, first + g.h, first + 2 * g.h, first + 3 * g.h};
}

double row_offset(const Grid& g, const StencilWeights& st, int b, double y) {
  return g.origin_y + (st.base_j + b) * g.h - y;
}

}  // namespace

void map_band_apic(World& w, int band) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  double* const arrays[3] = {g.mass.data(), g.px.data(), g.py.data()};
  const StencilWeights* const weights = w.weights.data();
  double kinetic = 0;
  scatter_band_in_runs(w, band, arrays, [&](int p, Lane4(&rows)[3][3]) {
    const StencilWeights& st = weights[p];
    const double m = pts.mass[p], vx = pts.vx[p], vy = pts.vy[p];
    kinetic += 0.5 * m * (vx * vx + vy * vy);
    const Lane4 dx = column_offsets(g, st, pts.x[p]);
    for (int b = 0; b < 3; ++b) {
      const double dy = row_offset(g, st, b, pts.y[p]);
      const Lane4 mS = x_weights(st) * st.wy[b] * m;
      rows[0][b] += mS;
      rows[1][b] += mS * (vx + pts.cxx[p] * dx + pts.cxy[p] * dy);
      rows[2][b] += mS * (vy + pts.cyx[p] * dx + pts.cyy[p] * dy);
    }
  });
  w.band_sums[band * kBandSums + kKineticBeforeGrid] = kinetic;
}

void grid_to_points_apic(World& w, const StepInput& in) {
  const Grid& g = w.grid;
  Particles& pts = w.points;
  const double keep = 1.0 / (1.0 + in.damping);
  gather_own_bands(w, [&](int band) {
    double gravity_work = 0, kinetic = 0, moving = 0, damped = 0, signal = 0;
    for (int s = w.band_start[band]; s < w.band_start[band + 1]; ++s) {
      const int p = w.order[s];
      const StencilWeights& st = w.weights[p];
      const Lane4 dx = column_offsets(g, st, pts.x[p]);
      Lane4 svx{}, svy{}, bxx{}, byx{};
      double bxy = 0, byy = 0, dyy = 0;
      for (int b = 0; b < 3; ++b) {
        const int row = g.node(st.base_i, st.base_j + b);
        const double dy = row_offset(g, st, b, pts.y[p]);
        const Lane4 S = x_weights(st) * st.wy[b];
        const Lane4 vx = S * load4(&g.vx[row]), vy = S * load4(&g.vy[row]);
        svx += vx;
        svy += vy;
        bxx += vx * dx;
        byx += vy * dx;
        bxy += sum3(vx) * dy;
        byy += sum3(vy) * dy;
        dyy += st.wy[b] * dy * dy;
      }
      const double dxx = sum3(x_weights(st) * dx * dx);
      const double vx = sum3(svx), vy = sum3(svy);
      pts.cxx[p] = keep * sum3(bxx) / dxx;
      pts.cyx[p] = keep * sum3(byx) / dxx;
      pts.cxy[p] = keep * bxy / dyy;
      pts.cyy[p] = keep * byy / dyy;
      const double ddx = in.dt * vx, ddy = in.dt * vy;  // Eq. (29)
      pts.x[p] += ddx;
      pts.y[p] += ddy;
      pts.vx[p] = keep * vx;
      pts.vy[p] = keep * vy;
      const double m = pts.mass[p], v2 = vx * vx + vy * vy, kept = keep * keep * v2;
      gravity_work += m * (in.gravity[0] * ddx + in.gravity[1] * ddy);
      kinetic += 0.5 * m * kept;
      moving += 0.5 * m * v2;
      damped += 0.5 * m * (v2 - kept);
      signal = std::max(signal, w.materials[pts.material[p]].wave_speed + std::sqrt(kept));
    }
    store_point_sums(w, band, {gravity_work, kinetic, moving, damped, signal, 0.0});
  });
}

void grid_kinetic_by_row(Grid& g, int first, int last, int which) {
  for (int j = first; j < last; ++j) {
    double kinetic = 0;
    for (int i = g.i_begin; i < g.i_end; ++i) {
      const int k = g.node(i, j);
      if (g.mass[k] > 0.0) kinetic += 0.5 * (g.px[k] * g.px[k] + g.py[k] * g.py[k]) / g.mass[k];
    }
    g.row_sums[(j - g.j_begin) * kRowSums + which] = kinetic;
  }
}

}  // namespace sim
