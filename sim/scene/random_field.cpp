#include "sim/scene/random_field.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sim {
namespace {

[[noreturn]] void bad(const std::string& name, double value, const std::string& allowed) {
  std::ostringstream os;
  os.precision(17);
  os << "random field: " << name << " = " << value << ": expected " << allowed;
  throw std::invalid_argument(os.str());
}

void require_positive(const std::string& name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) bad(name, value, "a finite number > 0");
}

// A uniform in (0, 1) from the top 53 bits; the half offset keeps 0 out of the
// logarithm of the polar method.
double uniform_open(std::mt19937_64& rng) {
  return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
}

// Lower Cholesky factor of the n by n matrix exp(-2 |i - j| h / theta).
Eigen::MatrixXd markov_factor(int n, double h, double theta, const std::string& axis) {
  Eigen::MatrixXd c(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) c(i, j) = std::exp(-2.0 * std::abs(i - j) * h / theta);
  Eigen::LLT<Eigen::MatrixXd> llt(c);
  // Only a spacing far below theta brings the matrix near singular (its
  // condition number is coth(h / theta)).
  if (llt.info() != Eigen::Success)
    bad("d" + axis, h, "a spacing that leaves the correlation matrix positive definite against theta_" + axis);
  return llt.matrixL();
}

double phi_density(double x) { return 0.39894228040143267794 * std::exp(-0.5 * x * x); }
double phi_lower(double x) { return 0.5 * std::erfc(-x * 0.70710678118654752440); }  // P(X <= x)
double phi_upper(double x) { return 0.5 * std::erfc(x * 0.70710678118654752440); }   // P(X > x)

struct Standardised {
  double mu, sigma, a, b;
};

Standardised standardise(const TruncatedNormal& d) {
  if (!std::isfinite(d.mean) || d.mean == 0.0)
    bad("mean", d.mean, "a finite nonzero number (the standard deviation is cov |mean|)");
  require_positive("cov", d.cov);
  if (!std::isfinite(d.lower)) bad("lower", d.lower, "a finite number");
  if (!(std::isfinite(d.upper) && d.upper > d.lower))
    bad("upper", d.upper, "a finite number > lower = " + std::to_string(d.lower));
  const double sigma = d.cov * std::abs(d.mean);
  return {d.mean, sigma, (d.lower - d.mean) / sigma, (d.upper - d.mean) / sigma};
}

// Probability of [a, b] under the standard normal, from the tail where it is accurate.
double mass(double a, double b) {
  return a > 0.0 ? phi_upper(a) - phi_upper(b) : phi_lower(b) - phi_lower(a);
}

// Solves Phi(y) = p (equivalently 1 - Phi(y) = q, used when p > 1/2 for its
// accuracy in the upper tail) for y in [a, b]: Newton's method, with a
// bisection step whenever Newton would leave the bracket.
double inverse_phi_in(double p, double q, double a, double b, double start) {
  double lo = a, hi = b, y = std::clamp(start, a, b);
  for (int it = 0; it < 200; ++it) {
    const double r = p <= 0.5 ? phi_lower(y) - p : q - phi_upper(y);
    if (r == 0.0) return y;
    (r < 0.0 ? lo : hi) = y;
    const double dens = phi_density(y);
    double next = dens > 0.0 ? y - r / dens : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - y) <= 1e-15 * std::max(1.0, std::abs(y)) || hi - lo <= 1e-15) return next;
    y = next;
  }
  return y;
}

}  // namespace

