// The two per-point phases of the step: the stress update (grid -> point
// strain increment, then the constitutive model) and the velocity and
// position update (grid -> point, Eqs. 29 and 30).
#include <algorithm>
#include <cmath>

#include "sim/constitutive.hpp"
#include "sim/step.hpp"

namespace sim {

double update_stress(World& w, double dt) {
  Particles& pts = w.points;
  const Grid& g = w.grid;
  const int n = static_cast<int>(pts.size());
  const int chunks = (n + kReductionChunk - 1) / kReductionChunk;
  w.chunk_sums.assign(static_cast<std::size_t>(chunks), 0.0);
#pragma omp parallel for schedule(static)
  for (int c = 0; c < chunks; ++c) {
    double work = 0;
    const int end = std::min(n, (c + 1) * kReductionChunk);
    for (int p = c * kReductionChunk; p < end; ++p) {
      const Stencil& st = w.stencils[p];
      // Velocity gradient L_ab = sum_i v_ia dS_ip/dx_b.
      double lxx = 0, lxy = 0, lyx = 0, lyy = 0;
      bool alone = true;
      for (int b = 0; b < 3; ++b) {
        const int row = g.node(st.base_i, st.base_j + b);
        for (int a = 0; a < 3; ++a) {
          alone = alone && (st.wx[a] * st.wy[b] == 0.0 || g.points[row + a] == 1);
          const double gx = st.dx[a] * st.wy[b], gy = st.wx[a] * st.dy[b];
          lxx += g.vx[row + a] * gx;
          lxy += g.vx[row + a] * gy;
          lyx += g.vy[row + a] * gx;
          lyy += g.vy[row + a] * gy;
        }
      }
      const StrainIncrement de{dt * lxx, dt * lyy, 0.5 * dt * (lxy + lyx)};  // Eq. (31)
      const MaterialConstants& mat = w.materials[pts.material[p]];
      const Stress old{pts.sxx[p], pts.syy[p], pts.sxy[p], pts.szz[p]};
      Stress s = old;
      jaumann_rotate(s, 0.5 * dt * (lxy - lyx));  // Eq. (24)
      elastic_predictor(s, de, mat);              // Eq. (21)
      if (mat.plastic)                            // Eqs. (20)-(23)
        pts.yielded[p] = mohr_coulomb_return(mat.mohr_coulomb, s) != ReturnRegion::Elastic;
      // A point that shares no node with another is a free body: traction-free
      // all round, so it carries no stress. Kept, its stress would push it off
      // every wall it touches (the grid cannot strain a lone point), and
      // clods thrown off a slide would bounce for ever. Not in the paper.
      if (alone) s = Stress{};
      pts.sxx[p] = s.xx;
      pts.syy[p] = s.yy;
      pts.sxy[p] = s.xy;
      pts.szz[p] = s.zz;
      // Stress power of Eq. (3) over the step, midpoint stress, current volume.
      const double volume = pts.mass[p] / pts.density[p];
      work += volume * 0.5 * ((old.xx + s.xx) * de.xx + (old.yy + s.yy) * de.yy +
                              2.0 * (old.xy + s.xy) * de.xy);
      pts.density[p] *= std::exp(-(de.xx + de.yy));  // Eq. (25)
      // A point torn off the flow keeps "stretching" with the grid until its
      // GIMP volume, which multiplies its stress in Eq. (16), is tens of times
      // the original; ramming back into the flow it then throws its neighbours
      // out of the grid (phi = 10 and 15 at 8370 points). Soil does not dilate
      // like that: a point's volume is held at most kMaxExpansion times its
      // initial one. Not in the paper.
      pts.density[p] =
          std::max(pts.density[p], w.material_specs[pts.material[p]].density / kMaxExpansion);
    }
    w.chunk_sums[c] = work;
  }
  double work = 0;
  for (int c = 0; c < chunks; ++c) work += w.chunk_sums[c];
  return work;
}

void grid_to_points(World& w, const StepInput& in, StepReport& report) {
  Particles& pts = w.points;
  const Grid& g = w.grid;
  const int n = static_cast<int>(pts.size());
  const int chunks = (n + kReductionChunk - 1) / kReductionChunk;
  w.chunk_sums.assign(6 * static_cast<std::size_t>(chunks), 0.0);
  const double keep = 1.0 / (1.0 + in.damping);  // v := v / (1 + theta)
#pragma omp parallel for schedule(static)
  for (int c = 0; c < chunks; ++c) {
    double work = 0, kinetic = 0, moving = 0, damped = 0, signal = 0, walled = 0;
    const int end = std::min(n, (c + 1) * kReductionChunk);
    for (int p = c * kReductionChunk; p < end; ++p) {
      const Stencil& st = w.stencils[p];
      double ax = 0, ay = 0, vx = 0, vy = 0, wx = 0, wy = 0;
      for (int b = 0; b < 3; ++b) {
        const int row = g.node(st.base_i, st.base_j + b);
        for (int a = 0; a < 3; ++a) {
          const double S = st.wx[a] * st.wy[b];
          ax += S * g.ax[row + a];
          ay += S * g.ay[row + a];
          // A held component's acceleration is all the wall's (its force is
          // zero). Masked by a multiply, not a branch: the same sums, faster.
          wx += S * g.fix_x[row + a] * g.ax[row + a];
          wy += S * g.fix_y[row + a] * g.ay[row + a];
          vx += S * g.vx[row + a];
          vy += S * g.vy[row + a];
        }
      }
      const double dx = in.dt * vx, dy = in.dt * vy;  // Eq. (29)
      pts.x[p] += dx;
      pts.y[p] += dy;
      const double ux = pts.vx[p] + in.dt * ax, uy = pts.vy[p] + in.dt * ay;  // Eq. (30)
      pts.vx[p] = ux * keep;  // damping of the gravity stage
      pts.vy[p] = uy * keep;
      const double m = pts.mass[p];
      const double v2 = pts.vx[p] * pts.vx[p] + pts.vy[p] * pts.vy[p];
      damped += 0.5 * m * (ux * ux + uy * uy - v2);
      work += m * (in.gravity[0] * dx + in.gravity[1] * dy);
      kinetic += 0.5 * m * v2;
      moving += 0.5 * m * (vx * vx + vy * vy);
      walled += 0.5 * m * in.dt * in.dt * (wx * wx + wy * wy);
      signal = std::max(signal, w.materials[pts.material[p]].wave_speed + std::sqrt(v2));
    }
    double* sums = &w.chunk_sums[6 * static_cast<std::size_t>(c)];
    sums[0] = work;
    sums[1] = kinetic;
    sums[2] = moving;
    sums[3] = damped;
    sums[4] = signal;
    sums[5] = walled;
  }
  for (int c = 0; c < chunks; ++c) {
    const double* sums = &w.chunk_sums[6 * static_cast<std::size_t>(c)];
    report.gravity_work += sums[0];
    report.kinetic_energy += sums[1];
    report.moving_kinetic_energy += sums[2];
    report.damping_loss += sums[3];
    report.max_signal = std::max(report.max_signal, sums[4]);
    report.wall_change_on_points += sums[5];
  }
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
