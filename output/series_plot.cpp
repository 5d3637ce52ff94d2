#include "output/series_plot.hpp"

#include <algorithm>
#include <cmath>

#include "render/line_plot.hpp"

namespace app {

namespace {

constexpr render::Rgba kRunoutBlue{31, 119, 180, 255};
constexpr render::Rgba kTotalOrange{255, 127, 14, 255};
constexpr render::Rgba kMovingGreen{44, 160, 44, 255};
constexpr int kMinPlotHeight = 360;

std::vector<double> column(const std::vector<SeriesRow>& rows, SeriesColumn c, double scale) {
  std::vector<double> v;
  for (const SeriesRow& r : rows) v.push_back(r.at(c) / scale);
  return v;
}

// J/m, kJ/m or MJ/m, whichever keeps the tick labels short.
std::pair<double, std::string> energy_unit(const std::vector<SeriesRow>& rows) {
  double peak = 0;
  for (const SeriesRow& r : rows)
    for (const SeriesColumn c : {kKinetic, kMovingKinetic})
      if (std::isfinite(r.at(c))) peak = std::max(peak, std::fabs(r.at(c)));
  if (peak >= 1e6) return {1e6, "MJ/m"};
  if (peak >= 1e3) return {1e3, "kJ/m"};
  return {1, "J/m"};
}

// Where each stage's rows begin.
std::vector<render::XMark> stage_marks(const std::vector<SeriesRow>& rows) {
  std::vector<render::XMark> marks;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (k == 0 || rows[k].stage != rows[k - 1].stage) marks.push_back({rows[k].time, rows[k].stage});
  return marks;
}

}  // namespace

render::Image series_plot(render::Font& font, const std::vector<SeriesRow>& rows, int width,
                          int height, const std::string& title, std::optional<double> marker) {
  if (rows.empty()) throw SeriesError("a series plot needs at least one row");
  render::Image img(width, height);
  const int px = std::max(render::kMinPlotTextPx, height / 40);
  int top = px / 2;
  if (!title.empty())
    top = font.draw(img, title, px, width / 2, top, render::HAlign::Centre, render::VAlign::Top)
              .bottom();
  std::vector<double> time;
  for (const SeriesRow& r : rows) time.push_back(r.time);
  const auto [scale, unit] = energy_unit(rows);

  render::LinePlot upper;
  upper.curves.push_back({time, column(rows, kRunout, 1), kRunoutBlue, ""});
  upper.x = render::axis_range(time, 8);
  upper.y = render::axis_range(upper.curves[0].y, 6);
  upper.y_label = "runout [m]";
  upper.x_tick_labels = false;
  upper.marks = stage_marks(rows);
  upper.marker = marker;
  upper.text_px = px;

  render::LinePlot lower = upper;
  lower.curves = {{time, column(rows, kKinetic, scale), kTotalOrange, "total"},
                  {time, column(rows, kMovingKinetic, scale), kMovingGreen, "moving"}};
  std::vector<double> energies = lower.curves[0].y;
  energies.insert(energies.end(), lower.curves[1].y.begin(), lower.curves[1].y.end());
  lower.y = render::axis_range(energies, 6);
  lower.y_label = "kinetic energy [" + unit + "]";
  lower.x_label = "time since the run began [s]";
  lower.x_tick_labels = true;
  for (render::XMark& m : lower.marks) m.label.clear();  // named once, above

  const int left = std::max(render::y_axis_width(font, upper), render::y_axis_width(font, lower));
  const int split = top + (height - top) * 9 / 20;  // the lower plot holds the x labels
  render::draw_line_plot(img, font, upper, {0, top, width, split - top}, left);
  render::draw_line_plot(img, font, lower, {0, split, width, height - split}, left);
  return img;
}

int series_plot_width(int frame_height) { return std::max(frame_height, kMinPlotHeight) * 4 / 3; }

render::Image beside_series(render::Font& font, const render::Image& frame,
                            const std::vector<SeriesRow>& rows, double time) {
  const int height = std::max(frame.height(), kMinPlotHeight);
  const int width = series_plot_width(frame.height());
  render::Image out(frame.width() + width, height);
  out.blit(frame, 0, (height - frame.height()) / 2);
  out.blit(series_plot(font, rows, width, height, "", time), frame.width(), 0);
  return out;
}

double run_time_of(const std::vector<SeriesRow>& rows, const std::string& stage,
                   double stage_time) {
  for (const SeriesRow& r : rows)
    if (!stage.empty() && r.stage == stage) return r.time - r.at(kStageTime) + stage_time;
  return stage_time;
}

}  // namespace app
