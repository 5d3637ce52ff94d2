#include "render/colour_map.hpp"

#include <cmath>
#include <sstream>

#include "render/error.hpp"

namespace render {

namespace {

std::uint8_t to_byte(double v) {
  v = v < 0 ? 0 : (v > 1 ? 1 : v);
  return std::uint8_t(std::lround(v * 255.0));
}

struct Knot {
  double x, y;
};

// Piecewise-linear channel through the knots (x ascending, 0..1).
template <std::size_t N>
double channel(const Knot (&k)[N], double x) {
  for (std::size_t i = 1; i < N; ++i) {
    if (x <= k[i].x) {
      const double f = (x - k[i - 1].x) / (k[i].x - k[i - 1].x);
      return k[i - 1].y + f * (k[i].y - k[i - 1].y);
    }
  }
  return k[N - 1].y;
}

// matplotlib's "jet" segment data (the rainbow used in the paper's figures).
constexpr Knot kJetRed[] = {{0, 0}, {0.35, 0}, {0.66, 1}, {0.89, 1}, {1, 0.5}};
constexpr Knot kJetGreen[] = {{0, 0}, {0.125, 0}, {0.375, 1}, {0.64, 1}, {0.91, 0}, {1, 0}};
constexpr Knot kJetBlue[] = {{0, 0.5}, {0.11, 1}, {0.34, 1}, {0.65, 0}, {1, 0}};

// Tableau 10, matplotlib's "tab10": distinct hues for material ids.
constexpr std::uint8_t kTab10[10][3] = {
    {31, 119, 180}, {255, 127, 14}, {44, 160, 44},  {214, 39, 40},  {148, 103, 189},
    {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};

}  // namespace

ColourMap ColourMap::viridis() {
  ColourMap m;
  m.name_ = "viridis";
  for (int i = 0; i < 256; ++i) {
    const float* c = detail::kViridis[i];
    m.table_[i] = Rgba{to_byte(c[0]), to_byte(c[1]), to_byte(c[2]), 255};
  }
  return m;
}

ColourMap ColourMap::jet() {
  ColourMap m;
  m.name_ = "jet";
  for (int i = 0; i < 256; ++i) {
    const double x = i / 255.0;
    m.table_[i] = Rgba{to_byte(channel(kJetRed, x)), to_byte(channel(kJetGreen, x)),
                       to_byte(channel(kJetBlue, x)), 255};
  }
  return m;
}

ColourMap ColourMap::categorical() {
  ColourMap m;
  m.name_ = "categorical";
  m.categorical_ = true;
  for (int i = 0; i < 256; ++i) {
    const std::uint8_t* c = kTab10[i % 10];
    m.table_[i] = Rgba{c[0], c[1], c[2], 255};
  }
  return m;
}

std::vector<std::string> ColourMap::names() { return {"viridis", "jet", "categorical"}; }

ColourMap ColourMap::by_name(const std::string& name) {
  if (name == "viridis" || name.empty()) return viridis();
  if (name == "jet") return jet();
  if (name == "categorical" || name == "tab10") return categorical();
  throw InvalidArgument("unknown colour map '" + name +
                        "' (known: viridis, jet, categorical)");
}

Rgba ColourMap::at(double t) const {
  if (std::isnan(t)) return nan_colour();
  if (categorical_) return table_[0];
  const double s = t * 256.0;
  const int i = s <= 0 ? 0 : (s >= 255 ? 255 : int(s));
  return table_[i];
}

Rgba ColourMap::map(double value, double lo, double hi) const {
  if (std::isnan(value)) return nan_colour();
  if (categorical_) {
    // Clamp before the cast so huge ids cannot overflow.
    const double r = std::round(value < -1e9 ? -1e9 : (value > 1e9 ? 1e9 : value));
    long id = long(r) % 10;
    if (id < 0) id += 10;
    return table_[std::size_t(id)];
  }
  return at((value - lo) / (hi - lo));
}

void validate_range(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
    std::ostringstream s;
    s << "colour range [" << lo << ", " << hi << "] is invalid (need finite lo < hi)";
    throw InvalidArgument(s.str());
  }
}

}  // namespace render
