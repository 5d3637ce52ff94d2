#include "sim/run/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/run/runout.hpp"

namespace sim {

namespace {

bool is_soil(const World& w, std::size_t p) { return w.materials[w.points.material[p]].plastic; }

// Labels the grid cells holding soil into 8-connected groups and returns, per
// point, whether it lies in the group with the most soil points. A lone point
// or clump thrown off the slide is not part of the main body.
std::vector<char> main_body(const World& w, std::size_t& soil_points, std::size_t& main_points) {
  const Particles& pts = w.points;
  const Grid& g = w.grid;
  const int nx = g.nx - 1, ny = g.ny - 1;  // cells
  std::vector<int> cell_of(pts.size(), -1), label(static_cast<std::size_t>(nx) * ny, -2);
  for (std::size_t p = 0; p < pts.size(); ++p) {
    if (!is_soil(w, p)) continue;
    const int i = std::clamp(static_cast<int>((pts.x[p] - g.origin_x) / g.h), 0, nx - 1);
    const int j = std::clamp(static_cast<int>((pts.y[p] - g.origin_y) / g.h), 0, ny - 1);
    cell_of[p] = j * nx + i;
    label[cell_of[p]] = -1;  // occupied, not yet labelled
  }
  std::vector<int> stack;
  int groups = 0;
  for (std::size_t c = 0; c < label.size(); ++c) {
    if (label[c] != -1) continue;
    label[c] = groups;
    stack.assign(1, static_cast<int>(c));
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      const int i = k % nx, j = k / nx;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= nx || b >= ny || label[b * nx + a] != -1) continue;
          label[b * nx + a] = groups;
          stack.push_back(b * nx + a);
        }
    }
    ++groups;
  }
  std::vector<std::size_t> count(groups, 0);
  soil_points = 0;
  for (std::size_t p = 0; p < pts.size(); ++p)
    if (cell_of[p] >= 0) ++count[label[cell_of[p]]], ++soil_points;
  const int biggest =
      groups ? static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin()) : -1;
  main_points = groups ? count[biggest] : 0;
  std::vector<char> in_main(pts.size(), 0);
  for (std::size_t p = 0; p < pts.size(); ++p)
    in_main[p] = cell_of[p] >= 0 && label[cell_of[p]] == biggest;
  return in_main;
}

// Deposit slope: the top of the main body per cell column is the surface;
// the columns whose surface lies between 10 % and 90 % of the deposit's
// height get a least-squares line, and the angle is atan(|slope|).
double deposit_slope(const World& w, const std::vector<char>& in_main) {
  const Particles& pts = w.points;
  const Grid& g = w.grid;
  const double low = std::numeric_limits<double>::lowest();
  std::vector<double> top(g.nx, low);
  double base = std::numeric_limits<double>::max(), peak = low;
  for (std::size_t p = 0; p < pts.size(); ++p) {
    if (!in_main[p]) continue;
    const int i = std::clamp(static_cast<int>((pts.x[p] - g.origin_x) / g.h), 0, g.nx - 1);
    top[i] = std::max(top[i], pts.y[p]);
    base = std::min(base, pts.y[p]);
    peak = std::max(peak, pts.y[p]);
  }
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < g.nx; ++i) {
    if (top[i] == low) continue;
    const double rel = (top[i] - base) / (peak - base);
    if (rel < 0.1 || rel > 0.9) continue;
    const double x = g.origin_x + (i + 0.5) * g.h;
    n += 1, sx += x, sy += top[i], sxx += x * x, sxy += x * top[i];
  }
  if (n < 3) return std::nan("");
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return std::atan(std::fabs(slope)) * 180.0 / M_PI;
}

}  // namespace

StageMetrics measure_stage(const World& w) {
  const Particles& pts = w.points;
  StageMetrics m;
  std::size_t soil = 0, main = 0, yielding = 0;
  const std::vector<char> in_main = main_body(w, soil, main);
  double soil_mass = 0, packed_mass = 0, disconnected_mass = 0;
  std::vector<double> sum_ux(w.materials.size(), 0), sum_uy(w.materials.size(), 0);
  std::vector<double> max_u(w.materials.size(), 0), count(w.materials.size(), 0);
  for (std::size_t p = 0; p < pts.size(); ++p) {
    const int mat = pts.material[p];
    const double ux = pts.x[p] - pts.x0[p], uy = pts.y[p] - pts.y0[p];
    sum_ux[mat] += ux;
    sum_uy[mat] += uy;
    count[mat] += 1;
    max_u[mat] = std::max(max_u[mat], std::hypot(ux, uy));
    if (!is_soil(w, p)) continue;
    m.max_soil_ux = std::max(m.max_soil_ux, std::fabs(ux));
    yielding += pts.yielded[p];
    soil_mass += pts.mass[p];
    const double ratio = pts.density[p] / w.material_specs[mat].density;
    if (std::fabs(ratio - 1.0) <= kPackedDensityBand) packed_mass += pts.mass[p];
    if (pts.density[p] < w.materials[mat].critical_density) disconnected_mass += pts.mass[p];
  }
  if (soil > 0) {
    const Runout r = measure_runout(w);
    m.initial_toe = r.initial_toe;
    m.toe = r.toe;
    m.runout = r.runout;
    m.packed_fraction = packed_mass / soil_mass;
    m.disconnected_fraction = disconnected_mass / soil_mass;
    m.main_body_fraction = static_cast<double>(main) / soil;
    m.yielding_fraction = static_cast<double>(yielding) / soil;
    m.deposit_slope_deg = deposit_slope(w, in_main);
  } else {
    m.deposit_slope_deg = std::nan("");
  }
  for (std::size_t k = 0; k < w.materials.size(); ++k) {
    if (count[k] == 0) continue;
    m.materials.push_back({w.material_specs[k].name, sum_ux[k] / count[k], sum_uy[k] / count[k],
                           max_u[k]});
  }
  return m;
}

double kinetic_energy(const World& w) {
  const Particles& p = w.points;
  double energy = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    energy += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  return energy;
}

double elastic_energy(const World& w) {
  const Particles& p = w.points;
  double energy = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const MaterialSpec& m = w.material_specs[p.material[i]];
    const double tr = p.sxx[i] + p.syy[i] + p.szz[i];
    const double ss = p.sxx[i] * p.sxx[i] + p.syy[i] * p.syy[i] + p.szz[i] * p.szz[i] +
                      2 * p.sxy[i] * p.sxy[i];
    // sigma : C^-1 : sigma = ((1 + nu) sigma:sigma - nu tr(sigma)^2) / E
    const double density = (1 + m.poisson_ratio) * ss - m.poisson_ratio * tr * tr;
    energy += 0.5 * p.volume(i) * density / m.youngs_modulus;
  }
  return energy;
}

}  // namespace sim
