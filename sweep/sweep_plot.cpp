// sweep-AXIS.png: runout against one axis, drawn as output/series_plot.cpp
// draws the time series (render/line_plot.hpp); sweep-exceedance.png is
// drawn by sweep_exceedance.cpp.
#include <limits>
#include <map>

#include "render/line_plot.hpp"
#include "render/png_io.hpp"
#include "sweep/sweep_results.hpp"

namespace sweep {

namespace {

using Json = nlohmann::json;



double number_or_nan(const Json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// The mean runout of the samples of one combination of the axes (the
// members results[first, first + samples)), over those that have one.
double mean_runout(const std::vector<MemberResult>& results, std::size_t first, int samples) {
  double sum = 0;
  int n = 0;
  for (std::size_t k = first; k < first + samples; ++k)
    if (results[k].runout_m.is_number()) sum += results[k].runout_m.get<double>(), ++n;
  return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

render::LinePlot axis_plot(const Sweep& s, const std::vector<MemberResult>& results,
                           std::size_t axis) {
  std::map<std::string, render::Curve> curves;  // by the other axes' values
  std::vector<std::string> order;
  const int samples = s.fields.samples;
  for (std::size_t first = 0; first < results.size(); first += samples) {
    const MemberResult& r = results[first];
    const std::string key = axes_label(s, r, axis);
    if (!curves.count(key)) order.push_back(key);
    render::Curve& c = curves[key];
    c.x.push_back(r.values[axis].get<double>());
    c.y.push_back(samples > 1 ? mean_runout(results, first, samples) : number_or_nan(r.runout_m));
  }
  render::LinePlot plot;
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < order.size(); ++k) {
    render::Curve c = curves[order[k]];
    c.colour = curve_colour(k);
    c.label = order.size() > 1 ? order[k] : "";
    xs.insert(xs.end(), c.x.begin(), c.x.end());
    ys.insert(ys.end(), c.y.begin(), c.y.end());
    plot.curves.push_back(c);
  }
  plot.x = render::axis_range(xs, 8);
  plot.y = render::axis_range(ys, 6);
  plot.x_label = s.axes[axis].path;
  plot.y_label = samples > 1 ? "mean runout of " + std::to_string(samples) + " samples [m]"
                             : "runout [m]";
  return plot;
}

}  // namespace

std::string axes_label(const Sweep& s, const MemberResult& r, std::size_t skip) {
  std::string label;
  for (std::size_t k = 0; k < s.axes.size(); ++k)
    if (k != skip) label += (label.empty() ? "" : ", ") + s.axes[k].path + " = " + r.values[k].dump();
  return label;
}

render::Rgba curve_colour(std::size_t k) {
  static const render::Rgba colours[] = {{31, 119, 180, 255}, {255, 127, 14, 255},
                                         {44, 160, 44, 255},  {214, 39, 40, 255},
                                         {148, 103, 189, 255}, {140, 86, 75, 255}};
  return colours[k % (sizeof colours / sizeof colours[0])];
}

namespace {

bool all_numbers(const Axis& a) {
  for (const Json& v : a.values)
    if (!v.is_number()) return false;
  return true;
}

}  // namespace

void write_plots(const Sweep& s, const std::vector<MemberResult>& results,
                 const std::filesystem::path& out) {
  render::Font font;
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    if (!all_numbers(s.axes[k])) continue;  // no x axis for strings
    render::Image img(960, 640);
    const render::LinePlot plot = axis_plot(s, results, k);
    render::draw_line_plot(img, font, plot, {0, 10, 960, 620}, render::y_axis_width(font, plot));
    render::write_png(img, (out / ("sweep-" + s.axes[k].path + ".png")).string());
  }
  if (!s.fields.fields.empty()) write_exceedance_plot(s, results, out);
}

}  // namespace sweep
