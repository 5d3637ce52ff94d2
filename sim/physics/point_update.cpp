// The two per-point phases of the step: the stress update (grid -> point
// strain increment, then the constitutive model) and the velocity and
// position update (grid -> point, Eqs. 29 and 30).
#include <algorithm>
#include <cmath>

#include "sim/physics/bands.hpp"
#include "sim/physics/constitutive.hpp"
#include "sim/physics/granular.hpp"
#include "sim/physics/step.hpp"

namespace sim {

namespace {

// The stress update of point p (Eqs. 31, 24, 21-23, 25); returns its stress
// work over the step (Eq. 3). `own`: each point's Mohr-Coulomb surface where
// a random field set them (sim/physics/point_strength.hpp), null otherwise;
// set once per step. One call site of the return, not one per kind of scene:
// with two (a template parameter), a scene without a field stepped 5-7 %
// slower (bench/throughput n8370, side by side), most likely because the
// return was no longer inlined; with the pointer it steps as before.
double update_point_stress(World& w, int p, double dt, const MohrCoulomb* own) {
  Particles& pts = w.points;
  const Grid& g = w.grid;
  const Stencil& st = w.stencils[p];
  // Velocity gradient L_ab = sum_i v_ia dS_ip/dx_b, a stencil row at a time.
  Lane4 lxx{}, lxy{}, lyx{}, lyy{};
  for (int b = 0; b < 3; ++b) {
    const int row = g.node(st.base_i, st.base_j + b);
    const Lane4 gx = lanes3(st.dx) * st.wy[b], gy = lanes3(st.wx) * st.dy[b];
    const Lane4 vx = load4(&g.vx[row]), vy = load4(&g.vy[row]);
    lxx += vx * gx;
    lxy += vx * gy;
    lyx += vy * gx;
    lyy += vy * gy;
  }
  const double Lxx = sum3(lxx), Lxy = sum3(lxy), Lyx = sum3(lyx), Lyy = sum3(lyy);
  const StrainIncrement de{dt * Lxx, dt * Lyy, 0.5 * dt * (Lxy + Lyx)};  // Eq. (31)
  const MaterialConstants& mat = w.materials[pts.material[p]];
  const Stress old{pts.sxx[p], pts.syy[p], pts.sxy[p], pts.szz[p]};
  const double volume = pts.volume(p);  // at the start of the step
  Stress s = old;
  jaumann_rotate(s, 0.5 * dt * (Lxy - Lyx));  // Eq. (24)
  elastic_predictor(s, de, mat);              // Eq. (21)
  if (mat.plastic) {  // Eqs. (20)-(23)
    const MohrCoulomb& mc = own ? own[p] : mat.mohr_coulomb;
    pts.yielded[p] = mohr_coulomb_return(mc, s) != ReturnRegion::Elastic;
  }
  pts.density[p] *= std::exp(-(de.xx + de.yy));  // Eq. (25)
  // Torn or loosened soil below its critical density carries no stress
  // (Dunatunga & Kamrin 2015): it counts as yielded, flowing freely.
  if (disconnect_below_critical_density(pts.density[p], mat, s)) pts.yielded[p] = 1;
  pts.sxx[p] = s.xx;
  pts.syy[p] = s.yy;
  pts.sxy[p] = s.xy;
  pts.szz[p] = s.zz;
  // Stress power of Eq. (3) over the step, midpoint stress.
  return volume * 0.5 * ((old.xx + s.xx) * de.xx + (old.yy + s.yy) * de.yy +
                         2.0 * (old.xy + s.xy) * de.xy);
}

// Adds point p's internal and body forces to its nodes, Eqs. (16), (17).
void scatter_point_force(World& w, int p, const Vec2& gravity) {
  const Particles& pts = w.points;
  Grid& g = w.grid;
  const Stencil& st = w.stencils[p];
  const double V = pts.volume(p);
  const double sxx = pts.sxx[p], syy = pts.syy[p], sxy = pts.sxy[p];
  const double mgx = pts.mass[p] * gravity[0], mgy = pts.mass[p] * gravity[1];
  for (int b = 0; b < 3; ++b) {
    const int row = g.node(st.base_i, st.base_j + b);
    const Lane4 S = lanes3(st.wx) * st.wy[b];
    const Lane4 gx = lanes3(st.dx) * st.wy[b], gy = lanes3(st.wx) * st.dy[b];  // grad S_ip
    // f_int = -sigma_p . grad S_ip V_p, Eq. (16); f_ext = m_p b S_ip, Eq. (17).
    store4(&g.fx[row], load4(&g.fx[row]) + (-V * (sxx * gx + sxy * gy) + S * mgx));
    store4(&g.fy[row], load4(&g.fy[row]) + (-V * (sxy * gx + syy * gy) + S * mgy));
  }
}

const MohrCoulomb* own_strength(const World& w) {
  return w.strength.active() ? w.strength.mohr_coulomb.data() : nullptr;
}

}  // namespace

double update_stress(World& w, double dt) {
  const MohrCoulomb* own = own_strength(w);
  double work = 0;
  for (std::size_t p = 0; p < w.points.size(); ++p)
    work += update_point_stress(w, static_cast<int>(p), dt, own);
  return work;
}

// One pass over the points for both: a point's new stress goes to its nodes
// while its stencil and stress are still in cache. The nodal velocities the
// stress update reads do not change in this phase.
void update_stress_and_forces(World& w, const StepInput& in) {
  const MohrCoulomb* own = own_strength(w);
  scatter_own_bands(w, [&](int band) {
    double work = 0;
    for (int s = w.band_start[band]; s < w.band_start[band + 1]; ++s) {
      const int p = w.order[s];
      work += update_point_stress(w, p, in.dt, own);
      scatter_point_force(w, p, in.gravity);
    }
    w.band_sums[band * kBandSums + kInternalWork] = work;
  });
}

void grid_to_points(World& w, const StepInput& in) {
  const Grid& g = w.grid;
  const double keep = 1.0 / (1.0 + in.damping);  // v := v / (1 + theta)
  // Raw pointers: the band's sums below stay in registers instead of being
  // reloaded after every store to a point array.
  double* const px = w.points.x.data();
  double* const py = w.points.y.data();
  double* const pvx = w.points.vx.data();
  double* const pvy = w.points.vy.data();
  const double* const mass = w.points.mass.data();
  const std::uint8_t* const material = w.points.material.data();
  for_own_bands(w, [&](int band) {
    double gravity_work = 0, kinetic = 0, moving = 0, damped = 0, signal = 0, walled = 0;
    for (int s = w.band_start[band]; s < w.band_start[band + 1]; ++s) {
      const int p = w.order[s];
      const Stencil& st = w.stencils[p];
      Lane4 sax{}, say{}, svx{}, svy{}, swx{}, swy{};
      for (int b = 0; b < 3; ++b) {
        const int row = g.node(st.base_i, st.base_j + b);
        const Lane4 S = lanes3(st.wx) * st.wy[b];
        sax += S * load4(&g.ax[row]);
        say += S * load4(&g.ay[row]);
        swx += S * load4(&g.held_ax[row]);
        swy += S * load4(&g.held_ay[row]);
        svx += S * load4(&g.vx[row]);
        svy += S * load4(&g.vy[row]);
      }
      const double vx = sum3(svx), vy = sum3(svy), wx = sum3(swx), wy = sum3(swy);
      const double dx = in.dt * vx, dy = in.dt * vy;  // Eq. (29)
      px[p] += dx;
      py[p] += dy;
      const double ux = pvx[p] + in.dt * sum3(sax), uy = pvy[p] + in.dt * sum3(say);  // Eq. (30)
      const double kx = ux * keep, ky = uy * keep;  // damping of the gravity stage
      pvx[p] = kx;
      pvy[p] = ky;
      const double m = mass[p];
      const double v2 = kx * kx + ky * ky;
      gravity_work += m * (in.gravity[0] * dx + in.gravity[1] * dy);
      kinetic += 0.5 * m * v2;
      moving += 0.5 * m * (vx * vx + vy * vy);
      damped += 0.5 * m * (ux * ux + uy * uy - v2);
      signal = std::max(signal, w.materials[material[p]].wave_speed + std::sqrt(v2));
      walled += 0.5 * m * in.dt * in.dt * (wx * wx + wy * wy);
    }
    store_point_sums(w, band, {gravity_work, kinetic, moving, damped, signal, walled});
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
