// Plane geometry of the bodies: area, inside test, simplicity, overlap.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "sim/scene/scenario_geometry.hpp"

namespace {

using sim::Vec2;
using Polygon = std::vector<Vec2>;

Polygon rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Polygon reversed(Polygon p) {
  std::reverse(p.begin(), p.end());
  return p;
}

TEST(GeometrySignedArea, OrientationAndValue) {
  EXPECT_EQ(sim::signed_area(rect(0, 0, 1, 1)), 1.0);
  EXPECT_EQ(sim::signed_area(reversed(rect(0, 0, 1, 1))), -1.0);
  EXPECT_EQ(sim::signed_area(rect(2, 3, 6, 5)), 8.0);
  EXPECT_EQ(sim::signed_area({{0, 0}, {4, 0}, {0, 3}}), 6.0);
  // The paper's slope (trapezoid) and an L shape.
  EXPECT_NEAR(sim::signed_area({{0, 0}, {55.87, 0}, {43.95, 10}, {0, 10}}), 499.1, 1e-9);
  EXPECT_EQ(sim::signed_area({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}), 3.0);
  EXPECT_EQ(sim::signed_area({{0, 0}, {1, 0}, {2, 0}}), 0.0);
}

TEST(GeometryPointInPolygon, InsideAndOutside) {
  const Polygon l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(sim::point_in_polygon(l, {0.5, 0.5}));
  EXPECT_TRUE(sim::point_in_polygon(l, {1.5, 0.5}));
  EXPECT_TRUE(sim::point_in_polygon(l, {0.5, 1.5}));
  EXPECT_FALSE(sim::point_in_polygon(l, {1.5, 1.5}));  // the notch
  EXPECT_FALSE(sim::point_in_polygon(l, {-0.5, 0.5}));
  EXPECT_FALSE(sim::point_in_polygon(l, {3, 0.5}));
  EXPECT_FALSE(sim::point_in_polygon(l, {0.5, 3}));
  // Orientation does not matter.
  EXPECT_TRUE(sim::point_in_polygon(reversed(l), {0.5, 1.5}));
  EXPECT_FALSE(sim::point_in_polygon(reversed(l), {1.5, 1.5}));
}

// Points on the edge two polygons share are claimed by exactly one of them.
void expect_one_claims(const Polygon& a, const Polygon& b, const Vec2& p) {
  const int claims = sim::point_in_polygon(a, p) + sim::point_in_polygon(b, p);
  EXPECT_EQ(claims, 1) << "(" << p[0] << ", " << p[1] << ")";
}

TEST(GeometryPointInPolygon, SharedAxisAlignedEdgeHasOneOwner) {
  // Side by side, one above the other, each in both orientations.
  for (bool flip : {false, true}) {
    const Polygon left = flip ? reversed(rect(0, 0, 1, 1)) : rect(0, 0, 1, 1);
    const Polygon right = rect(1, 0, 2, 1);
    const Polygon above = flip ? rect(0, 1, 1, 2) : reversed(rect(0, 1, 1, 2));
    for (int k = 1; k < 10; ++k) {
      expect_one_claims(left, right, {1, k / 10.0});
      expect_one_claims(left, above, {k / 10.0, 1});
    }
  }
}

TEST(GeometryPointInPolygon, SharedSlopedEdgeHasOneOwner) {
  // A quadrilateral cut along an oblique line into two; the points on the
  // cut are computed the way a seeder would, with round-off.
  const Vec2 a{0.1, 0.2}, b{3.7, 9.3};
  const Polygon lower = {{0.1, 0.2}, {5, 0}, {3.7, 9.3}};   // right of a->b
  const Polygon upper = {{0.1, 0.2}, {3.7, 9.3}, {-2, 6}};  // left of a->b
  for (bool flip : {false, true}) {
    const Polygon l = flip ? reversed(lower) : lower;
    for (int k = 1; k < 1000; ++k) {
      const double t = k / 1000.0;
      expect_one_claims(l, upper, {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  // The slope face of the paper and the air above it, at many heights.
  const Polygon slope = {{0, 0}, {55.87, 0}, {43.95, 10}, {0, 10}};
  const Polygon air = {{55.87, 0}, {60, 0}, {60, 10}, {43.95, 10}};
  for (int k = 1; k < 200; ++k) {
    const double y = 10.0 * k / 200;
    expect_one_claims(slope, air, {55.87 + (43.95 - 55.87) * y / 10, y});
  }
}

TEST(GeometryPointInPolygon, SharedCornerOfFourSquaresHasOneOwner) {
  const Polygon squares[4] = {rect(0, 0, 1, 1), rect(1, 0, 2, 1), rect(0, 1, 1, 2),
                              rect(1, 1, 2, 2)};
  int claims = 0;
  for (const Polygon& s : squares) claims += sim::point_in_polygon(s, {1, 1});
  EXPECT_EQ(claims, 1);
}

TEST(GeometryPolygonIsSimple, SimpleShapes) {
  EXPECT_TRUE(sim::polygon_is_simple(rect(0, 0, 1, 1)));
  EXPECT_TRUE(sim::polygon_is_simple(reversed(rect(0, 0, 1, 1))));
  EXPECT_TRUE(sim::polygon_is_simple({{0, 0}, {4, 0}, {0, 3}}));
  EXPECT_TRUE(sim::polygon_is_simple({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}));
  // A vertex in the middle of a straight side is fine.
  EXPECT_TRUE(sim::polygon_is_simple({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}));
}

TEST(GeometryPolygonIsSimple, BowTie) {
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
}

TEST(GeometryPolygonIsSimple, RepeatedVertex) {
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}));
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}));  // closed
  // Two loops pinched at one vertex (a figure eight).
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1},
                                       {0, 1}}));
}

