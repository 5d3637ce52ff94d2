#include "sim/physics/grid.hpp"

#include <cmath>

namespace sim {

namespace {

// Whether a wall holds the velocity component normal to it (normal) and the
// one along it (tangential). A friction wall holds neither outright: its
// contact acts on the momentum each step (sim/physics/wall_friction.cpp).
void wall_holds(const Wall& wall, bool& normal, bool& tangential) {
  normal = wall.kind == BoundaryKind::Fixed || wall.kind == BoundaryKind::Roller;
  tangential = wall.kind == BoundaryKind::Fixed;
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

  // Walls act on the nodes on their line and on every padding node beyond it,
  // so material that reaches a wall cannot pass through it.
  const int left = pad, right = pad + cells_x, bottom = pad, top = pad + cells_y;
  bool normal = false, tangential = false;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const int k = g.node(i, j);
      if (i <= left) {
        wall_holds(s.boundaries.left, normal, tangential);
        g.fix_x[k] |= normal;
        g.fix_y[k] |= tangential;
      }
      if (i >= right) {
        wall_holds(s.boundaries.right, normal, tangential);
        g.fix_x[k] |= normal;
        g.fix_y[k] |= tangential;
      }
      if (j <= bottom) {
        wall_holds(s.boundaries.bottom, normal, tangential);
        g.fix_y[k] |= normal;
        g.fix_x[k] |= tangential;
      }
      if (j >= top) {
        wall_holds(s.boundaries.top, normal, tangential);
        g.fix_y[k] |= normal;
        g.fix_x[k] |= tangential;
      }
    }
  }
  const auto acts = [](const Wall& wall) { return wall.kind != BoundaryKind::Free; };
  g.quiet_i_begin = acts(s.boundaries.left) ? left + 1 : 0;
  g.quiet_i_end = acts(s.boundaries.right) ? right : g.nx;
  g.quiet_j_begin = acts(s.boundaries.bottom) ? bottom + 1 : 0;
  g.quiet_j_end = acts(s.boundaries.top) ? top : g.ny;
  const Wall* sides[4] = {&s.boundaries.left, &s.boundaries.right, &s.boundaries.bottom,
                         &s.boundaries.top};
  const FrictionWall lines[4] = {{0, -1.0, 0, 0, left + 1, g.origin_x + left * g.h},
                                 {0, +1.0, 0, right, g.nx, g.origin_x + right * g.h},
                                 {1, -1.0, 0, 0, bottom + 1, g.origin_y + bottom * g.h},
                                 {1, +1.0, 0, top, g.ny, g.origin_y + top * g.h}};
  for (int k = 0; k < 4; ++k) {
    if (sides[k]->kind != BoundaryKind::Friction) continue;
    g.friction_walls.push_back(lines[k]);
    g.friction_walls.back().mu = sides[k]->friction;
  }
  if (!g.friction_walls.empty()) {
    for (auto* v : {&g.wall_gap_x, &g.wall_gap_y, &g.wall_impulse_x, &g.wall_impulse_y})
      v->resize(n);
  }
  return g;
}

}  // namespace sim
