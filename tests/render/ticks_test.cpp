#include <gtest/gtest.h>

#include <cmath>

#include "render/error.hpp"
#include "render/ticks.hpp"

namespace render {
namespace {

TEST(Ticks, NiceStepsAreOneTwoFiveTimesPowersOfTen) {
  EXPECT_DOUBLE_EQ(nice_step(117, 10), 20.0);
  EXPECT_DOUBLE_EQ(nice_step(117, 12), 10.0);
  EXPECT_DOUBLE_EQ(nice_step(20, 4), 5.0);
  EXPECT_DOUBLE_EQ(nice_step(1, 5), 0.2);
  EXPECT_DOUBLE_EQ(nice_step(0.3, 3), 0.1);
  EXPECT_DOUBLE_EQ(nice_step(7e-4, 7), 1e-4);
  for (double span : {0.013, 0.7, 3.3, 42.0, 980.0, 1.2e5}) {
    for (int n = 2; n <= 12; ++n) {
      const double s = nice_step(span, n);
      const double m = s / std::pow(10.0, std::floor(std::log10(s) + 1e-12));
      EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9)
          << span << " " << n << " -> " << s;
      EXPECT_LE(span / s, n + 1e-9);
    }
  }
}

TEST(Ticks, ValuesAndLabelsCoverTheRange) {
  const Ticks t = nice_ticks(0, 117, 10);
  ASSERT_EQ(t.values.size(), 6u);
  EXPECT_EQ(t.labels.front(), "0");
  EXPECT_EQ(t.labels.back(), "100");

  const Ticks f = nice_ticks(-0.3, 0.3, 6);
  EXPECT_EQ(f.decimals, 1);
  ASSERT_EQ(f.labels.size(), 7u);
  EXPECT_EQ(f.labels[0], "-0.3");
  EXPECT_EQ(f.values[3], 0.0);  // exactly zero, not 5.55e-17
  EXPECT_EQ(f.labels[3], "0.0");
  EXPECT_EQ(f.labels[6], "0.3");
}

TEST(Ticks, FormatNeverPrintsNegativeZero) {
  EXPECT_EQ(format_tick(-0.0, 2), "0.00");
  EXPECT_EQ(format_tick(-0.0001, 1), "0.0");
  EXPECT_EQ(format_tick(-2.5, 1), "-2.5");
}

TEST(Ticks, BadRangeThrows) {
  EXPECT_THROW(nice_ticks(1, 1, 5), InvalidArgument);
  EXPECT_THROW(nice_ticks(0, INFINITY, 5), InvalidArgument);
}

}  // namespace
}  // namespace render