TEST(GeometryPolygonIsSimple, FoldBack) {
  // The third vertex runs back along the second edge.
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));
  // A spike out and back along the same line.
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {2, 0}, {2, 1}, {3, 1}, {2, 1}, {0, 1}}));
  // A degenerate triangle.
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {2, 0}, {1, 0}}));
}

TEST(GeometryPolygonIsSimple, VertexTouchingAnotherEdge) {
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {4, 0}, {4, 2}, {2, 0}, {0, 2}}));
  EXPECT_FALSE(sim::polygon_is_simple({{0, 0}, {1, 0}}));
}

TEST(GeometryPolygonsOverlap, Disjoint) {
  EXPECT_FALSE(sim::polygons_overlap(rect(0, 0, 1, 1), rect(2, 0, 3, 1)));
  EXPECT_FALSE(sim::polygons_overlap(rect(0, 0, 1, 1), rect(0.5, 1.5, 3, 2)));
}

TEST(GeometryPolygonsOverlap, TouchingAlongAnEdgeOrAtAVertex) {
  EXPECT_FALSE(sim::polygons_overlap(rect(0, 0, 1, 1), rect(1, 0, 2, 1)));
  EXPECT_FALSE(sim::polygons_overlap(rect(0, 0, 1, 1), rect(1, 0.2, 2, 0.7)));  // part of an edge
  EXPECT_FALSE(sim::polygons_overlap(rect(0, 0, 1, 1), reversed(rect(1, 1, 2, 2))));
  // The paper's house on its slope.
  const Polygon slope = {{0, 0}, {55.87, 0}, {43.95, 10}, {0, 10}};
  EXPECT_FALSE(sim::polygons_overlap(slope, rect(35.95, 10, 41.95, 14)));
  EXPECT_FALSE(sim::polygons_overlap(rect(35.95, 10, 41.95, 14), slope));
  // Triangles sharing an oblique edge.
  EXPECT_FALSE(sim::polygons_overlap({{0.1, 0.2}, {5, 0}, {3.7, 9.3}},
                                     {{0.1, 0.2}, {3.7, 9.3}, {-2, 6}}));
}

TEST(GeometryPolygonsOverlap, OneInsideTheOther) {
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 10, 10), rect(4, 4, 5, 5)));
  EXPECT_TRUE(sim::polygons_overlap(rect(4, 4, 5, 5), rect(0, 0, 10, 10)));
  // Inside and sharing part of the boundary.
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 10, 10), rect(0, 0, 5, 5)));
  // A diamond inscribed in a square touches it only at the square's midpoints.
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 2, 2), {{1, 0}, {2, 1}, {1, 2}, {0, 1}}));
}

TEST(GeometryPolygonsOverlap, Crossing) {
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 2, 2), rect(1, 1, 3, 3)));
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 1, 10, 2), rect(4, 0, 5, 10)));  // a plus sign
  // The house sunk 1 m into the slope.
  EXPECT_TRUE(sim::polygons_overlap({{0, 0}, {55.87, 0}, {43.95, 10}, {0, 10}},
                                    rect(35.95, 9, 41.95, 13)));
  // Boundaries meet only at vertices yet the regions overlap.
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 2, 2), {{0, 0}, {4, 4}, {4, -2}}));
}

TEST(GeometryPolygonsOverlap, Identical) {
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 1, 1), rect(0, 0, 1, 1)));
  EXPECT_TRUE(sim::polygons_overlap(rect(0, 0, 1, 1), reversed(rect(0, 0, 1, 1))));
  const Polygon tri = {{0.1, 0.2}, {5, 0}, {3.7, 9.3}};
  EXPECT_TRUE(sim::polygons_overlap(tri, tri));
}

using Contact = std::optional<std::array<std::size_t, 2>>;

Contact pair(std::size_t i, std::size_t j) { return std::array<std::size_t, 2>{i, j}; }

