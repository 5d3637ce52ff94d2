// A log-log scatter plot drawn with the project's own render layers (Image,
// Font, ColourMap::categorical): decade grid, one marker colour per series,
// points of one series joined in the order given, an optional horizontal
// threshold line and a ring round one highlighted point. Local to bench/:
// the accuracy study is its only user.
#pragma once

#include <string>
#include <vector>

#include "render/font.hpp"
#include "render/image.hpp"

namespace bench {

struct PlotPoint {
  double x = 0, y = 0;  // both > 0; others are skipped (a zero error cannot be drawn)
  int series = 0;       // index into LogLogPlot::series
  int shape = 0;        // 0 disc, 1 square, 2 diamond (a second attribute, e.g. points per cell)
  int group = 0;        // points of one series and group are joined by a line
  std::string label;    // small grey text beside the marker (e.g. the cell count), or empty
};

struct LogLogPlot {
  std::string title, x_label, y_label;
  std::vector<std::string> series;       // legend entries, colours in this order
  std::vector<std::string> shape_names;  // legend entries for the shapes (empty: one shape)
  std::vector<PlotPoint> points;
  double threshold = 0;  // y of a dashed horizontal line; 0 for none
  std::string threshold_label;
  int highlight = -1;    // index into points ringed in red, or -1
  std::string highlight_label;
};

// Draws the plot into `area` of `image` (white background, legend on the right).
void draw_loglog(render::Image& image, const render::Rect& area, const LogLogPlot& plot,
                 render::Font& font);

}  // namespace bench
