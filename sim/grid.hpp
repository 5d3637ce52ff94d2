// The background grid of the GIMP step (paper Section 5): nodal mass, momentum
// and force on a regular mesh of cell size h. The mesh extends `padding`
// empty cells beyond every wall so that a particle's GIMP domain never
// reaches outside it (paper Section 6).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/scenario.hpp"

namespace sim {

struct Grid {
  double origin_x = 0, origin_y = 0;  // position of node (0, 0)
  double h = 0;                       // cell size
  int nx = 0, ny = 0;                 // nodes per axis

  // Per node, indexed j * stride + i: mass and momentum (Eqs. 26, 27), velocity
  // p/m, force (Eqs. 16, 17) and acceleration f/m.
  std::vector<double> mass, px, py, vx, vy, fx, fy, ax, ay;
  // The part of (ax, ay) that walls make: all of a held component's
  // acceleration (its force is zero), 0 for a free one.
  std::vector<double> held_ax, held_ay;
  // Points whose weight on the node is positive: a point alone on all its
  // nodes is a free body (see update_point_stress). Counted in doubles (exact
  // up to 2^53) so a stencil row adds to three nodes as one vector.
  std::vector<double> points;
  // Velocity components held at zero by the walls (1 = fixed).
  std::vector<std::uint8_t> fix_x, fix_y;

  // Nodes that particles touched this step: [i_begin, i_end) x [j_begin, j_end).
  // Every nodal loop runs over this window only, so empty air costs nothing.
  int i_begin = 0, i_end = 0, j_begin = 0, j_end = 0;

  std::vector<double> row_sums;  // per-row partial sums, added in a fixed order

  // Nodes per row in memory: nx and one spare node that no point weights.
  // A stencil row is read and written as four nodes (Lane4, gimp.hpp); the
  // fourth, past the stencil, is at worst this spare node of the same row,
  // so it never belongs to a row another thread is writing.
  int stride = 0;

  int node(int i, int j) const { return j * stride + i; }
};

// Builds the grid for a scenario: walls on the domain lines (the right and top
// walls on the first grid line at or beyond domain.max), boundary flags per
// node from the scenario's boundary kinds.
Grid make_grid(const Scenario& scenario);

}  // namespace sim