TEST(GeometrySelfContact, NamesTheEdgesThatMeet) {
  EXPECT_EQ(sim::polygon_self_contact(rect(0, 0, 1, 1)), std::nullopt);
  // Bow tie: edge 0 (v0-v1) crosses edge 2 (v2-v3).
  EXPECT_EQ(sim::polygon_self_contact({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), pair(0, 2));
  // Repeated vertex: edge 1 has no length.
  EXPECT_EQ(sim::polygon_self_contact({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}), pair(1, 1));
  // Closed like a path: the last edge (v4-v0) has no length.
  EXPECT_EQ(sim::polygon_self_contact({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}), pair(4, 4));
  // Vertex 3 lies on edge 0.
  EXPECT_EQ(sim::polygon_self_contact({{0, 0}, {4, 0}, {4, 2}, {2, 0}, {0, 2}}), pair(0, 2));
  EXPECT_EQ(sim::polygon_self_contact({{0, 0}, {1, 0}}), pair(0, 0));
}

TEST(GeometrySelfContact, SameAnswerWhereverThePolygonStarts) {
  // Two crossings; the smaller pair of edge indices is named, so rotating the
  // vertex list moves the answer with it.
  const Polygon star = {{0, 0}, {4, 3}, {4, 0}, {0, 3}, {2, -1}};
  const Contact first = sim::polygon_self_contact(star);
  ASSERT_TRUE(first.has_value());
  for (std::size_t shift = 1; shift < star.size(); ++shift) {
    Polygon rotated(star.begin() + shift, star.end());
    rotated.insert(rotated.end(), star.begin(), star.begin() + shift);
    EXPECT_TRUE(sim::polygon_self_contact(rotated).has_value()) << shift;
  }
  EXPECT_EQ(sim::polygon_self_contact(star), first);  // deterministic
}

TEST(GeometrySelfContact, LongTerrainProfileIsSimpleAndQuick) {
  // A 9997-vertex ground line closed along the base: the sweep compares
  // each edge with its few neighbours in x only.
  Polygon ground;
  for (int i = 0; i <= 9996; ++i) ground.push_back({i * 0.01, 5 + std::sin(i * 0.01)});
  ground.push_back({99.96, 0});
  ground.push_back({0, 0});
  EXPECT_TRUE(sim::polygon_is_simple(ground));
  ground[5000][1] = -1;  // a spike through the base
  EXPECT_FALSE(sim::polygon_is_simple(ground));
}

TEST(GeometryPolygonsOverlap, BoxesThatOnlyTouchOrInterlock) {
  // Boxes sharing only an edge: no overlap, decided from the boxes alone.
  EXPECT_FALSE(sim::polygons_overlap(rect(0, 0, 1, 1), rect(1, -5, 3, 5)));
  // Two interlocking L shapes: their boxes overlap, they do not.
  const Polygon l1 = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const Polygon l2 = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};  // fills the notch
  EXPECT_FALSE(sim::polygons_overlap(l1, l2));
  EXPECT_FALSE(sim::polygons_overlap(l2, l1));
  const Polygon l3 = {{0.5, 1}, {3, 1}, {3, 3}, {0.5, 3}};  // reaches into the upright
  EXPECT_TRUE(sim::polygons_overlap(l1, l3));
  EXPECT_TRUE(sim::polygons_overlap(l3, l1));
  // Degenerate inputs are never said to overlap.
  EXPECT_FALSE(sim::polygons_overlap({}, rect(0, 0, 1, 1)));
  EXPECT_FALSE(sim::polygons_overlap({{0, 0}, {1, 1}}, rect(0, 0, 1, 1)));
}

TEST(GeometryPolygonsOverlap, RoundOffWithinTheToleranceIsTouching) {
  const Polygon slope = {{0, 0}, {55.87, 0}, {43.95, 10}, {0, 10}};
  const Polygon sunk_by_round_off = rect(35.95, 10 - 1e-12, 41.95, 14);
  EXPECT_TRUE(sim::polygons_overlap(slope, sunk_by_round_off));  // exact by default
  EXPECT_FALSE(sim::polygons_overlap(slope, sunk_by_round_off, 1e-9));
  EXPECT_FALSE(sim::polygons_overlap(sunk_by_round_off, slope, 1e-9));
  // Deeper than the tolerance: found, however small.
  for (double depth : {1e-8, 1e-6, 1e-3, 1.0}) {
    const Polygon sunk = rect(35.95, 10 - depth, 41.95, 14);
    EXPECT_TRUE(sim::polygons_overlap(slope, sunk, 1e-9)) << depth;
    EXPECT_TRUE(sim::polygons_overlap(sunk, slope, 1e-9)) << depth;
  }
  // Strips stacked at i * t meet at coordinates that differ in the last bit.
  const double t = 5.0 / 1000;
  for (int i = 1; i < 1000; i += 7) {
    const Polygon lower = {{0, (i - 1) * t}, {90, (i - 1) * t + 9}, {90, (i - 1) * t + 9 + t},
                           {0, (i - 1) * t + t}};
    const Polygon upper = {{0, i * t}, {90, i * t + 9}, {90, i * t + 9 + t}, {0, i * t + t}};
    EXPECT_FALSE(sim::polygons_overlap(lower, upper, 1e-9)) << i;
  }
}

}  // namespace
