// The laterally confined elastic column under incrementally applied gravity
// against its closed form (method notes, section 5):
//   sigma_yy = -rho g (H - Y), sigma_xx = sigma_zz = nu / (1 - nu) sigma_yy,
//   u_y(Y) = -rho g (H Y - Y^2 / 2) / M, so u_y(H) = -rho g H^2 / (2 M),
// with Y the height of a point before loading and M the constrained modulus.
// Used by the column's tests and by `landslide validate`.
#pragma once

#include <cstddef>

#include "sim/scene/scenario.hpp"
#include "sim/physics/world.hpp"

namespace sim {

struct ElasticColumnErrors {
  double h = 0;
  std::size_t points = 0;
  double syy = 0, sxx = 0, szz = 0;  // relative L2 errors (volume-weighted)
  double settlement = 0;             // relative L2 error of u_y
  double top_settlement = 0;         // measured u_y of the top row of points, m
};

// The errors of the world's points against the closed form of the scenario's
// column: one material (the first), one body filling the domain, gravity -y.
ElasticColumnErrors elastic_column_errors(const Scenario& scenario, const World& world);

// The closed-form settlement of the top, rho g H^2 / (2 M), m (positive down).
double elastic_column_top_settlement(const Scenario& scenario);

// Least-squares slope of log(error) against log(h): the observed order.
double observed_order(const double* h, const double* error, std::size_t n);

}  // namespace sim
