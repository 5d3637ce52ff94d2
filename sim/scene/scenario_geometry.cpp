#include "sim/scene/scenario_geometry.hpp"

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

// Segments cross at a point inside both, each passing more than `tol` beyond
// the other's line at both ends.
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double tol) {
  const double ca = cross(c, d, a), cb = cross(c, d, b), cc = cross(a, b, c), cd = cross(a, b, d);
  if (!(sign(ca) * sign(cb) < 0 && sign(cc) * sign(cd) < 0)) return false;
  if (tol <= 0) return true;
  // |cross| / length is the distance from the line.
  const double t2 = tol * tol;
  const double cd2 = (d[0] - c[0]) * (d[0] - c[0]) + (d[1] - c[1]) * (d[1] - c[1]);
  const double ab2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
  return ca * ca > t2 * cd2 && cb * cb > t2 * cd2 && cc * cc > t2 * ab2 && cd * cd > t2 * ab2;
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

struct Box {
  Vec2 lo, hi;
};

Box box_of(const std::vector<Vec2>& poly) {
  Box box{poly.front(), poly.front()};
  for (const Vec2& v : poly)
    for (int k = 0; k < 2; ++k) {
      box.lo[k] = std::min(box.lo[k], v[k]);
      box.hi[k] = std::max(box.hi[k], v[k]);
    }
  return box;
}

bool inside_box(const Box& box, const Vec2& p) {
  return box.lo[0] <= p[0] && p[0] <= box.hi[0] && box.lo[1] <= p[1] && p[1] <= box.hi[1];
}

// Edges of `poly` that reach into `box` (only they can cross what lies in it).
std::vector<std::size_t> edges_meeting(const std::vector<Vec2>& poly, const Box& box) {
  std::vector<std::size_t> edges;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    if (std::max(p[0], q[0]) >= box.lo[0] && std::min(p[0], q[0]) <= box.hi[0] &&
        std::max(p[1], q[1]) >= box.lo[1] && std::min(p[1], q[1]) <= box.hi[1])
      edges.push_back(i);
  }
  return edges;
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

std::optional<std::array<std::size_t, 2>> polygon_self_contact(const std::vector<Vec2>& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return std::array<std::size_t, 2>{0, 0};
  // Edges sorted by their left end: an edge is compared only with those whose
  // x range meets its own, so a long terrain profile costs about n log n.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  auto lo = [&](std::size_t e) { return std::min(poly[e][0], poly[(e + 1) % n][0]); };
  auto hi = [&](std::size_t e) { return std::max(poly[e][0], poly[(e + 1) % n][0]); };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return lo(x) < lo(y); });
  std::optional<std::array<std::size_t, 2>> found;
  auto note = [&](std::size_t i, std::size_t j) {
    const std::array<std::size_t, 2> pair{std::min(i, j), std::max(i, j)};
    if (!found || pair < *found) found = pair;  // the same answer whatever the sort did
  };
  // A repeated vertex (a zero-length edge) touches its neighbours too; name
  // it as what it is.
  for (std::size_t i = 0; i < n; ++i)
    if (poly[i] == poly[(i + 1) % n]) return std::array<std::size_t, 2>{i, i};
  for (std::size_t oi = 0; oi < n; ++oi) {
    const std::size_t i = order[oi];
    const double right = hi(i);
    for (std::size_t oj = oi + 1; oj < n && lo(order[oj]) <= right; ++oj) {
      const std::size_t j = order[oj];
      const std::size_t first = std::min(i, j), second = std::max(i, j);
      const Vec2& a = poly[first];
      const Vec2& b = poly[(first + 1) % n];
      const Vec2& c = poly[second];
      const Vec2& d = poly[(second + 1) % n];
      const bool adjacent = second == first + 1 || (first == 0 && second == n - 1);
      if (!adjacent) {
        if (segments_touch(a, b, c, d)) note(first, second);
        continue;
      }
      // Adjacent edges may not fold back onto each other.
      const bool forward = second == first + 1;
      const Vec2& shared = forward ? b : a;
      const Vec2& other_ab = forward ? a : b;
      const Vec2& other_cd = forward ? d : c;
      if (cross(shared, other_ab, other_cd) == 0 &&
          ((other_ab[0] - shared[0]) * (other_cd[0] - shared[0]) +
           (other_ab[1] - shared[1]) * (other_cd[1] - shared[1])) > 0)
        note(first, second);
    }
  }
  return found;
}

bool polygon_is_simple(const std::vector<Vec2>& poly) { return !polygon_self_contact(poly); }

bool polygons_overlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double tolerance) {
  if (a.size() < 3 || b.size() < 3) return false;
  const Box ba = box_of(a), bb = box_of(b);
  // Regions that share positive area have boxes that share positive area.
  if (!(ba.lo[0] < bb.hi[0] && bb.lo[0] < ba.hi[0] && ba.lo[1] < bb.hi[1] && bb.lo[1] < ba.hi[1]))
    return false;
  const std::vector<std::size_t> ea = edges_meeting(a, bb), eb = edges_meeting(b, ba);
  for (std::size_t i : ea)
    for (std::size_t j : eb)
      if (segments_cross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], tolerance))
        return true;
  // No edges cross: either one holds the other, they coincide, or they are
  // apart or only touch. Points just inside each edge tell these apart.
  for (const Vec2& p : inner_probes(a))
    if (inside_box(bb, p) && point_in_polygon(b, p)) return true;
  for (const Vec2& p : inner_probes(b))
    if (inside_box(ba, p) && point_in_polygon(a, p)) return true;
  return false;
}

}  // namespace sim
