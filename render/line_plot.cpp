#include "render/line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "render/error.hpp"
#include "render/ticks.hpp"

namespace render {

namespace {

constexpr Rgba kInk{30, 30, 30, 255};
constexpr Rgba kGrid{228, 228, 228, 255};
constexpr Rgba kMarkGrey{120, 120, 120, 255};
constexpr Rgba kMarkerRed{214, 39, 40, 255};
constexpr int kMaxTicks = 8;

// Sizes that follow the text: one line of text, the gap between things, the
// length of a tick.
struct Metrics {
  int line = 0, gap = 0, tick = 0;
};

Metrics metrics(Font& font, int px) { return {font.line_height(px), std::max(2, px / 3), std::max(3, px / 3)}; }

void check(const LinePlot& p) {
  std::ostringstream why;
  if (p.text_px < kMinPlotTextPx)
    why << "plot text of " << p.text_px << " px: at least " << kMinPlotTextPx << " px";
  else if (!(p.x.lo < p.x.hi) || !(p.y.lo < p.y.hi) || !std::isfinite(p.x.hi - p.x.lo) ||
           !std::isfinite(p.y.hi - p.y.lo))
    why << "plot range x [" << p.x.lo << ", " << p.x.hi << "], y [" << p.y.lo << ", " << p.y.hi
        << "]: expected lo < hi, finite";
  if (!why.str().empty()) throw InvalidArgument(why.str());
}

// As many ticks as fit with about 2.5 lines of text between them.
int ticks_for(int pixels, int spacing) { return std::clamp(pixels / std::max(1, spacing), 2, kMaxTicks); }

void dashed_column(Image& img, const Rect& area, int col, Rgba colour) {
  if (col < area.x || col >= area.right()) return;
  for (int y = area.y; y < area.bottom(); ++y)
    if ((y - area.y) / 4 % 2 == 0) img.set(col, y, colour);
}

void draw_grid_and_marks(Image& img, Font& font, const LinePlot& p, const PlotFrame& f,
                         const Metrics& m) {
  const Rect& a = f.area;
  const Ticks yt = nice_ticks(p.y.lo, p.y.hi, ticks_for(a.h, 5 * m.line / 2));
  for (const double v : yt.values) img.fill_rect({a.x, f.row(v), a.w, 1}, kGrid);
  const Ticks xt = nice_ticks(p.x.lo, p.x.hi, ticks_for(a.w, 5 * p.text_px));
  for (const double v : xt.values) img.fill_rect({f.col(v), a.y, 1, a.h}, kGrid);
  for (const XMark& mark : p.marks) {
    const int col = f.col(mark.x);
    if (col > a.x) dashed_column(img, a, col, kMarkGrey);
    if (!mark.label.empty())
      font.draw(img, mark.label, p.text_px, std::max(col, a.x) + m.gap, a.y + m.gap / 2,
                HAlign::Left, VAlign::Top, kMarkGrey);
  }
}

void draw_axes(Image& img, Font& font, const LinePlot& p, const PlotFrame& f, const Rect& box,
               const Metrics& m) {
  const Rect& a = f.area;
  img.fill_rect({a.x - 1, a.y - 1, a.w + 2, 1}, kInk);
  img.fill_rect({a.x - 1, a.bottom(), a.w + 2, 1}, kInk);
  img.fill_rect({a.x - 1, a.y - 1, 1, a.h + 2}, kInk);
  img.fill_rect({a.right(), a.y - 1, 1, a.h + 2}, kInk);
  const Ticks yt = nice_ticks(p.y.lo, p.y.hi, ticks_for(a.h, 5 * m.line / 2));
  for (std::size_t k = 0; k < yt.values.size(); ++k) {
    const int row = f.row(yt.values[k]);
    img.fill_rect({a.x - 1 - m.tick, row, m.tick, 1}, kInk);
    font.draw(img, yt.labels[k], p.text_px, a.x - 1 - m.tick - m.gap, row, HAlign::Right,
              VAlign::Middle, kInk);
  }
  const Ticks xt = nice_ticks(p.x.lo, p.x.hi, ticks_for(a.w, 5 * p.text_px));
  const int label_top = a.bottom() + 1 + m.tick + m.gap;
  for (std::size_t k = 0; k < xt.values.size(); ++k) {
    const int col = f.col(xt.values[k]);
    img.fill_rect({col, a.bottom() + 1, 1, m.tick}, kInk);
    if (p.x_tick_labels)
      font.draw(img, xt.labels[k], p.text_px, col, label_top, HAlign::Centre, VAlign::Top, kInk);
  }
  if (!p.x_label.empty())
    font.draw(img, p.x_label, p.text_px, a.x + a.w / 2,
              label_top + (p.x_tick_labels ? m.line + m.gap : 0), HAlign::Centre, VAlign::Top,
              kInk);
  if (!p.y_label.empty())
    draw_mask(img, rotate_ccw(font.render(p.y_label, p.text_px)), box.x + m.gap,
              a.y + a.h / 2, HAlign::Left, VAlign::Middle, kInk);
}

// Top right, below the row of mark labels.
void draw_legend(Image& img, Font& font, const LinePlot& p, const PlotFrame& f, const Metrics& m) {
  int entries = 0, label_w = 0;
  for (const Curve& c : p.curves)
    if (!c.label.empty()) ++entries, label_w = std::max(label_w, font.text_width(c.label, p.text_px));
  if (entries == 0) return;
  const int sample = 2 * m.line;
  const Rect box{f.area.right() - 3 * m.gap - sample - label_w - m.gap, f.area.y + m.line + m.gap,
                 3 * m.gap + sample + label_w, entries * m.line + m.gap};
  img.fill_rect(box, kWhite);
  int y = box.y + m.gap / 2 + m.line / 2;
  for (const Curve& c : p.curves) {
    if (c.label.empty()) continue;
    draw_polyline(img, box, {box.x + m.gap, box.x + m.gap + sample}, {y, y}, c.colour, 2);
    font.draw(img, c.label, p.text_px, box.x + 2 * m.gap + sample, y, HAlign::Left,
              VAlign::Middle, kInk);
    y += m.line;
  }
}

// One polyline per run of finite points.
void draw_curve(Image& img, const PlotFrame& f, const Curve& c) {
  std::vector<int> cols, rows;
  const std::size_t n = std::min(c.x.size(), c.y.size());
  for (std::size_t k = 0; k <= n; ++k) {
    if (k < n && std::isfinite(c.x[k]) && std::isfinite(c.y[k])) {
      cols.push_back(f.col(c.x[k]));
      rows.push_back(f.row(c.y[k]));
      continue;
    }
    draw_polyline(img, f.area, cols, rows, c.colour, 2);
    cols.clear();
    rows.clear();
  }
}

void brush(Image& img, const Rect& clip, int x, int y, Rgba colour, int width) {
  for (int dy = -(width - 1) / 2; dy <= width / 2; ++dy)
    for (int dx = -(width - 1) / 2; dx <= width / 2; ++dx)
      if (clip.contains(x + dx, y + dy)) img.set(x + dx, y + dy, colour);
}

}  // namespace

AxisRange axis_range(const std::vector<double>& values, int max_ticks) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double v : values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) return {0, 1};
  if (hi - lo <= 1e-9 * std::max(std::fabs(lo), std::fabs(hi))) {
    const double mid = 0.5 * (lo + hi);
    const double pad = mid == 0 ? 1.0 : 0.1 * std::fabs(mid);
    lo = mid - pad;
    hi = mid + pad;
  }
  const double step = nice_step(hi - lo, max_ticks);
  // The tolerance keeps 0.3 / 0.1 = 2.9999999999999996 on the tick at 0.3.
  return {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step};
}

