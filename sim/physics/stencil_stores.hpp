// How locate stores eight points' stencils (locate.cpp): a transposition in
// registers, then each point's 56 bytes as one vector, or, in a scene too
// big for the cache, the block's seven whole cache lines with streaming
// stores (world.hpp, kMemoryBoundFrom).
#pragma once

#include <cstring>

#include "sim/physics/gimp.hpp"
#include "sim/physics/lanes.hpp"

namespace sim {

// Points [0, count) of a block, point[l] holding point l's seven words in
// lanes 0-6, each stored from its register with a store of seven lanes where
// the build has AVX-512. The lanes are taken by a constant index: copied by
// a loop to count, the eight vectors went to the stack first and then each
// point's 56 bytes were loaded and stored again as two overlapping halves
// (issue 17, thirty-third pass, objdump of locate).
//
// With AVX alone, as three stores of 4, 2 and 1 lanes from the register's
// halves: a copy by memcpy went through the stack the same way.
inline void store_points(StencilWeights* out, int count, const Lane8 point[8]) {
  for (int l = 0; l < 8; ++l) {
    if (l >= count) return;
    double* const to = reinterpret_cast<double*>(&out[l]);
#if defined(__AVX512F__)
    _mm512_mask_storeu_pd(to, 0x7f, point[l]);
#elif defined(__AVX__)
    const __m256d high = high4(point[l]);
    _mm256_storeu_pd(to, low4(point[l]));
    _mm_storeu_pd(to + 4, _mm256_castpd256_pd128(high));
    _mm_store_sd(to + 6, _mm256_extractf128_pd(high, 1));
#else
    std::memcpy(to, &point[l], sizeof(StencilWeights));
#endif
  }
}

// A whole 64-byte line, 64-byte aligned, written by a streaming store (two
// of 32 bytes with AVX alone).
inline void stream_line(double* line, const Lane8& v) {
#if defined(__AVX512F__)
  _mm512_stream_pd(line, v);
#elif defined(__AVX__)
  _mm256_stream_pd(line, low4(v));
  _mm256_stream_pd(line + 4, high4(v));
#else
  std::memcpy(line, &v, sizeof v);
#endif
}

// Eight points' stencils, point[l] holding point l's seven words in lanes
// 0-6, written as the block's seven whole cache lines (8 x 56 B = 7 x 64 B)
// with streaming stores, which write a line without first reading it.
inline void stream_block(StencilWeights* out, const Lane8 point[8]) {
  double* const line = reinterpret_cast<double*>(out);
  // Line k holds words 8k..8k+7 of the block: the tail of point k from its
  // word k, then the head of point k + 1.
  stream_line(line + 0, __builtin_shufflevector(point[0], point[1], 0, 1, 2, 3, 4, 5, 6, 8));
  stream_line(line + 8, __builtin_shufflevector(point[1], point[2], 1, 2, 3, 4, 5, 6, 8, 9));
  stream_line(line + 16, __builtin_shufflevector(point[2], point[3], 2, 3, 4, 5, 6, 8, 9, 10));
  stream_line(line + 24, __builtin_shufflevector(point[3], point[4], 3, 4, 5, 6, 8, 9, 10, 11));
  stream_line(line + 32, __builtin_shufflevector(point[4], point[5], 4, 5, 6, 8, 9, 10, 11, 12));
  stream_line(line + 40, __builtin_shufflevector(point[5], point[6], 5, 6, 8, 9, 10, 11, 12, 13));
  stream_line(line + 48, __builtin_shufflevector(point[6], point[7], 6, 8, 9, 10, 11, 12, 13, 14));
}

// Eight points' stencils stored, lanes [0, count) of the six weight lanes
// (wx then wy) and the base nodes: a transposition in registers makes each
// point's 56 bytes one vector, stored at once, where going through a buffer
// on the stack cost six loads and stores a point.
inline void store_stencils(StencilWeights* out, int count, const Lane8 w[6],
                           const Int32x8& base_i, const Int32x8& base_j, bool stream) {
  static_assert(sizeof(StencilWeights) == 7 * sizeof(double), "six weights, two ints");
  // The base nodes as StencilWeights lays them out: base_i in the low half
  // of the eighth word, base_j in the high half.
  const Lane8 ij = reinterpret_cast<Lane8>(__builtin_shufflevector(
      base_i, base_j, 0, 8, 1, 9, 2, 10, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15));
  const Lane8 a[8] = {w[0], w[1], w[2], w[3], w[4], w[5], ij, Lane8{}};
  Lane8 t[8], u[8], point[8];
  for (int k = 0; k < 4; ++k) {
    t[2 * k] = __builtin_shufflevector(a[2 * k], a[2 * k + 1], 0, 8, 2, 10, 4, 12, 6, 14);
    t[2 * k + 1] = __builtin_shufflevector(a[2 * k], a[2 * k + 1], 1, 9, 3, 11, 5, 13, 7, 15);
  }
  for (int k = 0; k < 2; ++k)
    for (int odd = 0; odd < 2; ++odd) {
      const Lane8 &lo = t[4 * k + odd], &hi = t[4 * k + 2 + odd];
      u[4 * k + 2 * odd] = __builtin_shufflevector(lo, hi, 0, 1, 8, 9, 4, 5, 12, 13);
      u[4 * k + 2 * odd + 1] = __builtin_shufflevector(lo, hi, 2, 3, 10, 11, 6, 7, 14, 15);
    }
  // u[m] (m = 2 * odd + pair) holds fields 0-3 of points {m', m' + 4}, fields
  // 4-7 in u[m + 4], where m' = odd + 2 * pair.
  for (int m = 0; m < 4; ++m) {
    const int l = (m >> 1) + 2 * (m & 1);
    point[l] = __builtin_shufflevector(u[m], u[m + 4], 0, 1, 2, 3, 8, 9, 10, 11);
    point[l + 4] = __builtin_shufflevector(u[m], u[m + 4], 4, 5, 6, 7, 12, 13, 14, 15);
  }
  if (stream && count == 8)
    stream_block(out, point);
  else
    store_points(out, count, point);
}

}  // namespace sim
