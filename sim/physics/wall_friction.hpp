// Coulomb friction at walls: the contact of Bardenhagen et al. (2001), "An
// improved contact algorithm for the material point method and application to
// stress propagation in granular material", CMES 2(4):509-522, in the limit
// where the second body is a rigid wall at rest.
//
// At a node of a friction wall with momentum p, mass m and unit normal n into
// the wall, the material is in contact when it moves into the wall; moving
// away, it separates. In contact the normal momentum J_n = p . n is taken,
// and the tangential momentum p_t changes by at most mu J_n (Coulomb's law on
// the impulses of the step):
//   p_t := 0                          if |p_t| <= mu J_n   (stick)
//   p_t := p_t - mu J_n p_t / |p_t|   otherwise            (slip)
//
// The step meets the contact twice, as it meets the walls' holds
// (sim/physics/step.cpp): on the momentum mapped from the points (Eq. 27), whose
// velocity the strain increment reads (Eq. 31), and on the momentum after the
// forces (Eq. 28). J_n adds both: the impact on the mapped momentum, and the
// force pressing the node into the wall, which is not applied (as a hold does
// not apply the force along what it holds). Friction acts on the second,
// with the step's whole J_n.
//
// Two rules are not in Bardenhagen et al.; both are departures, measured on
// the blocks of tests/sim/test_wall_friction.cpp (FLIP update, Eq. 30):
// - Contact needs touching: the edge of the GIMP domain (half-width l_p) of a
//   point that weights the node is at the wall or past it. A wall node stays
//   on the wall line whatever the material does, so velocities alone cannot
//   see a gap: nodes the material had left still counted as in contact, and
//   a plate sliding at 30 degrees with mu = 0.3 gained 2.2 times the work of
//   gravity as kinetic energy. The gap is the displacement check that
//   NairnMPM adds to the velocity test (Nairn's documentation, "Detecting
//   Contact").
// - Touching material that moves away on the mapped momentum keeps that
//   momentum, but the strain increment reads no normal velocity there; the
//   forces then decide whether it separates. Taking that momentum away made
//   the wall pull material back (adhesion), and the friction on the extra
//   compression elsewhere slowed the plate by 7 %; letting the strain read it
//   while the forces then held the node did work on a motion that never
//   happened, and a block at rest with mu = 0 crept up 1.1 mm in 1 s.
//
// Energies (Eq. 3): the impacts are the walls' inelastic loss; friction's
// work is its own term, as the points feel it: the tangential impulse J
// applied to the momentum before the forces, p0, gives
// (|p0|^2 - |p0 + J|^2) / (2m). A stuck node is held like a fixed one: its
// tangential force is not applied and p0 is taken.
#pragma once

#include "sim/physics/world.hpp"

namespace sim {

// Sets the gaps of the window's nodes in rows [first, last) to +infinity.
void reset_wall_gaps(Grid& grid, int first, int last);

// For the points of `band` whose stencil reaches a friction wall's lines:
// the gap between the wall and the edge of the point's domain, kept per node
// as the smallest over the points that weight it (as points_to_grid does,
// band by band). Negative where the material is pressed past the line.
void scatter_wall_gaps(World& world, int band);

// On the momentum of the nodes of every friction wall in rows [first, last)
// of the window, after the points' momentum is mapped (Eq. 27): the impact's
// velocity change is added to (ax, ay), its energy to row_sums, and the
// normal velocity the strain increment reads is zero at touching nodes.
void friction_walls_on_momentum(Grid& grid, int first, int last);

// After Eq. (28), on p + dt f: the normal hold and friction; the change, per
// unit time, is added to (ax, ay), friction's work to row_sums, and
// (held_ax, held_ay) become the walls' whole velocity change of the step
// divided by dt.
void friction_walls_on_update(Grid& grid, int first, int last, double dt);

}  // namespace sim
