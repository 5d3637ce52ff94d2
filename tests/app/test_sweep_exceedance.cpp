// The exceedance curve of a Monte Carlo sweep: P(runout > L) of the samples as
// a staircase, and the Dvoretzky-Kiefer-Wolfowitz band around it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sweep/sweep_results.hpp"

namespace {

TEST(Exceedance, StaircaseFallsByOneOverNAtEachRunout) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const sweep::Exceedance e = sweep::exceedance({30, 10, nan, 20, 20}, 0.95);
  ASSERT_EQ(e.n, 4);  // the member without a runout is left out
  const std::vector<double> x = {10, 10, 20, 20, 20, 20, 30, 30};
  const std::vector<double> p = {1, 0.75, 0.75, 0.5, 0.5, 0.25, 0.25, 0};
  EXPECT_EQ(e.x, x);
  EXPECT_EQ(e.p, p);
}

TEST(Exceedance, BandIsTheDkwHalfWidth) {
  std::vector<double> runouts;
  for (int k = 0; k < 100; ++k) runouts.push_back(k);
  // sqrt(ln(2 / 0.05) / 200) = 0.135810: at 100 samples P is known to +-0.136.
  EXPECT_NEAR(sweep::exceedance(runouts, 0.95).eps, 0.135810, 1e-6);
  EXPECT_NEAR(sweep::exceedance({1}, 0.95).eps, 1.358102, 1e-6);
  EXPECT_EQ(sweep::exceedance({}, 0.95).n, 0);
}

// The band holds for any distribution: over 400 sweeps of 100 uniform
// runouts, the empirical curve leaves it in about 5 % of them or fewer.
TEST(Exceedance, BandCoversTheTrueCurveInNineteenSweepsOfTwenty) {
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // a 64-bit LCG (Knuth's MMIX constants), top 53 bits
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) * 0x1.0p-53;
  };
  int missed = 0;
  for (int sweep = 0; sweep < 400; ++sweep) {
    std::vector<double> runouts;
    for (int k = 0; k < 100; ++k) runouts.push_back(uniform());
    const sweep::Exceedance e = sweep::exceedance(runouts, 0.95);
    bool outside = false;
    for (std::size_t k = 0; k < e.x.size(); ++k)  // true P(R > x) = 1 - x
      outside |= std::abs(e.p[k] - (1 - e.x[k])) > e.eps;
    missed += outside;
  }
  EXPECT_LE(missed, 20 + 9) << missed << " of 400 outside (the band is at most 5 % wrong; 9 is "
                               "two binomial standard deviations)";
}

}  // namespace
