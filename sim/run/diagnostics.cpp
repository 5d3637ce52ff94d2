#include "sim/run/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/run/point_chunks.hpp"
#include "sim/run/runout.hpp"

namespace sim {

namespace {

// The index of the cell that coordinate x lies in along an axis of `count`
// cells of size h from `origin`, clamped to the axis.
int cell_along(double x, double origin, double h, int count) {
  return std::clamp(static_cast<int>((x - origin) / h), 0, count - 1);
}

// The grid cells holding soil, labelled into 8-connected groups, and the
// group with the most soil points: the main body. A lone point or clump
// thrown off the slide is not part of it.
struct MainBody {
  int nx = 0, ny = 0;      // cells per axis
  std::vector<int> label;  // per cell: its group, -2 where no soil point lies
  int biggest = -1;        // -1 without soil
  std::size_t soil_points = 0, main_points = 0;

  int cell(const Grid& g, double x, double y) const {
    return cell_along(y, g.origin_y, g.h, ny) * nx + cell_along(x, g.origin_x, g.h, nx);
  }
  // For a soil point at (x, y).
  bool holds(const Grid& g, double x, double y) const { return label[cell(g, x, y)] == biggest; }
};

MainBody main_body(const World& w) {
  const Particles& pts = w.points;
  MainBody b;
  b.nx = w.grid.nx - 1;
  b.ny = w.grid.ny - 1;
  // Soil points per cell: counts, the same whatever order the threads add in.
  std::vector<int> in_cell(static_cast<std::size_t>(b.nx) * b.ny, 0);
  for_each_point(pts.size(), [&](std::size_t p) {
    if (is_soil(w, p))
      __atomic_fetch_add(&in_cell[b.cell(w.grid, pts.x[p], pts.y[p])], 1, __ATOMIC_RELAXED);
  });
  b.label.assign(in_cell.size(), -2);
  std::vector<std::size_t> count;  // soil points per group
  std::vector<int> stack;
  for (std::size_t c = 0; c < in_cell.size(); ++c) {
    if (in_cell[c] == 0 || b.label[c] != -2) continue;
    const int group = static_cast<int>(count.size());
    count.push_back(0);
    b.label[c] = group;
    stack.assign(1, static_cast<int>(c));
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      count[group] += in_cell[k];
      const int i = k % b.nx, j = k / b.nx;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, e = j + dj;
          if (a < 0 || e < 0 || a >= b.nx || e >= b.ny) continue;
          const int n = e * b.nx + a;
          if (in_cell[n] == 0 || b.label[n] != -2) continue;
          b.label[n] = group;
          stack.push_back(n);
        }
    }
  }
  for (const std::size_t n : count) b.soil_points += n;
  if (count.empty()) return b;
  b.biggest = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
  b.main_points = count[b.biggest];
  return b;
}

// Per material the mean and largest displacement, and the soil's largest
// horizontal one: summed over a chunk of points, then chunk by chunk.
struct MotionTally {
  std::vector<double> sum_ux, sum_uy, max_u, count;  // per material
  double max_soil_ux = 0;

  explicit MotionTally(std::size_t materials)
      : sum_ux(materials, 0), sum_uy(materials, 0), max_u(materials, 0), count(materials, 0) {}

  void add(const World& w, std::size_t begin, std::size_t end) {
    const Particles& pts = w.points;
    for (std::size_t p = begin; p < end; ++p) {
      const int mat = pts.material[p];
      const double ux = pts.x[p] - pts.x0[p], uy = pts.y[p] - pts.y0[p];
      sum_ux[mat] += ux;
      sum_uy[mat] += uy;
      count[mat] += 1;
      max_u[mat] = std::max(max_u[mat], std::hypot(ux, uy));
      if (is_soil(w, p)) max_soil_ux = std::max(max_soil_ux, std::fabs(ux));
    }
  }
  void add(const MotionTally& t) {  // the next chunk's
    for (std::size_t k = 0; k < count.size(); ++k) {
      sum_ux[k] += t.sum_ux[k];
      sum_uy[k] += t.sum_uy[k];
      count[k] += t.count[k];
      max_u[k] = std::max(max_u[k], t.max_u[k]);
    }
    max_soil_ux = std::max(max_soil_ux, t.max_soil_ux);
  }
};

// The soil's mass by state, its yielding points, and the top of the main
// body in each column of grid nodes (for the deposit slope).
struct BodyTally {
  double soil_mass = 0, packed_mass = 0, disconnected_mass = 0;
  std::size_t yielding = 0;
  std::vector<double> top;  // per column, lowest() where the main body has no point
  double base = std::numeric_limits<double>::max(), peak = std::numeric_limits<double>::lowest();

  explicit BodyTally(int columns) : top(columns, std::numeric_limits<double>::lowest()) {}

