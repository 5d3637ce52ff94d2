// The laterally confined elastic column under incrementally applied gravity
// against its closed form (validation/elastic_column.hpp, method notes section 5),
// at 4, 8, 16 and 32 cells over its height.
//
// With 2x2 points per cell (the paper's layout) both points of a cell row get
// the same strain: the velocity is linear inside a cell and neither GIMP
// domain straddles a node. The stress is then constant per cell, and a
// cell-wise constant field sampled at the points' initial places is off the
// linear closed form by a relative L2 error of sqrt(3) / (4 n) (2.7 % at
// n = 16): the error of the layout, not of the solver. (As the column settles
// the points move inside their cells and the measured error falls a little
// below it: 1.13 % against 1.35 % at n = 32, bench/README.md.) One point per cell sits at the cell centre, where
// the cell-constant stress is exact, and meets 2 % at 16 cells; its error
// (~0.2 %) is then set by how far the damped settling gets within the stage,
// not by the mesh, so only the 2x2 layout is held to a convergence order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "validation/elastic_column.hpp"
#include "sim/run/simulation.hpp"

namespace {

using ColumnErrors = sim::ElasticColumnErrors;

ColumnErrors run_column(int cells_over_height, int points_per_cell) {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/elastic-column.json");
  const double H = s.domain_max[1] - s.domain_min[1];
  s.cell_size = H / cells_over_height;
  s.points_per_cell = points_per_cell;
  s.output.frame_interval = 0;
  sim::Simulation simulation(s);
  sim::Observer quiet;
  simulation.run(quiet);
  return sim::elastic_column_errors(s, simulation.world());
}

// Runs the four resolutions, prints the table, returns the runs and the
// observed order of the sigma_yy error (least-squares slope in log-log).
std::vector<ColumnErrors> refinement_study(int points_per_cell, double& order) {
  const sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/elastic-column.json");
  std::printf("%d x %d points per cell; closed-form top settlement rho g H^2 / (2M) = %.6f m\n",
              points_per_cell, points_per_cell, -sim::elastic_column_top_settlement(s));
  std::printf("%6s %8s %7s %12s %12s %12s %12s %12s\n", "cells", "h [m]", "points", "L2 syy",
              "L2 sxx", "L2 szz", "L2 u_y", "u_y top [m]");
  std::vector<ColumnErrors> runs;
  std::vector<double> h, syy;
  for (const int n : {4, 8, 16, 32}) {
    runs.push_back(run_column(n, points_per_cell));
    const ColumnErrors& e = runs.back();
    std::printf("%6d %8.4f %7zu %12.4e %12.4e %12.4e %12.4e %12.6f\n", n, e.h, e.points, e.syy,
                e.sxx, e.szz, e.settlement, e.top_settlement);
    h.push_back(e.h);
    syy.push_back(e.syy);
  }
  order = sim::observed_order(h.data(), syy.data(), h.size());
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
