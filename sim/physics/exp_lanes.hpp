// exp of eight doubles at once, for the density update of Eq. (25),
// rho := rho exp(-tr d eps), which took one libm call per point (5 to 7 ns
// of a 66 ns step on one thread, perf on bench/phases, issue 17).
//
// The method is Tang's table-driven exponential (P. T. P. Tang, ACM TOMS
// 15(2), 1989, pp. 144-157): x = (k / N) ln 2 + r with N = 128 and
// |r| <= ln 2 / 256, so exp(x) = 2^(k div N) 2^((k mod N) / N) e^r, the middle
// factor from a table and e^r from a polynomial. The constants below (the two
// parts of ln 2 / N, the polynomial's coefficients, the rounding shift) and
// the order of every operation, fused or not, are those of the exp of
// Debian 12's glibc 2.36 (its x86-64 FMA variant, read off its machine code),
// so each lane is bit for bit what std::exp returns there: the step's results
// did not move (ExpLanes.* compare the two on millions of arguments). glibc
// picks that variant on processors with FMA and another, which rounds some
// arguments differently in the last bit, on those without; exp_lanes does the
// same arithmetic on every machine (std::fma is exact in software). Lanes
// with |x| < 2^-54 (0 among them) take 1 + x, as glibc's exp does; those
// with |x| >= 512 (infinities, NaN, overflow) take std::exp itself.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "sim/physics/gimp.hpp"

namespace sim {

// For k = 0..127: the bits of the double nearest (2^(k/128) - H_k) / H_k,
// then those of H_k, the double nearest 2^(k/128), less k << 45
// (sim/physics/exp_table.cpp, written by scripts/make_exp_table.py).
extern const std::uint64_t kExpTable[256];

namespace exp_detail {

typedef std::uint64_t Bits8 __attribute__((vector_size(64)));

// a * b + c rounded once, lane by lane (one vfmadd where the processor has it).
inline Lane8 fused(const Lane8& a, const Lane8& b, const Lane8& c) {
  Lane8 out;
  for (int l = 0; l < 8; ++l) out[l] = std::fma(a[l], b[l], c[l]);
  return out;
}

template <class To, class From>
To same_bits(const From& from) {
  static_assert(sizeof(To) == sizeof(From), "a reinterpretation keeps the size");
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

// Lanes of kExpTable: tail = entry k % N's first double, scale its second
// with k div N added to its exponent (2^(k/N)). Where the build has AVX-512,
// two gathers; lane by lane, each lane took the index out of its vector, two
// loads and an insertion back, and the stress phase, where the exponential
// is, took about 1 ns a point more on one thread (issue 17, thirty-third
// pass, bench/README.md). With AVX2 alone, four gathers of four lanes: on an
// AMD EPYC the stress phase went from 36.5/40.0 to 34.7/37.0 ns a point on
// the slope, one thread, least/median of 8 rounds (thirty-fifth pass). The
// same loads, so the same bits.
inline void table_lanes(const Bits8& k, Lane8& tail, Lane8& scale) {
  const Bits8 entry = 2 * (k % 128);
#if defined(__AVX512F__)
  const __m512i at = reinterpret_cast<__m512i>(entry);
  tail = reinterpret_cast<Lane8>(_mm512_i64gather_pd(at, kExpTable, 8));
  const Bits8 bits = reinterpret_cast<Bits8>(_mm512_i64gather_epi64(at, kExpTable + 1, 8));
#elif defined(__AVX2__)
  // Four gathers of four lanes, each half of the eight a gather.
  typedef std::uint64_t Bits4 __attribute__((vector_size(32)));
  const __m256i at[2] = {reinterpret_cast<__m256i>(Bits4{entry[0], entry[1], entry[2], entry[3]}),
                         reinterpret_cast<__m256i>(Bits4{entry[4], entry[5], entry[6], entry[7]})};
  const double* const table = reinterpret_cast<const double*>(kExpTable);
  const auto* const words = reinterpret_cast<const long long*>(kExpTable + 1);
  tail = join4(_mm256_i64gather_pd(table, at[0], 8), _mm256_i64gather_pd(table, at[1], 8));
  const Bits8 bits = reinterpret_cast<Bits8>(join4(
      reinterpret_cast<Lane4>(_mm256_i64gather_epi64(words, at[0], 8)),
      reinterpret_cast<Lane4>(_mm256_i64gather_epi64(words, at[1], 8))));
#else
  Bits8 bits;
  for (int l = 0; l < 8; ++l) {
    tail[l] = same_bits<double>(kExpTable[entry[l]]);
    bits[l] = kExpTable[entry[l] + 1];
  }
#endif
  scale = same_bits<Lane8>(bits + (k << 45));
}

}  // namespace exp_detail

inline Lane8 exp_lanes(const Lane8& x) {
  using exp_detail::Bits8;
  using exp_detail::fused;
  using exp_detail::same_bits;
  constexpr double inv_ln2_n = 0x1.71547652b82fep7;     // N / ln 2
  constexpr double neg_ln2_hi_n = -0x1.62e42fefa0000p-8;  // -(ln 2 / N), leading bits
  constexpr double neg_ln2_lo_n = -0x1.cf79abc9e3b3ap-47;  // and the rest
  constexpr double shift = 0x1.8p52;  // adding it rounds to an integer
  constexpr double c2 = 0x1.ffffffffffdbdp-2, c3 = 0x1.555555555543cp-3;
  constexpr double c4 = 0x1.55555cf172b91p-5, c5 = 0x1.1111167a4d017p-7;
  // Nearest integer k to x N / ln 2, in the low bits of z's mantissa.
  const Lane8 z = fused(x, Lane8{} + inv_ln2_n, Lane8{} + shift);
  const Bits8 k = same_bits<Bits8>(z);
  const Lane8 kd = z - shift;
  Lane8 r = fused(kd, Lane8{} + neg_ln2_hi_n, x);
  r = fused(kd, Lane8{} + neg_ln2_lo_n, r);  // x - k ln 2 / N
  Lane8 tail, scale;
  exp_detail::table_lanes(k, tail, scale);
  const Lane8 r2 = r * r;
  const Lane8 low = fused(r, Lane8{} + c3, Lane8{} + c2);
  const Lane8 high = fused(r, Lane8{} + c5, Lane8{} + c4);
  const Lane8 poly = fused(r2 * r2, high, fused(r2, low, tail + r));  // e^r - 1 and the tail
  Lane8 y = fused(scale, poly, scale);
  const Bits8 top = same_bits<Bits8>(x) >> 52 & 0x7ff;
  const Int8 outside = top - 0x3c9 > 0x3e;  // |x| < 2^-54 or |x| >= 512, or not finite
  if (every(outside == 0)) return y;  // one test for the eight lanes' eight branches
  // |x| < 2^-54: glibc's exp returns 1 + x there (rounded, 1 itself but for
  // the sign of the rounding), and so does this, without the call. Such
  // strain increments are common: soil at rest, or moving as a rigid body,
  // whose nodal velocities' gradients cancel to round-off, and the lanes'
  // calls of std::exp took 6.3 instructions a point-step of the step's 586
  // on the 66,787-point slope early in its gravity stage (callgrind,
  // bench/instructions.sh, issue 17, forty-third pass).
  const Int8 tiny = top < 0x3c9;
  y = tiny ? 1.0 + x : y;
  if (every((outside & ~tiny) == 0)) return y;
  for (int l = 0; l < 8; ++l)
    if (outside[l] && !tiny[l]) y[l] = std::exp(x[l]);
  return y;
}

}  // namespace sim
