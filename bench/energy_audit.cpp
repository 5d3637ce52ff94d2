// Where the energy balance of Eq. (3) leaves a residual: runs a scenario up
// to its last stage (a dynamic one), then that stage step by step, and splits
// each step's residual exactly into terms measured on the grid and the
// stencils after the step:
//   A = dt^2 sum_i g . f_i over free node components: gravity works on the
//       end velocity v^{k+1} (Eq. 29 moves the points with it), the forces
//       change the points' velocity from the start one (Eq. 30);
//   B = -sum_p m_p (|dv_p|^2 - |dv_p^wall|^2) / 2, dv_p = sum_i S_ip dt a_i:
//       the second-order kinetic energy the points gain from the force
//       change (Eq. 30) that StepReport::transfer_loss does not count (it
//       counts the walls' change alone), split into the cross term of the
//       wall and force changes and the force change's own square;
//   Q = work the internal forces do on the grid, -dt sum_i f_int,i . v_i
//       (USF: sigma^{k+1}, V^{k+1}, Eqs. 16, 31), minus the stress work
//       counted (midpoint stress, start volume), split into points that end
//       the step disconnected (below their critical density, stress zeroed,
//       sim/physics/granular.hpp) and the rest.
// residual = A + B + Q holds exactly for fixed and roller walls (derivation in
// tests/validation/README.md); all three are O(dt) per unit time when the
// motion is smooth. Friction walls add their own terms, not split here.
// Prints the stage totals as shares of the external work. A bench, not a test.
//
// Usage: energy_audit SCENARIO [cell_size] [courant]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sim/run/diagnostics.hpp"
#include "sim/run/simulation.hpp"

