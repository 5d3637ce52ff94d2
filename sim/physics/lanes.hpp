// The step's vector types, a lane a point (or a stencil node), and the one
// fused multiply-add the step's formulas use.
#pragma once

#include <cstdint>
#include <type_traits>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace sim {

// Eight doubles, and eight matching integers, in vector registers (the
// vector extensions of g++ and clang; without AVX-512 only clang keeps a
// Lane8 in registers, scripts/setup.sh): the stencils and stresses of eight
// points are computed at once. The formulas that take them are templates on
// the value type, double or Lane8, written with selects (?:) only, so one
// text gives both and each lane of a Lane8 is bit for bit what the double
// version gives.
typedef double Lane8 __attribute__((vector_size(64)));
// Four doubles: a stencil row's three nodes and a spare lane (gimp.hpp), in
// one AVX register where the build has AVX, two SSE halves where not. Each
// lane is computed with plain IEEE arithmetic, so the results do not depend
// on the vector width.
typedef double Lane4 __attribute__((vector_size(32)));
typedef std::int64_t Int8 __attribute__((vector_size(64)));
// Eight 32-bit integers: eight points' base nodes and bin keys (locate.cpp).
// AVX2 converts doubles to them and multiplies them, and does neither for
// 64-bit integers.
typedef std::int32_t Int32x8 __attribute__((vector_size(32)));
// Eight bytes, one per point or node (materials, yield flags, wall holds),
// widened to an Int8 with __builtin_convertvector.
typedef std::uint8_t Bytes8 __attribute__((vector_size(8)));

// Two stencil rows side by side: the velocity gradient's gather takes two
// points at once in the halves of a Lane8, G2P's two nodal arrays, one
// vector operation where two Lane4 took two (issue 17, tenth pass: on one
// thread the column's G2P went from 12.4 to 9.6 ns per point, its stress
// phase from 26.6 to 24.9, bench/README.md). Lane by lane the operations are
// the same, so are the bits.
inline Lane8 join4(const Lane4& a, const Lane4& b) {
  return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7);
}
// x in every lane, a broadcast: Lane4{} + x is an addition the compiler
// must keep (0 + -0 is +0), one per use where the step took it so.
template <class V>
inline V splat(double x) {
  V v;
  for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l) v[l] = x;
  return v;
}
inline Lane4 splat4(double x) { return splat<Lane4>(x); }
inline Lane4 low4(const Lane8& v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }
inline Lane4 high4(const Lane8& v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }

// Whether a mask holds in every lane (one point: whether it holds). The
// lanes are ANDed pairwise in registers: a loop over them that returned at
// the first lane that failed was compiled to a store of the mask and eight
// loads and branches, and perf put 4 % of the stress phase on it; the
// phase's least time over 6 to 8 rounds did not move beyond the noise
// (issue 17, thirtieth pass).
// M is a mask of eight lanes of 64 or 32 bits.
template <class M>
inline bool every_of_eight(const M& m) {
  const M set = m != 0;  // all bits of a lane that holds
  const M four = set & __builtin_shufflevector(set, set, 4, 5, 6, 7, 0, 1, 2, 3);
  const M two = four & __builtin_shufflevector(four, four, 2, 3, 0, 1, 2, 3, 0, 1);
  return (two[0] & two[1]) != 0;
}
inline bool every(bool m) { return m; }
inline bool every(const Int8& m) { return every_of_eight(m); }
inline bool every(const Int32x8& m) { return every_of_eight(m); }

// a * b + c rounded once (IEEE 754 fusedMultiplyAdd), for a double or lane by
// lane: one FMA instruction where the build has one for the width, else
// __builtin_fma lane by lane (glibc's correctly rounded software fma on a
// processor without FMA), so the bits do not depend on which. The build never
// fuses a * b + c by itself (-ffp-contract=off, CMakeLists.txt: g++ would
// fuse where it chose, other bits on another processor or compiler); the
// step fuses where `fused` is written, in the same places in its one-point
// and eight-point forms. Written by lane alone, the vector forms were not
// made one instruction inside the step's phases: g++ 12 took each lane apart.
// `b` may be one double for every lane.
template <class V>
inline V fused_by_lane(const V& a, const V& b, const V& c) {
  V r;
  for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
    r[l] = __builtin_fma(a[l], b[l], c[l]);
  return r;
}
inline double fused(double a, double b, double c) { return __builtin_fma(a, b, c); }
#if defined(__FMA__)
inline Lane4 fused(const Lane4& a, const Lane4& b, const Lane4& c) {
  return _mm256_fmadd_pd(a, b, c);
}
#else
inline Lane4 fused(const Lane4& a, const Lane4& b, const Lane4& c) {
  return fused_by_lane(a, b, c);
}
#endif
#if defined(__AVX512F__)
inline Lane8 fused(const Lane8& a, const Lane8& b, const Lane8& c) {
  return _mm512_fmadd_pd(a, b, c);
}
#elif defined(__FMA__)
inline Lane8 fused(const Lane8& a, const Lane8& b, const Lane8& c) {  // two halves of four
  return join4(fused(low4(a), low4(b), low4(c)), fused(high4(a), high4(b), high4(c)));
}
#else
inline Lane8 fused(const Lane8& a, const Lane8& b, const Lane8& c) {
  return fused_by_lane(a, b, c);
}
#endif
// b in every lane: a broadcast (splat), where V{} + b was an addition kept
// at every call. The two differ only for b = -0, which V{} + b made +0: the
// product a * b is then +-0 and, added to c, can differ from the old sum only
// where c is -0 too.
template <class V, class = std::enable_if_t<!std::is_same_v<V, double>>>
inline V fused(const V& a, double b, const V& c) {
  return fused(a, splat<V>(b), c);
}

}  // namespace sim
