#include "sim/run/runout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sim {

namespace {

// Bins per window of the profile.
constexpr int kBins = 8;

bool is_soil(const World& w, std::size_t p) { return w.materials[w.points.material[p]].plastic; }

// A point's square: centre and half side, now or as seeded.
void square(const World& w, std::size_t p, bool initial, double& x, double& half) {
  const Particles& pts = w.points;
  x = initial ? pts.x0[p] : pts.x[p];
  const double rho = initial ? w.material_specs[pts.material[p]].density : pts.density[p];
  half = 0.5 * std::sqrt(pts.mass[p] / rho);
}

}  // namespace

ThicknessProfile deposit_thickness(const World& w, const std::vector<char>& counted, bool initial,
                                   double window) {
  ThicknessProfile prof;
  prof.step = window / kBins;
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    if (!counted[p]) continue;
    double x, a;
    square(w, p, initial, x, a);
    lo = std::min(lo, x - a);
    hi = std::max(hi, x + a);
  }
  if (lo > hi) return prof;
  prof.x_begin = lo - window;
  const auto bins = static_cast<std::size_t>(std::ceil((hi + window - prof.x_begin) / prof.step));
  std::vector<double> area(bins + 1, 0.0);
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    if (!counted[p]) continue;
    double x, a;
    square(w, p, initial, x, a);
    const double per_length = 2.0 * a;  // the square's area (2a)^2 over its width 2a
    const double from = (x - a - prof.x_begin) / prof.step, to = (x + a - prof.x_begin) / prof.step;
    for (auto k = static_cast<std::size_t>(from); k <= static_cast<std::size_t>(to) && k < bins; ++k) {
      const double overlap = std::min(to, k + 1.0) - std::max(from, static_cast<double>(k));
      if (overlap > 0) area[k] += per_length * overlap * prof.step;
    }
  }
  // The window centred on each bin: kBins - 1 whole bins and two halves.
  prof.thickness.assign(bins, 0.0);
  const int half = kBins / 2;
  for (std::size_t k = 0; k < bins; ++k) {
    double sum = 0;
    for (int j = -half; j <= half; ++j) {
      const long b = static_cast<long>(k) + j;
      if (b < 0 || b >= static_cast<long>(bins)) continue;
      sum += (j == -half || j == half ? 0.5 : 1.0) * area[b];
    }
    prof.thickness[k] = sum / window;
  }
  return prof;
}

double toe_beyond(const ThicknessProfile& prof, double start, double threshold) {
  const std::size_t n = prof.thickness.size();
  if (n == 0) return start;
  std::size_t k = 0;
  while (k < n && prof.x(k) < start) ++k;
  for (const std::size_t first = k; k < n; ++k) {
    if (prof.thickness[k] >= threshold) continue;
    if (k == first) return std::max(start, prof.x(k) - prof.step);
    const double t = (prof.thickness[k - 1] - threshold) / (prof.thickness[k - 1] - prof.thickness[k]);
    return prof.x(k - 1) + t * prof.step;
  }
  return prof.x(n - 1);
}

Runout measure_runout(const World& w) {
  Runout r;
  std::vector<char> soil(w.points.size(), 0);
  double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
  double left = std::numeric_limits<double>::max();
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    if (!is_soil(w, p)) continue;
    soil[p] = 1;
    double x, a;
    square(w, p, true, x, a);
    low = std::min(low, w.points.y0[p] - a);
    high = std::max(high, w.points.y0[p] + a);
    left = std::min(left, x);
  }
  if (low > high) return r;
  r.threshold = kToeThicknessFraction * (high - low);
  r.window = kToeWindowFraction * (high - low);
  r.initial_toe = toe_beyond(deposit_thickness(w, soil, true, r.window), left, r.threshold);
  r.toe = toe_beyond(deposit_thickness(w, soil, false, r.window), r.initial_toe, r.threshold);
  r.runout = r.toe - r.initial_toe;
  return r;
}

}  // namespace sim
