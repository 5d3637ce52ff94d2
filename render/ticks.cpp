#include "render/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "render/error.hpp"
#include "render/font.hpp"

namespace render {

double nice_step(double span, int max_ticks) {
  max_ticks = std::max(max_ticks, 1);
  const double raw = span / max_ticks;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    // Tolerance so 0.3 / 3 picks 0.1, not 0.2, despite rounding.
    if (m * mag >= raw * (1 - 1e-9)) return m * mag;
  }
  return 10 * mag;
}

std::string format_tick(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::clamp(decimals, 0, 12), v);
  std::string s(buf);
  // A value that rounds to zero prints as "0", never "-0" or "-0.00".
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

Ticks nice_ticks(double lo, double hi, int max_ticks) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
    std::ostringstream s;
    s << "tick range [" << lo << ", " << hi << "] is empty or not finite";
    throw InvalidArgument(s.str());
  }
  Ticks t;
  t.step = nice_step(hi - lo, max_ticks);
  t.decimals = std::max(0, -int(std::floor(std::log10(t.step) + 1e-9)));
  const double eps = 1e-9 * t.step;
  const long first = long(std::ceil((lo - eps) / t.step));
  const long last = long(std::floor((hi + eps) / t.step));
  for (long i = first; i <= last; ++i) {
    // Multiply rather than accumulate so 0.1 * 3 does not drift.
    double v = double(i) * t.step;
    if (std::abs(v) < eps) v = 0;
    t.values.push_back(v);
    t.labels.push_back(format_tick(v, t.decimals));
  }
  return t;
}

int tick_pixel(double p, int lo, int hi) {
  if (p < lo + 0.5) return lo - 1;
  if (p > hi - 0.5) return hi;
  return int(std::floor(p));
}

int widest_label(Font& font, const Ticks& t, int px) {
  int w = 0;
  for (const std::string& s : t.labels) w = std::max(w, font.text_width(s, px));
  return w;
}

}  // namespace render
