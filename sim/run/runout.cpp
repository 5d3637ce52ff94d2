#include "sim/run/runout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/run/point_chunks.hpp"

namespace sim {

namespace {

// Bins per window of the profile.
constexpr int kBins = 8;

// A point's square: centre and half side, now or as seeded.
void square(const World& w, std::size_t p, bool initial, double& x, double& half) {
  const Particles& pts = w.points;
  x = initial ? pts.x0[p] : pts.x[p];
  const double rho = initial ? w.material_specs[pts.material[p]].density : pts.density[p];
  half = 0.5 * std::sqrt(pts.mass[p] / rho);
}

constexpr double kNone = std::numeric_limits<double>::max();

// The soil's extent along x, now or as seeded: [lo, hi] of its squares.
struct Extent {
  double lo = kNone, hi = -kNone;
};

// The soil's height as seeded, [low, high] of its squares, and its leftmost point.
struct Seeded {
  double low = kNone, high = -kNone, left = kNone;
};

// reduce_points over the soil's squares, now or as seeded: add(acc, p, x, a)
// takes point p's centre x and half side a into a chunk's `acc`.
template <class Acc, class Add, class Combine>
Acc reduce_soil_squares(const World& w, bool initial, const Acc& start, Add add, Combine combine) {
  return reduce_points(
      w.points.size(), start,
      [&](Acc& acc, std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          if (!is_soil(w, p)) continue;
          double x, a;
          square(w, p, initial, x, a);
          add(acc, p, x, a);
        }
      },
      combine);
}

}  // namespace

ThicknessProfile deposit_thickness(const World& w, bool initial, double window) {
  ThicknessProfile prof;
  prof.step = window / kBins;
  const Extent extent = reduce_soil_squares(
      w, initial, Extent{},
      [](Extent& e, std::size_t, double x, double a) {
        e.lo = std::min(e.lo, x - a);
        e.hi = std::max(e.hi, x + a);
      },
      [](Extent& total, const Extent& e) {
        total.lo = std::min(total.lo, e.lo);
        total.hi = std::max(total.hi, e.hi);
      });
  if (extent.lo > extent.hi) return prof;
  prof.x_begin = extent.lo - window;
  const auto bins =
      static_cast<std::size_t>(std::ceil((extent.hi + window - prof.x_begin) / prof.step));
  // Each chunk of points adds to bins of its own, summed in chunk order.
  const std::vector<double> area = reduce_soil_squares(
      w, initial, std::vector<double>(bins + 1, 0.0),
      [&](std::vector<double>& area, std::size_t, double x, double a) {
        const double per_length = 2.0 * a;  // the square's area (2a)^2 over its width 2a
        const double from = (x - a - prof.x_begin) / prof.step;
        const double to = (x + a - prof.x_begin) / prof.step;
        for (auto k = static_cast<std::size_t>(from);
             k <= static_cast<std::size_t>(to) && k < bins; ++k) {
          const double overlap = std::min(to, k + 1.0) - std::max(from, static_cast<double>(k));
          if (overlap > 0) area[k] += per_length * overlap * prof.step;
        }
      },
      [](std::vector<double>& total, const std::vector<double>& area) {
        for (std::size_t k = 0; k < total.size(); ++k) total[k] += area[k];
      });
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
  const Seeded s = reduce_soil_squares(
      w, true, Seeded{},
      [&](Seeded& seeded, std::size_t p, double x, double a) {
        seeded.low = std::min(seeded.low, w.points.y0[p] - a);
        seeded.high = std::max(seeded.high, w.points.y0[p] + a);
        seeded.left = std::min(seeded.left, x);
      },
      [](Seeded& total, const Seeded& s) {
        total.low = std::min(total.low, s.low);
        total.high = std::max(total.high, s.high);
        total.left = std::min(total.left, s.left);
      });
  if (s.low > s.high) return r;
  r.threshold = kToeThicknessFraction * (s.high - s.low);
  r.window = kToeWindowFraction * (s.high - s.low);
  r.initial_toe = toe_beyond(deposit_thickness(w, true, r.window), s.left, r.threshold);
  r.toe = toe_beyond(deposit_thickness(w, false, r.window), r.initial_toe, r.threshold);
  r.runout = r.toe - r.initial_toe;
  return r;
}

}  // namespace sim