namespace {

struct Totals {
  double ext = 0, dk = 0, internal = 0, damping = 0, wall = 0, transfer = 0;
  double friction = 0;
  double A = 0, B_cross = 0, B_force = 0, Q_disconnected = 0, Q_rest = 0;
  long steps = 0;
};

// The terms A, B and Q of one step (see the top of the file).
// s0, rho0, xy0: each point's stress, density and position before the step.
void audit_step(const sim::World& w, const sim::StepInput& in, const std::vector<double>& s0,
                const std::vector<double>& rho0, const std::vector<double>& xy0, Totals& t) {
  const sim::Grid& g = w.grid;
  const double dt = in.dt;
  for (int j = g.j_begin; j < g.j_end; ++j) {
    // The row's span: the step leaves the air outside it as it was.
    const int* span = g.span_of_row(j);
    for (int i = span[0]; i < span[1]; ++i) {
      const int k = g.node(i, j);
      const double m = g.mass[k];
      if (!(m > 0)) continue;
      const double f[2] = {g.fx[k], g.fy[k]};
      const bool held[2] = {g.fix_x[k] != 0, g.fix_y[k] != 0};
      for (int c = 0; c < 2; ++c)
        if (!held[c]) t.A += dt * dt * in.gravity[c] * f[c];
    }
  }
  const sim::Particles& pts = w.points;
  for (std::size_t p = 0; p < pts.size(); ++p) {
    // The step's stencil, made again where the point stood (the step keeps
    // only the weights).
    sim::StencilWeights st;
    sim::StencilSlopes d;
    sim::gimp_stencil(xy0[2 * p], xy0[2 * p + 1], g.origin_x, g.origin_y, w.gimp, st, d);
    double ax = 0, ay = 0, wx = 0, wy = 0, lxx = 0, lxy = 0, lyx = 0, lyy = 0;
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) {
        const int k = g.node(st.base_i + c, st.base_j + b);
        const double S = st.wx[c] * st.wy[b];
        const double gx = d.dx[c] * st.wy[b], gy = st.wx[c] * d.dy[b];
        ax += S * g.ax[k];
        ay += S * g.ay[k];
        wx += g.fix_x[k] ? S * g.ax[k] : 0.0;
        wy += g.fix_y[k] ? S * g.ay[k] : 0.0;
        // v' = v^{k+1} - dt f / m: the velocity the stress update read. A
        // held component's force is zero in the nodal update; the step no
        // longer stores it so (step.cpp), and f_i keeps the scatter's sum.
        const double inv = g.mass[k] > 0 ? 1.0 / g.mass[k] : 0.0;
        const double fx = g.fix_x[k] ? 0.0 : g.fx[k], fy = g.fix_y[k] ? 0.0 : g.fy[k];
        const double vx = g.vx[k] - dt * fx * inv, vy = g.vy[k] - dt * fy * inv;
        lxx += vx * gx;
        lxy += vx * gy;
        lyx += vy * gx;
        lyy += vy * gy;
      }
    const double m = pts.mass[p];
    t.B_cross -= m * dt * dt * (wx * (ax - wx) + wy * (ay - wy));
    t.B_force -= 0.5 * m * dt * dt * ((ax - wx) * (ax - wx) + (ay - wy) * (ay - wy));
    const double V1 = m / pts.density[p], V0 = m / rho0[p];
    const double dxx = dt * lxx, dyy = dt * lyy, dxy = 0.5 * dt * (lxy + lyx);
    const double on_grid = V1 * (pts.sxx[p] * dxx + pts.syy[p] * dyy + 2 * pts.sxy[p] * dxy);
    const double counted = V0 * 0.5 * ((s0[3 * p] + pts.sxx[p]) * dxx + (s0[3 * p + 1] + pts.syy[p]) * dyy +
                                       2 * (s0[3 * p + 2] + pts.sxy[p]) * dxy);
    const bool disconnected = pts.density[p] < w.materials[pts.material[p]].critical_density;
    double& q = disconnected ? t.Q_disconnected : t.Q_rest;
    q += on_grid - counted;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: energy_audit SCENARIO [cell_size] [courant]\n");
    return 2;
  }
  // The cell size and Courant number, where given, as positive numbers:
  // atof would read "C" as 0 and step with dt = 0.
  double given[2] = {0, 0};
  for (int a = 2; a < argc && a < 4; ++a) {
    char* end = nullptr;
    given[a - 2] = std::strtod(argv[a], &end);
    if (end == argv[a] || *end != '\0' || !(given[a - 2] > 0)) {
      std::fprintf(stderr, "energy_audit: %s = '%s': expected a positive number\n",
                   a == 2 ? "cell_size" : "courant", argv[a]);
      return 2;
    }
  }
  sim::Scenario s;
  try {
    s = sim::load_scenario(argv[1]);
  } catch (const sim::ScenarioError& e) {
    std::fprintf(stderr, "energy_audit: %s\n", e.what());
    return 2;
  }
  if (argc > 2) s.cell_size = given[0];
  if (argc > 3) s.time_step.courant = given[1];
  s.output.frame_interval = 0;
  s.output.vtk = "none";
  const sim::StageSpec stage = s.stages.back();
  s.stages.pop_back();
  sim::Simulation run(s);
  sim::Observer quiet;
  run.run(quiet);
  sim::World w = run.world();
  const sim::Vec2 gravity{s.gravity[0], s.gravity[1]};
  Totals t;
  double time = 0, max_signal = sim::max_signal_speed(w), moving = 0;
  const double k_start = sim::kinetic_energy(w);
  std::vector<double> s0(3 * w.points.size()), rho0(w.points.size()), xy0(2 * w.points.size());
  sim::StepReport r;
  while (time < stage.duration * (1 - 1e-9)) {
    if (t.steps > 0 && stage.rest.enabled && time >= stage.rest.min_time &&
        moving <= stage.rest.kinetic_ratio * std::max(t.ext, 0.0))
      break;
    const double dt = std::min(s.time_step.courant * w.grid.h / max_signal, stage.duration - time);
    for (std::size_t p = 0; p < w.points.size(); ++p) {
      s0[3 * p] = w.points.sxx[p];
      s0[3 * p + 1] = w.points.syy[p];
      s0[3 * p + 2] = w.points.sxy[p];
      rho0[p] = w.points.density[p];
      xy0[2 * p] = w.points.x[p];
      xy0[2 * p + 1] = w.points.y[p];
    }
    const sim::StepInput in{dt, gravity, stage.damping};
    sim::step(w, in, r);
    audit_step(w, in, s0, rho0, xy0, t);
    t.ext += r.gravity_work;
    t.internal += r.internal_work;
    t.damping += r.damping_loss;
    t.wall += r.wall_loss;
    t.friction += r.friction_work;
    t.transfer += r.transfer_loss;
    moving = r.moving_kinetic_energy;
    max_signal = r.max_signal;
    time += dt;
    ++t.steps;
  }
  t.dk = sim::kinetic_energy(w) - k_start;
  const double residual =
      t.ext - t.dk - t.internal - t.damping - t.wall - t.friction - t.transfer;
  const double e = std::fabs(t.ext);
  std::printf("%s  h = %g m  Courant %g  points %zu  steps %ld  time %.3f s\n", s.name.c_str(),
              w.grid.h, s.time_step.courant, w.points.size(), t.steps, time);
  std::printf("  external work %.6g J/m; shares of it (%%):\n", t.ext);
  std::printf("  kinetic change %+.3f  internal %+.3f  wall %+.3f  friction %+.3f  "
              "transfer(walls) %+.3f  damping %+.3f\n",
              100 * t.dk / e, 100 * t.internal / e, 100 * t.wall / e, 100 * t.friction / e,
              100 * t.transfer / e, 100 * t.damping / e);
  std::printf("  residual %+.3f = A %+.3f + B(cross) %+.3f + B(force) %+.3f + Q(disconnected) "
              "%+.3f + Q(rest) %+.3f\n  (A + B + Q = %+.3f)\n",
              100 * residual / e, 100 * t.A / e, 100 * t.B_cross / e, 100 * t.B_force / e,
              100 * t.Q_disconnected / e, 100 * t.Q_rest / e,
              100 * (t.A + t.B_cross + t.B_force + t.Q_disconnected + t.Q_rest) / e);
  // The split is an identity: a gap beyond round-off means the audit reads
  // the grid otherwise than the step left it (as when the step stopped
  // storing the forces it zeroes at held components).
  const double gap = residual - (t.A + t.B_cross + t.B_force + t.Q_disconnected + t.Q_rest);
  if (!(std::fabs(gap) <= 1e-6 * e)) {
    std::fprintf(stderr, "energy_audit: residual - (A + B + Q) = %.3g J/m, over 1e-6 of the external work\n", gap);
    return 1;
  }
  return 0;
}
