// The background grid of the GIMP step (paper Section 5): nodal mass, momentum
// and force on a regular mesh of cell size h. The mesh extends `padding`
// empty cells beyond every wall so that a particle's GIMP domain never
// reaches outside it (paper Section 6).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/physics/node_array.hpp"
#include "sim/physics/spec.hpp"

namespace sim {

// A Coulomb friction wall (sim/physics/wall_friction.hpp): the node lines it acts on,
// the wall's line and the padding beyond it, [first, last) along `axis`
// (0: a left or right wall, lines of constant i; 1: bottom or top, constant
// j). `into` is +1 where a positive velocity component along `axis` moves
// into the wall (right, top), -1 where a negative one does (left, bottom).
// `line` is the wall's coordinate along `axis`.
struct FrictionWall {
  int axis = 0;
  double into = 0;
  double mu = 0;
  int first = 0, last = 0;
  double line = 0;
};

// Node (i, j)'s index in a grid of `stride` nodes a row.
inline int node_index(int i, int j, int stride) { return j * stride + i; }

struct Grid {
  double origin_x = 0, origin_y = 0;  // position of node (0, 0)
  double h = 0;                       // cell size
  int nx = 0, ny = 0;                 // nodes per axis

  // Per node, indexed j * stride + i: mass and momentum (Eqs. 26, 27), velocity
  // p/m, force (Eqs. 16, 17) and acceleration f/m.
  NodeArray<double> mass, px, py, vx, vy, fx, fy, ax, ay;
  // The part of (ax, ay) that walls make: all of a held component's
  // acceleration (its force is zero), 0 for a free one.
  NodeArray<double> held_ax, held_ay;
  // Velocity components held at zero by the walls (1 = fixed).
  NodeArray<std::uint8_t> fix_x, fix_y;
  // Walls with Coulomb friction; empty in a scene without them, which then
  // pays nothing for them.
  std::vector<FrictionWall> friction_walls;
  // With friction walls only: per node, the smallest gap between a side or
  // wall line and the edge of a point's domain that weights the node, along
  // x (left and right walls) and y (bottom and top); see wall_friction.hpp.
  NodeArray<double> wall_gap_x, wall_gap_y;
  // The step's normal impulse at each friction-wall node (sim/physics/wall_friction.cpp).
  NodeArray<double> wall_impulse_x, wall_impulse_y;

  // Nodes that particles touched this step: [i_begin, i_end) x [j_begin, j_end).
  // Every nodal loop runs over this window only, and within a row over its
  // span (row_span) where the scene allows, so empty air costs nothing.
  int i_begin = 0, i_end = 0, j_begin = 0, j_end = 0;

  // Per row of the window, the nodes the step resets and updates:
  // [row_span[2 r], row_span[2 r + 1]) along i for row j_begin + r, the
  // nodes of the row that points weight (and the gaps between them), or the
  // whole window (step.cpp).
  std::vector<int> row_span;

  // The nodes no wall acts on: [quiet_i_begin, quiet_i_end) x
  // [quiet_j_begin, quiet_j_end). Their held_ax, held_ay are zero, so a point
  // whose stencil lies inside gets no velocity change from the walls.
  int quiet_i_begin = 0, quiet_i_end = 0, quiet_j_begin = 0, quiet_j_end = 0;

  // Per-row partial sums, row_sums[row * kRowSums + which] (RowSum below),
  // added row by row in a fixed order.
  std::vector<double> row_sums;

  // Nodes per row in memory: nx and one spare node that no point weights.
  // A stencil row is read and written as four nodes (Lane4, lanes.hpp); the
  // fourth, past the stencil, is at worst this spare node of the same row,
  // so it never belongs to a row another thread is writing.
  int stride = 0;

  int node(int i, int j) const { return node_index(i, j, stride); }
  // Row j's span: [span_of_row(j)[0], span_of_row(j)[1]) along i.
  const int* span_of_row(int j) const { return &row_span[2 * (j - j_begin)]; }
  int* span_of_row(int j) { return &row_span[2 * (j - j_begin)]; }
  // Whether a stencil with base node (i, j) reaches a node a wall acts on.
  bool reaches_walls(int i, int j) const {
    return i < quiet_i_begin || i + 3 > quiet_i_end || j < quiet_j_begin || j + 3 > quiet_j_end;
  }
};

// What row_sums holds for each row of the window (the StepReport fields of
// similar names): the kinetic energy the walls' holds take from the grid, the
// part friction takes, and sum_i m_i |dv_i|^2 / 2 of the velocity change the
// walls make (for the transfer loss).
// With APIC (sim/physics/apic.hpp), also the grid's kinetic energy as mapped from
// the points and after the step's update, for the transfer loss.
enum RowSum : int {
  kRowWallLoss,
  kRowFrictionWork,
  kRowWallChangeOnGrid,
  kRowGridKineticMapped,
  kRowGridKineticUpdated,
  kRowSums
};

// The domain a grid covers: its corners, cell size h, the padding cells
// beyond each wall and what each wall holds.
struct GridSpec {
  Vec2 domain_min{}, domain_max{};
  double cell_size = 0;
  int padding_cells = 0;
  Boundaries boundaries;
};

// Builds the grid: walls on the domain lines (the right and top walls on the
// first grid line at or beyond domain_max), boundary flags per node from the
// walls' kinds.
Grid make_grid(const GridSpec& spec);

}  // namespace sim
