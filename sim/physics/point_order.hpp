// Points stored in the order of their cells (issue 17).
//
// The step visits points band by band in the order of their base nodes
// (locate.cpp). Stored in the order the scene seeded them, a flowing soil
// soon has neighbours in a band far apart in memory, and every phase gathers
// them from all over its arrays: at 410 k points the step took 133 ns per
// point with the points in scene order and 104 ns with them stored in the
// order of the step before (bench/phases, one thread, granular column). So
// the time loop stores them in cell order every few steps, and puts them back
// in scene order before anything outside the step reads them.
//
// Where a point is stored never changes a result: the step breaks ties
// between the points of one base node by their index in the scene
// (locate.cpp), so it visits points in the same order, and sums them in the
// same order, however they are stored; and the first point off the grid is
// the first by scene index.
#pragma once

#include "sim/physics/world.hpp"

namespace sim {

// The time loop looks every kStepsPerSort steps, and sorts if more than
// kSortAtDisorder of the points in the last step's order are not stored
// right after the point before them. A sort costs about 10 ns per point at
// 410 k and at 6.5 M points (`bench/phases 4 40` and `16 10`, `--threads 1
// --sorts 10`, sorts 3-10: 10.1-10.7 and 9.7-11.2; 20 and 50 to 120 before
// 85eb75c), so points that stay in their cells, as a slope at rest does,
// are not sorted again.
constexpr long kStepsPerSort = 10;
constexpr double kSortAtDisorder = 0.1;

// Whether the time loop sorts before the step that follows `steps` steps of
// a stage.
bool sort_due(const World& world, long steps);

// Stores the points in the order of the last step (world.order), each point
// with its index in the scene (world.scene_index). Nothing to do before the
// first step.
void sort_points_by_cell(World& world);

// Stores the points in scene order again; nothing to do if they are. The
// last step's order follows them, so the next sort is by cell again.
void restore_scene_order(World& world);

// The slot of each point, in scene order (slots[scene] = slot), for reading
// the points in scene order where they are stored; empty while they are
// stored in scene order.
std::vector<int> slots_in_scene_order(const World& world);

// The index in the scene of the point stored at `slot`, and the slot of the
// point with scene index `scene` (a search: for error messages).
int scene_index_of(const World& world, int slot);
int slot_of_scene_index(const World& world, int scene);

}  // namespace sim
