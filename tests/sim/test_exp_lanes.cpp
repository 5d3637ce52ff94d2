// exp_lanes (sim/physics/exp_lanes.hpp) must give std::exp's bits in every
// lane: the density update of Eq. (25) moved from one to the other without
// changing any result, and the regression files rest on that.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "sim/physics/exp_lanes.hpp"

namespace {

std::uint64_t bits_of(double x) { return sim::exp_detail::same_bits<std::uint64_t>(x); }

// glibc picks its exp by processor: the FMA variant, whose arithmetic
// exp_lanes repeats on every machine (std::fma is exact in software too),
// or, without FMA, one that rounds some arguments differently in the last
// bit. Only the first is the reference.
bool libm_exp_is_the_fma_variant() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("fma");
#else
  return false;  // another architecture's libm: not the variant exp_lanes repeats
#endif
}

// Counts the arguments whose lane differs from std::exp (NaN matches NaN),
// and prints the first few.
long count_differences(const std::vector<double>& xs) {
  long differ = 0;
  for (std::size_t i = 0; i + 8 <= xs.size(); i += 8) {
    sim::Lane8 x;
    for (int l = 0; l < 8; ++l) x[l] = xs[i + l];
    const sim::Lane8 y = sim::exp_lanes(x);
    for (int l = 0; l < 8; ++l) {
      const double want = std::exp(x[l]);
      const bool same = std::isnan(want) ? std::isnan(y[l]) : bits_of(y[l]) == bits_of(want);
      if (!same && ++differ <= 5)
        ADD_FAILURE() << "exp(" << x[l] << ") = " << want << " (bits " << std::hex
                      << bits_of(want) << "), exp_lanes gave bits " << bits_of(y[l]) << std::dec;
    }
  }
  return differ;
}

TEST(ExpLanes, SameBitsAsStdExpForStrainTraces) {
  if (!libm_exp_is_the_fma_variant())
    GTEST_SKIP() << "glibc's exp here is not its x86-64 FMA variant";
  // -tr d eps of a step: small numbers of both signs, over many decades.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-16, 0);
  std::vector<double> xs(4'000'000);
  for (double& x : xs) x = mantissa(rng) * std::pow(10.0, decade(rng));
  EXPECT_EQ(count_differences(xs), 0);
}

// |x| < 2^-54, which exp_lanes takes as 1 + x without calling std::exp:
// the strain increments of soil at rest, zeros among them, in groups mixed
// with ordinary arguments.
TEST(ExpLanes, SameBitsAsStdExpForTinyArguments) {
  if (!libm_exp_is_the_fma_variant())
    GTEST_SKIP() << "glibc's exp here is not its x86-64 FMA variant";
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> power(-1080, -50);
  std::vector<double> xs;
  for (int i = 0; i < 1'000'000; ++i) {
    const int kind = static_cast<int>(rng() % 8);
    xs.push_back(kind == 0   ? 0.0
                 : kind == 1 ? -0.0
                 : kind == 2 ? mantissa(rng) * 1e-3  // an ordinary lane beside tiny ones
                             : std::ldexp(mantissa(rng), power(rng)));
  }
  EXPECT_EQ(count_differences(xs), 0);
}

TEST(ExpLanes, SameBitsAsStdExpOverTheWholeRange) {
  if (!libm_exp_is_the_fma_variant())
    GTEST_SKIP() << "glibc's exp here is not its x86-64 FMA variant";
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> wide(-760.0, 760.0);
  std::vector<double> xs;
  for (int i = 0; i < 1'000'000; ++i) xs.push_back(wide(rng));
  for (int i = 0; i < 1'000'000; ++i) {  // any bit pattern: NaNs, infinities, subnormals
    xs.push_back(sim::exp_detail::same_bits<double>(std::uint64_t{rng()}));
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double edges[] = {0.0, -0.0, 0x1p-54, -0x1p-54, 0x1.fffffffffffffp-55, 0x1p-53, 511.99,
                          512.0, -512.0, 709.78, 709.79, -708.4, -745.2, -745.1, 1e-300,
                          std::numeric_limits<double>::denorm_min(), inf, -inf,
                          std::numeric_limits<double>::quiet_NaN(), 1.0, -1.0, 0.5 * std::log(2.0)};
  for (double e : edges) xs.push_back(e);
  while (xs.size() % 8 != 0) xs.push_back(0.0);
  EXPECT_EQ(count_differences(xs), 0);
}

}  // namespace
