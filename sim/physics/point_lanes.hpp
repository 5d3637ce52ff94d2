// Eight points of a band as the lanes of vectors (lanes.hpp): their values
// read from the point arrays, and written back. The stress phase
// (point_update.cpp) and G2P (grid_to_points.cpp) take a band's points eight
// at a time in the band's order; lanes past a group's count repeat its last
// point and are never written.
#pragma once

#include <algorithm>
#include <cstring>

#include "sim/physics/lanes.hpp"

namespace sim {

// The eight slots of a group of count <= 8 points of `order` (a band's, in
// its order), the last repeated into the lanes past count. A whole group
// (nearly every one) is one copy: written as the loop alone, it was
// compiled to eight loads through clamped indices, and each index stored
// twice (issue 17, forty-fourth pass).
inline void group_of_eight(const int* order, int count, int q[8]) {
  if (count == 8) {
    std::memcpy(q, order, 8 * sizeof(int));
    return;
  }
  for (int l = 0; l < 8; ++l) q[l] = order[std::min(l, count - 1)];
}

// Whether eight points are stored one after another, as most groups of a
// band are while the points are stored in cell order (point_order.hpp): their
// arrays are then read and written as vectors instead of lane by lane.
inline bool stored_in_a_run(const int q[8], int count) {
  if (count < 8) return false;
  Int32x8 lanes;
  std::memcpy(&lanes, q, sizeof lanes);
  return every(lanes - q[0] == Int32x8{0, 1, 2, 3, 4, 5, 6, 7});
}

// The lanes of v (a Lane8 or Bytes8) as an array, for a loop that takes
// them a point at a time: a vector read at a lane that changes from point to
// point was compiled to a store of the whole vector to the stack at every
// point, and a load (issue 17, thirty-third pass: eight such stores a point
// in the stress phase).
template <class T, class V>
void put_lanes(T (&to)[8], const V& v) {
  static_assert(sizeof(V) == sizeof to, "eight lanes of T");
  std::memcpy(to, &v, sizeof to);
}

// The values of eight points in array `a`, one a lane (V: Lane8 of doubles,
// Bytes8 of bytes), and their store back, count lanes.
template <class V, class T>
V lanes_at(const T* a, const int q[8], bool run) {
  static_assert(sizeof(V) == 8 * sizeof(T), "eight lanes of T");
  V v;
  if (run) {
    std::memcpy(&v, a + q[0], sizeof v);
    return v;
  }
  for (int l = 0; l < 8; ++l) v[l] = a[q[l]];
  return v;
}
template <class T, class V>
void store_lanes(T* a, const int q[8], int count, bool run, const V& v) {
  static_assert(sizeof(V) == 8 * sizeof(T), "eight lanes of T");
  if (run) {
    std::memcpy(a + q[0], &v, sizeof v);
    return;
  }
  T lanes[8];
  put_lanes(lanes, v);
  for (int l = 0; l < count; ++l) a[q[l]] = lanes[l];
}

// Four quantities a, b, c, d of eight points, one point a lane, from the
// sums of the pairs (0, 1), (2, 3), (4, 5), (6, 7), each pair's as
// {a_0, a_1, b_0, b_1, c_0, c_1, d_0, d_1}: out = {a, b, c, d}.
inline void pairs_to_lanes(const Lane8 pairs[4], Lane8 out[4]) {
  const Lane8 ab01 = __builtin_shufflevector(pairs[0], pairs[1], 0, 1, 8, 9, 2, 3, 10, 11);
  const Lane8 ab23 = __builtin_shufflevector(pairs[2], pairs[3], 0, 1, 8, 9, 2, 3, 10, 11);
  const Lane8 cd01 = __builtin_shufflevector(pairs[0], pairs[1], 4, 5, 12, 13, 6, 7, 14, 15);
  const Lane8 cd23 = __builtin_shufflevector(pairs[2], pairs[3], 4, 5, 12, 13, 6, 7, 14, 15);
  out[0] = __builtin_shufflevector(ab01, ab23, 0, 1, 2, 3, 8, 9, 10, 11);
  out[1] = __builtin_shufflevector(ab01, ab23, 4, 5, 6, 7, 12, 13, 14, 15);
  out[2] = __builtin_shufflevector(cd01, cd23, 0, 1, 2, 3, 8, 9, 10, 11);
  out[3] = __builtin_shufflevector(cd01, cd23, 4, 5, 6, 7, 12, 13, 14, 15);
}

}  // namespace sim
