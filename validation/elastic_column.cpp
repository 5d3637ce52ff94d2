#include "validation/elastic_column.hpp"

#include <cmath>

namespace sim {

namespace {

double constrained_modulus(const MaterialSpec& m) {
  const double nu = m.poisson_ratio;
  return m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
}

}  // namespace

double elastic_column_top_settlement(const Scenario& s) {
  const MaterialSpec& m = s.materials[0];
  const double H = s.domain_max[1] - s.domain_min[1];
  return m.density * -s.gravity[1] * H * H / (2 * constrained_modulus(m));
}

ElasticColumnErrors elastic_column_errors(const Scenario& s, const World& w) {
  const MaterialSpec& m = s.materials[0];
  const double H = s.domain_max[1] - s.domain_min[1];
  const double rho = m.density, nu = m.poisson_ratio, g = -s.gravity[1];
  const double M = constrained_modulus(m);
  const double k0 = nu / (1 - nu);
  const Particles& p = w.points;
  double e_yy = 0, e_xx = 0, e_zz = 0, ref = 0, e_u = 0, ref_u = 0, top_y = -1, top_u = 0;
  int top_n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double Y = p.y0[i] - s.domain_min[1];
    const double V = p.volume(i);
    const double syy = -rho * g * (H - Y);
    e_yy += V * std::pow(p.syy[i] - syy, 2);
    e_xx += V * std::pow(p.sxx[i] - k0 * syy, 2);
    e_zz += V * std::pow(p.szz[i] - k0 * syy, 2);
    ref += V * syy * syy;
    const double u = -rho * g * (H * Y - 0.5 * Y * Y) / M;
    e_u += V * std::pow(p.y[i] - p.y0[i] - u, 2);
    ref_u += V * u * u;
    if (Y > top_y + 1e-9) top_y = Y, top_u = 0, top_n = 0;
    if (std::fabs(Y - top_y) < 1e-9) top_u += p.y[i] - p.y0[i], ++top_n;
  }
  ElasticColumnErrors e;
  e.h = s.cell_size;
  e.points = p.size();
  e.syy = std::sqrt(e_yy / ref);
  e.sxx = std::sqrt(e_xx / (k0 * k0 * ref));
  e.szz = std::sqrt(e_zz / (k0 * k0 * ref));
  e.settlement = std::sqrt(e_u / ref_u);
  e.top_settlement = top_n > 0 ? top_u / top_n : 0.0;
  return e;
}

double observed_order(const double* h, const double* error, std::size_t n) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = std::log(h[k]), y = std::log(error[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double k = static_cast<double>(n);
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

}  // namespace sim
