#include "sim/physics/grid.hpp"

#include <cmath>

namespace sim {

namespace {

// Node k's holds from one wall: the velocity component normal to it (x for
// a side wall, y for the base or the top) and, for a no-slip (fixed) wall,
// the one along it. A friction wall holds neither outright: its contact acts
// on the momentum each step (sim/physics/wall_friction.cpp).
void hold_for_wall(Grid& g, int k, const Wall& wall, bool normal_is_x) {
  const bool normal = wall.kind == BoundaryKind::Fixed || wall.kind == BoundaryKind::Roller;
  const bool tangential = wall.kind == BoundaryKind::Fixed;
  (normal_is_x ? g.fix_x : g.fix_y)[k] |= normal;
  (normal_is_x ? g.fix_y : g.fix_x)[k] |= tangential;
}

// The wall lines' node indices: the first and last nodes inside the domain.
struct WallLines {
  int left, right, bottom, top;
};

// Walls act on the nodes on their line and on every padding node beyond it,
// so material that reaches a wall cannot pass through it. Only those nodes
// are written: the others stay untouched zero pages (node_array.hpp).
void set_wall_holds(Grid& g, const Boundaries& b, const WallLines& at) {
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const int k = g.node(i, j);
      if (i <= at.left) hold_for_wall(g, k, b.left, true);
      if (i >= at.right) hold_for_wall(g, k, b.right, true);
      if (j <= at.bottom) hold_for_wall(g, k, b.bottom, false);
      if (j >= at.top) hold_for_wall(g, k, b.top, false);
    }
  }
  const auto acts = [](const Wall& wall) { return wall.kind != BoundaryKind::Free; };
  g.quiet_i_begin = acts(b.left) ? at.left + 1 : 0;
  g.quiet_i_end = acts(b.right) ? at.right : g.nx;
  g.quiet_j_begin = acts(b.bottom) ? at.bottom + 1 : 0;
  g.quiet_j_end = acts(b.top) ? at.top : g.ny;
}

// The walls with Coulomb friction (sim/physics/wall_friction.hpp), and the
// node arrays only they use.
void add_friction_walls(Grid& g, const Boundaries& b, const WallLines& at, std::size_t nodes) {
  const Wall* sides[4] = {&b.left, &b.right, &b.bottom, &b.top};
  const FrictionWall lines[4] = {{0, -1.0, 0, 0, at.left + 1, g.origin_x + at.left * g.h},
                                 {0, +1.0, 0, at.right, g.nx, g.origin_x + at.right * g.h},
                                 {1, -1.0, 0, 0, at.bottom + 1, g.origin_y + at.bottom * g.h},
                                 {1, +1.0, 0, at.top, g.ny, g.origin_y + at.top * g.h}};
  for (int k = 0; k < 4; ++k) {
    if (sides[k]->kind != BoundaryKind::Friction) continue;
    g.friction_walls.push_back(lines[k]);
    g.friction_walls.back().mu = sides[k]->friction;
  }
  if (!g.friction_walls.empty()) {
    for (auto* v : {&g.wall_gap_x, &g.wall_gap_y, &g.wall_impulse_x, &g.wall_impulse_y})
      v->resize(nodes);
  }
}

// Cells needed to cover a length; a length that is a whole number of cells up
// to round-off does not get an extra cell.
int cells_covering(double length, double h) {
  return static_cast<int>(std::ceil(length / h - 1e-9));
}

}  // namespace

Grid make_grid(const GridSpec& s) {
  Grid g;
  g.h = s.cell_size;
  const int pad = s.padding_cells;
  const int cells_x = cells_covering(s.domain_max[0] - s.domain_min[0], g.h);
  const int cells_y = cells_covering(s.domain_max[1] - s.domain_min[1], g.h);
  g.origin_x = s.domain_min[0] - pad * g.h;
  g.origin_y = s.domain_min[1] - pad * g.h;
  g.nx = cells_x + 2 * pad + 1;
  g.ny = cells_y + 2 * pad + 1;
  g.stride = g.nx + 1;
  const std::size_t n = static_cast<std::size_t>(g.stride) * g.ny;
  // Zeros that take no memory until written (node_array.hpp).
  for (auto* v : {&g.mass, &g.px, &g.py, &g.vx, &g.vy, &g.fx, &g.fy, &g.ax, &g.ay, &g.held_ax,
                  &g.held_ay})
    v->resize(n);
  g.fix_x.resize(n);
  g.fix_y.resize(n);
  const WallLines at{pad, pad + cells_x, pad, pad + cells_y};
  set_wall_holds(g, s.boundaries, at);
  add_friction_walls(g, s.boundaries, at, n);
  return g;
}

}  // namespace sim
