// The random-field generator of issue 16 against what was asked of it, over
// 400 fields of 64 by 32 nodes: the sample mean and standard deviation of the
// log-normal and truncated normal fields within 5 % of their requested (or,
// truncated, closed-form) values, the correlation of the Gaussian field at
// lags theta/2 and theta in x and y, seeds, and the refusal of bad parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/scene/random_field.hpp"

namespace {

constexpr int kFields = 400;
const sim::FieldLattice kLattice{64, 32, 0.0, 0.0, 0.5, 0.5};  // 32 m by 16 m
const sim::ScaleOfFluctuation kTheta{4.0, 2.0};                // 8 by 4 spacings

// All kFields standard Gaussian fields, one after another (seeds 1..kFields).
const std::vector<std::vector<double>>& gaussian_fields() {
  static const std::vector<std::vector<double>> fields = [] {
    const sim::GaussianFieldGenerator gen(kLattice, kTheta);
    std::vector<std::vector<double>> f;
    for (int s = 1; s <= kFields; ++s) f.push_back(gen.standard_field(static_cast<std::uint64_t>(s)));
    return f;
  }();
  return fields;
}

sim::Moments sample_moments(const std::vector<std::vector<double>>& fields) {
  double sum = 0.0, sum2 = 0.0, n = 0.0;
  for (const auto& f : fields)
    for (double v : f) sum += v, sum2 += v * v, n += 1.0;
  const double mean = sum / n;
  return {mean, std::sqrt((sum2 - n * mean * mean) / (n - 1.0))};
}

// Ensemble correlation at a lag of (li, lj) nodes about the field's known
// mean: subtracting each field's own mean would bias it low by the variance of
// that mean (about 0.03 here).
double correlation(const std::vector<std::vector<double>>& fields, int li, int lj, double mean) {
  double cross = 0.0, square = 0.0, pairs = 0.0, points = 0.0;
  const int nx = kLattice.nx, ny = kLattice.ny;
  for (const auto& f : fields) {
    for (double v : f) square += (v - mean) * (v - mean), points += 1.0;
    for (int j = 0; j + lj < ny; ++j)
      for (int i = 0; i + li < nx; ++i) {
        cross += (f[i + nx * j] - mean) * (f[i + li + nx * (j + lj)] - mean);
        pairs += 1.0;
      }
  }
  return (cross / pairs) / (square / points);
}

std::vector<std::vector<double>> transformed(const sim::LogNormal& d) {
  std::vector<std::vector<double>> out;
  for (const auto& g : gaussian_fields()) out.push_back(sim::to_lognormal(g, d));
  return out;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RandomField, GaussianFieldHasUnitVariance) {
  const sim::Moments m = sample_moments(gaussian_fields());
  std::printf("gaussian: mean %.4f sd %.4f\n", m.mean, m.standard_deviation);
  EXPECT_NEAR(m.mean, 0.0, 0.05);
  EXPECT_NEAR(m.standard_deviation, 1.0, 0.05);
}

// Within 5 % of rho, relative: the stricter reading at rho = e^-2 = 0.135
// (absolute 0.05 would be 37 % there). It fails for theta taken as the
// e-folding length (e^-1 for e^-2), the commonest mix-up of conventions.
TEST(RandomField, CorrelationFollowsTheMarkovFunction) {
  const auto& f = gaussian_fields();
  struct Lag {
    int li, lj;
    double distance, theta;
  };
  const Lag lags[] = {{4, 0, 2.0, kTheta.theta_x}, {8, 0, 4.0, kTheta.theta_x},
                      {0, 2, 1.0, kTheta.theta_y}, {0, 4, 2.0, kTheta.theta_y}};
  for (const Lag& lag : lags) {
    const double expected = std::exp(-2.0 * lag.distance / lag.theta);
    const double measured = correlation(f, lag.li, lag.lj, 0.0);
    std::printf("lag (%d, %d) nodes: rho %.4f, expected %.4f\n", lag.li, lag.lj, measured, expected);
    EXPECT_NEAR(measured, expected, 0.05 * expected) << "lag " << lag.li << ", " << lag.lj;
  }
  // Separable: a diagonal lag multiplies the two.
  const double diagonal = correlation(f, 4, 2, 0.0);
  std::printf("lag (4, 2) nodes: rho %.4f, expected %.4f\n", diagonal, std::exp(-2.0));
  EXPECT_NEAR(diagonal, std::exp(-2.0), 0.05 * std::exp(-2.0));
}

TEST(RandomField, LogNormalMomentsAreTheRequestedOnes) {
  // COV 0.5, so that dropping the -sigma_ln^2 / 2 of mu_ln (+11.8 % on the
  // mean) cannot hide inside 5 %, as it would at COV 0.3 (+4.4 %).
  const sim::LogNormal cohesion{10e3, 0.5};  // Pa
  const auto fields = transformed(cohesion);
  const sim::Moments m = sample_moments(fields);
  std::printf("lognormal: mean %.1f (10000) sd %.1f (5000)\n", m.mean, m.standard_deviation);
  EXPECT_NEAR(m.mean, cohesion.mean, 0.05 * cohesion.mean);
  EXPECT_NEAR(m.standard_deviation, cohesion.cov * cohesion.mean, 0.05 * cohesion.cov * cohesion.mean);
  // Its correlation at lag theta_x / 2 is the Gaussian's e^-1 seen through exp.
  const double s2 = std::log1p(cohesion.cov * cohesion.cov);
  const double expected = std::expm1(s2 * std::exp(-1.0)) / std::expm1(s2);
  const double measured = correlation(fields, 4, 0, cohesion.mean);
  std::printf("lognormal: rho at theta_x / 2 %.4f (%.4f)\n", measured, expected);
  EXPECT_NEAR(measured, expected, 0.05 * expected);
}

TEST(RandomField, TruncatedNormalStaysInItsBoundsWithItsMoments) {
  const sim::TruncatedNormal phi{30.0, 0.2, 22.0, 36.0};  // degrees; sd 6, asymmetric bounds
  const sim::Moments expected = sim::truncated_normal_moments(phi);
  // The truncation must have moved them, or the test would not see it.
  ASSERT_GT(std::abs(expected.mean - phi.mean), 0.5);
  ASSERT_LT(expected.standard_deviation, 0.8 * phi.cov * phi.mean);
  std::vector<std::vector<double>> fields;
  double lo = 1e300, hi = -1e300;
  for (const auto& g : gaussian_fields()) {
    fields.push_back(sim::to_truncated_normal(g, phi));
    for (double v : fields.back()) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  const sim::Moments m = sample_moments(fields);
  std::printf("truncated: mean %.3f (%.3f) sd %.3f (%.3f), range [%.3f, %.3f]\n", m.mean,
              expected.mean, m.standard_deviation, expected.standard_deviation, lo, hi);
  EXPECT_GE(lo, phi.lower);
  EXPECT_LE(hi, phi.upper);
  EXPECT_NEAR(m.mean, expected.mean, 0.05 * expected.mean);
  EXPECT_NEAR(m.standard_deviation, expected.standard_deviation, 0.05 * expected.standard_deviation);
}

TEST(RandomField, TruncatedNormalMapIsTheInverseDistribution) {
  // Untruncated in effect (bounds at +-12 sigma): the map is the identity.
  const sim::TruncatedNormal wide{1.0, 1.0, -11.0, 13.0};
  const std::vector<double> g{-3.0, -0.7, 0.0, 0.4, 2.5, 5.0};
  const std::vector<double> y = sim::to_truncated_normal(g, wide);
  for (std::size_t k = 0; k < g.size(); ++k) EXPECT_NEAR(y[k], 1.0 + g[k], 1e-9) << g[k];
}

TEST(RandomField, SameSeedSameFieldOtherSeedOtherField) {
  const sim::GaussianFieldGenerator a(kLattice, kTheta), b(kLattice, kTheta);
  const std::vector<double> f1 = a.standard_field(42), f2 = b.standard_field(42);
  EXPECT_EQ(f1, f2);  // bit-identical
  const std::vector<double> f3 = a.standard_field(43);
  int equal = 0;
  for (std::size_t k = 0; k < f1.size(); ++k) equal += f1[k] == f3[k];
  EXPECT_EQ(equal, 0);
}

TEST(RandomField, NearestNodeSampling) {
  const std::vector<double>& f = gaussian_fields().front();
  const double dx = kLattice.dx, dy = kLattice.dy;
  EXPECT_EQ(sim::sample_nearest(kLattice, f, 3 * dx, 5 * dy), f[3 + 64 * 5]);
  EXPECT_EQ(sim::sample_nearest(kLattice, f, 3.4 * dx, 4.6 * dy), f[3 + 64 * 5]);
  EXPECT_EQ(sim::sample_nearest(kLattice, f, -0.4 * dx, 31.4 * dy), f[0 + 64 * 31]);
  const std::string e = error_of([&] { sim::sample_nearest(kLattice, f, 64 * dx, 0.0); });
  EXPECT_NE(e.find("x = 32"), std::string::npos) << e;
}

TEST(RandomField, BadParametersAreRefusedByName) {
  const auto expect_error = [](const std::function<void()>& f, const std::string& text) {
    const std::string e = error_of(f);
    EXPECT_NE(e.find(text), std::string::npos) << "got: '" << e << "', wanted: " << text;
  };
  const std::vector<double> g{0.0};
  expect_error([] { sim::GaussianFieldGenerator(kLattice, {0.0, 1.0}); }, "theta_x = 0: expected a finite number > 0");
  expect_error([] { sim::GaussianFieldGenerator(kLattice, {1.0, -2.0}); }, "theta_y = -2: expected");
  expect_error([] { sim::GaussianFieldGenerator({0, 4, 0, 0, 1, 1}, kTheta); }, "nx = 0: expected an integer >= 1");
  expect_error([] { sim::GaussianFieldGenerator({4, 4, 0, 0, 1, 0}, kTheta); }, "dy = 0: expected");
  expect_error([&] { sim::to_lognormal(g, {10.0, 0.0}); }, "cov = 0: expected a finite number > 0");
  expect_error([&] { sim::to_lognormal(g, {10.0, -0.1}); }, "cov = -0.1");
  expect_error([&] { sim::to_lognormal(g, {-5.0, 0.2}); }, "mean = -5: expected a finite number > 0");
  expect_error([&] { sim::to_truncated_normal(g, {30.0, 0.2, 40.0, 20.0}); }, "upper = 20: expected a finite number > lower = 40");
  expect_error([&] { sim::to_truncated_normal(g, {30.0, 0.0, 20.0, 40.0}); }, "cov = 0");
  expect_error([&] { sim::truncated_normal_moments({30.0, 0.01, 90.0, 100.0}); }, "bounds that hold some probability");
}

}  // namespace
