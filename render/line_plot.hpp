#pragma once
// Line plots of quantities against one x axis (time), for report figures:
// a plot rectangle with nice ticks on both axes, tick labels and axis titles,
// polylines clipped to the rectangle, dashed vertical marks with labels
// (stage boundaries), a solid marker line (the time of a frame) and a
// legend. Plots stacked in one image share their x range and their left
// margin (the widest y_axis_width), so their x axes line up.
#include <optional>
#include <string>
#include <vector>

#include "render/font.hpp"
#include "render/image.hpp"

namespace render {

// Smallest text a plot draws, in pixels of em size: DejaVu's digits are then
// 12 px tall (0.73 em).
constexpr int kMinPlotTextPx = 17;

struct AxisRange {
  double lo = 0, hi = 1;
};

// [min, max] of the finite values, widened outward to multiples of a nice
// step (about max_ticks intervals). Values all equal (or just one) get
// +-10 % around them, +-1 around 0; no finite value at all gives [0, 1].
AxisRange axis_range(const std::vector<double>& values, int max_ticks);

struct Curve {
  std::vector<double> x, y;  // the same length; a non-finite value breaks the line
  Rgba colour = kBlack;
  std::string label;  // listed in the legend; "": not listed
};

struct XMark {
  double x = 0;
  std::string label;  // written at the top of the plot, right of the line
};

struct LinePlot {
  std::vector<Curve> curves;
  AxisRange x, y;  // the ranges shown (see axis_range); lo < hi
  std::string x_label, y_label;
  bool x_tick_labels = true;  // false: ticks only, for a plot stacked above another
  std::vector<XMark> marks;
  std::optional<double> marker;
  int text_px = kMinPlotTextPx;  // every text; at least kMinPlotTextPx
};

// Where the data of a laid-out plot lands: x.lo on the area's left column,
// x.hi on its right one, y.lo on its bottom row, y.hi on its top one.
struct PlotFrame {
  Rect area;
  AxisRange x, y;
  int col(double v) const;
  int row(double v) const;
};

// Pixels left of the plot area that its y tick labels and title need.
int y_axis_width(Font& font, const LinePlot& plot);

// The plot area inside `box` with `left` pixels (at least y_axis_width)
// for the y axis. Throws InvalidArgument for an empty range, text below
// kMinPlotTextPx, or a box too small to hold a plot.
PlotFrame layout_line_plot(Font& font, const LinePlot& plot, const Rect& box, int left);
PlotFrame draw_line_plot(Image& img, Font& font, const LinePlot& plot, const Rect& box, int left);

// Straight segments between the points (pixel coordinates), `width` px
// wide, drawn only inside `clip`.
void draw_polyline(Image& img, const Rect& clip, const std::vector<int>& cols,
                   const std::vector<int>& rows, Rgba colour, int width);

}  // namespace render
