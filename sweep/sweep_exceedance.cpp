// sweep-exceedance.png: the Monte Carlo answer to "how far may this slope's
// slide go, and with what probability" (Random MPM, Wang, Hicks & Vardon
// 2016): P(runout > L) over the samples of each combination of the axes.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/line_plot.hpp"
#include "render/png_io.hpp"
#include "sweep/sweep_results.hpp"

namespace sweep {

namespace {

constexpr double kConfidence = 0.95;

render::Rgba lighter(render::Rgba c) {
  auto mix = [](unsigned char v) { return static_cast<unsigned char>((v + 2 * 255) / 3); };
  return {mix(c.r), mix(c.g), mix(c.b), 255};
}

void add_curves(render::LinePlot& plot, const Exceedance& e, render::Rgba colour,
                const std::string& label) {
  render::Curve mid{e.x, e.p, colour, label + (label.empty() ? "" : ": ") + "P(runout > L), " +
                                          std::to_string(e.n) + " samples"};
  render::Curve lo{e.x, e.p, lighter(colour), ""}, hi{e.x, e.p, lighter(colour), ""};
  for (std::size_t k = 0; k < e.p.size(); ++k) {
    lo.y[k] = std::max(0.0, e.p[k] - e.eps);
    hi.y[k] = std::min(1.0, e.p[k] + e.eps);
  }
  char eps[16];
  std::snprintf(eps, sizeof eps, "%.3f", e.eps);
  hi.label = "95 % band (Dvoretzky-Kiefer-Wolfowitz), +-" + std::string(eps);
  plot.curves.push_back(lo);
  plot.curves.push_back(hi);
  plot.curves.push_back(mid);
}

}  // namespace

Exceedance exceedance(std::vector<double> runouts, double confidence) {
  Exceedance e;
  runouts.erase(std::remove_if(runouts.begin(), runouts.end(),
                               [](double v) { return !std::isfinite(v); }),
                runouts.end());
  std::sort(runouts.begin(), runouts.end());
  e.n = static_cast<int>(runouts.size());
  if (e.n == 0) return e;
  e.eps = std::sqrt(std::log(2.0 / (1.0 - confidence)) / (2.0 * e.n));
  // P(R > L) is 1 below the smallest runout and drops by 1/n at each one.
  double p = 1.0;
  for (int k = 0; k < e.n; ++k) {
    e.x.push_back(runouts[k]);
    e.p.push_back(p);
    p = double(e.n - k - 1) / e.n;
    e.x.push_back(runouts[k]);
    e.p.push_back(p);
  }
  return e;
}

void write_exceedance_plot(const Sweep& s, const std::vector<MemberResult>& results,
                           const std::filesystem::path& out) {
  render::LinePlot plot;
  std::vector<double> xs;
  const int samples = s.fields.samples;
  for (std::size_t first = 0; first < results.size(); first += samples) {
    std::vector<double> runouts;
    for (std::size_t k = first; k < first + samples; ++k)
      if (results[k].runout_m.is_number()) runouts.push_back(results[k].runout_m.get<double>());
    const Exceedance e = exceedance(runouts, kConfidence);
    if (e.n == 0) continue;
    const std::size_t group = first / samples;
    add_curves(plot, e, curve_colour(group), axes_label(s, results[first], s.axes.size()));
    xs.insert(xs.end(), e.x.begin(), e.x.end());
  }
  plot.x = render::axis_range(xs, 8);
  // The staircase runs on to both ends of the axis: 1 left of the smallest
  // runout, 0 right of the largest.
  for (render::Curve& c : plot.curves) {
    c.x.insert(c.x.begin(), plot.x.lo);
    c.y.insert(c.y.begin(), c.y.front());
    c.x.push_back(plot.x.hi);
    c.y.push_back(c.y.back());
  }
  plot.y = {0, 1};
  plot.x_label = "runout L [m]";
  plot.y_label = "P(runout > L)";
  render::Font font;
  render::Image img(960, 640);
  render::draw_line_plot(img, font, plot, {0, 10, 960, 620}, render::y_axis_width(font, plot));
  render::write_png(img, (out / "sweep-exceedance.png").string());
}

}  // namespace sweep