std::vector<double> standard_normals(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::vector<double> out;
  out.reserve(n + 1);
  while (out.size() < n) {
    double u, v, s;
    do {
      u = 2.0 * uniform_open(rng) - 1.0;
      v = 2.0 * uniform_open(rng) - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    out.push_back(u * f);
    out.push_back(v * f);
  }
  out.resize(n);
  return out;
}

GaussianFieldGenerator::GaussianFieldGenerator(const FieldLattice& lattice,
                                               const ScaleOfFluctuation& theta)
    : lattice_(lattice) {
  if (lattice.nx < 1) bad("nx", lattice.nx, "an integer >= 1");
  if (lattice.ny < 1) bad("ny", lattice.ny, "an integer >= 1");
  if (!std::isfinite(lattice.x0)) bad("x0", lattice.x0, "a finite number");
  if (!std::isfinite(lattice.y0)) bad("y0", lattice.y0, "a finite number");
  require_positive("dx", lattice.dx);
  require_positive("dy", lattice.dy);
  require_positive("theta_x", theta.theta_x);
  require_positive("theta_y", theta.theta_y);
  lx_ = markov_factor(lattice.nx, lattice.dx, theta.theta_x, "x");
  ly_ = markov_factor(lattice.ny, lattice.dy, theta.theta_y, "y");
}

std::vector<double> GaussianFieldGenerator::standard_field(std::uint64_t seed) const {
  const int nx = lattice_.nx, ny = lattice_.ny;
  std::vector<double> z = standard_normals(seed, static_cast<std::size_t>(nx) * ny);
  // Column-major, so entry (i, j) of Z and of the field is index i + nx j.
  const Eigen::Map<const Eigen::MatrixXd> zm(z.data(), nx, ny);
  const Eigen::MatrixXd g = lx_.triangularView<Eigen::Lower>() * zm * ly_.transpose();
  return std::vector<double>(g.data(), g.data() + g.size());
}

std::vector<double> to_lognormal(const std::vector<double>& g, const LogNormal& d) {
  require_positive("mean", d.mean);
  require_positive("cov", d.cov);
  const double var_ln = std::log1p(d.cov * d.cov);
  const double mu_ln = std::log(d.mean) - 0.5 * var_ln, sigma_ln = std::sqrt(var_ln);
  std::vector<double> out(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) out[k] = std::exp(mu_ln + sigma_ln * g[k]);
  return out;
}

std::vector<double> to_truncated_normal(const std::vector<double>& g, const TruncatedNormal& d) {
  const Standardised s = standardise(d);
  const double z = mass(s.a, s.b);
  if (!(z > 0.0)) bad("lower", d.lower, "bounds that hold some probability of the parent normal");
  const double pa = phi_lower(s.a), qb = phi_upper(s.b);
  std::vector<double> out(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) {
    // P(Y <= y) = Phi(g): p from below, q from above, each where it is accurate.
    const double p = pa + phi_lower(g[k]) * z, q = qb + phi_upper(g[k]) * z;
    const double y = inverse_phi_in(p, q, s.a, s.b, g[k]);
    out[k] = std::clamp(s.mu + s.sigma * y, d.lower, d.upper);
  }
  return out;
}

Moments truncated_normal_moments(const TruncatedNormal& d) {
  const Standardised s = standardise(d);
  const double z = mass(s.a, s.b);
  if (!(z > 0.0)) bad("lower", d.lower, "bounds that hold some probability of the parent normal");
  const double fa = phi_density(s.a), fb = phi_density(s.b);
  const double shift = (fa - fb) / z;
  const double var = 1.0 + (s.a * fa - s.b * fb) / z - shift * shift;
  return {s.mu + s.sigma * shift, s.sigma * std::sqrt(std::max(var, 0.0))};
}

double sample_nearest(const FieldLattice& lattice, const std::vector<double>& values, double x,
                      double y) {
  if (values.size() != static_cast<std::size_t>(lattice.nx) * lattice.ny)
    bad("values.size()", static_cast<double>(values.size()), "nx ny of the lattice");
  const double fi = (x - lattice.x0) / lattice.dx, fj = (y - lattice.y0) / lattice.dy;
  if (!(fi >= -0.5 && fi <= lattice.nx - 0.5))
    bad("x", x, "within half a spacing of the lattice [x0, x0 + (nx - 1) dx]");
  if (!(fj >= -0.5 && fj <= lattice.ny - 0.5))
    bad("y", y, "within half a spacing of the lattice [y0, y0 + (ny - 1) dy]");
  const int i = std::clamp(static_cast<int>(std::lround(fi)), 0, lattice.nx - 1);
  const int j = std::clamp(static_cast<int>(std::lround(fj)), 0, lattice.ny - 1);
  return values[static_cast<std::size_t>(i) + static_cast<std::size_t>(lattice.nx) * j];
}

FieldLattice field_lattice(const Scenario& s) {
  const double spacing = s.cell_size / s.points_per_cell;
  FieldLattice l;
  l.nx = static_cast<int>(std::lround(std::ceil((s.domain_max[0] - s.domain_min[0]) / spacing)));
  l.ny = static_cast<int>(std::lround(std::ceil((s.domain_max[1] - s.domain_min[1]) / spacing)));
  l.x0 = s.domain_min[0] + 0.5 * spacing;
  l.y0 = s.domain_min[1] + 0.5 * spacing;
  l.dx = l.dy = spacing;
  return l;
}

double field_draw_peak_bytes(const FieldLattice& lattice) {
  const double big = std::max(lattice.nx, lattice.ny), small = std::min(lattice.nx, lattice.ny);
  const double factors = big * big + small * small, nodes = double(lattice.nx) * lattice.ny;
  return sizeof(double) * std::max(3 * big * big + small * small, factors + 3 * nodes);
}

std::vector<double> field_at_points(const RandomFieldSpec& field, const Scenario& s,
                                    const Particles& points, int material) {
  const FieldLattice lattice = field_lattice(s);
  const GaussianFieldGenerator generator(lattice, {field.theta_x, field.theta_y});
  const std::vector<double> g = generator.standard_field(field.seed);
  const std::vector<double> values =
      field.distribution == RandomFieldSpec::Distribution::LogNormal
          ? to_lognormal(g, {field.mean, field.cov})
          : to_truncated_normal(g, {field.mean, field.cov, field.lower, field.upper});
  std::vector<double> out(points.size(), 0.0);
  for (std::size_t p = 0; p < points.size(); ++p)
    if (points.material[p] == material)
      out[p] = sample_nearest(lattice, values, points.x0[p], points.y0[p]);
  return out;
}

}  // namespace sim
