// Measures of the final state of the Bui et al. (2008) column, taken the
// same way on the experiment's digitised curves and on the simulation's
// points (validation/bui_experiment.hpp; tests/validation/README.md says why each is
// defined as it is).
#include "validation/bui_experiment.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>

#include "sim/scene/scenario.hpp"

namespace app {

namespace {

// The range a coordinate of the column's curves may take, metres: the scene
// is 0.6 m long and 0.12 m high; a value outside is a broken file.
constexpr double kLowest = -1.0, kHighest = 10.0;

[[noreturn]] void bad(const std::string& path, int line, const std::string& what) {
  throw sim::ScenarioError(path + ": line " + std::to_string(line) + ": " + what);
}

double number(const std::string& path, int line, const char* name, const std::string& text) {
  const std::string allowed = std::string("; expected ") + name + " as a number of metres in [" +
                              std::to_string(static_cast<int>(kLowest)) + ", " +
                              std::to_string(static_cast<int>(kHighest)) + "]";
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const char* rest = end;
  const bool whole = end != text.c_str() && std::all_of(rest, text.c_str() + text.size(),
                                                        [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
  if (!whole || errno == ERANGE || !std::isfinite(v))
    bad(path, line, name + std::string(" '") + text + "' is not a finite number" + allowed);
  if (v < kLowest || v > kHighest)
    bad(path, line, name + std::string(" ") + text + " is out of range" + allowed);
  return v;
}

// Half the side of a point's square, the painter's sqrt(V) / 2.
double half_side(const sim::Particles& p, std::size_t i) {
  return 0.5 * std::sqrt(p.volume(i));
}

}  // namespace

Curve read_curve(const std::string& path, std::size_t min_points) {
  std::ifstream in(path);
  if (!in)
    throw sim::ScenarioError(path + ": cannot read file: " + std::strerror(errno) +
                             "; expected a file of x,y points (tests/validation/README.md)");
  Curve c;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos || text[first] == '#') continue;
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
      bad(path, line, "'" + text + "' is not one pair x,y; expected two numbers separated by one comma");
    const double x = number(path, line, "x", text.substr(0, comma));
    const double y = number(path, line, "y", text.substr(comma + 1));
    if (!c.x.empty() && x < c.x.back()) {
      std::ostringstream msg;
      msg << "x " << x << " is less than the previous point's " << c.x.back()
          << "; expected x not decreasing along the file";
      bad(path, line, msg.str());
    }
    c.x.push_back(x);
    c.y.push_back(y);
  }
  if (c.x.size() < min_points)
    throw sim::ScenarioError(path + ": " + std::to_string(c.x.size()) + " points; expected at least " +
                             std::to_string(min_points));
  return c;
}

double curve_toe(const Curve& s, double min_height) {
  if (s.x.empty()) return std::nan("");
  if (s.y[0] < min_height) return s.x[0];
  for (std::size_t i = 1; i < s.x.size(); ++i) {
    if (s.y[i] >= min_height) continue;
    const double t = (s.y[i - 1] - min_height) / (s.y[i - 1] - s.y[i]);
    return s.x[i - 1] + t * (s.x[i] - s.x[i - 1]);
  }
  return s.x.back();
}

double surface_height(const sim::Particles& p, double x, double half_width) {
  double top = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::fabs(p.x[i] - x) <= half_width) top = std::max(top, p.y[i] + half_side(p, i));
  return top;
}

Marks unmoved_boundary(const sim::Particles& p, double spacing, double y_low, double y_high,
                       double moved) {
  // Row r holds the points with r*spacing <= y0 < (r+1)*spacing; per row, the
  // x0 of its first point that moved (inf: none moved).
  double top = 0;
  for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.y0[i]);
  const int rows = static_cast<int>(top / spacing) + 1;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> first_moved(rows, inf);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int r = std::clamp(static_cast<int>(p.y0[i] / spacing), 0, rows - 1);
    if (p.x[i] - p.x0[i] > moved) first_moved[r] = std::min(first_moved[r], p.x0[i]);
  }
  Marks m;
  for (int r = 0; r < rows; ++r) {
    const double y = (r + 0.5) * spacing;
    if (y < y_low || y > y_high || !std::isfinite(first_moved[r])) continue;
    m.x.push_back(first_moved[r] - 0.5 * spacing);
    m.y.push_back(y);
  }
  return m;
}

Marks curve_band(const Curve& c, double y_low, double y_high) {
  Marks m;
  for (std::size_t i = 0; i < c.x.size(); ++i)
    if (c.y[i] >= y_low && c.y[i] <= y_high) m.x.push_back(c.x[i]), m.y.push_back(c.y[i]);
  return m;
}

double line_angle_deg(const Marks& m) {
  const double n = static_cast<double>(m.x.size());
  if (n < 3) return std::nan("");
  double sy = 0, sx = 0, syy = 0, sxy = 0;
  for (std::size_t i = 0; i < m.x.size(); ++i)
    sy += m.y[i], sx += m.x[i], syy += m.y[i] * m.y[i], sxy += m.y[i] * m.x[i];
  const double b = (n * sxy - sy * sx) / (n * syy - sy * sy);
  return std::atan2(1.0, std::fabs(b)) * 180.0 / M_PI;
}

double curve_x_at_height(const Curve& c, double y) {
  std::vector<std::size_t> order(c.x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.y[a] < c.y[b]; });
  if (order.empty()) return std::nan("");
  if (y <= c.y[order.front()]) return c.x[order.front()];
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t i = order[k - 1], j = order[k];
    if (y > c.y[j]) continue;
    const double t = c.y[j] > c.y[i] ? (y - c.y[i]) / (c.y[j] - c.y[i]) : 0.0;
    return c.x[i] + t * (c.x[j] - c.x[i]);
  }
  return c.x[order.back()];
}

double rms_offset_x(const Marks& m, const Curve& c) {
  if (m.x.empty()) return std::nan("");
  double sum = 0;
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    const double d = m.x[i] - curve_x_at_height(c, m.y[i]);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(m.x.size()));
}

double rms_surface_difference(const sim::Particles& p, const Curve& surface, double half_width) {
  double sum = 0;
  for (std::size_t i = 0; i < surface.x.size(); ++i) {
    const double d = surface_height(p, surface.x[i], half_width) - surface.y[i];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(surface.x.size()));
}

}  // namespace app
