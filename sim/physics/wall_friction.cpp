// Coulomb friction walls, in the order the step meets them: the gaps between
// the walls and the material (while the points are mapped to the grid), the
// contact on the mapped momentum, and the contact with friction on the
// momentum after the forces. The header gives the method and its sources.
#include "sim/physics/wall_friction.hpp"

#include <algorithm>
#include <cmath>

namespace sim {

namespace {

// Calls visit(k, row) for every node of `wall` in rows [first, last) of the
// window, row by row; `row` indexes row_sums.
template <class Visit>
void for_wall_nodes(const Grid& g, const FrictionWall& wall, int first, int last, Visit visit) {
  int j0 = first, j1 = last, i0 = g.i_begin, i1 = g.i_end;
  if (wall.axis == 1) {
    j0 = std::max(j0, wall.first);
    j1 = std::min(j1, wall.last);
  } else {
    i0 = std::max(i0, wall.first);
    i1 = std::min(i1, wall.last);
  }
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i) visit(g.node(i, j), j - g.j_begin);
}

// Whether node k is on the lines of `wall`.
bool on_wall(const Grid& g, const FrictionWall& wall, int k) {
  const int at = wall.axis == 0 ? k % g.stride : k / g.stride;
  return at >= wall.first && at < wall.last;
}

// False for a corner node of two friction walls when looking from the
// later one, so that the sums count each node once.
bool first_wall_of(const Grid& g, std::size_t w, int k) {
  for (std::size_t v = 0; v < w; ++v)
    if (on_wall(g, g.friction_walls[v], k)) return false;
  return true;
}

// The components of node k along the wall's axis (n) and along the wall (t).
struct NodeView {
  double& pn;
  double& pt;
  double& vn;
  double& vt;
  double& an;
  double& at;
  double& fn;
  double& ft;
};

NodeView view(Grid& g, const FrictionWall& wall, int k) {
  if (wall.axis == 0)
    return {g.px[k], g.py[k], g.vx[k], g.vy[k], g.ax[k], g.ay[k], g.fx[k], g.fy[k]};
  return {g.py[k], g.px[k], g.vy[k], g.vx[k], g.ay[k], g.ax[k], g.fy[k], g.fx[k]};
}

NodeArray<double>& impulses(Grid& g, const FrictionWall& wall) {
  return wall.axis == 0 ? g.wall_impulse_x : g.wall_impulse_y;
}

// A node not in contact in this step.
constexpr double kNoContact = -1.0;

}  // namespace

void reset_wall_gaps(Grid& g, int first, int last) {
  for (int j = first; j < last; ++j) {
    const int row = g.node(0, j);
    std::fill(g.wall_gap_x.begin() + row + g.i_begin, g.wall_gap_x.begin() + row + g.i_end,
              HUGE_VAL);
    std::fill(g.wall_gap_y.begin() + row + g.i_begin, g.wall_gap_y.begin() + row + g.i_end,
              HUGE_VAL);
  }
}

void scatter_wall_gaps(World& w, int band) {
  Grid& g = w.grid;
  const double lp = w.gimp.lp;
  for (int s = w.band_start[band]; s < w.band_start[band + 1]; ++s) {
    const int p = w.order[s];
    const StencilWeights& st = w.weights[p];
    for (const FrictionWall& wall : g.friction_walls) {
      const int base = wall.axis == 0 ? st.base_i : st.base_j;
      if (base >= wall.last || base + 2 < wall.first) continue;  // the stencil misses the wall
      const double at = wall.axis == 0 ? w.points.x[p] : w.points.y[p];
      const double gap = wall.into * (wall.line - at) - lp;
      NodeArray<double>& gaps = wall.axis == 0 ? g.wall_gap_x : g.wall_gap_y;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          double& here = gaps[g.node(st.base_i + a, st.base_j + b)];
          here = std::min(here, gap);
        }
    }
  }
}

