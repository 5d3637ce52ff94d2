#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render/error.hpp"
#include "render/line_plot.hpp"

namespace render {
namespace {

constexpr Rgba kBlue{31, 119, 180, 255};

bool dark(Rgba c) { return c.r < 128 && c.g < 128 && c.b < 128; }

// A 10 x 10 plot of y = x in a 480 x 320 image.
struct Drawn {
  Image img{480, 320};
  PlotFrame frame;
  int left = 0;
};

Drawn draw(Font& font, const LinePlot& plot) {
  Drawn d;
  d.left = y_axis_width(font, plot);
  d.frame = draw_line_plot(d.img, font, plot, {0, 0, d.img.width(), d.img.height()}, d.left);
  return d;
}

LinePlot diagonal() {
  LinePlot p;
  p.curves.push_back({{0, 10}, {0, 10}, kBlue, "y = x"});
  p.x = {0, 10};
  p.y = {0, 10};
  p.x_label = "time [s]";
  p.y_label = "runout [m]";
  return p;
}

TEST(AxisRange, WidensToMultiplesOfANiceStep) {
  const AxisRange r = axis_range({0.3, 9.7, 4}, 5);
  EXPECT_DOUBLE_EQ(r.lo, 0);
  EXPECT_DOUBLE_EQ(r.hi, 10);
  const AxisRange t = axis_range({-0.3, 0.3}, 6);  // on the ticks already: kept
  EXPECT_NEAR(t.lo, -0.3, 1e-12);
  EXPECT_NEAR(t.hi, 0.3, 1e-12);
}

TEST(AxisRange, DegenerateValuesGetASaneRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::vector<double>& values :
       {std::vector<double>{5}, std::vector<double>{5, 5, 5}, std::vector<double>{5, nan}}) {
    const AxisRange r = axis_range(values, 5);
    EXPECT_LT(r.lo, 5);
    EXPECT_GT(r.hi, 5);
    EXPECT_LE(r.hi - r.lo, 2.0) << "+-10 % of 5, widened to the ticks";
  }
  const AxisRange zero = axis_range({0, 0}, 5);
  EXPECT_DOUBLE_EQ(zero.lo, -1);
  EXPECT_DOUBLE_EQ(zero.hi, 1);
  const AxisRange none = axis_range({nan}, 5);
  EXPECT_DOUBLE_EQ(none.lo, 0);
  EXPECT_DOUBLE_EQ(none.hi, 1);
  EXPECT_DOUBLE_EQ(axis_range({}, 5).hi, 1);
}

TEST(LinePlot, AKnownPolylineLandsOnItsPixels) {
  Font font;
  const Drawn d = draw(font, diagonal());
  const PlotFrame& f = d.frame;
  EXPECT_EQ(f.area.x, d.left);
  EXPECT_EQ(f.col(0), f.area.x);
  EXPECT_EQ(f.col(10), f.area.right() - 1);
  EXPECT_EQ(f.row(0), f.area.bottom() - 1);
  EXPECT_EQ(f.row(10), f.area.y);
  for (const double v : {1.0, 2.5, 5.0, 7.5})
    EXPECT_EQ(d.img.pixel(f.col(v), f.row(v)), kBlue) << v;
  EXPECT_NE(d.img.pixel(f.col(5), f.row(2)), kBlue);
  EXPECT_NE(d.img.pixel(f.col(2), f.row(5)), kBlue);
}

TEST(LinePlot, CurvesStayInsideThePlotArea) {
  Font font;
  LinePlot p = diagonal();
  p.curves[0] = {{0, 10}, {0, 40}, kBlue, ""};  // leaves the top at x = 2.5
  const Drawn d = draw(font, p);
  int outside = 0, inside = 0;
  for (int y = 0; y < d.img.height(); ++y)
    for (int x = 0; x < d.img.width(); ++x)
      if (d.img.at(x, y) == kBlue) (d.frame.area.contains(x, y) ? inside : outside)++;
  EXPECT_EQ(outside, 0);
  EXPECT_GT(inside, d.frame.area.h / 2);
}

// Rows holding dark ink in the columns [x0, x1) and rows [y0, y1).
int ink_rows(const Image& img, int x0, int x1, int y0, int y1) {
  int rows = 0;
  for (int y = std::max(0, y0); y < std::min(img.height(), y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width(), x1); ++x)
      if (dark(img.at(x, y))) {
        ++rows;
        break;
      }
  return rows;
}

TEST(LinePlot, TicksAreLabelledInLegibleText) {
  Font font;
  const Drawn d = draw(font, diagonal());
  const Rect& a = d.frame.area;
  const int line = font.line_height(kMinPlotTextPx);
  // y labels "0", "5", "10" (ticks 2.5 lines apart at most) left of the
  // axis: digits at least 12 px tall.
  for (const double v : {0.0, 5.0, 10.0}) {
    const int row = d.frame.row(v);
    const int rows = ink_rows(d.img, line + 4, a.x - 8, row - line / 2, row + line / 2);
    EXPECT_GE(rows, 12) << "label of y = " << v;
  }
  // x labels below the axis.
  const int below = a.bottom() + 8;
  EXPECT_GE(ink_rows(d.img, d.frame.col(5) - 6, d.frame.col(5) + 6, below, below + line), 12);

  LinePlot stacked = diagonal();
  stacked.x_tick_labels = false;
  stacked.x_label.clear();
  const Drawn s = draw(font, stacked);
  EXPECT_EQ(ink_rows(s.img, s.frame.col(5) - 6, s.frame.col(5) + 6, s.frame.area.bottom() + 8,
                     s.img.height()),
            0)
      << "a plot stacked above another shows no x labels";
}

TEST(LinePlot, MarkerAndStageMarks) {
  Font font;
  LinePlot p = diagonal();
  p.marker = 6.0;
  p.marks = {{0, "gravity"}, {4, "slide"}};
  const Drawn d = draw(font, p);
  const PlotFrame& f = d.frame;
  const Rgba red = d.img.pixel(f.col(6), f.row(1));
  EXPECT_GT(red.r, 200);
  EXPECT_LT(red.g, 80);
  int dashes = 0;
  for (int y = f.area.y; y < f.area.bottom(); ++y) dashes += d.img.at(f.col(4), y) != kWhite;
  EXPECT_GT(dashes, f.area.h / 3);
  EXPECT_LT(dashes, f.area.h) << "dashed, not solid";
}

TEST(LinePlot, OneRowOrAConstantSeriesDraws) {
  Font font;
  LinePlot one;
  one.curves.push_back({{3}, {7}, kBlue, "one row"});
  one.x = axis_range({3}, 5);
  one.y = axis_range({7}, 5);
  const Drawn d = draw(font, one);
  EXPECT_EQ(d.img.pixel(d.frame.col(3), d.frame.row(7)), kBlue);

  LinePlot flat;
  flat.curves.push_back({{0, 5, 10}, {7, 7, 7}, kBlue, ""});
  flat.x = axis_range({0, 10}, 5);
  flat.y = axis_range({7, 7, 7}, 5);
  const Drawn c = draw(font, flat);
  const int row = c.frame.row(7);
  EXPECT_GT(row, c.frame.area.y);
  EXPECT_LT(row, c.frame.area.bottom() - 1);
  for (const double x : {0.5, 5.0, 9.5}) EXPECT_EQ(c.img.pixel(c.frame.col(x), row), kBlue);
}

TEST(LinePlot, RefusesWhatItCannotDraw) {
  Font font;
  Image img(480, 320);
  LinePlot small_text = diagonal();
  small_text.text_px = 10;
  EXPECT_THROW(y_axis_width(font, small_text), InvalidArgument);
  LinePlot empty = diagonal();
  empty.y = {1, 1};
  EXPECT_THROW(draw_line_plot(img, font, empty, {0, 0, 480, 320}, 60), InvalidArgument);
  EXPECT_THROW(draw_line_plot(img, font, diagonal(), {0, 0, 80, 40}, 60), InvalidArgument);
}

}  // namespace
}  // namespace render
