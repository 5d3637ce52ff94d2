#include "sim/scenario_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace sim {

namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

int sign(double v) { return (v > 0) - (v < 0); }

bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

// Segments share at least one point.
bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int d1 = sign(cross(c, d, a)), d2 = sign(cross(c, d, b));
  const int d3 = sign(cross(a, b, c)), d4 = sign(cross(a, b, d));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && on_segment(a, c, d)) || (d2 == 0 && on_segment(b, c, d)) ||
         (d3 == 0 && on_segment(c, a, b)) || (d4 == 0 && on_segment(d, a, b));
}

// Segments cross at a point inside both.
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return sign(cross(c, d, a)) * sign(cross(c, d, b)) < 0 &&
         sign(cross(a, b, c)) * sign(cross(a, b, d)) < 0;
}

// Points just inside `poly` next to the middle of each edge.
std::vector<Vec2> inner_probes(const std::vector<Vec2>& poly) {
  const double orientation = signed_area(poly) > 0 ? 1.0 : -1.0;
  double size = 0;
  for (const Vec2& v : poly) size = std::max({size, std::fabs(v[0]), std::fabs(v[1])});
  std::vector<Vec2> probes;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
    const double eps = 1e-7 * std::max(size, len);
    // The inward normal of a counter-clockwise edge points left.
    probes.push_back({0.5 * (a[0] + b[0]) - orientation * eps * dy / len,
                      0.5 * (a[1] + b[1]) + orientation * eps * dx / len});
  }
  return probes;
}

}  // namespace

double signed_area(const std::vector<Vec2>& poly) {
  double twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * twice;
}

bool point_in_polygon(const std::vector<Vec2>& poly, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    // Each edge is taken from its lower end, so two polygons that share it
    // (traversing it in opposite directions) compute the same crossing x to
    // the last bit, and exactly one of them claims a point on it.
    const bool up = poly[i][1] < poly[j][1] || (poly[i][1] == poly[j][1] && poly[i][0] < poly[j][0]);
    const Vec2& a = up ? poly[i] : poly[j];
    const Vec2& b = up ? poly[j] : poly[i];
    if ((a[1] > p[1]) != (b[1] > p[1])) {
      const double x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (p[0] < x) inside = !inside;
    }
  }
  return inside;
}

bool polygon_is_simple(const std::vector<Vec2>& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    if (a == b) return false;  // repeated vertex
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2& c = poly[j];
      const Vec2& d = poly[(j + 1) % n];
      if (!adjacent) {
        if (segments_touch(a, b, c, d)) return false;
        continue;
      }
      // Adjacent edges may not fold back onto each other.
      const Vec2& shared = j == i + 1 ? b : a;
      const Vec2& other_ab = j == i + 1 ? a : b;
      const Vec2& other_cd = j == i + 1 ? d : c;
      if (cross(shared, other_ab, other_cd) == 0 &&
          ((other_ab[0] - shared[0]) * (other_cd[0] - shared[0]) +
           (other_ab[1] - shared[1]) * (other_cd[1] - shared[1])) > 0)
        return false;
    }
  }
  return true;
}

bool polygons_overlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (segments_cross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
  // No edges cross: either one holds the other, they coincide, or they are
  // apart or only touch. Points just inside each edge tell these apart.
  for (const Vec2& p : inner_probes(a))
    if (point_in_polygon(b, p)) return true;
  for (const Vec2& p : inner_probes(b))
    if (point_in_polygon(a, p)) return true;
  return false;
}

}  // namespace sim