void friction_walls_on_momentum(Grid& g, int first, int last) {
  for (const FrictionWall& wall : g.friction_walls) {
    NodeArray<double>& impulse = impulses(g, wall);
    const NodeArray<double>& gaps = wall.axis == 0 ? g.wall_gap_x : g.wall_gap_y;
    for_wall_nodes(g, wall, first, last, [&](int k, int row) {
      if (!(gaps[k] <= 0.0 && g.mass[k] > 0.0)) {
        impulse[k] = kNoContact;
        return;
      }
      NodeView n = view(g, wall, k);
      const double into = wall.into * n.pn;
      impulse[k] = std::max(0.0, into);
      n.vn = 0.0;  // what the strain increment (Eq. 31) reads
      if (!(into > 0.0)) return;
      // An impact: the momentum into the wall is taken, inelastically.
      const double inv = 1.0 / g.mass[k];
      n.an -= n.pn * inv;
      g.row_sums[row * kRowSums + kRowWallLoss] += 0.5 * n.pn * n.pn * inv;
      n.pn = 0.0;
    });
  }
}

// One node of a wall after the forces: the normal hold, then Coulomb's law
// on the tangential impulse; returns the work of friction as the points feel
// it. pt0 - dt ft is the tangential momentum before the forces.
double slide_or_stick(const FrictionWall& wall, NodeView n, double m, double impulse,
                      double dt) {
  const double inv = 1.0 / m, inv_dt = 1.0 / dt;
  const double pressed = std::max(0.0, wall.into * n.pn);
  if (pressed > 0.0) {
    n.fn -= wall.into * pressed * inv_dt;  // the force into the wall is not applied
    n.an -= wall.into * pressed * inv * inv_dt;
    n.pn = 0.0;
    n.vn = 0.0;
  }
  const double cap = wall.mu * (impulse + pressed);
  const double pt0 = n.pt, start = pt0 - dt * n.ft;
  double change, work;
  if (std::fabs(pt0) <= cap) {
    // Stick: the node is held like a fixed one, its tangential force not
    // applied and the momentum it had taken.
    change = -pt0;
    work = 0.5 * start * start * inv;
    n.ft = 0.0;
  } else {
    // Slip: the friction impulse J = -cap sign(p_t) acts on the motion; the
    // points feel it on the momentum they brought, start.
    change = -std::copysign(cap, pt0);
    work = 0.5 * (start * start - (start + change) * (start + change)) * inv;
  }
  n.pt = pt0 + change;
  n.at += change * inv * inv_dt;
  n.vt = n.pt * inv;
  return work;
}

void friction_walls_on_update(Grid& g, int first, int last, double dt) {
  const auto& walls = g.friction_walls;
  for (const FrictionWall& wall : walls) {
    const NodeArray<double>& impulse = impulses(g, wall);
    for_wall_nodes(g, wall, first, last, [&](int k, int row) {
      if (impulse[k] == kNoContact) return;
      g.row_sums[row * kRowSums + kRowFrictionWork] +=
          slide_or_stick(wall, view(g, wall, k), g.mass[k], impulse[k], dt);
    });
  }
  // The walls' share of the step's velocity change: all but the applied
  // force's f / m. Components held by fixed or roller walls were counted by
  // the holds already.
  for (std::size_t w = 0; w < walls.size(); ++w) {
    for_wall_nodes(g, walls[w], first, last, [&](int k, int row) {
      if (!(g.mass[k] > 0.0) || !first_wall_of(g, w, k)) return;
      const double inv = 1.0 / g.mass[k];
      g.held_ax[k] = g.ax[k] - g.fx[k] * inv;
      g.held_ay[k] = g.ay[k] - g.fy[k] * inv;
      const double hx = g.fix_x[k] ? 0.0 : g.held_ax[k], hy = g.fix_y[k] ? 0.0 : g.held_ay[k];
      g.row_sums[row * kRowSums + kRowWallChangeOnGrid] +=
          0.5 * g.mass[k] * dt * dt * (hx * hx + hy * hy);
    });
  }
}

}  // namespace sim