  void add(const World& w, const MainBody& body, std::size_t begin, std::size_t end) {
    const Particles& pts = w.points;
    const Grid& g = w.grid;
    for (std::size_t p = begin; p < end; ++p) {
      if (!is_soil(w, p)) continue;
      const int mat = pts.material[p];
      yielding += pts.yielded[p];
      soil_mass += pts.mass[p];
      const double ratio = pts.density[p] / w.material_specs[mat].density;
      if (std::fabs(ratio - 1.0) <= kPackedDensityBand) packed_mass += pts.mass[p];
      if (pts.density[p] < w.materials[mat].critical_density) disconnected_mass += pts.mass[p];
      if (!body.holds(g, pts.x[p], pts.y[p])) continue;
      const int i = cell_along(pts.x[p], g.origin_x, g.h, g.nx);  // top: a column of nodes
      top[i] = std::max(top[i], pts.y[p]);
      base = std::min(base, pts.y[p]);
      peak = std::max(peak, pts.y[p]);
    }
  }
  void add(const BodyTally& t) {  // the next chunk's
    soil_mass += t.soil_mass;
    packed_mass += t.packed_mass;
    disconnected_mass += t.disconnected_mass;
    yielding += t.yielding;
    for (std::size_t i = 0; i < top.size(); ++i) top[i] = std::max(top[i], t.top[i]);
    base = std::min(base, t.base);
    peak = std::max(peak, t.peak);
  }
};

// Deposit slope: the top of the main body per cell column is the surface;
// the columns whose surface lies between 10 % and 90 % of the deposit's
// height get a least-squares line, and the angle is atan(|slope|).
double deposit_slope(const Grid& g, const BodyTally& t) {
  const double low = std::numeric_limits<double>::lowest();
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < g.nx; ++i) {
    if (t.top[i] == low) continue;
    const double rel = (t.top[i] - t.base) / (t.peak - t.base);
    if (rel < 0.1 || rel > 0.9) continue;
    const double x = g.origin_x + (i + 0.5) * g.h;
    n += 1, sx += x, sy += t.top[i], sxx += x * x, sxy += x * t.top[i];
  }
  if (n < 3) return std::nan("");
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return std::atan(std::fabs(slope)) * 180.0 / M_PI;
}

}  // namespace

StageMotion measure_motion(const World& w) {
  StageMotion m;
  const MotionTally t = reduce_points(
      w.points.size(), MotionTally(w.materials.size()),
      [&](MotionTally& chunk, std::size_t begin, std::size_t end) { chunk.add(w, begin, end); },
      [](MotionTally& total, const MotionTally& chunk) { total.add(chunk); });
  m.max_soil_ux = t.max_soil_ux;
  const Runout r = measure_runout(w);  // all zero without soil
  m.initial_toe = r.initial_toe;
  m.toe = r.toe;
  m.runout = r.runout;
  for (std::size_t k = 0; k < w.materials.size(); ++k) {
    if (t.count[k] == 0) continue;
    m.materials.push_back({w.material_specs[k].name, t.sum_ux[k] / t.count[k],
                           t.sum_uy[k] / t.count[k], t.max_u[k]});
  }
  return m;
}

StageMetrics measure_stage(const World& w) {
  StageMetrics m;
  static_cast<StageMotion&>(m) = measure_motion(w);
  const MainBody body = main_body(w);
  if (body.soil_points == 0) {
    m.deposit_slope_deg = std::nan("");
    return m;
  }
  const BodyTally t = reduce_points(
      w.points.size(), BodyTally(w.grid.nx),
      [&](BodyTally& chunk, std::size_t begin, std::size_t end) { chunk.add(w, body, begin, end); },
      [](BodyTally& total, const BodyTally& chunk) { total.add(chunk); });
  m.packed_fraction = t.packed_mass / t.soil_mass;
  m.disconnected_fraction = t.disconnected_mass / t.soil_mass;
  m.main_body_fraction = static_cast<double>(body.main_points) / body.soil_points;
  m.yielding_fraction = static_cast<double>(t.yielding) / body.soil_points;
  m.deposit_slope_deg = deposit_slope(w.grid, t);
  return m;
}

double kinetic_energy(const World& w) {
  const Particles& p = w.points;
  return sum_over_points(p.size(), [&](std::size_t i) {
    return 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  });
}

double elastic_energy(const World& w) {
  const Particles& p = w.points;
  return sum_over_points(p.size(), [&](std::size_t i) {
    const MaterialSpec& m = w.material_specs[p.material[i]];
    const double tr = p.sxx[i] + p.syy[i] + p.szz[i];
    const double ss = p.sxx[i] * p.sxx[i] + p.syy[i] * p.syy[i] + p.szz[i] * p.szz[i] +
                      2 * p.sxy[i] * p.sxy[i];
    // sigma : C^-1 : sigma = ((1 + nu) sigma:sigma - nu tr(sigma)^2) / E
    const double density = (1 + m.poisson_ratio) * ss - m.poisson_ratio * tr * tr;
    return 0.5 * p.volume(i) * density / m.youngs_modulus;
  });
}

}  // namespace sim
