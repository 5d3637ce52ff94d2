// The laterally confined elastic column under incrementally applied gravity
// against its closed form (method notes, section 5):
//   sigma_yy = -rho g (H - Y), sigma_xx = sigma_zz = nu / (1 - nu) sigma_yy,
//   u_y(Y) = -rho g (H Y - Y^2 / 2) / M, so u_y(H) = -rho g H^2 / (2 M),
// with Y the height of a point before loading. The column runs at 4, 8, 16
// and 32 cells over its height.
//
// With 2x2 points per cell (the paper's layout) both points of a cell row get
// the same strain: the velocity is linear inside a cell and neither GIMP
// domain straddles a node. The stress is then constant per cell, and no
// cell-wise constant field is closer to the linear closed form than a relative
// L2 error of sqrt(3) / (4 n) (2.7 % at n = 16): the error floor of the
// layout, not of the solver. One point per cell sits at the cell centre, where
// the cell-constant stress is exact, and meets 2 % at 16 cells; its error
// (~0.2 %) is then set by how far the damped settling gets within the stage,
// not by the mesh, so only the 2x2 layout is held to a convergence order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "sim/simulation.hpp"

namespace {

struct ColumnErrors {
  double h = 0;
  std::size_t points = 0;
  double syy = 0, sxx = 0, szz = 0;  // relative L2 errors
  double settlement = 0;             // relative error of the top row's displacement
  double top_settlement = 0;         // measured u_y of the top row, m
};

ColumnErrors run_column(int cells_over_height, int points_per_cell) {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/elastic-column.json");
  const double H = s.domain_max[1] - s.domain_min[1];
  s.cell_size = H / cells_over_height;
  s.points_per_cell = points_per_cell;
  s.output.frame_interval = 0;
  sim::Simulation simulation(s);
  sim::Observer quiet;
  simulation.run(quiet);

  const sim::MaterialSpec& m = s.materials[0];
  const double rho = m.density, nu = m.poisson_ratio, g = -s.gravity[1];
  const double M = m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double k0 = nu / (1 - nu);
  const sim::Particles& p = simulation.world().points;
  double e_yy = 0, e_xx = 0, e_zz = 0, ref = 0, e_u = 0, ref_u = 0, top_y = -1, top_u = 0;
  int top_n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double Y = p.y0[i] - s.domain_min[1];
    const double V = p.mass[i] / p.density[i];
    const double syy = -rho * g * (H - Y);
    e_yy += V * std::pow(p.syy[i] - syy, 2);
    e_xx += V * std::pow(p.sxx[i] - k0 * syy, 2);
    e_zz += V * std::pow(p.szz[i] - k0 * syy, 2);
    ref += V * syy * syy;
    const double u = -rho * g * (H * Y - 0.5 * Y * Y) / M;
    e_u += V * std::pow(p.y[i] - p.y0[i] - u, 2);
    ref_u += V * u * u;
    if (Y > top_y + 1e-9) top_y = Y, top_u = 0, top_n = 0;
    if (std::fabs(Y - top_y) < 1e-9) top_u += p.y[i] - p.y0[i], ++top_n;
  }
  ColumnErrors e;
  e.h = s.cell_size;
  e.points = p.size();
  e.syy = std::sqrt(e_yy / ref);
  e.sxx = std::sqrt(e_xx / (k0 * k0 * ref));
  e.szz = std::sqrt(e_zz / (k0 * k0 * ref));
  e.settlement = std::sqrt(e_u / ref_u);
  e.top_settlement = top_u / top_n;
  return e;
}

// Runs the four resolutions, prints the table, returns the runs and the
// observed order of the sigma_yy error (least-squares slope in log-log).
std::vector<ColumnErrors> refinement_study(int points_per_cell, double& order) {
  const sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/elastic-column.json");
  const sim::MaterialSpec& m = s.materials[0];
  const double H = s.domain_max[1] - s.domain_min[1], nu = m.poisson_ratio;
  const double M = m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  std::printf("%d x %d points per cell; closed-form top settlement rho g H^2 / (2M) = %.6f m\n",
              points_per_cell, points_per_cell, -m.density * -s.gravity[1] * H * H / (2 * M));
  std::printf("%6s %8s %7s %12s %12s %12s %12s %12s\n", "cells", "h [m]", "points", "L2 syy",
              "L2 sxx", "L2 szz", "L2 u_y", "u_y top [m]");
  std::vector<ColumnErrors> runs;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const int n : {4, 8, 16, 32}) {
    runs.push_back(run_column(n, points_per_cell));
    const ColumnErrors& e = runs.back();
    std::printf("%6d %8.4f %7zu %12.4e %12.4e %12.4e %12.4e %12.6f\n", n, e.h, e.points, e.syy,
                e.sxx, e.szz, e.settlement, e.top_settlement);
    sx += std::log(e.h);
    sy += std::log(e.syy);
    sxx += std::log(e.h) * std::log(e.h);
    sxy += std::log(e.h) * std::log(e.syy);
  }
  const double k = static_cast<double>(runs.size());
  order = (k * sxy - sx * sy) / (k * sxx - sx * sx);
  std::printf("observed order of the sigma_yy error: %.3f\n", order);
  return runs;
}

TEST(ElasticColumn, OnePointPerCellIsBelowTwoPercentFromSixteenCells) {
  double order = 0;
  const std::vector<ColumnErrors> runs = refinement_study(1, order);
  EXPECT_LT(runs[2].syy, 0.02) << "16 cells over the height";
  EXPECT_LT(runs[3].syy, 0.02) << "32 cells over the height";
  EXPECT_LT(runs[2].sxx, 0.02);
  EXPECT_LT(runs[2].szz, 0.02);
  EXPECT_LT(runs[2].settlement, 0.02);
}

TEST(ElasticColumn, TwoByTwoPointsConvergeAtTheCellConstantFloor) {
  double order = 0;
  const std::vector<ColumnErrors> runs = refinement_study(2, order);
  for (std::size_t k = 1; k < runs.size(); ++k) EXPECT_LT(runs[k].syy, runs[k - 1].syy);
  EXPECT_GE(order, 1.0);
  const int cells[] = {4, 8, 16, 32};
  for (std::size_t k = 0; k < runs.size(); ++k)
    EXPECT_LT(runs[k].syy, 1.1 * std::sqrt(3.0) / (4.0 * cells[k])) << cells[k] << " cells";
  EXPECT_LT(runs[2].settlement, 0.02);
}

}  // namespace
