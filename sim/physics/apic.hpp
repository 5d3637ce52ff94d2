// The affine particle-in-cell transfer (APIC) of Jiang, Schroeder, Selle,
// Teran & Stomakhin (2015), "The affine particle-in-cell method", ACM Trans.
// Graph. 34(4):51, as a scene's alternative (`"transfer": "apic"`) to the
// paper's FLIP-like update (Eq. 30). Measured against it in bench/accuracy
// as a cure for the transfer loss (issue 13).
//
// Each point carries an affine velocity field v_p + C_p (x - x_p):
//   P2G:  m_i = sum_p S_ip m_p,  p_i = sum_p S_ip m_p (v_p + C_p (x_i - x_p))
//   G2P:  v_p = sum_i S_ip v_i,  C_p = B_p D_p^-1,
//         B_p = sum_i S_ip v_i (x_i - x_p)^T,  D_p = sum_i S_ip (x_i - x_p)(x_i - x_p)^T
// (their Eqs. 8, 10 and 11). The points take the grid's velocity, not its
// change: no null space keeps motion the grid does not see, and an affine
// velocity field goes to the grid and back exactly. With GIMP weights D_p is
// not the constant of B-splines: the stencil reproduces linear functions, so
// D_p is diagonal, D_xx = sum_a w_a (x_a - x_p)^2 over the x weights (and so
// for y), and is computed per point from its stencil.
//
// Energy (Eq. 3): the transfers' loss is measured, not the FLIP walls' term:
// (the points' kinetic energy before P2G - the grid's as mapped) + (the
// grid's after the update - the points' after G2P).
#pragma once

#include "sim/physics/step.hpp"

namespace sim {

// Nodal mass and momentum of one band's points with each point's affine
// field; their kinetic energy goes to band_sums (kKineticBeforeGrid). The
// band visit of points_to_grid (step.hpp) for this transfer.
void map_band_apic(World& world, int band);

// Velocities, affine fields and positions from the grid (Eq. 29 moves the
// points as in the FLIP update), the step's point sums to band_sums; damping
// v := v / (1 + theta) scales C_p too.
void grid_to_points_apic(World& world, const StepInput& input);

// sum_i |p_i|^2 / (2 m_i) over the window's nodes in rows [first, last), into
// row_sums[which] (kRowGridKineticMapped or kRowGridKineticUpdated).
void grid_kinetic_by_row(Grid& grid, int first, int last, int which);

}  // namespace sim
