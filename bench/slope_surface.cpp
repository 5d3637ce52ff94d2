#include "bench/slope_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bench {

SurfaceProfile soil_surface(const sim::Scenario& s, const sim::World& w, double bin) {
  SurfaceProfile p;
  p.x0 = s.domain_min[0];
  p.bin = bin;
  p.floor = s.domain_min[1];
  const int bins = static_cast<int>(std::ceil((s.domain_max[0] - s.domain_min[0]) / bin));
  p.top.assign(bins, std::nan(""));
  const sim::Particles& pts = w.points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!w.materials[pts.material[i]].plastic) continue;
    const int k = std::clamp(static_cast<int>((pts.x[i] - p.x0) / bin), 0, bins - 1);
    const double top = pts.y[i] + 0.5 * std::sqrt(pts.volume(i));
    if (std::isnan(p.top[k]) || top > p.top[k]) p.top[k] = top;
  }
  return p;
}

double surface_rms_difference(const SurfaceProfile& a, const SurfaceProfile& b) {
  if (a.top.size() != b.top.size() || a.x0 != b.x0 || a.bin != b.bin)
    throw std::invalid_argument("surface profiles over different bins");
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < a.top.size(); ++k) {
    if (std::isnan(a.top[k]) && std::isnan(b.top[k])) continue;
    const double ha = std::isnan(a.top[k]) ? a.floor : a.top[k];
    const double hb = std::isnan(b.top[k]) ? b.floor : b.top[k];
    sum += (ha - hb) * (ha - hb);
    ++n;
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

}  // namespace bench
