// Plane geometry of the scenario's bodies: what validation needs (simple
// polygons, overlap) and what the point seeder needs (inside test, area).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "sim/scene/scenario.hpp"

namespace sim {

// Positive for counter-clockwise vertices.
double signed_area(const std::vector<Vec2>& polygon);

// Even-odd rule with half-open edges: a point exactly on an edge or vertex
// gets the same answer every time, and two polygons sharing an edge never
// both claim a point on it.
bool point_in_polygon(const std::vector<Vec2>& polygon, const Vec2& p);

// No two non-adjacent edges touch, and adjacent edges meet only at their
// shared vertex.
bool polygon_is_simple(const std::vector<Vec2>& polygon);

// Two edges that break the rule above (edge k runs from vertex k to vertex
// k + 1), smaller index first; nothing when the polygon is simple. {k, k}:
// edge k has no length (a vertex repeated). Among several contacts, the
// smallest pair. A polygon of fewer than 3 vertices reports {0, 0}.
std::optional<std::array<std::size_t, 2>> polygon_self_contact(const std::vector<Vec2>& polygon);

// The two simple polygons share a region of positive area (touching along an
// edge or at a vertex does not count).
// With a `tolerance` (a distance), edges that pass within it of each other's
// ends count as touching, so bodies built from rounded coordinates that were
// meant to touch do not overlap by round-off; overlaps deeper than about
// 1e-7 of the coordinates' size are always found.
bool polygons_overlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b,
                      double tolerance = 0);

}  // namespace sim
