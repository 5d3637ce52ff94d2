// Spatially correlated random fields of soil strength (issue 16), set by a
// material-change stage (scenarios/README.md, "Random fields"). A stationary standard Gaussian field g with the separable
// Markov correlation of Fenton and Griffiths (2008, "Risk Assessment in
// Geotechnical Engineering", Wiley, Ch. 3):
//   rho(dx, dy) = exp(-2|dx|/theta_x - 2|dy|/theta_y),
// so theta is the scale of fluctuation (the integral of rho over all lags),
// not the e-folding length, which is theta/2. It is generated exactly on a
// regular lattice by covariance-matrix decomposition (Davis 1987, Math.
// Geology 19(2):91-98; Fenton and Griffiths 2008, Ch. 6): the separable
// covariance is Cy (x) Cx, whose Cholesky factor is Ly (x) Lx, so a field is
// Lx Z Ly^T with Z a matrix of independent standard normals. The marginal
// transforms to a log-normal or truncated normal value act point by point.
// docs/method.md, "Random fields", has the equations.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "sim/physics/particles.hpp"
#include "sim/scene/scenario.hpp"

namespace sim {

// A regular lattice of nx by ny nodes; node (i, j) sits at
// (x0 + i dx, y0 + j dy) and its value at index i + nx j.
struct FieldLattice {
  int nx = 0;
  int ny = 0;
  double x0 = 0.0;
  double y0 = 0.0;
  double dx = 0.0;
  double dy = 0.0;
};

// Scales of fluctuation (m) in x and y (the Fenton-Griffiths theta).
struct ScaleOfFluctuation {
  double theta_x = 0.0;
  double theta_y = 0.0;
};

// `n` independent standard normals fixed by `seed` alone: std::mt19937_64 (its
// output is defined exactly by the C++ standard) turned into uniforms with 53
// bits, then Marsaglia and Bray's (1964) polar method. Not
// std::normal_distribution: its algorithm is left to the library, so the same
// seed would give other fields under libstdc++, libc++ or MSVC.
std::vector<double> standard_normals(std::uint64_t seed, std::size_t n);

// Factors the two one-dimensional correlation matrices once; each field then
// costs two small matrix products.
class GaussianFieldGenerator {
 public:
  // Throws std::invalid_argument naming the value and what is allowed.
  GaussianFieldGenerator(const FieldLattice& lattice, const ScaleOfFluctuation& theta);

  // The standard Gaussian field (mean 0, variance 1) of `seed`.
  std::vector<double> standard_field(std::uint64_t seed) const;

  const FieldLattice& lattice() const { return lattice_; }

 private:
  FieldLattice lattice_;
  Eigen::MatrixXd lx_;  // lower Cholesky factor of Cx (nx by nx)
  Eigen::MatrixXd ly_;  // lower Cholesky factor of Cy (ny by ny)
};

// A log-normal value of mean `mean` (> 0) and coefficient of variation `cov`.
struct LogNormal {
  double mean = 0.0;
  double cov = 0.0;
};

// A normal of mean `mean` and standard deviation cov |mean| truncated to
// [lower, upper]. mean and cov are those of the parent normal: truncation
// moves the field's moments to truncated_normal_moments().
struct TruncatedNormal {
  double mean = 0.0;
  double cov = 0.0;
  double lower = 0.0;
  double upper = 0.0;
};

struct Moments {
  double mean = 0.0;
  double standard_deviation = 0.0;
};

// exp(mu_ln + sigma_ln g), sigma_ln^2 = ln(1 + cov^2), mu_ln = ln mean - sigma_ln^2 / 2.
std::vector<double> to_lognormal(const std::vector<double>& g, const LogNormal& d);

// F^-1(Phi(g)) with F the truncated normal's distribution function, so the
// values follow the truncated normal exactly and keep g's rank correlation.
std::vector<double> to_truncated_normal(const std::vector<double>& g, const TruncatedNormal& d);

// Mean and standard deviation of the truncated normal (Johnson, Kotz and
// Balakrishnan 1994, Continuous Univariate Distributions 1, Ch. 13).
Moments truncated_normal_moments(const TruncatedNormal& d);

// The value of the lattice node nearest to (x, y): nearest rather than
// bilinear because interpolation would lower the variance between nodes.
// Throws std::invalid_argument for a point more than half a spacing outside.
double sample_nearest(const FieldLattice& lattice, const std::vector<double>& values, double x,
                      double y);

// The lattice a scene's fields are drawn on: its nodes are the sub-cell
// centres where points are seeded (spacing cell_size / points_per_cell) over
// the whole domain, so each point starts on a node of its own.
FieldLattice field_lattice(const Scenario& s);

// The most memory drawing one field on `lattice` holds at once, bytes: the
// Cholesky of the larger axis (its correlation matrix, the factorisation's
// copy and the factor returned, with the other axis' factor: 3 n^2 + m^2
// doubles), or, drawing, both factors and three lattice-sized arrays (the
// normals, Eigen's product temporary and the field). Read off
// random_field.cpp; for a 601,148-point slope (the 66,787-point paper slope
// at cell 0.059 m, a 3933 x 678 lattice) it gives 375 MB, where the run took
// 365 MB more peak RSS than the same run without a field (issue 17,
// README.md "What a run will cost").
double field_draw_peak_bytes(const FieldLattice& lattice);

// The field's value for each point of `material`, at the lattice node
// nearest its initial position (x0, y0): the field moves with the soil.
// Entries of other points are 0. Throws std::invalid_argument (parameters the
// scene reader lets through are never refused).
std::vector<double> field_at_points(const RandomFieldSpec& field, const Scenario& s,
                                    const Particles& points, int material);

}  // namespace sim