int PlotFrame::col(double v) const {
  const double t = std::clamp((v - x.lo) / (x.hi - x.lo), -1.0, 2.0);
  return area.x + int(std::lround(t * (area.w - 1)));
}

int PlotFrame::row(double v) const {
  const double t = std::clamp((v - y.lo) / (y.hi - y.lo), -1.0, 2.0);
  return area.bottom() - 1 - int(std::lround(t * (area.h - 1)));
}

int y_axis_width(Font& font, const LinePlot& p) {
  check(p);
  const Metrics m = metrics(font, p.text_px);
  const int title = p.y_label.empty() ? 0 : m.line + m.gap;
  return m.gap + title + widest_label(font, nice_ticks(p.y.lo, p.y.hi, kMaxTicks), p.text_px) +
         m.gap + m.tick + 1;
}

PlotFrame layout_line_plot(Font& font, const LinePlot& p, const Rect& box, int left) {
  check(p);
  const Metrics m = metrics(font, p.text_px);
  const int top = m.line / 2 + 1;  // the top tick label's upper half
  int bottom = 1 + m.tick + m.gap + m.line / 2;
  if (p.x_tick_labels) bottom += m.line;
  if (!p.x_label.empty()) bottom += m.gap + m.line;
  const int right = 2 * m.line;  // the last x tick label's right half
  PlotFrame f{{box.x + left, box.y + top, box.w - left - right, box.h - top - bottom}, p.x, p.y};
  if (f.area.w < 2 * m.line || f.area.h < 2 * m.line) {
    std::ostringstream why;
    why << "a " << box.w << " x " << box.h << " px box cannot hold a plot with " << p.text_px
        << " px text";
    throw InvalidArgument(why.str());
  }
  return f;
}

PlotFrame draw_line_plot(Image& img, Font& font, const LinePlot& p, const Rect& box, int left) {
  const PlotFrame f = layout_line_plot(font, p, box, left);
  const Metrics m = metrics(font, p.text_px);
  draw_grid_and_marks(img, font, p, f, m);
  for (const Curve& c : p.curves) draw_curve(img, f, c);
  if (p.marker && std::isfinite(*p.marker)) {
    const int col = f.col(*p.marker);
    if (f.area.contains(col, f.area.y)) img.fill_rect({col, f.area.y, 2, f.area.h}, kMarkerRed);
  }
  draw_legend(img, font, p, f, m);
  draw_axes(img, font, p, f, box, m);
  return f;
}

// Bresenham between consecutive points; a single point is a dot.
void draw_polyline(Image& img, const Rect& clip, const std::vector<int>& cols,
                   const std::vector<int>& rows, Rgba colour, int width) {
  const std::size_t n = std::min(cols.size(), rows.size());
  if (n == 1) brush(img, clip, cols[0], rows[0], colour, width);
  for (std::size_t k = 1; k < n; ++k) {
    int x = cols[k - 1], y = rows[k - 1];
    const int dx = std::abs(cols[k] - x), dy = -std::abs(rows[k] - y);
    const int sx = x < cols[k] ? 1 : -1, sy = y < rows[k] ? 1 : -1;
    int err = dx + dy;
    while (true) {
      brush(img, clip, x, y, colour, width);
      if (x == cols[k] && y == rows[k]) break;
      const int e2 = 2 * err;
      if (e2 >= dy) err += dy, x += sx;
      if (e2 <= dx) err += dx, y += sy;
    }
  }
}

}  // namespace render
